"""Pendulab against its peers (issue 5, parts 3 and 4), side by side in one process.

Cases (t_end = 100 s, l = 1 m, m = 1 kg, g = 9.81 m/s²): the scenarios ``rosette``, ``near_top``
(1° below the top) and ``over_the_top`` (planar revolutions, J₃ = 0) of examples/scenarios/.
Reference: Pendulab's exact solution at t = 100 s (``pl.exact``), itself checked here against the
40-digit mpmath golden data of testdata/golden_states.json (the difference is printed and stored).
Error: the final position error |x(100 s) − x_ref|/l. For every method a step size (fixed-step) or a
tolerance (adaptive; atol = rtol/100) is scanned from coarse to fine until the error stops improving,
falls below 1e-13, one run takes more than ``--cap`` seconds (default 5) or the whole scan 10 times
that; "time to 1e-10" is the cheapest setting that reaches it. Every wall time is a median of
repeated runs (5 for fast runs, at least 3, 1 beyond 1.5 s), and every comparison is a ratio of
figures measured in this one run.

Peers (each behind a function, so this module imports with numpy and pendulab alone):
- SciPy ``solve_ivp`` RK45 and DOP853 on the Cartesian ODE T-2.4 (ẋ = v, v̇ = −g e₃ + λ x,
  λ = (g z − |v|²)/l²) — not the angle ODE, which is singular at the poles (sin θ in a denominator;
  the over-the-top case passes through both);
- numba: a fixed-step RK4 loop on T-2.4 (``@njit``, compile time excluded);
- C: rk4.c, a plain RK4 loop and a hand-vectorised ensemble (SoA blocks of 64, ``omp simd``, OpenMP
  over 1 or 2 threads), built with ``gcc -O3 -march=native -fopenmp``, called once per run via ctypes;
- MuJoCo: a point mass on a ball joint, RK4 integrator, contacts and constraints disabled, stepped
  in C with ``mj_step(m, d, nstep=n)``; the body carries a tiny isotropic inertia I_c = 1e-6 m l²
  (MuJoCo needs one) and gravity is raised by the factor (1 + I_c/(m l²)) that makes the motion of
  its centre of mass exactly the spherical pendulum's (the spin about the rod stays zero);
- JAX + Diffrax on CPU, float64: Tsit5 and Dopri8 with a PID controller (pcoeff = icoeff = 0.3),
  ``jax.jit``-compiled once per solver (compile time excluded).
Pendulab: every method of ``pl.methods()`` through ``pl.simulate``, DOP853 also with ``conserve``,
the ensemble kernel (``_core.EnsembleRun``, the kernel of ``pl.simulate_ensemble``) and the exact
solution.

Run: ``make bench-peers`` (installs the peers into bench/peers/.venv, builds Pendulab there, runs
this script, writes bench/peers/results/, docs/img/peers_work_precision.png and the "Against peers"
section of docs/performance.md). ``--quick`` is a short smoke run that writes
results/peers_quick.json only.
"""

from __future__ import annotations

import argparse
import ctypes
import datetime as dt_mod
import json
import math
import os
import platform
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import harness as hz

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
RESULTS = HERE / "results"
BUILD = HERE / "build"
DOCS = REPO / "docs" / "performance.md"
PLOT = REPO / "docs" / "img" / "peers_work_precision.png"
T_END = 100.0
CASES = ("rosette", "near_top", "over_the_top")
TOL_LO, TOL_HI = 1e-6, 1e-10
FLOOR = 1e-13
MUJOCO_IC = 1e-6  # the bob's isotropic inertia about its centre, in units of m l²


@dataclass
class Case:
    name: str
    length: float
    mass: float
    g: float
    x0: np.ndarray
    v0: np.ndarray
    x_ref: np.ndarray
    v_ref: np.ndarray
    exact_vs_golden: float
    floor: float

    @property
    def omega0(self) -> float:
        return math.sqrt(abs(self.g) / self.length)

    @property
    def y0(self) -> np.ndarray:
        return np.concatenate([self.x0, self.v0])


Runner = Callable[[float], tuple[np.ndarray, np.ndarray, int]]


@dataclass
class Method:
    """A method to scan: ``prepare(case)`` returns ``run(setting) -> (x, v, steps)``; ``kind`` is
    "fixed" (setting = number of steps over [0, 100 s]) or "adaptive" (setting = rtol)."""

    name: str
    family: str  # "pendulab" or the peer's name
    kind: str
    prepare: Callable[[Case], Runner]


def fixed_settings(quick: bool) -> list[int]:
    """Numbers of steps over [0, 100 s]: 500 (dt = 0.2 s) up by factors √2 to 1.6·10⁹ (dt ≈ 6e-8 s);
    the scan stops long before the end (``should_refine``)."""
    return [round(500 * 2 ** (k / 2)) for k in range(0, 44 if not quick else 24)]


def adaptive_settings(quick: bool) -> list[float]:
    """rtol = 1e-3 … 1e-14 by factors √10 (quick: … 1e-10)."""
    return [10.0 ** (-k / 2) for k in range(6, 29 if not quick else 21)]


# --------------------------------------------------------------------------------------------------
# Cases and reference


def load_cases(names: tuple[str, ...]) -> list[Case]:
    import pendulab as pl

    golden = json.loads((REPO / "testdata" / "golden_states.json").read_text())
    out = []
    for name in names:
        sc = pl.load_scenario(REPO / "examples" / "scenarios" / f"{name}.toml")
        p, s0 = sc.pendulum(), sc.initial_state()
        ref = pl.exact(p, s0).state(T_END)
        gcase = next(c for c in golden["cases"] if c["name"] == name)
        gs = next(s for s in gcase["samples"] if s["t"] == T_END)
        x0, v0 = np.asarray(s0.x, dtype=float), np.asarray(s0.v, dtype=float)
        if not (
            np.allclose(x0, gcase["x0"], rtol=0, atol=1e-15) and np.allclose(v0, gcase["v0"], atol=1e-15)
        ):
            raise SystemExit(f"{name}: the scenario's start is not the golden data's start")
        c = Case(
            name,
            p.length,
            p.mass,
            p.g,
            x0,
            v0,
            np.asarray(ref.x, dtype=float),
            np.asarray(ref.v, dtype=float),
            0.0,
            float(gs["floor"]),
        )
        c.exact_vs_golden = hz.state_error(
            c.x_ref, c.v_ref, np.array(gs["x"]), np.array(gs["v"]), c.length, c.omega0
        )
        out.append(c)
    return out


# --------------------------------------------------------------------------------------------------
# Pendulab


def pendulab_methods() -> list[Method]:
    import pendulab as pl

    out = []
    for info in pl.methods():
        name = info["name"]
        kind = "adaptive" if info["adaptive"] else "fixed"
        out.append(Method(f"pendulab {name}", "pendulab", kind, _pendulab_prepare(name, kind, False)))
        if name == "dop853":
            out.append(
                Method("pendulab dop853 conserve", "pendulab", kind, _pendulab_prepare(name, kind, True))
            )
    return out


