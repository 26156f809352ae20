"""``pl.exact`` at its degenerate limits (docs/exact.md, "Degenerate motions and limits").

- The regression starts of ``testdata/degenerate_cases.json`` (``testdata/generate/degenerate_cases.py``:
  50–270 digits with mpmath, the golden generator's exact solution) within 1e-13 — starts the float64
  solution once refused ("invalid n1"), returned NaN for, or got wrong by 1e-9 … 1.
- What each limit returns: at rest at the top (θ = π) and the bottom, exactly at the top with a tiny
  velocity, the separatrix (E = mgl, J₃ = 0: ``period_z`` = inf), an exactly conical orbit, g < 0,
  g = 0, huge and tiny l and g — against DOP853 at rtol 1e-13 where there is motion.
- Property tests (hypothesis) over families of degenerate starts: nearly planar (J₃ down to 1e-300 of
  its scale), nearly conical, next to the top, tiny swings at the bottom (down to 1e-8 rad), near the
  separatrix, random. Each start is accepted; the states are finite, on TS², keep E and J₃ to a few
  ulps of their scale, the Weierstrass z (T-4.7) equals the Jacobi z, and DOP853 (rtol 1e-13) agrees
  over τ = ω₀t ≤ 2.

Examples per family: 25 (derandomised, CI); ``PENDULAB_LONG=1`` runs 1000 each. SI units; error
measure max(|Δx|/l, |Δv|/(lω₀ + |v|)).
"""

from __future__ import annotations

import json
import math
import os
from typing import Any

import numpy as np
import pytest
from conftest import TESTDATA
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import pendulab as pl

LONG = bool(os.environ.get("PENDULAB_LONG"))
PROPS = settings(
    max_examples=1000 if LONG else 25,
    deadline=None,
    derandomize=not LONG,
    database=None,
    suppress_health_check=list(HealthCheck),
)
CASES: list[dict[str, Any]] = json.loads((TESTDATA / "degenerate_cases.json").read_text())["cases"]
EPS = np.finfo(float).eps


def error(p: pl.Pendulum, x: Any, v: Any, x_ref: Any, v_ref: Any, v0: Any) -> float:
    """max(|Δx|/l, |Δv|/(lω₀ + |v₀|)), over all samples."""
    vs = p.length * p.omega0 + float(np.linalg.norm(v0))
    dx = np.abs(np.asarray(x) - np.asarray(x_ref)).max() / p.length
    return float(max(dx, np.abs(np.asarray(v) - np.asarray(v_ref)).max() / vs))


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_degenerate_cases_match_the_high_precision_states(case: dict[str, Any]) -> None:
    """Within 1e-13 of the 50–270-digit states at τ = 0.37, 1.3, 3 (measured ≤ 2.6e-15)."""
    p = pl.Pendulum(length=case["length"], g=case["g"], mass=case["mass"])
    s0 = p.state(case["x0"], case["v0"])
    sol = pl.exact(p, s0)
    for s in case["samples"]:
        st_ = sol.state(s["t"])
        want_x = [float(c) for c in s["x_str"]]
        want_v = [float(c) for c in s["v_str"]]
        assert error(p, st_.x, st_.v, want_x, want_v, s0.v) < 1e-13, (case["name"], s["tau"])


def dop853(p: pl.Pendulum, s0: pl.State, t: np.ndarray) -> pl.Trajectory:
    return pl.simulate(p, s0, float(t[-1]), method="dop853", rtol=1e-13, atol=1e-18 * p.length, save_at=t)


