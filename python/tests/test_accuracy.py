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
    # the reference run's work (save_every even: the coarse 2·dt companion), with the plain run ≤ 2.5x
    if method != "dop853":
        assert est.reference["companion"] == "2dt", est.reference
    assert est.cost <= 1.5, f"{method}: reference run cost {est.cost:.2f}x the plain run"


def test_the_coarse_companion_needs_save_times_on_its_grid() -> None:
    # every step saved: each 2·dt step would be shortened to land on the odd samples, so dt/2
    tr = pl.simulate(IDEAL, START, 2.0, method="rattle4", dt=1e-2, save_every=1, error_estimate=True)
    est = tr.error_estimate
    assert est.reference["companion"] == "dt/2" and "2·dt grid" in est.reference["why"]
    assert est.cost == pytest.approx(2.0, rel=0.01)
    # a few save_at times off the grid: one shortened step each, a small share: still 2·dt
    tr = pl.simulate(
        IDEAL, START, 20.0, method="rattle8", dt=0.0415, save_at=[1.0, 10.0, 20.0], error_estimate=True
    )
    assert tr.error_estimate.reference["companion"] == "2dt"
    ratio = tr.error_estimate.position / tr.error.position
    assert ratio.min() > 0.5 and ratio.max() < 2.0, ratio
    # the true error with save_at leaving out t0: measured from the start at t0, not from t[0]
    assert tr.error.max_position < 1e-4, tr.error.position


def _sampled_pivot(t_end: float) -> tuple[pl.Pendulum, pl.State]:
    """A pivot path sampled every 10 ms over [−0.1, t_end + 0.1] s (kinks in p̈ at the samples)."""
    t = np.arange(-0.1, t_end + 0.105, 0.01)
    path = np.stack([0.3 * np.sin(1.3 * t), 0.2 * np.sin(0.7 * t + 0.5), 0.1 * np.cos(2 * t)], axis=-1)
    p = pl.Pendulum(length=1.0, g=9.81, pivot_samples=(t, path), damping=0.03)
    return p, p.state_from_angles(theta=1.3, phi=0.9, theta_dot=0.6, phi_dot=2.5)


def test_a_sampled_pivot_needs_its_samples_on_the_coarse_grid() -> None:
    """A fixed step holding a sample of a sampled pivot's path is split there, so a 2·dt run off the
    samples' grid splits its steps in another pattern than the plain run and the Richardson difference
    misjudges the error: at dt = 16 ms on samples every 10 ms the 2·dt estimate was 46× too low (0.022
    of the true error; 0.64 at 3.7 ms). The samples count like save times: off the 2·dt grid, dt/2 —
    and that companion halves each of the plain run's (sub-)steps: a run at dt/2 splits on the samples
    elsewhere, and with dt above the spacing its estimate read 0.70 (rk4), 0.57 (rattle) of the truth."""
    p, s0 = _sampled_pivot(3.0)
    cases = [
        ("rk4", 1.6e-2, "dt/2"),
        ("rk4", 3.7e-3, "dt/2"),
        ("rk4", 1e-3, "2dt"),
        ("rattle", 1.6e-2, "dt/2"),
    ]
    for method, dt, companion in cases:
        tr = pl.simulate(p, s0, 3.0, method=method, dt=dt, save_every=10, error_estimate=True)
        # DOP853 ends its steps on the samples (to round-off of the independent reference, T-7.2)
        ref = pl.simulate(p, s0, 3.0, method="dop853", rtol=1e-13, atol=1e-14, save_at=tr.t)
        true = np.linalg.norm(tr.x - ref.x, axis=1)
        assert true.max() > 1e-10, (dt, true.max())  # the reference: ~1e-14 m
        est = tr.error_estimate
        assert est.reference["companion"] == companion, (dt, est.reference)
        if companion == "dt/2":
            assert "pivot's samples" in est.reference["why"] and "halved" in est.reference, est.reference
        big = true > 0.1 * true.max()
        ratio = est.position[big] / true[big]
        assert ratio.min() > 0.95 and ratio.max() < 1.05, (method, dt, ratio.min(), ratio.max())


def test_accuracy_on_a_sampled_pivot_steps_at_most_the_sample_spacing() -> None:
    """``accuracy=`` on a sampled pivot starts RATTLE8 at most at the samples' spacing (a whole fraction
    of it): the first guess 0.5·a^{1/8}/ω = 16 ms at a = 1e-8 split every step on the 10-ms samples
    (1.6× the steps of dt = 10 ms, for no better accuracy), and every run of the search did so too."""
    p, s0 = _sampled_pivot(10.0)
    a = 1e-8
    tr = pl.simulate(p, s0, 10.0, accuracy=a, save_every=10)
    assert tr.method == "rattle8" and tr.options["dt"] == pytest.approx(0.01, rel=1e-12), tr.options
    ref = pl.simulate(p, s0, 10.0, method="dop853", rtol=1e-13, atol=1e-14, save_at=tr.t)
    true = float(np.max(np.linalg.norm(tr.x - ref.x, axis=1)))
    assert true <= a * p.length, true
    # honest: the estimate the search stopped on is about the true error (near the float64 floor)
    assert 0.5 < tr.error_estimate.max_position / true < 2.0, (tr.error_estimate.max_position, true)
    # the steps end on the samples: none split (the steps are the grid's), the run of the first guess
    # (what the search ran before) splits each
    assert tr.stats["steps"] == 1000, tr.stats
    guess = 0.5 * a ** (1 / 8) / max(np.sqrt(9.81), float(np.linalg.norm(s0.v)))
    before = pl.simulate(p, s0, 10.0, method="rattle8", dt=guess, save_every=10)
    assert guess > 0.015 and before.stats["steps"] > 1.6 * tr.stats["steps"], (guess, before.stats)


