"""The golden generator's verification of an exact solution (checks 1-4 and 6) and its
conditioning floors, with the invariants and error measures they use. Equation numbers (T-x.y)
refer to docs/theory.md; units SI (m, kg, s; E in J, J3 in kg m^2/s); errors are relative.

Checks (the file is not written unless all pass; check 5, the recomputation at 60 digits,
is in golden_case.run_case):

1. x(0), v(0) reproduce the (projected) initial state to 1e-30 relative.
2. At every output time |x| = l, x.v = 0, E and J3 equal their initial values (1e-30).
3. At t = 0.37 s and the output times, mpmath.diff of x(t) equals v(t) and mpmath.diff
   of v(t) equals the T-2.4 acceleration, to 1e-25.
4. mpmath.odefun (Taylor series, 30 digits) on the 6-dim T-2.4 system from t = 0 to
   2 s agrees with the formula to 1e-25.
6. Generic orbits: phase_dynamic + phase_geometric = Delta_phi to 1e-25, and
   phase_dynamic equals its closed form (4/(j lam)) [K (eps - u1) - (u3 - u1)(K - E)]
   (from sigma3 = |v|^2 = 2(eps - u)) to 1e-25 relative.

Invariants (T-2.6): E = m(|v|^2/2 + g z), J3 = m(x1 v2 - x2 v1); acceleration (T-2.4):
v' = -g e3 + ((g z - |v|^2)/l^2) x.

Conditioning floors: the start is perturbed by 2^-53 with all 64 sign patterns,
projected onto TS^2 and solved exactly again; the floor is the max over the patterns of
max(|dx|/l, |dv|/max(|v|, l w0)) at each output time. "floor": componentwise relative
perturbation c -> c (1 +- 2^-53), what rounding the start to float64 does.
"floor_normwise": absolute perturbation 2^-53 l (x) and 2^-53 max(|v0|, l w0) (v), the
size of one rounding of a whole state, as an integrator step makes. The perturbed orbits that
set the floors are solved again at 60 digits (part of check 5, to 1e-25).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from typing import Any

import mpmath
from golden_base import (
    DIFF_TIMES,
    DPS,
    FLOOR_REL,
    HIGH_DPS,
    ODE_DPS,
    ODE_T_END,
    TIMES,
    TOL_FLOOR,
    TOL_ODE,
    TOL_PHASE,
    TOL_STATE,
    GoldenError,
    Scenario,
    State,
    Vec,
    dot,
    norm,
    project,
    sub,
    to_mp,
)
from golden_generic import GenericSolution, Solution
from golden_special import solve
from mpmath import mp, mpf

# --------------------------------------------------------------------------------------
# Invariants, scales, errors


def energy(mass: Any, g: Any, x: Vec, v: Vec) -> Any:
    return mass * (dot(v, v) / 2 + g * x[2])


def j3(mass: Any, x: Vec, v: Vec) -> Any:
    return mass * (x[0] * v[1] - x[1] * v[0])


def acceleration(length: Any, g: Any, x: Vec, v: Vec) -> Vec:
    """T-2.4: v' = -g e3 + ((g z - |v|^2)/l^2) x."""
    lam = (g * x[2] - dot(v, v)) / length**2
    return [lam * x[0], lam * x[1], lam * x[2] - g]


def v_scale(length: Any, g: Any, v: Vec) -> Any:
    """max(|v|, l w0): the velocity scale of relative errors."""
    s = max(norm(v), length * mp.sqrt(abs(g) / length))
    return s if s > 0 else mpf(1)


def state_error(length: Any, vs: Any, a: State, b: State) -> Any:
    return max(norm(sub(a[0], b[0])) / length, norm(sub(a[1], b[1])) / vs)


