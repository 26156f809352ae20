"""The pendulum on a string (model ``string``, docs/models.md; T-7.5) against an independent hybrid
integration: the taut phases by Lagrange's equations in angles (tests/variants_reference.py) with
SciPy's DOP853 and its event location of the tension T = 0, the slack phases as free flight under
gravity, the return to |x| = l found by bracketing on a grid and Brent's method, the snap as the
inelastic (e = 0) loss of the radial velocity. Model definition only (a string pulls, never pushes;
T from the radial Lagrange equation: T/m = l(θ̇² + sin²θ φ̇²) + F·u with F = −g e₃). SI units."""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from variants_reference import frame, start, to_angles, to_cartesian

import pendulab as pl

G, L = 9.81, 1.0


def taut(y0: np.ndarray, t0: float, t_end: float) -> tuple[float, np.ndarray, bool]:
    """Rod motion from angle state y0 at t0 until T = 0 or t_end: (time, angle state, left?)."""

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        th, ph, thd, phd = y
        _, e_th, e_ph = frame(th, ph)
        f = np.array([0.0, 0.0, -G])
        st, ct = np.sin(th), np.cos(th)
        return np.array(
            [thd, phd, st * ct * phd**2 + f @ e_th / L, -2 * ct / st * thd * phd + f @ e_ph / (L * st)]
        )

    def tension(_t: float, y: np.ndarray) -> float:
        th, ph, thd, phd = y
        return L * (thd**2 + np.sin(th) ** 2 * phd**2) + np.array([0.0, 0.0, -G]) @ frame(th, ph)[0]

    tension.terminal, tension.direction = True, -1  # type: ignore[attr-defined]
    sol = solve_ivp(
        rhs, (t0, t_end), y0[[1, 2, 4, 5]], method="DOP853", rtol=1e-13, atol=1e-14, events=tension
    )
    y = sol.y[:, -1]
    return float(sol.t[-1]), np.array([L, y[0], y[1], 0.0, y[2], y[3]]), sol.status == 1


def flight(x: np.ndarray, v: np.ndarray) -> tuple[float, np.ndarray, np.ndarray]:
    """Free flight x + v τ − ½ g τ² e₃ from the sphere, to the first τ > 0 with |x(τ)| = l again."""

    def gap(tau: float) -> float:
        return float(np.linalg.norm(x + v * tau - 0.5 * G * tau**2 * np.array([0, 0, 1.0]))) - L

    grid = np.linspace(1e-6, 3.0, 30001)
    inside = np.linalg.norm(x + np.outer(grid, v) - np.outer(0.5 * G * grid**2, [0, 0, 1.0]), axis=1) - L
    k = int(np.argmax(inside > 0))
    assert k > 0 and inside[k - 1] < 0
    tau = brentq(gap, grid[k - 1], grid[k], xtol=1e-15, rtol=1e-15)
    xe = x + v * tau - 0.5 * G * tau**2 * np.array([0, 0, 1.0])
    return tau, xe, v - G * tau * np.array([0, 0, 1.0])


def test_string_slack_flights_and_snaps_match_an_independent_hybrid_run() -> None:
    """A 3-D swing that rises above the pivot, goes slack, flies and snaps taut (e = 0), over 4 s."""
    x0, v0 = start(L, 1.45, 0.2, 0.5, 6.0)  # a 3-D swing fast enough to rise above the pivot
    t_end, t, y = 4.0, 0.0, to_angles(x0, v0)
    events: list[tuple[str, float, np.ndarray]] = []
    while True:
        t, y, left = taut(y, t, t_end)
        if not left:
            break
        (x,), (v,) = to_cartesian(y[:, None])
        events.append(("slack", t, x))
        tau, x, v = flight(x, v)
        t += tau
        v = v - (x @ v) / L**2 * x  # e = 0: the radial velocity is lost
        events.append(("taut", t, x))
        y = to_angles(x, v)
    (x_end,), (v_end,) = to_cartesian(y[:, None])

    p = pl.Pendulum(length=L, g=G, model="string", restitution=0.0)
    tr = pl.simulate(p, p.state(x0, v0), t_end, method="rattle8", dt=1e-3, save_every=1000)
    ev = tr.events
    assert len(events) >= 2 and list(ev["kind"]) == [k for k, _, _ in events]
    # measured: event times to 4e-15 s, places to 4e-14 m, the end state to 2e-14 m, 1e-13 m/s
    np.testing.assert_allclose(ev["t"], [tt for _, tt, _ in events], rtol=0, atol=1e-12)
    np.testing.assert_allclose(ev["x"], [xx for _, _, xx in events], rtol=0, atol=1e-12 * L)
    assert np.abs(tr.x[-1] - x_end).max() < 1e-11 * L
    assert np.abs(tr.v[-1] - v_end).max() < 1e-11 * np.sqrt(G * L)