def test_accuracy_on_unevenly_spaced_samples_steps_on_every_sample() -> None:
    """On samples 7 … 13 ms apart ``accuracy=`` takes each interval between samples in ⌈span/dt⌉ equal
    steps (``steps_on_samples``): none holds a sample, where p̈ is kinked. The plain grid at the same dt
    splits nearly every step on a sample (more steps)."""
    rng = np.random.default_rng(7)
    gaps = 0.01 * (1.0 + 0.6 * (rng.random(330) - 0.5))
    t = np.concatenate([[-0.1, -0.05], np.cumsum(np.concatenate([[0.0], gaps]))])
    path = np.stack([0.3 * np.sin(1.3 * t), 0.2 * np.sin(0.7 * t + 0.5), 0.1 * np.cos(2 * t)], axis=-1)
    p = pl.Pendulum(length=1.0, g=9.81, pivot_samples=(t, path), damping=0.03)
    s0 = p.state_from_angles(theta=1.3, phi=0.9, theta_dot=0.6, phi_dot=2.5)
    a = 1e-8
    tr = pl.simulate(p, s0, 3.0, accuracy=a, save_every=10)
    dt = tr.options["dt"]
    assert tr.method == "rattle8" and tr.options["steps_on_samples"] is True, tr.options
    ref = pl.simulate(p, s0, 3.0, method="dop853", rtol=1e-13, atol=1e-14, save_at=tr.t)
    true = float(np.max(np.linalg.norm(tr.x - ref.x, axis=1)))
    assert true <= a * p.length, true
    # the steps: ⌈span/dt⌉ per interval, the one holding t_end = 3 s up to it
    starts = t[(t >= 0.0) & (t < 3.0)]
    ends = np.append(starts[1:], t[t > starts[-1]][0])
    n = np.ceil((ends - starts) / dt)
    n[-1] = np.ceil((3.0 - starts[-1]) / ((ends[-1] - starts[-1]) / n[-1]) - 1e-9)
    assert tr.stats["steps"] == int(n.sum()), (tr.stats, n.sum())
    plain = pl.simulate(p, s0, 3.0, method="rattle8", dt=dt, save_every=10)
    assert plain.stats["steps"] > 1.3 * tr.stats["steps"], (plain.stats, tr.stats)


def test_an_unstable_coarse_run_falls_back_to_the_half_step() -> None:
    # RATTLE8 at 0.15/ω is stable, at 0.3/ω (the 2·dt run) it blows up next to the top
    s0 = IDEAL.state_from_angles(theta=np.radians(150), phi_dot=0.3)
    dt = 0.15 / np.sqrt(9.81)
    tr = pl.simulate(IDEAL, s0, 20.0, method="rattle8", dt=dt, save_every=20, error_estimate=True)
    est = tr.error_estimate
    assert est.reference["companion"] == "dt/2" and "2·dt run failed" in est.reference["why"]
    big = tr.error.position > 0.1 * tr.error.max_position
    ratio = est.position[big] / tr.error.position[big]
    assert ratio.min() > 0.5 and ratio.max() < 2.0, ratio


def test_a_coarse_run_outside_the_asymptotic_regime_falls_back() -> None:
    # 0.1/ω next to the top: the 2·dt run is 9e-2 l off the plain one (its phase is going)
    s0 = IDEAL.state_from_angles(theta=np.radians(150), phi_dot=0.3)
    dt = 100.0 / (2 * round(100.0 / (2 * 0.1 / np.sqrt(9.81))))
    tr = pl.simulate(IDEAL, s0, 100.0, method="rattle8", dt=dt, save_every=100, error_estimate=True)
    assert tr.error_estimate.reference["companion"] == "dt/2", tr.error_estimate.reference
    assert "off the plain run" in tr.error_estimate.reference["why"]


def test_round_off_is_not_divided_away() -> None:
    # at rest 0.01° from the top RATTLE8 at a small step is dominated by round-off (the energy
    # errors of the plain and the 2·dt run are alike, not 2^8 apart): the half-step companion,
    # whose difference keeps round-off at its size (y_2h − y_h divided by 255 would hide it)
    s0 = IDEAL.state_from_angles(theta=np.radians(179.99))
    tr = pl.simulate(IDEAL, s0, 60.0, method="rattle8", dt=2e-3, save_every=1000, error_estimate=True)
    est, true = tr.error_estimate, tr.error
    assert est.reference["companion"] == "dt/2" and "round-off" in est.reference["why"]
    assert true.max_position > 1e-10, "round-off is expected to dominate here"
    # round-off is random: two realisations differ by about its size, not sample by sample
    assert 0.1 < est.max_position / true.max_position < 10, (est.max_position, true.max_position)
    coarse = pl.simulate(IDEAL, s0, 60.0, method="rattle8", dt=4e-3, save_at=tr.t)
    hidden = np.max(np.linalg.norm(coarse.x - tr.x, axis=1)) / 255
    assert hidden < 0.1 * true.max_position  # what the 2·dt estimate would have said


def test_dop853_at_the_tightest_tolerance_uses_a_looser_companion() -> None:
    tr = pl.simulate(IDEAL, START, 5.0, method="dop853", rtol=1e-9, error_estimate=True)
    assert tr.error_estimate.reference["rtol"] == pytest.approx(1e-10)
    tr = pl.simulate(IDEAL, START, 5.0, method="dop853", rtol=1e-15, atol=1e-17, error_estimate=True)
    assert tr.error_estimate.reference["rtol"] == pytest.approx(1e-14)
    assert tr.error_estimate.cost < 1.0


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
    assert "estimate: max |dx|" in summary and "(richardson, 2dt)" in summary and "(exact)" in summary


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
