"""The slewing crane's linear theory (docs/theory.md T-7.2) against the nonlinear model: the closed-form
static offset ω²R/(ω₀² − ω² + icω) and the track of a damped run, and the natural frequencies ω₀ ± ω
as the two spectral peaks (FFT) of a small undamped sway; the resonance ω = ω₀ is refused; the
payload track in the boom frame (``Trajectory.boom``) from Python and in files. SI units."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl

G = 9.81


def test_static_offset_and_damped_track_match_the_nonlinear_model() -> None:
    p = pl.Pendulum(model="slewing", radius=0.02, rate=0.5, damping=0.2)  # m, rad/s, 1/s
    s0 = p.state([0.0, 0.0, -1.0], [0.0, 0.0, 0.0])
    tr = pl.simulate(p, s0, 150.0, method="rattle4", dt=5e-3, save_every=100)
    sway = pl.slewing_sway(p, tr.t, s0)
    w, w0sq, c = 0.5, G, 0.2
    offset = w * w * 0.02 / complex(w0sq - w * w, c * w)
    assert sway.static_offset == pytest.approx((offset.real, offset.imag), rel=1e-15)
    assert offset.real == pytest.approx(w * w * 0.02 / (w0sq - w * w), rel=2e-4)  # T-7.2 for small c
    assert tr.boom is not None
    # transients have decayed as e^{−ct/2} = 3e-7; what is left is the nonlinearity, O(offset²/l²)
    assert tr.boom[-1, 0] == pytest.approx(offset.real, rel=1e-6)
    assert tr.boom[-1, 1] == pytest.approx(offset.imag, rel=1e-4)
    # the whole track: the linear theory is exact to O(offset³/l²) here
    assert np.max(np.abs(tr.boom[:, 0] - sway.radial)) < 2e-5 * offset.real
    assert np.max(np.abs(tr.boom[:, 1] - sway.tangential)) < 2e-5 * offset.real


def test_natural_frequencies_are_the_spectral_peaks_of_a_small_sway() -> None:
    p = pl.Pendulum(model="slewing", radius=0.0, rate=0.5)
    theta0 = 0.02  # rad
    s0 = p.state_from_angles(theta0, 0.0, 0.0, 0.0)
    tr = pl.simulate(p, s0, 200.0, method="rattle4", dt=1e-3, save_every=20)  # samples every 0.02 s
    sway = pl.slewing_sway(p, tr.t, s0)
    w0, w = math.sqrt(G), 0.5
    assert sway.frequencies == pytest.approx((w0 - w, w0 + w), rel=1e-15)
    radial = tr.boom[:, 0]
    n_pad = 16 * len(radial)
    spectrum = np.abs(np.fft.rfft(radial - radial.mean(), n_pad))
    omega = 2 * np.pi * np.fft.rfftfreq(n_pad, d=0.02)
    inner = np.flatnonzero((spectrum[1:-1] > spectrum[:-2]) & (spectrum[1:-1] > spectrum[2:])) + 1
    top = np.sort(omega[inner[np.argsort(spectrum[inner])[-2:]]])
    resolution = 2 * np.pi / 200.0
    assert np.all(np.abs(top - np.array(sway.frequencies)) < resolution), (top, sway.frequencies)
    # the track itself, over 20 s: apart from the amplitude's frequency shift ω₀θ₀²/16 (nonlinear),
    # the same; bound twice the phase drift it causes
    early = tr.t <= 20.0
    bound = 2 * theta0 * (w0 * theta0**2 / 16) * 20.0
    assert np.max(np.abs(tr.boom[early, 0] - sway.radial[early])) < bound
    assert np.max(np.abs(tr.boom[early, 1] - sway.tangential[early])) < bound


def test_resonance_and_bad_input_are_refused() -> None:
    resonant = pl.Pendulum(model="slewing", radius=5.0, rate=math.sqrt(G / 1.0))
    with pytest.raises(pl.InvalidInputError, match="resonance"):
        pl.slewing_sway(resonant, [0.0, 1.0])
    damped = pl.Pendulum(model="slewing", radius=5.0, rate=math.sqrt(G), damping=0.1)
    assert np.isfinite(pl.slewing_sway(damped, [0.0, 1.0]).radial).all()  # damping bounds it
    with pytest.raises(pl.InvalidInputError, match="model='slewing'"):
        pl.slewing_sway(pl.Pendulum(), [0.0])
    with pytest.raises(pl.InvalidInputError, match="underdamped"):
        pl.slewing_sway(pl.Pendulum(model="slewing", damping=7.0), [0.0])
    with pytest.raises(pl.InvalidInputError, match="non-finite"):
        pl.slewing_sway(pl.Pendulum(model="slewing"), [0.0, float("nan")])


def test_boom_frame_in_trajectories_and_files(tmp_path: Path) -> None:
    p = pl.Pendulum(model="slewing", radius=2.0, rate=0.4)
    tr = pl.simulate(p, p.state_from_angles(0.1, 0.3, 0.0, 0.0), 1.0, dt=1e-3, save_every=100)
    assert tr.boom is not None
    rot = tr.t * 0.4
    np.testing.assert_allclose(tr.boom[:, 0], tr.x[:, 0] * np.cos(rot) + tr.x[:, 1] * np.sin(rot), atol=1e-15)
    np.testing.assert_allclose(np.linalg.norm(tr.boom, axis=1), 1.0, atol=1e-14)
    np.testing.assert_array_equal(tr.sway_angle, tr.theta)
    header = (tr.save(tmp_path / "crane.csv")).read_text().splitlines()[1]
    assert "boom_radial [m]" in header and "boom_tangential [m]" in header
    plain = pl.simulate(pl.Pendulum(), pl.Pendulum().state_from_angles(0.1), 0.1)
    assert plain.boom is None


def circle_samples(radius: float, rate: float, step: float, t_end: float) -> tuple[np.ndarray, np.ndarray]:
    """The slewing circle p(t) = R(cos ωt, sin ωt, 0) [m] sampled every ``step`` [s] on [0, t_end]."""
    t = np.arange(0.0, t_end + step / 2, step)
    return t, np.column_stack([radius * np.cos(rate * t), radius * np.sin(rate * t), np.zeros_like(t)])


def test_pivot_given_as_samples_follows_the_analytic_path() -> None:
    """Spline through the slewing circle every 10 ms: the same run as the analytic path, to a stated
    1e-8 m and 5e-8 m/s after 10 s (the spline's p̈ is accurate to O(h²), 2.9e-6 m/s² here)."""
    exact = pl.Pendulum(model="slewing", radius=5.0, rate=0.3)
    sampled = pl.Pendulum(pivot_samples=circle_samples(5.0, 0.3, 0.01, 12.0))
    assert sampled.model == "sampled_pivot" and "sampled_pivot" in {m["name"] for m in pl.models()}
    s0 = exact.state_from_angles(0.3, 0.0, 0.0, 0.5)
    a = pl.simulate(exact, s0, 10.0, method="rattle4", dt=1e-3, save_every=1000)
    b = pl.simulate(sampled, s0, 10.0, method="rattle4", dt=1e-3, save_every=1000)
    assert np.max(np.abs(a.x - b.x)) < 1e-8 and np.max(np.abs(a.v - b.v)) < 5e-8
    assert b.pivot is not None and np.max(np.abs(a.pivot - b.pivot)) < 1e-7  # spline position O(h⁴)
    assert np.max(np.abs(a.power - b.power)) < 1e-5  # p̈·v with the spline's p̈


@pytest.mark.parametrize(
    ("samples", "needle"),
    [
        ((np.array([0.0, 1.0, 2.0]), np.zeros((3, 3))), "at least 4"),
        ((np.array([0.0, 1.0, 0.5, 2.0]), np.zeros((4, 3))), "strictly increasing"),
        ((np.array([0.0, 1.0, np.nan, 2.0]), np.zeros((4, 3))), "finite"),
        (
            (np.arange(4.0), np.array([[0, 0, 0], [0, np.inf, 0], [0, 0, 0], [0, 0, 0]])),
            r"positions\[1\]\[1\] = inf",
        ),
        ((np.arange(4.0), np.zeros((4, 2))), "shape"),
        ((np.arange(5.0), np.zeros((4, 3))), "5 times but 4 positions"),
    ],
)
def test_bad_pivot_samples_are_refused(samples: tuple[np.ndarray, np.ndarray], needle: str) -> None:
    with pytest.raises(pl.InvalidInputError, match=needle):
        pl.Pendulum(pivot_samples=samples)


def test_a_run_must_stay_within_the_samples() -> None:
    p = pl.Pendulum(pivot_samples=circle_samples(1.0, 0.3, 0.1, 2.0))
    with pytest.raises(pl.InvalidInputError, match="span"):
        pl.simulate(p, p.state_from_angles(0.1), 3.0)
    with pytest.raises(pl.InvalidInputError, match="pivot times"):
        pl.Pendulum(model="sampled_pivot")
    with pytest.raises(pl.InvalidInputError, match="damping"):
        pl.Pendulum(pivot_samples=circle_samples(1.0, 0.3, 0.1, 2.0), rate=0.1)


def test_sampled_pivot_in_scenario_files() -> None:
    t, p = circle_samples(2.0, 0.3, 0.05, 1.0)
    head = 'title = "s"\n[pendulum]\nmodel = "sampled_pivot"\nlength = 1.0\nmass = 1.0\n'
    arrays = f"pivot_times = {t.tolist()!r}\npivot_positions = {p.tolist()!r}\n"
    tail = "[initial]\ntheta_deg = 10.0\n[simulation]\nt_end = {t_end}\ndt = 1e-3\n"
    sc = pl.Scenario.from_toml_str(head + arrays + tail.format(t_end=1.0))
    assert pl.Scenario.from_toml_str(sc.to_toml()) == sc
    reference = pl.simulate(pl.Pendulum(pivot_samples=(t, p)), sc.initial_state(), 1.0)
    np.testing.assert_array_equal(sc.run(progress=False).x, reference.x)
    with pytest.raises(pl.ScenarioError, match="span"):
        pl.Scenario.from_toml_str(head + arrays + tail.format(t_end=2.0))
    with pytest.raises(pl.ScenarioError, match="needs pivot_times"):
        pl.Scenario.from_toml_str(head + tail.format(t_end=1.0))
    with pytest.raises(pl.ScenarioError, match="belong to model 'sampled_pivot'"):
        pl.Scenario.from_toml_str(head.replace("sampled_pivot", "slewing") + arrays + tail.format(t_end=1.0))
    with pytest.raises(pl.ScenarioError, match="strictly increasing"):
        bad = arrays.replace("0.05,", "0.5,", 1)
        pl.Scenario.from_toml_str(head + bad + tail.format(t_end=1.0))


def test_vanishing_extras_reduce_to_the_ideal_pendulum(pendulum: pl.Pendulum) -> None:
    """A pivot sampled at rest is the ideal pendulum bit for bit; the linear sway with R = ω = 0 is the
    small-oscillation pendulum x₀ cos ω₀t + (ẋ₀/ω₀) sin ω₀t."""
    t = np.linspace(0.0, 3.0, 7)
    at_rest = pl.Pendulum(pivot_samples=(t, np.zeros((7, 3))))
    s0 = pendulum.state_from_angles(0.4, 0.2, 0.1, 1.0)
    for method in ("rattle", "rattle4", "dop853"):
        a = pl.simulate(pendulum, s0, 3.0, method=method)
        b = pl.simulate(at_rest, s0, 3.0, method=method)
        np.testing.assert_array_equal(a.x, b.x)
        np.testing.assert_array_equal(a.v, b.v)
    still = pl.Pendulum(model="slewing", radius=0.0, rate=0.0)
    small = still.state([0.01, 0.0, -math.sqrt(1 - 1e-4)], [0.0, 0.0, 0.0], project=True)
    times = np.linspace(0.0, 5.0, 11)
    sway = pl.slewing_sway(still, times, small)
    w0 = math.sqrt(G)
    np.testing.assert_allclose(sway.radial, small.x[0] * np.cos(w0 * times), rtol=0, atol=1e-15)
    np.testing.assert_allclose(sway.tangential, 0.0, atol=1e-15)
    assert sway.static_offset == (0.0, 0.0) and sway.frequencies == pytest.approx((w0, w0), rel=1e-15)
