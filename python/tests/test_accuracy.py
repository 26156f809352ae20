"""Error estimates (``simulate(..., error_estimate=True)``), runs to a requested accuracy
(``accuracy=``) and the Weierstrass form of the exact solution (issue 17). SI units.

The estimates are checked against the true error from the exact solution (``tr.error``, T-4.x) for
every registered method; the validation on 34 hard 40-digit cases is ``test_accuracy_hard_cases.py``.
"""

from __future__ import annotations

import numpy as np
import pytest

import pendulab as pl

IDEAL = pl.Pendulum(length=1.0, g=9.81)
START = IDEAL.state_from_angles(theta=np.radians(60), phi_dot=2.0)

# A step per method where its error is well above round-off over 20 s but the method is stable.
STEPS = {
    "rk4": 2e-3,
    "rattle": 1e-3,
    "rattle4": 1e-2,
    "rattle6": 2e-2,
    "rattle8": 4e-2,
    "rkmk4": 2e-3,
    "rk4_angles": 2e-3,
}


@pytest.mark.parametrize("method", pl.method_names())
def test_the_estimate_is_within_a_factor_two_of_the_true_error_for_every_method(method: str) -> None:
    kw = {"rtol": 1e-9} if method == "dop853" else {"dt": STEPS[method]}
    tr = pl.simulate(IDEAL, START, 20.0, method=method, save_every=20, error_estimate=True, **kw)
    est, true = tr.error_estimate, tr.error
    assert est is not None and true is not None
    assert est.how == ("companion" if method == "dop853" else "richardson")
    assert est.position.shape == tr.t.shape and est.velocity.shape == tr.t.shape
    assert true.max_position > 1e-11, f"{method}: choose a coarser step, error {true.max_position:e}"
    big = true.position > 0.1 * true.max_position
    ratio = est.position[big] / true.position[big]
    assert ratio.min() > 0.5 and ratio.max() < 2.0, (
        f"{method}: estimate/true in [{ratio.min()}, {ratio.max()}]"
    )
    # the reference run's work: 2x for the half step, at most 2.5x for the companion
    assert est.cost <= 2.5, f"{method}: reference run cost {est.cost:.2f}x the plain run"


def test_other_models_get_an_estimate_and_no_true_error() -> None:
    damped = pl.Pendulum(length=1.0, g=9.81, model="damped", damping=0.2)
    s0 = damped.state_from_angles(theta=1.0, phi_dot=1.0)
    tr = pl.simulate(damped, s0, 5.0, method="rattle4", dt=1e-2, error_estimate=True)
    assert tr.error is None and tr.error_estimate is not None
    # the estimate converges like dt⁴: halving the step cuts it by about 16
    finer = pl.simulate(damped, s0, 5.0, method="rattle4", dt=5e-3, error_estimate=True)
    ratio = tr.error_estimate.max_position / finer.error_estimate.max_position
    assert 10 < ratio < 25, ratio


def test_files_and_summary_carry_the_errors(tmp_path) -> None:
    tr = pl.simulate(IDEAL, START, 2.0, method="rattle", dt=1e-3, save_every=100, error_estimate=True)
    cols = tr.columns()
    for name, unit in (("err_x_est", "m"), ("err_v_est", "m/s"), ("err_x", "m"), ("err_v", "m/s")):
        assert cols[name][0] == unit
    np.testing.assert_array_equal(cols["err_x_est"][1], tr.error_estimate.position)
    path = tr.save(tmp_path / "run.csv")
    text = path.read_text()
    assert "err_x_est" in text and "err_v" in text
    assert tr.metadata()["error_estimate"]["how"] == "richardson"
    summary = tr.summary()
    assert "estimate: max |dx|" in summary and "(richardson)" in summary and "(exact)" in summary


@pytest.mark.parametrize("accuracy", [1e-6, 1e-10])
def test_accuracy_is_met(accuracy: float) -> None:
    tr = pl.simulate(IDEAL, START, 30.0, accuracy=accuracy)
    assert tr.method == "rattle8" and tr.options["accuracy"] == accuracy
    assert tr.error_estimate.max_position <= accuracy * IDEAL.length
    assert tr.error.max_position <= accuracy * IDEAL.length, tr.options["accuracy_search"]


def test_accuracy_with_a_user_force_uses_dop853() -> None:
    forced = pl.Pendulum(length=1.0, g=9.81, force=lambda t, x, v: np.array([0.1 * np.cos(t), 0.0, 0.0]))
    s0 = forced.state_from_angles(theta=0.5)
    tr = pl.simulate(forced, s0, 3.0, accuracy=1e-8)
    assert tr.method == "dop853" and tr.error_estimate.max_position <= 1e-8


def test_an_accuracy_beyond_float64_raises_with_the_best_reached() -> None:
    with pytest.raises(pl.InvalidInputError, match=r"out of reach in float64.*best estimated error"):
        pl.simulate(IDEAL, START, 200.0, accuracy=1e-15)


@pytest.mark.parametrize("bad", [0.0, -1e-8, 1.0, float("nan"), "x"])
def test_bad_accuracy_is_refused(bad: object) -> None:
    with pytest.raises(pl.InvalidInputError, match="accuracy"):
        pl.simulate(IDEAL, START, 1.0, accuracy=bad)  # type: ignore[arg-type]


def test_accuracy_refuses_a_method_or_step() -> None:
    with pytest.raises(pl.InvalidInputError, match="leave out dt"):
        pl.simulate(IDEAL, START, 1.0, accuracy=1e-8, dt=1e-3)


def test_weierstrass_form_agrees_with_the_jacobi_form() -> None:
    sol = pl.exact(IDEAL, START)
    w = sol.weierstrass
    e1, e2, e3 = w["e"]
    assert e1 >= e2 >= e3 and abs(e1 + e2 + e3) < 1e-15
    assert w["g2"] == pytest.approx(-4 * (e1 * e2 + e1 * e3 + e2 * e3), rel=1e-14)
    assert 2 * w["omega1"] / sol.omega0 == pytest.approx(sol.period_z, rel=1e-14)
    t = np.linspace(-5.0, 50.0, 301)
    z, zdot = sol.height_weierstrass(t)
    x, v = sol.state(t)
    assert np.max(np.abs(z - x[:, 2])) < 1e-13
    assert np.max(np.abs(zdot - v[:, 2])) < 1e-13 * (1 + np.max(np.abs(v)))
    rest = pl.exact(IDEAL, IDEAL.state_from_angles(theta=0.0))
    assert rest.weierstrass is None
    with pytest.raises(pl.InvalidInputError, match="no Weierstrass form"):
        rest.height_weierstrass([1.0])
    with pytest.raises(pl.InvalidInputError, match="finite"):
        sol.height_weierstrass([float("nan")])
