"""The methods the peers benchmark scans (bench/peers/run.py): every Pendulab method through
``pl.simulate`` (DOP853 also with ``conserve``), and the light peers, each behind a function so that
this module imports with numpy alone:

- SciPy ``solve_ivp`` RK45 and DOP853 on the Cartesian ODE T-2.4 (ẋ = v, v̇ = −g e₃ + λ x,
  λ = (g z − |v|²)/l²), not the angle ODE, which is singular at the poles;
- numba: a fixed-step RK4 loop on T-2.4 (``@njit``, compile time excluded);
- C: rk4.c, a plain RK4 loop and a hand-vectorised ensemble (SoA blocks of 64, ``omp simd``, OpenMP
  over 1 or 2 threads), built with ``gcc -O3 -march=native -fopenmp``, called once per run via ctypes.

Every ``Runner`` returns the state (x [m], v [m/s]) at t = 100 s and the number of steps taken.
"""

from __future__ import annotations

import ctypes
import subprocess
from collections.abc import Callable
from typing import Any

import numpy as np
from peers_cases import BUILD, HERE, T_END, Case, Method, Runner

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