def test_rest_at_the_top_and_the_bottom_is_rest() -> None:
    """θ = fl(π) puts the bob 1.2e-16 l off the axis; at rest there it is the (unstable) equilibrium,
    kind "rest", not a planar swing that falls off after 37/ω₀. Likewise the bottom, and both for
    g < 0 (where the stable point is the top)."""
    for g in (9.81, -9.81):
        p = pl.Pendulum(length=2.0, g=g)
        for theta in (math.pi, 0.0):
            s0 = p.state_from_angles(theta=theta, phi=0.4)
            sol = pl.exact(p, s0)
            assert sol.kind == "rest" and sol.period_z is None
            x, v = sol.state(np.array([0.0, 10.0, 1e4]))
            assert np.array_equal(x, np.tile(s0.x, (3, 1))) and not v.any()
    # 1e-12 rad from the top is a real motion: it falls off, as DOP853 says while it is still close
    # (every rounding there grows like e^{ω₀t}: at t = 9 s, where it has fallen to z = 0.65 l, the
    # float64 floor is ~1e-4 and DOP853 is 1.7e-7 away) and as the Weierstrass form says after
    p = pl.Pendulum(length=1.0, g=9.81)
    s0 = p.state_from_angles(theta=math.pi - 1e-12)
    sol = pl.exact(p, s0)
    assert sol.kind == "planar"
    t = np.array([1.0, 5.0])
    ref = dop853(p, s0, t)
    x, v = sol.state(t)
    assert error(p, x, v, ref.x[-2:], ref.v[-2:], s0.v) < 1e-12
    z, _ = sol.height_weierstrass(9.0)
    assert sol.state(9.0).x[2] < 0.7 and abs(z - sol.state(9.0).x[2]) < 1e-13


def test_exactly_at_the_top_with_a_tiny_velocity_goes_over_the_top() -> None:
    p = pl.Pendulum(length=1.0, g=9.81)
    for speed in (1e-12, 1e-6):
        s0 = p.state([0.0, 0.0, 1.0], [speed, 0.0, 0.0])
        sol = pl.exact(p, s0)
        assert sol.kind == "planar_rotating" and math.isfinite(sol.period_z)
        back = sol.state(sol.period_z)
        assert error(p, back.x, back.v, s0.x, s0.v, s0.v) < 1e-12
        t = np.array([0.5, 3.0])
        ref = dop853(p, s0, t)
        x, v = sol.state(t)
        assert error(p, x, v, ref.x[-2:], ref.v[-2:], s0.v) < 1e-9


def test_the_separatrix_and_the_exactly_conical_orbit() -> None:
    p = pl.Pendulum(length=1.0, g=9.81)
    # released at the bottom with 2√(gl) (exact in float64 for g = 9.81? use g = 4: √(4·1)·2 = 4)
    q = pl.Pendulum(length=1.0, g=4.0)
    sep = pl.exact(q, q.state([0.0, 0.0, -1.0], [4.0, 0.0, 0.0]))
    assert sep.kind == "separatrix" and sep.period_z == math.inf and sep.azimuth_advance is None
    late = sep.state(30.0)
    assert late.x[2] > 1.0 - 1e-12 and np.all(np.isfinite(late.v))
    with pytest.raises(pl.InvalidInputError, match="J3"):
        sep.phases()
    # conical: φ̇² = g/(l cos α) at θ = π − α … here below the equator, θ = 60°
    theta = math.radians(60)
    s0 = p.state_from_angles(theta=theta, phi_dot=math.sqrt(9.81 / math.cos(theta)))
    con = pl.exact(p, s0)
    assert con.kind == "conical"
    t = np.array([0.3, 2.0])
    x, v = con.state(t)
    assert np.allclose(x[:, 2], s0.x[2], rtol=0, atol=1e-12)
    ref = dop853(p, s0, t)
    assert error(p, x, v, ref.x[-2:], ref.v[-2:], s0.v) < 1e-10


@pytest.mark.parametrize("length", [1e-3, 0.01, 100.0, 1e3])
@pytest.mark.parametrize("g", [1e-6, 9.81, -274.0, 0.0])
def test_huge_and_tiny_length_and_gravity(length: float, g: float) -> None:
    """Generic motion (great circles for g = 0) at the extremes of l and g agrees with DOP853."""
    p = pl.Pendulum(length=length, g=g)
    w = math.sqrt(abs(g) / length) if g else 1.0 / length
    s0 = p.state_from_angles(theta=1.0, theta_dot=0.2 * w, phi_dot=0.3 * w)
    sol = pl.exact(p, s0)
    assert sol.kind == ("great_circle" if g == 0 else "generic")
    t = np.array([0.7, 2.0]) / w
    x, v = sol.state(t)
    ref = dop853(p, s0, t)
    assert error(p, x, v, ref.x[-2:], ref.v[-2:], s0.v) < 1e-10