def phase_split(name: str, gen: GenericSolution) -> dict[str, Any]:
    """Check 6: the T-5.1 phases by quadrature sum to Delta_phi (T-4.5), and the dynamic
    phase equals its closed form, both to 1e-25."""
    dyn, geom, dyn_closed = gen.phases()
    err_sum = abs(dyn + geom - gen.delta_phi)
    err_dyn = abs(dyn - dyn_closed) / abs(dyn)
    if not (err_sum <= TOL_PHASE and err_dyn <= TOL_PHASE):
        raise GoldenError(
            f"{name}: phases: dyn + geom - delta_phi = {mpmath.nstr(err_sum, 5)}, "
            f"dyn vs closed form {mpmath.nstr(err_dyn, 5)} (tolerance {TOL_PHASE})"
        )
    return {"phase_dynamic": dyn, "phase_geometric": geom, "6_sum": err_sum, "6_closed": err_dyn}


def initial_state(sc: Scenario) -> State:
    """The float64 start projected onto TS^2 at twice the working precision (the values keep
    it): a start rounded to the working precision would move a nearly conical orbit's
    u2 - u1 (conical: 7e-18) by 1e-24 relative."""
    with mp.extraprec(mp.prec):
        return project(mpf(sc.length), to_mp(sc.x0), to_mp(sc.v0))


def verify(sc: Scenario, sol: Solution, x0: Vec, v0: Vec, log: Callable[[str], None]) -> dict[str, float]:
    """Checks 1 to 4; raises GoldenError on failure, returns the worst error of each."""
    ell, g, mass = mpf(sc.length), mpf(sc.g), mpf(sc.mass)
    vs = v_scale(ell, g, v0)
    e0, jz0 = energy(mass, g, x0, v0), j3(mass, x0, v0)
    e_scale = mass * (vs**2 + abs(g) * ell)
    j_scale = mass * ell * vs
    res: dict[str, float] = {}

    def need(name: str, err: Any, tol: Any) -> None:
        res[name] = max(res.get(name, 0.0), float(err))
        if not err <= tol:
            raise GoldenError(f"{sc.name}: check {name} failed: {mpmath.nstr(err, 5)} > {tol}")

    # 1. initial state
    need("1_initial", state_error(ell, vs, sol.state(mpf(0)), (x0, v0)), TOL_STATE)
    raw = (to_mp(sc.x0), to_mp(sc.v0))
    res["projection_shift"] = float(state_error(ell, vs, raw, (x0, v0)))
    if res["projection_shift"] > 1e-15:
        raise GoldenError(f"{sc.name}: float64 start is far from TS^2 ({res['projection_shift']})")

    # 2. invariants at the output times
    for t in TIMES:
        x, v = sol.state(mpf(t))
        need("2_length", abs(norm(x) - ell) / ell, TOL_STATE)
        need("2_tangency", abs(dot(x, v)) / (ell * vs), TOL_STATE)
        need("2_energy", abs(energy(mass, g, x, v) - e0) / e_scale, TOL_STATE)
        need("2_j3", abs(j3(mass, x, v) - jz0) / j_scale, TOL_STATE)

    # 3. the formula solves T-2.4 (numerical derivative of the closed form)
    cache: dict[tuple[Any, int], State] = {}

    def st(t: Any) -> State:
        key = (mpf(t)._mpf_, mp.prec)
        if key not in cache:
            cache[key] = sol.state(t)
        return cache[key]

    for t in DIFF_TIMES:
        tt = mpf(t)
        x, v = sol.state(tt)
        acc = acceleration(ell, g, x, v)
        a_scale = max(norm(acc), abs(g), dot(v, v) / ell, mpf(1e-300))
        dx = [mp.diff(lambda s, i=i: st(s)[0][i], tt) for i in range(3)]
        dv = [mp.diff(lambda s, i=i: st(s)[1][i], tt) for i in range(3)]
        need("3_dx_dt", norm(sub(dx, v)) / vs, TOL_ODE)
        need("3_dv_dt", norm(sub(dv, acc)) / a_scale, TOL_ODE)

    # 4. independent Taylor-series integration of T-2.4
    with mp.workdps(ODE_DPS):
        lw, gw = +ell, +g

        def rhs(_t: Any, y: Sequence[Any]) -> list[Any]:
            xx, vv = list(y[:3]), list(y[3:])
            return vv + acceleration(lw, gw, xx, vv)

        f = mpmath.odefun(rhs, 0, [+c for c in x0 + v0])
        y_end = f(mpf(ODE_T_END))
    x_ref, v_ref = sol.state(mpf(ODE_T_END))
    need(
        "4_odefun",
        state_error(ell, vs, (list(y_end[:3]), list(y_end[3:])), (x_ref, v_ref)),
        TOL_ODE,
    )
    log(f"    checks 1-4 passed (odefun to t = {ODE_T_END} s: {res['4_odefun']:.1e})")
    return res


