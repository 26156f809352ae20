"""The exact solution from Python (docs/theory.md §4): ``pl.exact`` against the 40-digit golden states and an
independent integrator, its time handling (scalar, array, negative, huge t), the group property and
time reversal, continuity of the azimuth, every kind of motion of T-4.6, and bad input.

Error measure (as in test_golden.py): max(|Δx|/l, |Δv|/(l ω₀ + |v|)), SI units throughout.
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import pytest
from conftest import TESTDATA
from scipy.special import ellipk

import pendulab as pl

CASES: list[dict[str, Any]] = json.loads((TESTDATA / "golden_states.json").read_text())["cases"]
IDS = [c["name"] for c in CASES]


def relative_error(p: pl.Pendulum, x: Any, v: Any, x_ref: Any, v_ref: Any) -> float:
    x, v, x_ref, v_ref = (np.asarray(a, dtype=float) for a in (x, v, x_ref, v_ref))
    ex = np.linalg.norm(x - x_ref) / p.length
    ev = np.linalg.norm(v - v_ref) / (p.length * p.omega0 + np.linalg.norm(v_ref))
    return float(max(ex, ev))


def case_solution(case: dict[str, Any]) -> tuple[pl.Pendulum, pl.State, pl.ExactSolution]:
    p = pl.Pendulum(length=case["length"], g=case["g"], mass=case["mass"])
    s0 = p.state(case["x0"], case["v0"])
    return p, s0, pl.exact(p, s0)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_matches_the_golden_states(case: dict[str, Any]) -> None:
    """Every golden sample (t = 1 … 10⁴ s) within max(1e-12, 100 × the conditioning floor): the exact
    solution is as good as the float64 start allows, with no growth of error in t beyond it."""
    p, _, sol = case_solution(case)
    samples = case["samples"]
    x, v = sol.state(np.array([s["t"] for s in samples]))
    for k, s in enumerate(samples):
        err = relative_error(p, x[k], v[k], s["x"], s["v"])
        bound = max(1e-12, 100 * s["floor"])
        assert err <= bound, f"{case['name']} t = {s['t']}: error {err:.3e} > {bound:.1e}"
    if case["kind"] == "generic":
        assert sol.kind in ("generic", "conical")
        assert sol.period_z == pytest.approx(case["period_z"], rel=1e-12)
        assert sol.azimuth_advance == pytest.approx(case["delta_phi"], rel=1e-12)
        z = sol.turning_heights
        sign = -1.0 if case["g"] < 0 else 1.0
        expected = sorted(sign * case["length"] * u for u in (case["u1"], case["u2"]))
        assert z[:2] == pytest.approx(expected, abs=1e-12) and z[0] <= z[1]
        assert len(z) == 3 and abs(z[2]) >= case["length"]
    else:
        assert sol.kind == case["kind"]


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_agrees_with_rattle8_at_100_s(case: dict[str, Any]) -> None:
    """An independent path, the 8th-order symplectic RATTLE composition at dt = 2 ms, lands on the exact
    state at t = 100 s to 1e-9."""
    p, s0, sol = case_solution(case)
    tr = pl.simulate(p, s0, 100.0, method="rattle8", dt=2e-3, save_at=[100.0])
    exact = sol.state(100.0)
    assert relative_error(p, tr.x[-1], tr.v[-1], exact.x, exact.v) <= 1e-9


def test_scalar_array_and_shapes(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """Scalar t gives a State, arrays give (x, v) of shape t.shape + (3,), all equal; t = 0 is the start."""
    sol = pl.exact(pendulum, rosette)
    s = sol.state(2.5)
    assert isinstance(s, pl.State) and s.x.shape == (3,) and not s.x.flags.writeable
    x, v = sol.state(np.array([0.0, 2.5]))
    assert x.shape == v.shape == (2, 3)
    assert np.array_equal(x[1], s.x) and np.array_equal(v[1], s.v)
    assert relative_error(pendulum, x[0], v[0], rosette.x, rosette.v) <= 1e-15
    x2, _ = sol.state(np.full((2, 3), 2.5))
    assert x2.shape == (2, 3, 3) and np.array_equal(x2[1, 2], s.x)
    assert isinstance(sol.azimuth(2.5), float) and sol.azimuth(np.zeros((4, 1))).shape == (4, 1)
    assert sol.state(np.array([]))[0].shape == (0, 3)


def test_negative_time_is_time_reversal_and_group_property(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """x(−t) from (x₀, v₀) equals x(t) from (x₀, −v₀) with v negated (the equations are reversible), and
    restarting from the state at t₁ gives the state at t₁ + t₂ (the flow is a one-parameter group)."""
    sol = pl.exact(pendulum, rosette)
    back = pl.exact(pendulum, pendulum.state(rosette.x, -rosette.v))
    for t in (0.3, 7.0, 123.4):
        a, b = sol.state(-t), back.state(t)
        assert relative_error(pendulum, a.x, a.v, b.x, -b.v) <= 1e-13
    mid = pl.exact(pendulum, sol.state(4.2))
    a, b = sol.state(4.2 + 5.9), mid.state(5.9)
    assert relative_error(pendulum, a.x, a.v, b.x, b.v) <= 1e-13


def test_the_same_cost_and_accuracy_at_huge_t(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """At t = 10⁶ s the state is still on TS² with the start's E and J₃ (the argument is reduced by the
    period, so nothing accumulates) and consistent with its own period: x(t + T_z) has the same height."""
    sol = pl.exact(pendulum, rosette)
    t = 1e6
    s = sol.state(t)
    assert abs(np.linalg.norm(s.x) - 1.0) <= 1e-15 and abs(s.x @ s.v) <= 1e-14
    assert pendulum.energy(s) == pytest.approx(pendulum.energy(rosette), abs=1e-13 * 9.81)
    assert pendulum.j3(s) == pytest.approx(pendulum.j3(rosette), abs=1e-14)
    assert sol.state(t + sol.period_z).x[2] == pytest.approx(s.x[2], abs=1e-9)


def test_azimuth_is_continuous_and_matches_atan2(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """φ(t) has no 2π jumps, equals atan2(y, x) modulo 2π, and advances by Δφ per z-period (T-4.5)."""
    sol = pl.exact(pendulum, rosette)
    t = np.linspace(-20.0, 20.0, 40001)
    phi = sol.azimuth(t)
    x, _ = sol.state(t)
    assert np.max(np.abs(np.diff(phi))) < 0.01
    wrapped = np.angle(np.exp(1j * (phi - np.arctan2(x[:, 1], x[:, 0]))))
    assert np.max(np.abs(wrapped)) <= 1e-12
    advance = sol.azimuth(3.0 + sol.period_z) - sol.azimuth(3.0)
    assert advance == pytest.approx(sol.azimuth_advance, abs=1e-12)
    assert sol.rotation_number == pytest.approx(sol.azimuth_advance / (2 * math.pi), rel=1e-15)


def test_trajectory_carries_the_exact_states(pendulum: pl.Pendulum, rosette: pl.State, tmp_path: Any) -> None:
    """sol.trajectory(t) is a Trajectory (method "exact") with conserved E and J₃ and writable files."""
    sol = pl.exact(pendulum, rosette)
    tr = sol.trajectory(np.linspace(0.0, 50.0, 501))
    assert isinstance(tr, pl.Trajectory) and tr.method == "exact" and len(tr) == 501
    assert np.max(np.abs(tr.energy - tr.energy[0])) <= 1e-13 * 9.81
    assert np.max(np.abs(tr.j3 - tr.j3[0])) <= 1e-14
    assert np.max(np.abs(tr.constraint_error)) <= 4e-16
    assert "energy:" in tr.summary()
    assert tr.save(tmp_path / "exact.csv").stat().st_size > 0


def test_kinds_of_motion() -> None:
    """T-4.6: planar swing (φ jumps by π at the pole only), over the top, the separatrix (infinite
    period), rest at the bottom and the top, great circles for g = 0, the mirror image for g < 0."""
    p = pl.Pendulum(length=1.0, g=1.0, mass=1.0)
    swing = pl.exact(p, p.state_from_angles(theta=1.0))
    assert swing.kind == "planar" and swing.azimuth_advance is None and swing.rotation_number is None
    assert swing.period_z == pytest.approx(4 * ellipk(math.sin(0.5) ** 2), rel=1e-14)  # T-6.2, ω₀ = 1/s
    phi = swing.azimuth(np.linspace(0.0, swing.period_z, 2001))
    jumps = np.abs(np.diff(phi))
    assert np.count_nonzero(jumps > 1e-9) == 2 and np.allclose(jumps[jumps > 1e-9], math.pi)
    over = pl.exact(p, p.state([0.0, 0.0, -1.0], [2.5, 0.0, 0.0]))
    assert over.kind == "planar_rotating" and over.turning_heights == (-1.0, 1.0)
    sep = pl.exact(p, p.state([0.0, 0.0, -1.0], [2.0, 0.0, 0.0]))  # E = ½·4 − 1 = +mgl exactly
    assert sep.kind == "separatrix" and sep.period_z == math.inf
    assert sep.state(30.0).x[2] == pytest.approx(1.0, abs=1e-9)  # creeps up to the top
    for z in (-1.0, 1.0):
        rest = pl.exact(p, p.state([0.0, 0.0, z], [0.0, 0.0, 0.0]))
        assert rest.kind == "rest" and rest.period_z is None and np.array_equal(rest.state(1e3).x, [0, 0, z])
    free = pl.Pendulum(length=2.0, g=0.0)
    circle = pl.exact(free, free.state([2.0, 0.0, 0.0], [0.0, 0.0, 3.0]))
    assert circle.kind == "great_circle" and circle.period_z == pytest.approx(2 * math.pi * 2.0 / 3.0)
    assert np.allclose(circle.state(circle.period_z / 4).x, [0.0, 0.0, 2.0], atol=1e-14)
    up, down = pl.Pendulum(g=-9.81), pl.Pendulum(g=9.81)
    a = pl.exact(up, up.state_from_angles(theta=math.radians(120), phi_dot=2.0))
    b = pl.exact(down, down.state_from_angles(theta=math.radians(60), phi_dot=2.0))
    assert a.azimuth_advance == pytest.approx(b.azimuth_advance, rel=1e-14)
    assert a.turning_heights[:2] == pytest.approx(sorted(-z for z in b.turning_heights[:2]), abs=1e-14)
    assert a.state(7.0).x == pytest.approx(b.state(7.0).x * [1, 1, -1], abs=1e-12)


def test_constants_of_a_generic_orbit(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """constants(): u₁ ≤ u₂ ≤ u₃ are the roots of P(u) = 2(ε − u)(1 − u²) − j² (T-4.1) and
    m = (u₂ − u₁)/(u₃ − u₁)."""
    c = pl.exact(pendulum, rosette).constants()
    assert c["u1"] <= c["u2"] <= 1.0 <= c["u3"]
    for u in (c["u1"], c["u2"], c["u3"]):
        assert 2 * (c["epsilon"] - u) * (1 - u * u) - c["j"] ** 2 == pytest.approx(0.0, abs=1e-13)
    assert c["m"] == pytest.approx((c["u2"] - c["u1"]) / (c["u3"] - c["u1"]), rel=1e-14)
    assert c["omega0"] == pytest.approx(math.sqrt(9.81))
    assert pl.exact(pendulum, pendulum.state_from_angles(theta=0.5)).constants()["j"] == 0.0


def test_bad_input(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """A state off TS², non-finite times, a planar orbit's phases, a 2-D time grid for trajectory() and
    wrong argument types all raise InvalidInputError naming the problem."""
    with pytest.raises(pl.InvalidInputError, match=r"TS²|TS2|sphere"):
        pl.exact(pendulum, pl.State(np.array([2.0, 0.0, 0.0]), np.zeros(3)))
    sol = pl.exact(pendulum, rosette)
    with pytest.raises(pl.InvalidInputError, match="nan"):
        sol.state(float("nan"))
    with pytest.raises(pl.InvalidInputError, match="inf"):
        sol.state(np.array([0.0, np.inf]))
    with pytest.raises(pl.InvalidInputError, match="planar"):
        pl.exact(pendulum, pendulum.state_from_angles(theta=0.5)).phases()
    free = pl.Pendulum(g=0.0)
    with pytest.raises(pl.InvalidInputError, match="g = 0"):
        pl.exact(free, free.state_from_angles(theta=1.0, phi_dot=1.0)).phases()
    with pytest.raises(pl.InvalidInputError, match="1-D"):
        sol.trajectory(np.zeros((2, 2)))
    with pytest.raises(pl.InvalidInputError, match="State"):
        pl.exact(pendulum, (rosette.x, rosette.v))  # type: ignore[arg-type]
