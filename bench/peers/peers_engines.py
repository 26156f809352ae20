"""The peers benchmark's simulation frameworks (bench/peers/run.py), each behind a function so that
this module imports with numpy alone:

- MuJoCo: a point mass on a ball joint, RK4 integrator, contacts and constraints disabled, stepped
  in C with ``mj_step(m, d, nstep=n)``; the body carries a tiny isotropic inertia I_c = 1e-6 m l²
  (MuJoCo needs one) and gravity is raised by the factor (1 + I_c/(m l²)) that makes the motion of
  its centre of mass exactly the spherical pendulum's (the spin about the rod stays zero); the state
  maps to (x, v) by x = R (0, 0, −l), v = (R ω_body) × x;
- JAX + Diffrax on CPU, float64: Tsit5 and Dopri8 with a PID controller (pcoeff = icoeff = 0.3) on
  T-2.4 (ẋ = v, v̇ = −g e₃ + λ x, λ = (g z − |v|²)/l²), ``jax.jit``-compiled once per solver
  (compile time excluded).

Units SI (m, kg, s; rates in rad/s).
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from typing import Any

import numpy as np
from peers_cases import MUJOCO_IC, T_END, Case, Method, Runner

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
