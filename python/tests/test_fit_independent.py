"""``pl.fit`` with a user's defaults (``sigma`` left out) on data from an independent integrator
(``testdata/generate/independent_pendulum.py``: SciPy DOP853 of a hand-written Cartesian model with a
Lagrange multiplier, no Pendulab code): the truth within a few stderr on a few seeds, a warning when
the model lacks what made the data, a clear answer on degenerate data, and no dependence on the unit
of the numbers. Coverage needs many trials: ``bench/fit_validate.py`` (docs/fit.md, "Validation").
SI units (m, s, rad, m/s²).
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "testdata" / "generate"))
import independent_pendulum as ip

LIMIT = 30.0  # s of search per fit: a bound, not a speed target
#: Warnings that say the search stopped, not that the data disagree with the model.
NOT_A_DIAGNOSIS = ("time limit", "did not converge", "interrupted", "encountered")
VIDEO = ip.Truth(length=0.6, g=9.81, damping=0.010)
PIVOT = (0.31, 0.0, 1.25)


def _video(truth: ip.Truth, seed: int, start: tuple = (0.5, 0.0, 0.0, 0.8), **kw: float) -> tuple:
    """A filmed elliptical swing seen from the side (x, z), from mid-swing at 1.3 s, 30 fps, 12 s,
    σ 1.5 mm, the pivot off the origin."""
    t = 1.3 + np.arange(0.0, 12.0, 1 / 30)
    x, _, _, _ = ip.simulate(truth, ip.start_state(truth, *start), t)
    rng = np.random.default_rng(seed)
    return t, ip.measure_positions(x, rng, 1.5e-3, PIVOT, (0, 2), **kw)


def _fit(t: np.ndarray, pos: np.ndarray, fit: list[str], **kw: object) -> tuple[pl.FitResult, list[str]]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(t, positions=pos, pendulum=pl.Pendulum(model="damped"), fit=fit, time_limit=LIMIT, **kw)
    return res, _said(caught, res)


def _said(caught: list, res: object) -> list[str]:
    """The fit's diagnoses: its warnings (and ``res.warnings`` if it has them), without those that
    only say the search stopped."""
    said = [str(w.message) for w in caught] + [str(m) for m in getattr(res, "warnings", []) or []]
    return [m for m in said if not any(s in m for s in NOT_A_DIAGNOSIS)]


def test_the_generator_is_exact() -> None:
    """Its own checks (a planar swing's exact period 4K/ω₀, energy, J_z, |x| = l, the work balance with
    every force on) and agreement with Pendulab's exact solution on an elliptical swing."""
    errors = ip.check()
    assert max(errors.values()) < 1e-9, errors
    p = pl.Pendulum(length=0.8, g=9.79)
    s = p.state_from_angles(0.7, 0.3, 0.2, 1.1)
    t = np.linspace(0.0, 20.0, 401)
    x_ref, v_ref = pl.exact(p, s).state(t)
    x, v, _, _ = ip.simulate(ip.Truth(length=0.8, g=9.79), (np.asarray(s.x), np.asarray(s.v)), t)
    assert np.max(np.abs(x - x_ref)) < 1e-9 * 0.8
    assert np.max(np.abs(v - v_ref)) < 1e-8


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_truth_within_a_few_stderr_with_sigma_left_out(seed: int) -> None:
    t, pos = _video(VIDEO, seed)
    res, said = _fit(t, pos, ["length", "g", "damping", "pivot"])
    truth = {"length": 0.6, "g": 9.81, "damping": 0.010, "pivot_x": PIVOT[0], "pivot_z": PIVOT[2]}
    for name, value in truth.items():
        assert res.determined[name], name
        assert abs(res.params[name] - value) <= 3.5 * res.stderr[name], (
            name,
            res.params[name],
            res.stderr[name],
        )
    assert not said, said  # the model is right: no false alarm


def test_the_wrong_damping_law_is_said() -> None:
    """Quadratic drag fitted with viscous damping: the misfit is ≫ the noise, so a warning."""
    t, pos = _video(ip.Truth(length=0.6, drag=0.3), 4, start=(0.9, 0.0, 0.0, 0.3))
    _, said = _fit(t, pos, ["length", "g", "damping", "pivot"])
    assert said


def test_a_wrong_damping_law_is_a_misfit_not_outliers() -> None:
    """An encoder's swing with quadratic drag fitted with viscous damping: the fit misses the first
    swings most, a smooth run of residuals 5-8 robust standard deviations out. That is a misfit to be
    said as one; it was also called outliers with the advice loss='soft_l1', which fits worse and
    leaves the misfit."""
    truth = ip.Truth(length=0.8, drag=0.5)
    t = np.arange(0.0, 30.0, 0.02)
    x, _, _, _ = ip.simulate(truth, ip.start_state(truth, 0.9, 0.0, -0.5), t)
    angle = ip.measure_encoder(x, np.random.default_rng(0), sigma=0.003)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(
            t,
            planar_angle=angle,
            pendulum=pl.Pendulum(model="damped", g=9.81),
            fit=["length", "damping"],
            time_limit=LIMIT,
        )
    said = _said(caught, res)
    assert any("misses the data systematically" in m for m in said), said
    assert not any("outliers" in m or "soft_l1" in m for m in said), said