def floor_patterns() -> list[tuple[int, ...]]:
    """All 2^6 sign patterns of a perturbation of (x1, x2, x3, v1, v2, v3)."""
    return list(itertools.product((-1, 1), repeat=6))


def conditioning_floors(sc: Scenario, samples: list[State], normwise: bool) -> tuple[list[float], float]:
    """Worst relative state error at each output time from a 2^-53 change of the start.

    Componentwise (normwise=False): each component c -> c (1 +- 2^-53), the rounding of
    the start to float64 (zero components stay exact). Normwise: x_i -> x_i +- 2^-53 l
    and v_i -> v_i +- 2^-53 max(|v0|, l w0), the size of one rounding of a whole state.
    Either way the result is projected onto TS^2 and solved exactly. The perturbed orbits
    that set the floors are solved again at HIGH_DPS digits; returns the floors and the
    largest difference found (check 5).
    """

    def perturbed(signs: tuple[int, ...]) -> list[State]:
        ell, g = mpf(sc.length), mpf(sc.g)
        raw = to_mp(sc.x0) + to_mp(sc.v0)
        rel = mpf(FLOOR_REL)
        if normwise:
            vs0 = v_scale(ell, g, raw[3:])
            y = [
                c + s * rel * (ell if i < 3 else vs0) for i, (c, s) in enumerate(zip(raw, signs, strict=True))
            ]
        else:
            y = [c * (1 + s * rel) for c, s in zip(raw, signs, strict=True)]
        with mp.extraprec(mp.prec):  # as initial_state: near-conical orbits need it
            x0, v0 = project(ell, y[:3], y[3:])
        sol = solve(ell, g, x0, v0)
        return [sol.state(mpf(t)) for t in TIMES]

    ell, g = mpf(sc.length), mpf(sc.g)
    scales = [v_scale(ell, g, ref[1]) for ref in samples]
    worst = [mpf(0)] * len(TIMES)
    worst_at: list[tuple[int, ...]] = [()] * len(TIMES)
    states: dict[tuple[int, ...], list[State]] = {}
    for signs in floor_patterns():
        states[signs] = perturbed(signs)
        for i, (got, ref, vs) in enumerate(zip(states[signs], samples, scales, strict=True)):
            err = state_error(ell, vs, got, ref)
            if err > worst[i]:
                worst[i], worst_at[i] = err, signs
    recheck = mpf(0)
    for signs in sorted(set(worst_at)):
        with mp.workdps(HIGH_DPS):
            high = perturbed(signs)
        for lo, hi, vs in zip(states[signs], high, scales, strict=True):
            recheck = max(recheck, state_error(ell, vs, lo, hi))
    if not recheck <= TOL_FLOOR:
        kind = "normwise" if normwise else "componentwise"
        raise GoldenError(
            f"{sc.name}: {kind} floor orbits differ by {recheck} at {DPS} and {HIGH_DPS} digits"
        )
    return [float(mpmath.nstr(w, 3)) for w in worst], float(recheck)