def _pendulab_prepare(method: str, kind: str, conserve: bool) -> Callable[[Case], Runner]:
    def prepare(case: Case) -> Runner:
        import pendulab as pl

        p = pl.Pendulum(length=case.length, g=case.g, mass=case.mass)
        s0 = p.state(case.x0, case.v0)

        def run(setting: float) -> tuple[np.ndarray, np.ndarray, int]:
            if kind == "adaptive":
                tr = pl.simulate(
                    p, s0, T_END, method=method, rtol=setting, atol=setting * 1e-2, conserve=conserve,
                    save_every=10**9, progress=False,
                )  # fmt: skip
            else:
                tr = pl.simulate(
                    p, s0, T_END, method=method, dt=T_END / setting, save_every=10**9, progress=False
                )
            return tr.x[-1], tr.v[-1], int(tr.stats["steps"])

        return run

    return prepare


# --------------------------------------------------------------------------------------------------
# SciPy


def scipy_methods() -> list[Method]:
    return [Method(f"scipy {m}", "scipy", "adaptive", _scipy_prepare(m)) for m in ("RK45", "DOP853")]


def _scipy_prepare(method: str) -> Callable[[Case], Runner]:
    def prepare(case: Case) -> Runner:
        from scipy.integrate import solve_ivp

        l2inv, g = 1.0 / case.length**2, case.g

        def rhs(_t: float, y: np.ndarray) -> np.ndarray:
            lam = (g * y[2] - (y[3] * y[3] + y[4] * y[4] + y[5] * y[5])) * l2inv
            return np.array([y[3], y[4], y[5], lam * y[0], lam * y[1], lam * y[2] - g])

        def run(rtol: float) -> tuple[np.ndarray, np.ndarray, int]:
            sol = solve_ivp(rhs, (0.0, T_END), case.y0, method=method, rtol=rtol, atol=rtol * 1e-2)
            if sol.status != 0:
                raise RuntimeError(sol.message)
            y = sol.y[:, -1]
            return y[:3], y[3:], int(sol.t.size - 1)

        return run

    return prepare


# --------------------------------------------------------------------------------------------------
# numba


_NUMBA: dict[str, Any] = {}


def numba_rk4() -> Callable[..., None]:
    if "rk4" not in _NUMBA:
        import numba

        @numba.njit(cache=False)
        def rk4(y: np.ndarray, l2inv: float, g: float, dt: float, n: int) -> None:
            x0, x1, x2, v0, v1, v2 = y[0], y[1], y[2], y[3], y[4], y[5]
            h2, h6 = 0.5 * dt, dt / 6.0
            for _ in range(n):
                l1 = (g * x2 - (v0 * v0 + v1 * v1 + v2 * v2)) * l2inv
                a0, a1, a2, b0, b1, b2 = v0, v1, v2, l1 * x0, l1 * x1, l1 * x2 - g
                y0, y1, y2 = x0 + h2 * a0, x1 + h2 * a1, x2 + h2 * a2
                w0, w1, w2 = v0 + h2 * b0, v1 + h2 * b1, v2 + h2 * b2
                l2 = (g * y2 - (w0 * w0 + w1 * w1 + w2 * w2)) * l2inv
                c0, c1, c2, d0, d1, d2 = w0, w1, w2, l2 * y0, l2 * y1, l2 * y2 - g
                y0, y1, y2 = x0 + h2 * c0, x1 + h2 * c1, x2 + h2 * c2
                w0, w1, w2 = v0 + h2 * d0, v1 + h2 * d1, v2 + h2 * d2
                l3 = (g * y2 - (w0 * w0 + w1 * w1 + w2 * w2)) * l2inv
                e0, e1, e2, f0, f1, f2 = w0, w1, w2, l3 * y0, l3 * y1, l3 * y2 - g
                y0, y1, y2 = x0 + dt * e0, x1 + dt * e1, x2 + dt * e2
                w0, w1, w2 = v0 + dt * f0, v1 + dt * f1, v2 + dt * f2
                l4 = (g * y2 - (w0 * w0 + w1 * w1 + w2 * w2)) * l2inv
                g0, g1, g2, k0, k1, k2 = w0, w1, w2, l4 * y0, l4 * y1, l4 * y2 - g
                x0 += h6 * (a0 + 2.0 * c0 + 2.0 * e0 + g0)
                x1 += h6 * (a1 + 2.0 * c1 + 2.0 * e1 + g1)
                x2 += h6 * (a2 + 2.0 * c2 + 2.0 * e2 + g2)
                v0 += h6 * (b0 + 2.0 * d0 + 2.0 * f0 + k0)
                v1 += h6 * (b1 + 2.0 * d1 + 2.0 * f1 + k1)
                v2 += h6 * (b2 + 2.0 * d2 + 2.0 * f2 + k2)
            y[0], y[1], y[2], y[3], y[4], y[5] = x0, x1, x2, v0, v1, v2

        rk4(np.zeros(6), 1.0, 9.81, 1e-3, 10)  # compile outside the timings
        _NUMBA["rk4"] = rk4
    return _NUMBA["rk4"]


def numba_methods() -> list[Method]:
    def prepare(case: Case) -> Runner:
        rk4 = numba_rk4()
        l2inv = 1.0 / case.length**2

        def run(n: float) -> tuple[np.ndarray, np.ndarray, int]:
            y = case.y0.copy()
            rk4(y, l2inv, case.g, T_END / n, int(n))
            return y[:3], y[3:], int(n)

        return run

    return [Method("numba rk4", "numba", "fixed", prepare)]


# --------------------------------------------------------------------------------------------------
# C


_C: dict[str, Any] = {}
C_FLAGS = ["-O3", "-march=native", "-fopenmp", "-shared", "-fPIC"]


def c_library() -> Any:
    if "lib" not in _C:
        BUILD.mkdir(exist_ok=True)
        so = BUILD / "librk4.so"
        subprocess.run(["gcc", *C_FLAGS, str(HERE / "rk4.c"), "-o", str(so)], check=True)
        lib = ctypes.CDLL(str(so))
        dp = ctypes.POINTER(ctypes.c_double)
        lib.rk4_run.argtypes = [dp, ctypes.c_double, ctypes.c_double, ctypes.c_double, ctypes.c_long]
        lib.rk4_run.restype = None
        lib.rk4_ensemble.argtypes = [
            dp, dp, dp, ctypes.c_long, ctypes.c_double, ctypes.c_long, ctypes.c_int,
        ]  # fmt: skip
        lib.rk4_ensemble.restype = None
        _C["lib"] = lib
    return _C["lib"]


def _dp(a: np.ndarray) -> Any:
    return a.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


