"""The crane's nonlinear 3-D dynamics (pendulab.crane.Crane, the core's crane module; docs/theory.md
T-11.5, T-11.7) against an independent code, crane_reference.py: Lagrange's equations in the spherical
angles of the rope and the rigging (minimal coordinates, no constraint forces, no projection) with the
prescribed rope length l(t) and pivot path P(t), drag and damping as generalised forces, integrated by
SciPy's DOP853 at rtol = atol = 1e-12 and piecewise between the paths' breaks. The reference evaluates
the moves, the slew, the hoist's spline and the gust from their definitions (T-11.3, T-11.7) itself;
its hand-written equations are checked against a SymPy derivation from L = T − V when SymPy is
installed. Hook and payload positions agree within 5e-9 m over 12–30 s (measured: ≤ 8e-10 m; a measured
path was 2e-8 m off and an LQR loop's path 3e-7 m while the core stepped across their kinks)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from crane_reference import Body, Model, Steps, chart, cubic_pieces, gantry, gust_wind, tower
from scipy.interpolate import CubicSpline

from pendulab import crane

G = 9.81
STILL = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))


def _unit(th: float, ph: float) -> tuple[float, float, float]:
    return math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), -math.cos(th)


def _steps(prof: crane.Profile) -> Steps:
    """The move's definition (its steps c_k at τ_k of the n-th derivative), evaluated by the reference."""
    return Steps(prof.knots.tolist(), prof.coeffs.tolist(), prof.order, prof.start)


def _rope(t: list[float], length: list[float]) -> Callable[[float], tuple[float, float, float]]:
    """The hoist's definition: the clamped C² cubic spline through the samples, held outside them."""
    s = CubicSpline(t, length, bc_type="clamped")
    return cubic_pieces(s.x, s.c)


def _still_swing() -> tuple[crane.Crane, dict[str, Any], Model, list[float]]:
    # (a) hook + payload below a still pivot, a large 3-D swing: the rope tilted 0.7 rad towards x,
    # the rigging 1.0 rad towards azimuth 1.3 rad (the rigging swings up to 1.4 rad, the rope 0.8)
    c = crane.Crane(rope=8.0, payload_mass=1000.0, hook_mass=200.0, rigging=3.0)
    m = Model(
        hook=Body(200.0), payload=Body(1000.0), rigging=3.0, pivot=lambda t: STILL, rope=lambda t: (8.0, 0, 0)
    )
    return c, {"t_end": 25.0, "sway": (0.7, 0.0), "rigging_sway": (1.0, 1.3)}, m, []


def _hoist_during_move() -> tuple[crane.Crane, dict[str, Any], Model, list[float]]:
    # (b) hook + payload, hoisting 12 → 9 → 7 m (three samples: the spline has an inner node) during
    # a jerk-limited 6 m trolley move along (0.8, 0.6, 0), from a 3-D start
    prof = crane.profile(6.0, 0.8, 0.5, j_max=1.0, t_start=1.0)
    ht, hl = [2.0, 8.0, 14.0], [12.0, 9.0, 7.0]
    path = crane.Gantry(trolley=prof, trolley_axis=(0.8, 0.6, 0.0))
    c = crane.Crane(
        rope=12.0, pivot=path, payload_mass=1200.0, hook_mass=300.0, rigging=3.5, hoist=crane.Hoist(ht, hl)
    )
    m = Model(
        hook=Body(300.0),
        payload=Body(1200.0),
        rigging=3.5,
        pivot=gantry(_steps(prof), (0.8, 0.6, 0.0)),
        rope=_rope(ht, hl),
    )
    return c, {"t_end": 30.0, "sway": (0.3, 0.4), "rigging_sway": (0.5, 2.0)}, m, [*prof.knots, *ht]


def _wind_gust() -> tuple[crane.Crane, dict[str, Any], Model, list[float]]:
    # (c) hook + payload, a steady wind with a 3-D (1 − cos) gust and seeded turbulence (its cosines'
    # amplitudes and phases from Wind.modes, the definition) on both bodies (their own c_W A), linear
    # damping, a trapezoidal bridge move of −5 m from a raised origin
    prof = crane.profile(-5.0, 0.6, 0.4, t_start=2.0)
    wind = crane.Wind(
        velocity=(8.0, 3.0, 0.0),
        area=4.0,
        drag_coefficient=1.1,
        air_density=1.2,
        gust=(10.0, -4.0, 1.0),
        gust_start=5.0,
        gust_duration=6.0,
        hook_area=0.5,
        hook_drag_coefficient=1.4,
        turbulence=1.5,
        turbulence_scale=400.0,
        turbulence_modes=8,
        seed=5,
    )
    path = crane.Gantry(bridge=prof, origin=(1.0, 2.0, 3.0))
    c = crane.Crane(
        rope=9.0, pivot=path, payload_mass=800.0, hook_mass=250.0, rigging=3.0, wind=wind, damping=0.02
    )
    m = Model(
        hook=Body(250.0, 1.4 * 0.5),
        payload=Body(800.0, 1.1 * 4.0),
        rigging=3.0,
        pivot=gantry(_steps(prof), (0.0, 1.0, 0.0), (1.0, 2.0, 3.0)),
        rope=lambda t: (9.0, 0.0, 0.0),
        wind=gust_wind((8.0, 3.0, 0.0), (10.0, -4.0, 1.0), 5.0, 6.0, wind.modes()),
        air_density=1.2,
        damping=0.02,
    )
    return c, {"t_end": 25.0, "sway": (0.2, -0.5), "rigging_sway": (0.35, 0.8)}, m, [*prof.knots, 5.0, 11.0]


