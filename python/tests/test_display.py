"""Notebook friendliness: short reprs and HTML tables with units for every result object, the
overview figures ``tr.plot()`` and ``sol.plot()``, and angles in degrees on request (radians stay the
default)."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl


@pytest.fixture
def run(pendulum: pl.Pendulum, rosette: pl.State) -> pl.Trajectory:
    return pl.simulate(pendulum, rosette, t_end=2.0, dt=1e-3, save_every=10)


def test_reprs_are_short_and_carry_units(
    pendulum: pl.Pendulum, rosette: pl.State, run: pl.Trajectory
) -> None:
    sol = pl.exact(pendulum, rosette)
    ens = pl.simulate_ensemble(pendulum, np.stack([rosette.as_array()] * 3), t_end=0.1, dt=1e-3)
    spring = pl.simulate_spring(pl.SwingingSpring.resonant(), [0.1, 0.0, -1.0], [0.0, 0.1, 0.0], 1.0, dt=1e-3)
    sw = pl.sweep({"theta0": np.linspace(0.2, 1.0, 4)}, "period")
    for obj, words in [
        (rosette, ["θ=60°", "m/s"]),
        (run, ["rattle", "201 samples", "t = 0 … 2 s", "kg m²/s"]),
        (sol, ["generic", "T_z =", " s"]),
        (ens, ["3 trajectories", "100 steps"]),
        (spring, ["samples", " m"]),
        (sw, ["4 points", "period"]),
    ]:
        text = repr(obj)
        assert len(text) < 250, text
        for w in words:
            assert w in text, (w, text)
        page = obj._repr_html_()
        assert page.startswith("<div class='pendulab'>") and "<table" in page
    assert "m/s²" in pendulum._repr_html_() and "rad/s" in pendulum._repr_html_()
    # the small-swing period 2π√(l/g) is among the pendulum's key numbers
    assert f"{2 * math.pi * math.sqrt(1.0 / 9.81):.6g}" in pendulum._repr_html_()
    assert "1.6" in sol._repr_html_() or "T_z" in sol._repr_html_()


def test_html_escapes_what_it_shows() -> None:
    from pendulab.display import html_table

    page = html_table("<b>", [("a<b", "x&y", "m")])
    assert "<b>" not in page.replace("<b>&lt;b&gt;</b>", "") and "a&lt;b" in page and "x&amp;y" in page


def test_energy_drift_in_the_repr_is_the_summary_figure(run: pl.Trajectory) -> None:
    p = run.pendulum
    drift = float(np.max(np.abs(run.energy - run.energy[0])) / (p.mass * abs(p.g) * p.length))
    assert f"{drift:.3g}" in repr(run)


def test_degrees_on_request(pendulum: pl.Pendulum) -> None:
    a = pendulum.state_from_angles(np.radians(60), np.radians(30), 0.1, np.radians(90))
    b = pendulum.state_from_angles(theta_deg=60, phi_deg=30, theta_dot=0.1, phi_dot_deg=90)
    np.testing.assert_allclose(a.as_array(), b.as_array(), rtol=1e-15, atol=1e-15)
    theta, phi = b.angles_deg()
    assert theta == pytest.approx(60.0, abs=1e-12) and phi == pytest.approx(30.0, abs=1e-12)
    with pytest.raises(pl.InvalidInputError, match=r"either in radians .* or in degrees"):
        pendulum.state_from_angles(theta=1.0, theta_deg=60)
    with pytest.raises(pl.InvalidInputError, match="theta"):
        pendulum.state_from_angles()
    with pytest.raises(pl.InvalidInputError, match=r"invalid theta_deg = '60': .* degrees"):
        pendulum.state_from_angles(theta_deg="60")


def test_radians_stay_the_default_but_a_big_theta_is_warned_about(pendulum: pl.Pendulum) -> None:
    with pytest.warns(UserWarning, match="theta_deg=60") as said:
        s = pendulum.state_from_angles(theta=60)
    with pytest.warns(UserWarning, match="theta_deg=7.0") as more:
        pl.states_from_angles(pendulum, theta=[0.5, 7.0])  # the same check, one start at a time
    assert [w.filename for w in [*said, *more]] == [__file__, __file__]  # the caller's line
    assert s.angles()[0] == pytest.approx(abs(math.remainder(60.0, 2 * math.pi)), abs=1e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pendulum.state_from_angles(theta=3.0)


def test_trajectory_plot_draws_path_height_and_drifts(run: pl.Trajectory, tmp_path: Path) -> None:
    pytest.importorskip("matplotlib")
    fig = run.plot(tmp_path / "run.png")
    assert (tmp_path / "run.png").stat().st_size > 10_000
    _, axz, axd = fig.axes[:3]
    assert axz.get_ylabel() == "height z [m]" and axd.get_xlabel() == "time t [s]"
    assert axd.get_yscale() == "log"
    np.testing.assert_array_equal(axz.lines[0].get_ydata(), run.x[:, 2])
    labels = [line.get_label() for line in axd.lines]
    assert "float64 ε" in labels and any("J₃" in lab for lab in labels)


def test_exact_plot_marks_the_turning_heights(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    pytest.importorskip("matplotlib")
    sol = pl.exact(pendulum, rosette)
    fig = sol.plot()
    axz = fig.axes[1]
    z = axz.lines[0].get_ydata()
    z1, z2 = sol.turning_heights[:2]
    dashed = sorted(float(line.get_ydata()[0]) for line in axz.lines[1:3])
    assert dashed == pytest.approx([z1, z2], abs=1e-15)
    # the exact path touches both turning heights within three z-periods, and never leaves them
    assert z.min() == pytest.approx(z1, abs=1e-6) and z.max() == pytest.approx(z2, abs=1e-6)
    assert z.min() >= z1 - 1e-12 and z.max() <= z2 + 1e-12