def c_methods() -> list[Method]:
    def prepare(case: Case) -> Runner:
        lib = c_library()

        def run(n: float) -> tuple[np.ndarray, np.ndarray, int]:
            y = case.y0.copy()
            lib.rk4_run(_dp(y), case.length, case.g, T_END / n, int(n))
            return y[:3], y[3:], int(n)

        return run

    return [Method("C rk4", "C", "fixed", prepare)]


def c_ensemble(
    y_soa: np.ndarray, length: np.ndarray, g: np.ndarray, dt: float, steps: int, threads: int
) -> None:
    lib = c_library()
    n = length.size
    lib.rk4_ensemble(_dp(y_soa), _dp(length), _dp(g), n, dt, steps, threads)


# --------------------------------------------------------------------------------------------------
# MuJoCo


def mujoco_model(case: Case, dt: float) -> tuple[Any, Any]:
    import mujoco

    ic = MUJOCO_IC * case.mass * case.length**2
    gz = -case.g * (1.0 + ic / (case.mass * case.length**2))
    xml = f"""<mujoco>
  <option timestep="{dt!r}" integrator="RK4" gravity="0 0 {gz!r}">
    <flag contact="disable" constraint="disable"/>
  </option>
  <worldbody>
    <body name="bob"><joint type="ball"/>
      <inertial pos="0 0 {-case.length!r}" mass="{case.mass!r}" diaginertia="{ic!r} {ic!r} {ic!r}"/>
    </body>
  </worldbody>
</mujoco>"""
    m = mujoco.MjModel.from_xml_string(xml)
    return m, mujoco.MjData(m)