# --- property tests over families of degenerate starts ---


def _frame(th: float, ph: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    x = np.array([math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), -math.cos(th)])
    e_th = np.array([math.cos(th) * math.cos(ph), math.cos(th) * math.sin(ph), math.sin(th)])
    e_ph = np.array([-math.sin(ph), math.cos(ph), 0.0])
    return x, e_th, e_ph


U = st.floats(0.0, 1.0, exclude_max=True)
SIGN = st.sampled_from([-1.0, 1.0])
PHI = st.floats(-math.pi, math.pi)


@st.composite
def nearly_planar(draw: Any) -> tuple[np.ndarray, np.ndarray]:
    """Any height and energy; J₃ from 1e-300 to 1e-1 of its in-plane scale."""
    x, e_th, e_ph = _frame(math.pi * draw(U), draw(PHI))
    speed = 10 ** (-8 + 8.8 * draw(U))
    return x, speed * (e_th + draw(SIGN) * 10 ** (-300 + 299 * draw(U)) * e_ph)


@st.composite
def nearly_conical(draw: Any) -> tuple[np.ndarray, np.ndarray]:
    """The conical rate at α ∈ (0, π/2) perturbed by 1e-16 … 1e-2."""
    th = 1e-3 + (math.pi / 2 - 2e-3) * draw(U)
    x, e_th, e_ph = _frame(th, draw(PHI))
    rel = 10 ** (-16 + 14 * draw(U))
    w = math.sqrt(1.0 / math.cos(th))
    return x, w * math.sin(th) * (1 + draw(SIGN) * rel) * e_ph + rel * (draw(U) - 0.5) * e_th


@st.composite
def next_to_the_top(draw: Any) -> tuple[np.ndarray, np.ndarray]:
    """1e-8 … 1e-1 rad from the top, speeds 1e-10 … 1."""
    x, e_th, e_ph = _frame(math.pi - 10 ** (-8 + 7 * draw(U)), draw(PHI))
    return x, 10 ** (-10 + 10 * draw(U)) * ((draw(U) - 0.5) * e_th + (draw(U) - 0.5) * e_ph)


@st.composite
def tiny_swings(draw: Any) -> tuple[np.ndarray, np.ndarray]:
    """Amplitudes 1e-8 … 1e-1 rad about the bottom."""
    a = 10 ** (-8 + 7 * draw(U))
    x, e_th, e_ph = _frame(a * draw(U), draw(PHI))
    return x, a * ((draw(U) - 0.5) * e_th + (draw(U) - 0.5) * e_ph)


@st.composite
def near_the_separatrix(draw: Any) -> tuple[np.ndarray, np.ndarray]:
    """E = mgl to 1e-16 … 1e-3, J₃ from 1e-16 … 1e-2 of the speed."""
    th = math.pi * draw(U)
    x, e_th, e_ph = _frame(th, draw(PHI))
    speed = math.sqrt(2 * (1 + math.cos(th)) * (1 + draw(SIGN) * 10 ** (-16 + 13 * draw(U))))
    rel = 10 ** (-16 + 14 * draw(U))
    return x, speed * (math.sqrt(1 - rel * rel) * e_th + rel * e_ph)


@st.composite
def random_starts(draw: Any) -> tuple[np.ndarray, np.ndarray]:
    """Any height; speeds 1e-3 … 30 (high energy)."""
    x, e_th, e_ph = _frame(math.pi * draw(U), draw(PHI))
    return x, 10 ** (-3 + 4.5 * draw(U)) * ((draw(U) - 0.5) * e_th + (draw(U) - 0.5) * e_ph)