def _slewing_tower() -> tuple[crane.Crane, dict[str, Any], Model, list[float]]:
    # (d) one load on a tower crane slewing 1.2 rad (jerk-limited) at radius 25 m, hoisting 20 → 15 m,
    # in a steady wind
    slew = crane.profile(1.2, 0.15, 0.1, j_max=0.2, t_start=1.0)
    ht, hl = [3.0, 12.0], [20.0, 15.0]
    wind = crane.Wind(velocity=(6.0, -2.0, 0.0), area=2.0, drag_coefficient=1.2)
    path = crane.Tower(slew=slew, radius=25.0, height=30.0)
    c = crane.Crane(rope=20.0, pivot=path, payload_mass=1500.0, wind=wind, hoist=crane.Hoist(ht, hl))
    m = Model(
        hook=Body(1500.0, 2.4),
        pivot=tower(_steps(slew), 25.0, 30.0),
        rope=_rope(ht, hl),
        wind=lambda t: (6.0, -2.0, 0.0),
    )
    return c, {"t_end": 30.0, "sway": (0.15, 2.5)}, m, [*slew.knots, *ht]


def _measured_path() -> tuple[crane.Crane, dict[str, Any], Model, list[float]]:
    # (e) hook + payload below a measured path (crane.Sampled: the spline through irregular samples
    # 0.05 – 0.15 s apart with 1 mm noise, so its nodes fall between the core's 0.05 s knots and P⃛
    # jumps there), hoisted through 17 noisy samples
    rng = np.random.default_rng(11)
    ts = np.cumsum(np.r_[0.0, rng.uniform(0.05, 0.15, 200)])
    ts = ts[ts <= 12.0]
    x = 2.0 * (1 - np.cos(np.pi * np.clip(ts / 10.0, 0, 1))) + rng.normal(0, 1e-3, ts.size)
    ps = np.stack([x, 0.3 * x, np.zeros_like(x)], axis=1)
    ht = np.linspace(1.0, 9.0, 17)
    hl = 10.0 - 0.4 * (ht - 1.0) + rng.normal(0, 2e-3, ht.size)
    hoist = crane.Hoist(ht, hl)
    c = crane.Crane(
        rope=float(hl[0]),
        pivot=crane.Sampled(ts, ps),
        payload_mass=1000.0,
        hook_mass=250.0,
        rigging=3.0,
        hoist=hoist,
    )
    s = CubicSpline(ts, ps, axis=0)  # the path's definition, evaluated by the reference

    def pivot(t: float) -> Any:
        return tuple(s(t).tolist()), tuple(s(t, 1).tolist()), tuple(s(t, 2).tolist())

    m = Model(
        hook=Body(250.0), payload=Body(1000.0), rigging=3.0, pivot=pivot, rope=_rope(list(ht), list(hl))
    )
    # the run ends at the last sample (11.9985 s): a measured path is not extrapolated
    return c, {"t_end": float(ts[-1]), "sway": (0.3, 0.2), "rigging_sway": (0.5, 1.0)}, m, [*ts, *ht]


def _lqr_run() -> tuple[crane.Crane, dict[str, Any], Model, list[float]]:
    # (f) one load below a trolley driven by the LQR loop (crane.LQRRun) whose acceleration limit acts
    # three times (u clipped at ±0.3 m/s², five switches: P̈ kinks where the clip starts and stops) and
    # steps from 0 at t_start = 1 s; a 3-D start (the planar loop sees only the x swing)
    run = crane.lqr(10.0, q=(4.0, 1.0, 10.0, 1.0), r=1.0, a_max=0.3).simulate(5.0, t_end=25.0, t_start=1.0)
    assert run.switches.size == 5
    c = crane.Crane(rope=10.0, pivot=run, payload_mass=500.0)

    def pivot(t: float) -> Any:
        x, v, a = (float(q[0]) for q in run.trolley(t))  # the path's definition: the loop's solution
        return (x, 0.0, 0.0), (v, 0.0, 0.0), (a, 0.0, 0.0)

    m = Model(hook=Body(500.0), pivot=pivot, rope=lambda t: (10.0, 0.0, 0.0))
    return c, {"t_end": 25.0, "sway": (0.1, 1.0)}, m, [1.0, *run.switches]