def test_outliers_with_the_plain_loss_are_said() -> None:
    t, pos = _video(VIDEO, 5, outlier_fraction=0.1)
    _, said = _fit(t, pos, ["length", "g", "damping", "pivot"])
    assert said


def _constant(seed: int, value: tuple[float, ...], sigma: float) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    t = np.arange(300) / 30.0
    return t, np.tile(value, (300, 1)) + sigma * rng.standard_normal((300, len(value)))


DEGENERATE = [
    pytest.param(
        "constant 3-D positions + noise",
        (0.0, 0.0, -1.0),
        1e-3,
        ["length", "g"],
    ),
    pytest.param("constant 3-D positions, no noise", (0.0, 0.0, -1.0), 0.0, ["length", "g"]),
    pytest.param(
        "bob at rest, x z, pivot unknown",
        (0.31, 0.65),
        1.5e-3,
        ["length", "g", "damping", "pivot"],
    ),
]


@pytest.mark.parametrize(("what", "value", "sigma", "fit"), DEGENERATE)
def test_degenerate_data_get_a_clear_answer_in_seconds(
    what: str, value: tuple, sigma: float, fit: list
) -> None:
    """A clear error, a warning, or g reported as not determined — never another exception or a
    confident number."""
    t, pos = _constant(6, value, sigma)
    began = time.perf_counter()
    try:
        res, said = _fit(t, pos, fit)
    except pl.InvalidInputError as e:
        assert str(e)
        return
    finally:
        assert time.perf_counter() - began < 2 * LIMIT + 30
    assert said or not res.determined["g"], (what, res.params["g"], res.stderr["g"])


def test_pure_noise_as_a_planar_angle_gets_a_clear_answer() -> None:
    rng = np.random.default_rng(7)
    t = np.arange(0.0, 20.0, 0.02)
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            res = pl.fit(
                t,
                planar_angle=0.01 * rng.standard_normal(len(t)),
                pendulum=pl.Pendulum(model="damped", length=0.5),
                fit=["g", "damping"],
                time_limit=LIMIT,
            )
    except pl.InvalidInputError:
        return
    assert _said(caught, res) or not res.determined["g"], res.params


def test_the_fit_does_not_depend_on_the_unit() -> None:
    """The same swing in m and in mm: the same values (scaled) and error bars, to 0.1 stderr."""
    t, pos = _video(VIDEO, 8)
    res, _ = _fit(t, pos, ["length", "g", "damping", "pivot"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mm = pl.fit(
            t,
            positions=pos * 1e3,
            pendulum=pl.Pendulum(model="damped", length=1e3, g=9810.0),
            fit=["length", "g", "damping", "pivot"],
            time_limit=LIMIT,
        )
    scale = {"length": 1e3, "g": 1e3, "damping": 1.0, "pivot_x": 1e3, "pivot_z": 1e3}
    for name, k in scale.items():
        assert abs(mm.params[name] / k - res.params[name]) < 0.1 * res.stderr[name], name
        assert mm.stderr[name] / k == pytest.approx(res.stderr[name], rel=0.01), name


REAL = Path(__file__).resolve().parents[2] / "testdata" / "real"


@pytest.mark.parametrize(
    ("name", "step"), [("multiarm_single_small_decay", 5), ("multiarm_single_large_decay", 4)]
)
def test_a_real_decay_with_dry_friction_says_the_model_lacks_something(name: str, step: int) -> None:
    """Real encoder recordings (testdata/real/README.md: MIT-licensed, by others) whose amplitude
    decays by dry friction and drag: viscous damping alone must not pass silently."""
    d = np.loadtxt(REAL / f"{name}.csv", delimiter=",", comments="#", skiprows=4)
    t, angle = d[::step, 0], d[::step, 1]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(
            t,
            planar_angle=angle,
            pendulum=pl.Pendulum(model="damped", g=9.81, length=0.15),
            fit=["length", "damping"],
            time_limit=LIMIT,
        )
    assert _said(caught, res)


def test_a_planar_swing_starting_on_the_negative_side() -> None:
    """An encoder's swing released at rest at −0.5 rad (no noise): the planar angle is signed, so the
    fit must find it as it finds the mirror image at +0.5 rad (to 1e-6)."""
    truth = ip.Truth(length=0.155, damping=0.03)
    t = np.arange(0.0, 10.0, 0.02)
    x, _, _, _ = ip.simulate(truth, ip.start_state(truth, -0.5), t)
    res = pl.fit(
        t,
        planar_angle=np.arctan2(x[:, 0], -x[:, 2]),
        pendulum=pl.Pendulum(model="damped", g=9.81, length=0.15),
        fit=["length", "damping"],
        time_limit=LIMIT,
    )
    assert res.params["length"] == pytest.approx(0.155, rel=1e-6)
    assert res.params["damping"] == pytest.approx(0.03, rel=1e-6)