PENDULUMS = st.tuples(st.sampled_from([0.01, 1.0, 100.0, 0.37]), st.sampled_from([9.81, 1e-6, -274.0, 1.0]))


def check(unit: tuple[np.ndarray, np.ndarray], lg: tuple[float, float]) -> None:
    length, g = lg
    p = pl.Pendulum(length=length, g=g)
    w0 = p.omega0
    mirror = np.array([1.0, 1.0, -1.0 if g < 0 else 1.0])
    s0 = p.state(length * unit[0] * mirror, length * w0 * unit[1] * mirror, project=True)
    sol = pl.exact(p, s0)  # accepted: never an error for a state on TS²
    t = np.array([0.0, 0.37, 1.3, 2.0]) / w0
    x, v = sol.state(t)
    assert np.isfinite(x).all() and np.isfinite(v).all()
    vs = length * w0 + float(np.linalg.norm(s0.v))
    assert np.abs(np.linalg.norm(x, axis=1) - length).max() <= 4 * EPS * length
    energy = 0.5 * (v * v).sum(axis=1) + g * x[:, 2]
    j3 = x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]
    assert np.abs(energy - p.energy(s0) / p.mass).max() <= 16 * EPS * (abs(g) * length + s0.v @ s0.v)
    assert np.abs(j3 - p.j3(s0) / p.mass).max() <= 16 * EPS * length * vs
    if sol.weierstrass is not None:
        z, zdot = sol.height_weierstrass(t)
        assert np.abs(z - x[:, 2]).max() < 1e-13 * length and np.abs(zdot - v[:, 2]).max() < 1e-13 * vs
    ref = dop853(p, s0, t[1:])
    # DOP853's own error at rtol 1e-13 over τ ≤ 2 is ≤ ~1e-11; the defects guarded against were 1e-9 … 1
    assert error(p, x[1:], v[1:], ref.x[-3:], ref.v[-3:], s0.v) < 1e-10, sol.kind


@PROPS
@given(nearly_planar(), PENDULUMS)
def test_nearly_planar_starts(unit: Any, lg: Any) -> None:
    check(unit, lg)


@PROPS
@given(nearly_conical(), PENDULUMS)
def test_nearly_conical_starts(unit: Any, lg: Any) -> None:
    check(unit, lg)


@PROPS
@given(next_to_the_top(), PENDULUMS)
def test_starts_next_to_the_top(unit: Any, lg: Any) -> None:
    check(unit, lg)


@PROPS
@given(tiny_swings(), PENDULUMS)
def test_tiny_swings_at_the_bottom(unit: Any, lg: Any) -> None:
    check(unit, lg)


@PROPS
@given(near_the_separatrix(), PENDULUMS)
def test_starts_near_the_separatrix(unit: Any, lg: Any) -> None:
    check(unit, lg)


@PROPS
@given(random_starts(), PENDULUMS)
def test_random_starts(unit: Any, lg: Any) -> None:
    check(unit, lg)


@pytest.mark.parametrize("g", [1e-300, -1e-300, 1e-200, 5e-324])
def test_negligible_gravity_moves_on_the_great_circle(g: float) -> None:
    """Issue 30 audit: with |g| = 1e-200 … 5e-324 m/s² beside |v| = 0.84 m/s the elliptic form
    overflowed ("conical", a z-period of 0 s, no state; /api/exact answered that with 200)."""
    free = pl.Pendulum(g=0.0)
    p = pl.Pendulum(g=g)
    sol, ref = (
        pl.exact(p, p.state_from_angles(1.0, 0.0, 0.0, 1.0)),
        pl.exact(free, free.state_from_angles(1.0, 0.0, 0.0, 1.0)),
    )
    assert sol.kind == "great_circle"
    assert sol.period_z == pytest.approx(2 * math.pi / math.sin(1.0), rel=1e-14)
    t = np.array([0.3, 7.0, 1e4])
    for a, b in zip(sol.state(t), ref.state(t), strict=True):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-12)