CASES = {
    "two bodies, still pivot, large 3-D swing": _still_swing,
    "two bodies, hoisting during a jerk-limited trolley move": _hoist_during_move,
    "two bodies, wind with a gust and turbulence, damping, trapezoidal move": _wind_gust,
    "one body, slewing tower, hoisting, wind": _slewing_tower,
    "two bodies, measured path, hoisting through noisy samples": _measured_path,
    "one body, LQR trolley loop with its acceleration limit acting": _lqr_run,
}


@pytest.mark.parametrize("case", list(CASES))
def test_the_crane_agrees_with_lagrange_in_minimal_coordinates(case: str) -> None:
    c, kw, model, breaks = CASES[case]()
    run = c.simulate(output_spacing=0.05, rtol=1e-12, atol=1e-12, **kw)
    u2 = _unit(*kw["rigging_sway"]) if "rigging_sway" in kw else None
    hook, payload, pole = model.run(run.t, _unit(*kw["sway"]), u2, breaks=[float(b) for b in breaks])
    assert pole > 0.2  # the chart stays away from its poles (sin θ ≥ 0.27 in case a)
    np.testing.assert_allclose(run.hook, hook, rtol=0, atol=5e-9)
    np.testing.assert_allclose(run.payload, payload, rtol=0, atol=5e-9)
    assert np.ptp(run.payload[:, :2], axis=0).max() > 1.0  # the loads do move


def test_the_reference_evaluates_the_paths_as_pendulab_does() -> None:
    # not the subject (the dynamics are), but a disagreement here would name the culprit at once
    t_all = np.linspace(0.0, 30.0, 601)
    for make in CASES.values():
        c, _, model, _ = make()
        # a measured path is defined on its samples' span only (crane.Sampled refuses other times)
        lo, hi = c.pivot.span if isinstance(c.pivot, crane.Sampled) else (-np.inf, np.inf)
        t = t_all[(t_all >= lo) & (t_all <= hi)]
        ref = np.array([np.array(model.pivot(x)) for x in t])  # (N, 3 (p, v, a), 3)
        np.testing.assert_allclose(ref[:, 0], c.pivot.position(t), atol=1e-12)
        np.testing.assert_allclose(ref[:, 1], c.pivot.velocity(t), atol=1e-12)
        np.testing.assert_allclose(ref[:, 2], c.pivot.acceleration(t), atol=1e-12)
        t = t_all
        rope = np.array([model.rope(x) for x in t])
        np.testing.assert_allclose(rope[:, 0], c.hoist.length(t), atol=1e-12)
        np.testing.assert_allclose(rope[:, 1], c.hoist.velocity(t)[:, 0], atol=1e-12)
        np.testing.assert_allclose(rope[:, 2], c.hoist.acceleration(t)[:, 0], atol=1e-12)
    wind = _wind_gust()[0].wind
    np.testing.assert_allclose(
        np.array([_wind_gust()[2].wind(x) for x in t]), wind.velocity_at(t), atol=1e-12
    )
    assert chart((1.0, 0.0, 0.0))[0] == 0.0


@pytest.mark.parametrize("bodies", [1, 2])
def test_the_hand_written_equations_are_euler_lagrange(bodies: int) -> None:
    # crane_reference's M q̈ = Σ Jᵀ(F − m a) against SymPy's Euler–Lagrange equations of L = T − V with
    # the drag's and the damping's virtual work, at random states, pivot motions, hoist rates and winds
    from crane_reference import sympy_accelerations

    pytest.importorskip("sympy")
    acc = sympy_accelerations(bodies)
    rng = np.random.default_rng(7)
    par = (200.0, 900.0, 3.0, 0.7, 4.4, 1.2, 0.03, G)
    for _ in range(20):
        n = 2 * bodies
        q = [*(v for _ in range(bodies) for v in (rng.uniform(0.4, 2.7), rng.uniform(-3.1, 3.1)))]
        dq = rng.normal(size=n).tolist()
        p, dp, ddp = (tuple(rng.normal(size=3).tolist()) for _ in range(3))
        ls = (rng.uniform(3.0, 12.0), rng.normal(), rng.normal())
        w = tuple(rng.normal(scale=10.0, size=3).tolist())
        model = Model(
            hook=Body(par[0], par[3]),
            payload=Body(par[1], par[4]) if bodies == 2 else None,
            rigging=par[2],
            pivot=lambda t, p=p, dp=dp, ddp=ddp: (p, dp, ddp),
            rope=lambda t, ls=ls: ls,
            wind=lambda t, w=w: w,
            air_density=par[5],
            damping=par[6],
            g=par[7],
        )
        hand = model.rhs(0.0, np.array(q + dq))[n:]
        np.testing.assert_allclose(hand, acc(q, dq, p, dp, ddp, ls, w, par), rtol=1e-12, atol=1e-12)