def _quat_rotating(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Unit quaternion (w, x, y, z) of the rotation taking the unit vector a to the unit vector b."""
    axis = np.cross(a, b)
    s = np.linalg.norm(axis)
    angle = math.atan2(s, float(np.dot(a, b)))
    if s < 1e-300:  # a = ±b: any axis perpendicular to a
        axis = np.cross(a, [1.0, 0.0, 0.0] if abs(a[0]) < 0.9 else [0.0, 1.0, 0.0])
        s = np.linalg.norm(axis)
    return np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * axis / s])


def mujoco_set_state(case: Case, m: Any, d: Any) -> None:
    import mujoco

    mujoco.mj_resetData(m, d)
    q = _quat_rotating(np.array([0.0, 0.0, -1.0]), case.x0 / np.linalg.norm(case.x0))
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, q)
    omega = np.cross(case.x0, case.v0) / case.length**2  # world frame; ω × x = v on TS²
    d.qpos[:] = q
    d.qvel[:] = rot.reshape(3, 3).T @ omega  # a ball joint's qvel is in the body's frame


def mujoco_state(case: Case, d: Any) -> tuple[np.ndarray, np.ndarray]:
    import mujoco

    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, d.qpos / np.linalg.norm(d.qpos))
    r = rot.reshape(3, 3)
    x = r @ np.array([0.0, 0.0, -case.length])
    return x, np.cross(r @ d.qvel, x)


def mujoco_methods() -> list[Method]:
    def prepare(case: Case) -> Runner:
        import mujoco

        m, d = mujoco_model(case, 1e-3)
        mujoco_set_state(case, m, d)
        mujoco.mj_forward(m, d)
        x, v = mujoco_state(case, d)
        if np.linalg.norm(x - case.x0) > 1e-12 or np.linalg.norm(v - case.v0) > 1e-12:
            raise RuntimeError(f"MuJoCo start differs from the case's: {x}, {v}")
        if np.linalg.norm(d.xipos[1] - case.x0) > 1e-12:
            raise RuntimeError("MuJoCo's centre of mass is not where the state says")

        def run(n: float) -> tuple[np.ndarray, np.ndarray, int]:
            m.opt.timestep = T_END / n
            mujoco_set_state(case, m, d)
            mujoco.mj_step(m, d, nstep=int(n))
            x, v = mujoco_state(case, d)
            return x, v, int(n)

        return run

    return [Method("mujoco rk4", "mujoco", "fixed", prepare)]


# --------------------------------------------------------------------------------------------------
# JAX + Diffrax


_JAX: dict[str, Any] = {}


def diffrax_solve(solver_name: str) -> Callable[..., Any]:
    if solver_name not in _JAX:
        os.environ.setdefault("JAX_PLATFORMS", "cpu")
        import jax

        jax.config.update("jax_enable_x64", True)
        import diffrax
        import jax.numpy as jnp

        def f(_t: Any, y: Any, args: Any) -> Any:
            l2inv, g = args
            lam = (g * y[2] - (y[3] * y[3] + y[4] * y[4] + y[5] * y[5])) * l2inv
            return jnp.stack([y[3], y[4], y[5], lam * y[0], lam * y[1], lam * y[2] - g])

        solver = {"tsit5": diffrax.Tsit5(), "dopri8": diffrax.Dopri8()}[solver_name]
        term = diffrax.ODETerm(f)

        @jax.jit
        def solve(y0: Any, rtol: Any, atol: Any, args: Any) -> Any:
            ctrl = diffrax.PIDController(rtol=rtol, atol=atol, pcoeff=0.3, icoeff=0.3)
            sol = diffrax.diffeqsolve(
                term, solver, t0=0.0, t1=T_END, dt0=None, y0=y0, args=args, stepsize_controller=ctrl,
                saveat=diffrax.SaveAt(t1=True), max_steps=2**20, throw=False,
            )  # fmt: skip
            return sol.ys[-1], sol.stats["num_accepted_steps"], sol.result == diffrax.RESULTS.successful

        y0 = jnp.asarray(np.array([0.5, 0.0, -math.sqrt(0.75), 0.0, 1.0, 0.0]))
        out = solve(y0, 1e-3, 1e-5, (1.0, 9.81))
        out[0].block_until_ready()  # compile outside the timings
        _JAX[solver_name] = solve
    return _JAX[solver_name]


def diffrax_methods() -> list[Method]:
    def make(solver_name: str) -> Callable[[Case], Runner]:
        def prepare(case: Case) -> Runner:
            import jax.numpy as jnp

            solve = diffrax_solve(solver_name)
            y0 = jnp.asarray(case.y0)
            args = (1.0 / case.length**2, case.g)

            def run(rtol: float) -> tuple[np.ndarray, np.ndarray, int]:
                y, steps, ok = solve(y0, rtol, rtol * 1e-2, args)
                y = np.asarray(y.block_until_ready())
                if not bool(ok):
                    raise RuntimeError("diffrax did not reach t_end (max_steps or step size)")
                return y[:3], y[3:], int(steps)

            return run

        return prepare

    return [Method(f"diffrax {s}", "diffrax", "adaptive", make(s)) for s in ("tsit5", "dopri8")]


# --------------------------------------------------------------------------------------------------
# Scans


def scan(method: Method, case: Case, quick: bool, cap: float, budget: float) -> list[hz.Run]:
    run = method.prepare(case)
    settings = adaptive_settings(quick) if method.kind == "adaptive" else fixed_settings(quick)
    runs: list[hz.Run] = []
    scan_start = time.perf_counter()
    for s in settings:
        if time.perf_counter() - scan_start > 10 * cap:  # e.g. many slow failures in a row
            print(f"  {method.name:26s} {case.name:13s} scan stopped after {10 * cap:g} s", flush=True)
            break
        kind = "rtol" if method.kind == "adaptive" else "steps"
        t0 = time.perf_counter()
        try:
            wall, (x, v, steps), reps = hz.median_time(lambda s=s: run(s), budget=budget)
            x, v = np.asarray(x, dtype=float), np.asarray(v, dtype=float)
            err = hz.position_error(x, case.x_ref, case.length)
            de, dc = hz.drifts(x, v, case.x0, case.v0, case.length, case.g)
            r = hz.Run(
                method.name, case.name, float(s), kind, wall, steps, err,
                hz.state_error(x, v, case.x_ref, case.v_ref, case.length, case.omega0),
                de, dc, reps,
            )  # fmt: skip
        except Exception as exc:  # a diverged or refused run is a result too
            r = hz.Run(
                method.name, case.name, float(s), kind, time.perf_counter() - t0, 0,
                failed=f"{type(exc).__name__}: {exc}",
            )  # fmt: skip
        runs.append(r)
        print(
            f"  {method.name:26s} {case.name:13s} {kind}={s:<10.3g} err={r.error:9.2e} "
            f"wall={hz.fmt_time(r.wall):>10s} steps={r.steps}"
            + (f"  FAILED {r.failed[:60]}" if r.failed else ""),
            flush=True,
        )
        errors = [q.error if q.ok else math.nan for q in runs]
        walls = [q.wall for q in runs]
        if not hz.should_refine(errors, walls, FLOOR, cap):
            break
    return runs


def exact_run(case: Case) -> hz.Run:
    import pendulab as pl

    p = pl.Pendulum(length=case.length, g=case.g, mass=case.mass)
    s0 = p.state(case.x0, case.v0)
    wall, st, reps = hz.median_time(lambda: pl.exact(p, s0).state(T_END), repeats=101)
    golden = json.loads((REPO / "testdata" / "golden_states.json").read_text())
    gs = next(
        s for s in next(c for c in golden["cases"] if c["name"] == case.name)["samples"] if s["t"] == T_END
    )
    x, v = np.asarray(st.x), np.asarray(st.v)
    de, dc = hz.drifts(x, v, case.x0, case.v0, case.length, case.g)
    return hz.Run(
        "pendulab exact", case.name, math.nan, "none", wall, 0,
        hz.position_error(x, np.array(gs["x"]), case.length),
        hz.state_error(x, v, np.array(gs["x"]), np.array(gs["v"]), case.length, case.omega0),
        de, dc, reps, extra={"note": "error against the mpmath golden data (the reference is this solution)"},
    )  # fmt: skip


# --------------------------------------------------------------------------------------------------
# Step rates, ensembles, the rotation-number map


def step_rates(cases: list[Case], quick: bool, available: dict[str, str | None]) -> dict[str, dict[str, Any]]:
    """Steps per second at dt = 1e-3 s on the rosette (median of 7; MuJoCo 5)."""
    import pendulab as pl

    case = cases[0]
    p = pl.Pendulum(length=case.length, g=case.g, mass=case.mass)
    s0 = p.state(case.x0, case.v0)
    n = 200_000 if quick else 1_000_000
    rates: dict[str, dict[str, Any]] = {}

    def put(name: str, steps: int, fn: Callable[[], Any], repeats: int = 7) -> None:
        wall, _, reps = hz.median_time(fn, repeats=repeats)
        rates[name] = {"steps": steps, "wall": wall, "steps_per_s": steps / wall, "repeats": reps}
        print(f"  rate {name:34s} {steps / wall:10.3e} steps/s", flush=True)

    for info in pl.methods():
        if info["adaptive"]:
            continue
        m = info["name"]
        k = n if m in ("rattle", "rk4") else n // 5
        put(f"pendulab {m} (Stepper.step)", k, lambda m=m, k=k: pl.Stepper(p, s0, method=m, dt=1e-3).step(k))
    w_sim, _, _ = hz.median_time(
        lambda: pl.simulate(p, s0, 1e-3, method="rattle", dt=1e-3, save_every=10**9, progress=False),
        repeats=301,
    )
    w_step, _, _ = hz.median_time(lambda: pl.Stepper(p, s0, method="rattle", dt=1e-3).step(1), repeats=301)
    rates["_overhead"] = {"simulate_one_step": w_sim, "stepper_one_step": w_step}
    print(f"  overhead of one call: simulate {w_sim * 1e6:.1f} µs, Stepper {w_step * 1e6:.1f} µs", flush=True)
    put(
        "pendulab rattle (simulate)",
        n,
        lambda: pl.simulate(p, s0, n * 1e-3, method="rattle", dt=1e-3, save_every=10**9, progress=False),
    )
    sol, times = pl.exact(p, s0), np.linspace(0.0, T_END, n // 10)
    put("pendulab exact (states at many times)", len(times), lambda: sol.state(times))
    if available.get("C") is None:
        lib = c_library()

        def c_run() -> None:
            y = case.y0.copy()
            lib.rk4_run(_dp(y), case.length, case.g, 1e-3, n)

        put("C rk4", n, c_run)
    if available.get("numba") is None:
        rk4 = numba_rk4()
        put("numba rk4", n, lambda: rk4(case.y0.copy(), 1.0 / case.length**2, case.g, 1e-3, n))
    if available.get("mujoco") is None:
        import mujoco

        m_, d_ = mujoco_model(case, 1e-3)
        k = n // 20

        def mj() -> None:
            mujoco_set_state(case, m_, d_)
            mujoco.mj_step(m_, d_, nstep=k)

        put("mujoco rk4 (mj_step, nstep)", k, mj, repeats=5)
        kk = k // 5

        def mj_loop() -> None:
            mujoco_set_state(case, m_, d_)
            for _ in range(kk):
                mujoco.mj_step(m_, d_)

        put("mujoco rk4 (mj_step from a Python loop)", kk, mj_loop, repeats=5)
    return rates


def ensemble_starts(n: int, seed: int = 5) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """n rosette-like starts (θ₀ ∈ [20°, 100°], φ̇₀ ∈ [0.5, 3] rad/s, l = 1 m, g = 9.81 m/s²)."""
    rng = np.random.default_rng(seed)
    th = np.radians(rng.uniform(20.0, 100.0, n))
    ph = rng.uniform(0.0, 2 * np.pi, n)
    phd = rng.uniform(0.5, 3.0, n)
    x = np.stack([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), -np.cos(th)], axis=1)
    v = np.stack([-np.sin(th) * np.sin(ph) * phd, np.sin(th) * np.cos(ph) * phd, np.zeros(n)], axis=1)
    return x, v, np.ones(n)


def ensemble_worker(n: int, steps: int, repeats: int, threads: int, with_c: int) -> dict[str, Any]:
    """Run in a fresh child process (RAYON_NUM_THREADS = threads): Pendulab's ensemble kernel, the same
    through ``pl.simulate_ensemble``, and the C RK4 ensemble on ``threads`` OpenMP threads, timed."""
    import pendulab as pl
    from pendulab import _core

    x, v, ell = ensemble_starts(n)
    g = np.full(n, 9.81)
    dt = 1e-3

    def kernel() -> Any:
        spec, options = _core.EnsembleSpec(ell, g), _core.RunOptions(dt=dt)
        return _core.EnsembleRun(spec, x, v, options, steps, False).result()

    def api() -> Any:
        p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
        return pl.simulate_ensemble(p, np.hstack([x, v]), steps * dt, dt=dt, summary=False, progress=False)

    kernel()
    wk, _, rk = hz.median_time(kernel, repeats=repeats)
    wa, _, _ = hz.median_time(api, repeats=repeats)
    res: dict[str, Any] = {
        "threads": threads,
        "kernel_wall": wk,
        "api_wall": wa,
        "repeats": rk,
        "rate": n * steps / wk,
        "api_rate": n * steps / wa,
    }
    if with_c:
        y = np.ascontiguousarray(np.hstack([x, v]).T)

        def c_run() -> None:
            c_ensemble(y.copy(), ell, g, dt, steps, threads)

        c_run()
        wc, _, _ = hz.median_time(c_run, repeats=repeats)
        res |= {"c_wall": wc, "c_rate": n * steps / wc}
    return res


def ensembles(quick: bool, c_ok: bool) -> dict[str, Any]:
    """Both ensembles in fresh child processes, 1 and 2 threads, alternating (to spread the load of
    the other users of the machine evenly); each figure is the median of ``reps`` runs."""
    n, steps = (1024, 1000) if quick else (4096, 2000)
    reps = 3 if quick else 7
    out: dict[str, Any] = {"n": n, "steps": steps, "dt": 1e-3, "pendulab": {}, "C rk4": {}}
    samples: dict[int, list[dict[str, Any]]] = {1: [], 2: []}
    for _ in range(1 if quick else 3):
        for threads in (1, 2):
            env = dict(os.environ, RAYON_NUM_THREADS=str(threads), OMP_NUM_THREADS=str(threads))
            cmd = [sys.executable, __file__, "--ensemble-worker", str(n), str(steps), str(reps), str(threads)]
            res = subprocess.run([*cmd, str(int(c_ok))], env=env, check=True, capture_output=True, text=True)
            samples[threads].append(json.loads(res.stdout.strip().splitlines()[-1]))
    for threads, ws in samples.items():
        med = {k: float(np.median([w[k] for w in ws])) for k in ws[0] if k != "threads"}
        out["pendulab"][threads] = {k: med[k] for k in ("kernel_wall", "api_wall", "rate", "api_rate")}
        print(f"  ensemble pendulab {threads} thread(s): {med['rate']:.3e} trajectory-steps/s", flush=True)
        if c_ok:
            out["C rk4"][threads] = {"wall": med["c_wall"], "rate": med["c_rate"]}
            print(f"  ensemble C rk4 {threads} thread(s): {med['c_rate']:.3e} trajectory-steps/s", flush=True)
    return out


def rotation_map(quick: bool) -> dict[str, Any]:
    import pendulab as pl

    p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    side = 300 if quick else 1000
    wall, em, reps = hz.median_time(lambda: pl.em_map(p, grid=(side, side)), repeats=3)
    finite = int(np.isfinite(em.W).sum())
    print(f"  em_map {side}x{side}: {hz.fmt_time(wall)} ({finite} finite values)", flush=True)
    return {"points": side * side, "wall": wall, "finite": finite, "repeats": reps}


# --------------------------------------------------------------------------------------------------
# Report


def peer_versions() -> dict[str, str | None]:
    """Version of each peer, or None when it does not import (then its methods are skipped)."""
    out: dict[str, str | None] = {}
    for mod in ("pendulab", "numpy", "scipy", "numba", "mujoco", "jax", "diffrax", "matplotlib"):
        try:
            out[mod] = __import__(mod).__version__
        except Exception:
            out[mod] = None
    try:
        out["gcc"] = subprocess.run(
            ["gcc", "-dumpfullversion"], capture_output=True, text=True
        ).stdout.strip()
    except OSError:
        out["gcc"] = None
    return out


def all_methods(
    versions: dict[str, str | None], only: set[str] | None
) -> tuple[list[Method], dict[str, str | None]]:
    """The methods to scan and, per family, why it is skipped (None: included)."""
    families: dict[str, tuple[str | None, Callable[[], list[Method]]]] = {
        "pendulab": ("pendulab", pendulab_methods),
        "C": ("gcc", c_methods),
        "numba": ("numba", numba_methods),
        "mujoco": ("mujoco", mujoco_methods),
        "scipy": ("scipy", scipy_methods),
        "diffrax": ("diffrax", diffrax_methods),
    }
    methods: list[Method] = []
    skipped: dict[str, str | None] = {}
    for fam, (mod, make) in families.items():
        if only is not None and fam not in only:
            skipped[fam] = "not selected"
        elif mod is not None and versions.get(mod) is None:
            skipped[fam] = f"{mod} is not installed"
        elif fam == "diffrax" and versions.get("jax") is None:
            skipped[fam] = "jax is not installed"
        else:
            skipped[fam] = None
            methods += make()
    return methods, skipped


def plot(runs: list[hz.Run], cases: list[Case], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(dict.fromkeys(r.method for r in runs))
    fig, axes = plt.subplots(1, len(cases), figsize=(6.2 * len(cases), 6.2), squeeze=False)
    cmap = plt.get_cmap("tab20")
    for ax, case in zip(axes[0], cases, strict=True):
        for i, name in enumerate(names):
            # in scan order (coarse to fine), as work-precision diagrams are drawn
            rs = [r for r in runs if r.method == name and r.case == case.name and r.ok]
            if not rs:
                continue
            style = "-" if name.startswith("pendulab") else "--"
            marker = "*" if name == "pendulab exact" else "o"
            ax.loglog(
                [r.wall for r in rs], [max(r.error, 1e-17) for r in rs], style, marker=marker,
                ms=9 if marker == "*" else 3, color=cmap(i % 20), label=name,
            )  # fmt: skip
        for lvl in (TOL_LO, TOL_HI):
            ax.axhline(lvl, color="0.6", lw=0.8, ls=":")
        ax.set_title(f"{case.name}, t = {T_END:g} s")
        ax.set_xlabel("wall time [s] (median)")
        ax.set_ylabel("final position error |x − x_ref| / l")
        ax.set_ylim(1e-16, 10)
        ax.grid(True, which="major", alpha=0.3)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=9, fontsize=8, frameon=False)
    fig.suptitle("Work–precision: Pendulab (solid) vs peers (dashed); 2-core machine, loaded")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def best_of(
    runs: list[hz.Run], case: str, tol: float, family: str | None, exclude_exact: bool = True
) -> hz.Run | None:
    sel = [
        r
        for r in runs
        if r.case == case
        and (family is None or (r.method.startswith("pendulab") == (family == "pendulab")))
        and not (exclude_exact and r.method == "pendulab exact")
    ]
    return hz.cheapest(sel, tol)


def targets(
    runs: list[hz.Run], rates: dict[str, Any], ens: dict[str, Any], rmap: dict[str, Any], cases: list[Case]
) -> list[dict[str, Any]]:
    """The issue's targets, each as a measured ratio with PASS/MISS."""
    out: list[dict[str, Any]] = []

    def add(name: str, value: float | None, target: float, higher: bool, detail: str) -> None:
        out.append(
            {
                "target": name,
                "value": value,
                "goal": target,
                "higher_is_better": higher,
                "verdict": hz.ratio_verdict(value, target, higher),
                "detail": detail,
            }
        )

    rat = rates.get("pendulab rattle (Stepper.step)", {}).get("steps_per_s")
    crk = rates.get("C rk4", {}).get("steps_per_s")
    mj = rates.get("mujoco rk4 (mj_step, nstep)", {}).get("steps_per_s")
    add(
        "RATTLE steps/s ≥ 1.2 × C RK4 loop", rat / crk if rat and crk else None, 1.2, True,
        f"{hz.fmt_sci(rat)} vs {hz.fmt_sci(crk)} steps/s",
    )  # fmt: skip
    add(
        "RATTLE steps/s ≥ 50 × MuJoCo (RK4)", rat / mj if rat and mj else None, 50.0, True,
        f"{hz.fmt_sci(rat)} vs {hz.fmt_sci(mj)} steps/s",
    )  # fmt: skip
    pe, ce = ens["pendulab"], ens.get("C rk4", {})
    p2, c2 = pe.get(2, {}).get("rate"), ce.get(2, {}).get("rate")
    add(
        "ensemble ≥ 0.8 × C RK4 ensemble (2 threads)", p2 / c2 if p2 and c2 else None, 0.8, True,
        f"{hz.fmt_sci(p2)} vs {hz.fmt_sci(c2)} trajectory-steps/s",
    )  # fmt: skip
    p1 = pe.get(1, {}).get("rate")
    add(
        "ensemble speed-up 1 → 2 threads ≥ 1.8", p2 / p1 if p1 and p2 else None, 1.8, True,
        f"{hz.fmt_sci(p1)} → {hz.fmt_sci(p2)} (C RK4: "
        + (f"{ce[2]['rate'] / ce[1]['rate']:.2f}" if 1 in ce and 2 in ce else "—")
        + ")",
    )  # fmt: skip
    ros = "rosette"
    best = best_of(runs, ros, TOL_HI, "pendulab")
    for peer, goal in (("C rk4", 0.2), ("mujoco rk4", 0.01)):
        peer_runs = [r for r in runs if r.method == peer and r.case == ros and r.ok]
        pr = hz.cheapest(peer_runs, TOL_HI)
        if not peer_runs:
            val, det = None, f"{peer} was not run"
        elif best and pr:
            val, det = (
                best.wall / pr.wall,
                f"{best.method} {hz.fmt_time(best.wall)} vs {hz.fmt_time(pr.wall)}",
            )
        elif best:
            longest = max(r.wall for r in peer_runs)
            val = best.wall / longest
            det = (
                f"{best.method} {hz.fmt_time(best.wall)}; {peer} never reached 1e-10 (its longest run, "
                f"{hz.fmt_time(longest)}, gives this ratio as an upper bound)"
            )
        else:
            val, det = None, "Pendulab did not reach 1e-10"
        add(f"time to ≤1e-10 (rosette) ≤ {goal:g} × {peer}", val, goal, False, det)
    misses: list[str] = []
    worst = 0.0
    compared = 0
    for case in cases:
        for lvl in hz.LEVELS:
            b = best_of(runs, case.name, lvl, "pendulab")
            pb = best_of(runs, case.name, lvl, "peers")
            if pb is None:
                continue
            compared += 1
            if b is None:
                misses.append(f"{case.name} {lvl:.0e} (not reached)")
                worst = math.inf
                continue
            worst = max(worst, b.wall / pb.wall)
            if b.wall >= pb.wall:
                misses.append(
                    f"{case.name} {lvl:.0e}: {b.method} {hz.fmt_time(b.wall)} "
                    f"vs {pb.method} {hz.fmt_time(pb.wall)}"
                )
    add(
        "every level 1e-4…1e-12, every case: Pendulab's best faster than every peer's best",
        worst if compared else None, 1.0, False,
        f"{compared} (case, level) pairs compared; largest ratio Pendulab/peer "
        + (f"{worst:.3g}" if math.isfinite(worst) else "∞")
        + ("; misses: " + "; ".join(misses) if misses else ""),
    )  # fmt: skip
    reached = {c.name: best_of(runs, c.name, TOL_HI, "pendulab") for c in cases}
    n_ok = sum(r is not None for r in reached.values())
    add(
        "robustness: every case reaches ≤1e-10 (Pendulab's best)", n_ok / len(cases), 1.0, True,
        ", ".join(f"{k}: {r.method if r else 'not reached'}" for k, r in reached.items()),
    )  # fmt: skip
    add(
        f"rotation-number map of {rmap['points']:.0e} points ≤ 10 s", rmap["wall"] / 10.0, 1.0, False,
        f"pl.em_map: {hz.fmt_time(rmap['wall'])}",
    )  # fmt: skip
    return out


def markdown(
    runs: list[hz.Run], cases: list[Case], rates: dict[str, Any], ens: dict[str, Any], rmap: dict[str, Any],
    tgt: list[dict[str, Any]], meta: dict[str, Any],
) -> str:  # fmt: skip
    v = meta["versions"]
    # the benchmark itself keeps one core busy (load ≈ 1); the wheel build just before adds to the start
    busy = max(meta["load_start"], meta["load_end"]) >= 1.6
    setting = "**while other work was running on it**" if busy else "with nothing else running on it"
    caveat = "absolute figures are pessimistic and noisy, and only the ratios" if busy else "the ratios"
    lines = [
        f"Measured {meta['date']} by `make bench-peers` (`bench/peers/run.py`, "
        f"{meta['wall_total']:.0f} s) on the 2-core machine {setting} (load average "
        f"{meta['load_start']:.1f} at the start, {meta['load_end']:.1f} at the end; the benchmark itself "
        f"accounts for about 1): {caveat}, all taken within this one run, are what carries over to other "
        "machines. Every time is a median of repeated runs (5 for fast runs, at least 3, a "
        "single run beyond 1.5 s).",
        "",
        f"Peers: SciPy {v.get('scipy')}, numba {v.get('numba')}, MuJoCo {v.get('mujoco')}, "
        f"JAX {v.get('jax')} + Diffrax {v.get('diffrax')} (CPU, float64), gcc {v.get('gcc')} "
        f"(`{' '.join(C_FLAGS[:3])}`), numpy {v.get('numpy')}, all in their own virtual environment "
        f"bench/peers/.venv with Pendulab {v.get('pendulab')} installed there from a release wheel of "
        "this checkout (`maturin build --release`, "
        + (
            f"RUSTFLAGS=`{meta['rustflags']}`)."
            if meta.get("rustflags")
            else "the portable build: baseline x86-64, the hot loops dispatched to AVX2/AVX-512 at run time)."
        )
        + "".join(f" **{k}: skipped, {why}.**" for k, why in meta["skipped"].items() if why),
        "",
        "Cases (examples/scenarios/, l = 1 m, g = 9.81 m/s²) to t = 100 s. Reference: `pl.exact` at "
        "t = 100 s; its difference from the mpmath golden data (max(|Δx|/l, |Δv|/(lω₀+|v|))) is "
        + ", ".join(f"{c.name} {c.exact_vs_golden:.1e} (conditioning floor {c.floor:.1e})" for c in cases)
        + ". Error = final position error |x − x_ref|/l. The peers integrate the Cartesian ODE T-2.4 "
        "(ẋ = v, v̇ = −g e₃ + λx, λ = (g z − |v|²)/l²) without projection — the angle ODE is singular "
        "at the poles, which the over-the-top case crosses; MuJoCo integrates its ball joint's "
        "quaternion. Each method's step count (fixed-step: dt = 100 s/n, n up by √2) or rtol "
        "(adaptive: 1e-3 … 1e-14 by √10, atol = rtol/100) is scanned until the error stops improving "
        "(once below 1e-9), "
        f"drops below {FLOOR:.0e}, or one run exceeds {meta['cap']:g} s; a tolerance is reached by the "
        "cheapest setting that reaches it.",
        "",
        "### Targets of issue 5",
        "",
    ]
    rows = []
    for t in tgt:
        val = t["value"]
        if val is None:
            shown = "—"
        elif "robustness" in t["target"]:
            shown = f"{round(val * len(cases))}/{len(cases)} cases"
        elif "map" in t["target"]:
            shown = f"{val * 10:.3g} s"
        else:
            shown = f"{val:.3g}" if math.isfinite(val) else "∞"
        goal = ("≥ " if t["higher_is_better"] else "≤ ") + f"{t['goal']:g}"
        if "robustness" in t["target"]:
            goal = "all"
        elif "map" in t["target"]:
            goal = "≤ 10 s"
        elif "every level" in t["target"]:
            goal = "< 1"
        rows.append([t["target"], shown, goal, f"**{t['verdict']}**", t["detail"]])
    lines += [hz.markdown_table(["target", "measured (ratio)", "goal", "verdict", "detail"], rows), ""]

    lines += ["### Step rates (rosette, dt = 1 ms, no saving)", ""]
    base = rates.get("C rk4", {}).get("steps_per_s")
    listed = {k: r for k, r in rates.items() if "steps_per_s" in r}
    rrows = [
        [f"`{k}`", hz.fmt_sci(r["steps_per_s"]), f"{r['steps_per_s'] / base:.3g}" if base else "—"]
        for k, r in sorted(listed.items(), key=lambda kv: -kv[1]["steps_per_s"])
    ]
    lines += [hz.markdown_table(["method", "steps/s", "relative to the C RK4 loop"], rrows), ""]
    if "_overhead" in rates:
        oh = rates["_overhead"]
        lines += [
            f"Fixed cost of one call (median of 301): `pl.simulate` of one RATTLE step "
            f"{hz.fmt_time(oh['simulate_one_step'])}, `pl.Stepper(...)` + `step(1)` "
            f"{hz.fmt_time(oh['stepper_one_step'])}; it matters only for runs of less than a millisecond "
            "(the coarsest error levels below).",
            "",
        ]

    pe, ce = ens["pendulab"], ens.get("C rk4", {})
    lines += [
        f"### Ensembles ({ens['n']} rosette-like starts × {ens['steps']} steps, dt = 1 ms, "
        "final states only)",
        "",
    ]
    erows = []
    for th in (1, 2):
        p = pe.get(th, {})
        c = ce.get(th, {})
        erows.append(
            [
                th,
                hz.fmt_sci(p.get("rate")),
                hz.fmt_sci(p.get("api_rate")),
                hz.fmt_sci(c.get("rate")),
                f"{p['rate'] / c['rate']:.3g}" if p and c else "—",
            ]
        )
    lines += [
        hz.markdown_table(
            [
                "threads",
                "Pendulab RATTLE kernel (`_core.EnsembleRun`)",
                "`pl.simulate_ensemble`",
                "C RK4 ensemble (OpenMP, simd)",
                "Pendulab / C",
            ],
            erows,
        ),
        "",
        "Trajectory-steps/s. Pendulab's thread count is set with RAYON_NUM_THREADS in a child process. "
        "`pl.simulate_ensemble` polls the background run every 50 ms, so on runs this short its wall time "
        "includes up to 50 ms of waiting; the kernel column times the same run without the poll.",
        "",
    ]

    for case in cases:
        lines += [f"### {case.name}: cheapest settings reaching 1e-6 and 1e-10 at t = 100 s", ""]
        crow = []
        names = list(dict.fromkeys(r.method for r in runs if r.case == case.name))
        for name in names:
            rs = [r for r in runs if r.case == case.name and r.method == name]
            lo, hi = hz.cheapest(rs, TOL_LO), hz.cheapest(rs, TOL_HI)
            ok = [r for r in rs if r.ok]
            best = min(ok, key=lambda r: r.error) if ok else None
            shown = hi or best
            fails = [r for r in rs if r.failed]

            def setting(r: hz.Run | None) -> str:
                if r is None or r.setting_kind == "none":
                    return ""
                if r.setting_kind == "rtol":
                    return f" (rtol {r.setting:.0e})"
                return f" (dt {T_END / r.setting:.2g} s)"

            crow.append(
                [
                    name,
                    (hz.fmt_time(lo.wall) + setting(lo)) if lo else "not reached",
                    (hz.fmt_time(hi.wall) + setting(hi)) if hi else "not reached",
                    hz.fmt_err(best.error) if best else ("failed: " + fails[0].failed[:50] if fails else "—"),
                    hz.fmt_sci(shown.steps / shown.wall) if shown and shown.steps else "—",
                    hz.fmt_err(shown.energy_drift) if shown else "—",
                    hz.fmt_err(shown.constraint_drift) if shown else "—",
                ]
            )
        lines += [
            hz.markdown_table(
                [
                    "method",
                    "time to ≤ 1e-6",
                    "time to ≤ 1e-10",
                    "smallest error",
                    "steps/s",
                    "energy drift",
                    "constraint drift [m]",
                ],
                crow,
            ),
            "",
        ]
    lines += [
        "Steps/s, energy drift |E(100 s) − E(0)|/(m g l) and constraint drift ||x(100 s)| − l| are "
        "those of the setting that reaches 1e-10 (or, where none does, of the most accurate one). "
        "`pendulab exact` is the elliptic-function solution (set-up and one state, median of 101 "
        "calls); its error column is against the mpmath golden data.",
        "",
        "### Work–precision (rosette): least wall time to reach each error level",
        "",
    ]
    wrow = []
    for lvl in hz.LEVELS:
        b = best_of(runs, "rosette", lvl, "pendulab")
        pb = best_of(runs, "rosette", lvl, "peers")
        wrow.append(
            [
                f"{lvl:.0e}",
                f"{b.method} {hz.fmt_time(b.wall)}" if b else "not reached",
                f"{pb.method} {hz.fmt_time(pb.wall)}" if pb else "not reached",
                f"{pb.wall / b.wall:.3g}" if b and pb else "—",
            ]
        )
    lines += [
        hz.markdown_table(["error ≤", "Pendulab's best", "best peer", "peer / Pendulab time"], wrow),
        "",
        "![work-precision](img/peers_work_precision.png)",
        "",
        f"Rotation-number map: `pl.em_map(p, grid=({math.isqrt(rmap['points'])}, "
        f"{math.isqrt(rmap['points'])}))`, {rmap['points']:,} points from the exact solution's "
        f"formulas (T-4.5), {hz.fmt_time(rmap['wall'])} (median of {rmap['repeats']}). Machine-readable "
        "results: bench/peers/results/peers.json (every run) and peers_runs.csv.",
    ]
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="short smoke run (rosette only, coarse scans)")
    ap.add_argument("--only", help="comma-separated families: pendulab,C,numba,mujoco,scipy,diffrax")
    ap.add_argument("--cap", type=float, help="stop refining a scan after a run longer than this [s]")
    ap.add_argument("--docs", type=Path, help="Markdown file to update between the peers markers")
    ap.add_argument(
        "--out", type=Path, help="results JSON (default results/peers.json, quick: peers_quick.json)"
    )
    ap.add_argument(
        "--no-report", action="store_true", help="write the results JSON only (no CSV, plot or docs)"
    )
    ap.add_argument("--ensemble-worker", nargs=5, type=int, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.ensemble_worker:
        print(json.dumps(ensemble_worker(*args.ensemble_worker)))
        return

    t_start = time.perf_counter()
    load_start = os.getloadavg()[0]
    cap = args.cap if args.cap is not None else (0.5 if args.quick else 5.0)
    budget = 0.3 if args.quick else 1.5
    versions = peer_versions()
    if versions["pendulab"] is None:
        raise SystemExit(
            "pendulab does not import: run `make bench-peers` (builds it into bench/peers/.venv)"
        )
    only = set(args.only.split(",")) if args.only else None
    methods, skipped = all_methods(versions, only)
    print("versions:", versions, "\nskipped:", {k: v for k, v in skipped.items() if v}, flush=True)
    cases = load_cases(("rosette",) if args.quick else CASES)
    for c in cases:
        print(f"case {c.name}: exact vs golden {c.exact_vs_golden:.1e}, floor {c.floor:.1e}", flush=True)

    runs: list[hz.Run] = []
    for case in cases:
        runs.append(exact_run(case))
        for m in methods:
            try:
                runs += scan(m, case, args.quick, cap, budget)
            except Exception as exc:  # a peer that cannot even be set up is reported, not fatal
                print(f"  {m.name} {case.name}: set-up failed: {exc}", flush=True)
                runs.append(hz.Run(m.name, case.name, math.nan, "none", math.nan, 0, failed=f"set-up: {exc}"))
    print("step rates", flush=True)
    rates = step_rates(cases, args.quick, skipped)
    print("ensembles", flush=True)
    ens = ensembles(args.quick, skipped.get("C") is None)
    print("rotation-number map", flush=True)
    rmap = rotation_map(args.quick)
    tgt = targets(runs, rates, ens, rmap, cases)
    meta = {
        "date": dt_mod.datetime.now(dt_mod.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "quick": args.quick,
        "cap": cap,
        "versions": versions,
        "skipped": skipped,
        "rustflags": os.environ.get("PEERS_RUSTFLAGS", ""),
        "machine": {
            "cpus": os.cpu_count(),
            "platform": platform.platform(),
            "processor": platform.processor(),
        },
        "load_start": load_start,
        "load_end": os.getloadavg()[0],
        "wall_total": time.perf_counter() - t_start,
    }
    for t in tgt:
        print(f"{t['verdict']:4s}  {t['target']}: {t['value']}  ({t['detail']})")
    RESULTS.mkdir(exist_ok=True)
    out = args.out or RESULTS / ("peers_quick.json" if args.quick else "peers.json")
    payload = {
        "meta": meta,
        "cases": [
            {
                "name": c.name, "x0": c.x0.tolist(), "v0": c.v0.tolist(), "x_ref": c.x_ref.tolist(),
                "v_ref": c.v_ref.tolist(), "exact_vs_golden": c.exact_vs_golden, "floor": c.floor,
            }
            for c in cases
        ],
        "targets": tgt,
        "rates": rates,
        "ensembles": ens,
        "rotation_map": rmap,
        "runs": [r.as_dict() for r in runs],
    }  # fmt: skip
    out.write_text(json.dumps(payload, indent=1, default=str) + "\n")
    if not args.quick and not args.no_report:
        import csv

        with (RESULTS / "peers_runs.csv").open("w", newline="") as fh:
            cols = list(runs[0].as_dict())
            w = csv.DictWriter(fh, fieldnames=cols)
            w.writeheader()
            for r in runs:
                w.writerow({k: (json.dumps(v) if isinstance(v, dict) else v) for k, v in r.as_dict().items()})
        plot(runs, cases, PLOT)
    docs = args.docs or (None if args.quick or args.no_report else DOCS)
    if docs is not None:
        body = markdown(runs, cases, rates, ens, rmap, tgt, meta)
        docs.write_text(hz.replace_between_markers(docs.read_text(), body))
        print(f"wrote {docs}")
    print(f"wrote {out} ({time.perf_counter() - t_start:.0f} s)")


if __name__ == "__main__":
    main()
