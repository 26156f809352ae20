"""Building a validated scenario's pendulum (or swinging spring) and start, and the core's checks.

Each function takes sections of a :class:`pendulab.scenario.schema.ScenarioSpec` that pydantic has
already validated and does what needs the core: :func:`build_pendulum` builds the rod models'
:class:`Pendulum` (length [m], mass [kg], g [m/s²], the model's own parameters in SI units, the
sampled pivot's times [s] and positions [m], which must span the run [t0, t_end] [s]);
:func:`start_state` turns ``[initial]`` into a state on TS² (x [m], v [m/s]; a string may start
slack inside the sphere); :func:`check_run_settings` lets the core check ``[simulation]`` up
front (method, step [s], tolerances, memory of the saved samples, save times) without stepping;
:func:`build_spring` does all of this for the swinging spring (rest length [m], stiffness [N/m]),
which leaves the sphere. Every problem raises :class:`ScenarioError` naming ``source``.
"""

from __future__ import annotations

import math
import re

import numpy as np

from .._core import InvalidInputError, RunOptions, Solver, spring_simulate
from ..model import Pendulum, State, _frozen
from ..variants.spring import SwingingSpring
from .errors import ScenarioError
from .schema import InitialSection, ScenarioSpec, SimulationSection, _degree_keys, _own_params, _show

SPRING_ORDERS = {"rattle": 2, "rattle4": 4}
"""Methods a ``model = "spring"`` scenario may name: the unconstrained Störmer–Verlet and triple jump."""


def build_pendulum(spec: ScenarioSpec, source: str) -> Pendulum:
    """The pendulum of ``[pendulum]`` (every model but the spring), its samples checked against the run."""
    p, sim = spec.pendulum, spec.simulation
    try:
        # **p.extras() holds only the model's own float parameters by name (never model/force/pivot_samples)
        pendulum = Pendulum(
            length=p.length,
            g=p.g,
            mass=p.mass,
            model=p.model,
            pivot_samples=p.pivot_samples(),
            **p.extras(),  # type: ignore[arg-type]
        )
    except InvalidInputError as e:
        given = "".join(
            f" (given as {deg} = {p.params[deg]!r} degrees)"
            for deg, rad in _degree_keys(p.model).items()
            if deg in p.params and rad in str(e)
        )
        raise ScenarioError(source, f"[pendulum] {e}{given}") from None
    if (samples := pendulum.pivot_samples) is not None:
        first, last = float(samples[0][0]), float(samples[0][-1])
        if not (first <= sim.t0 and sim.t_end <= last):
            raise ScenarioError(
                source,
                f"[simulation] the run [t0, t_end] = [{sim.t0!r}, {sim.t_end!r}] s leaves the pivot "
                f"samples' span [{first!r}, {last!r}] s (pendulum.pivot_times)",
            )
    return pendulum


def start_state(pendulum: Pendulum, ini: InitialSection, source: str) -> State:
    """The start of ``[initial]`` for ``pendulum``: on TS², or strictly inside the sphere for a string."""
    if pendulum.model == "string" and ini.cartesian and not ini.project:
        # a string may start slack: strictly inside the sphere, x and v as given (the core checks
        # them when the run starts; on the sphere the TS² rules below apply)
        x, v = np.asarray(ini.x, dtype=np.float64), np.asarray(ini.v, dtype=np.float64)
        if np.linalg.norm(x) < pendulum.length * (1.0 - 1e-9):
            return State(_frozen(x), _frozen(v))
    try:
        if not ini.cartesian:
            return pendulum.state_from_angles(*ini.angles())
        if ini.project:
            return pendulum.state(ini.x, ini.v, project=True)
        return pendulum.state(ini.x, ini.v)
    except InvalidInputError as e:
        if not ini.cartesian or ini.project or "not on TS²" not in str(e):
            raise ScenarioError(source, f"[initial] {e}") from None
        x, v = np.asarray(ini.x), np.asarray(ini.v)
        m = re.search(r": (.*?); pass project=True", str(e))
        why = f" ({m.group(1)})" if m else ""
        raise ScenarioError(
            source,
            f"[initial] the start x = {_show(ini.x)}, v = {_show(ini.v)} is not on TS² "
            "(|x| = l, x·v = 0): "
            f"|x| - l = {np.linalg.norm(x) - pendulum.length:.6g} m, x·v = {float(x @ v):.6g} m²/s{why}; "
            "set project = true in [initial] to move it onto TS²",
        ) from None


def check_run_settings(pendulum: Pendulum, state: State, sim: SimulationSection, source: str) -> None:
    """The core's checks of ``[simulation]`` for ``pendulum`` starting at ``state``, without stepping."""
    if pendulum.model == "string":  # hybrid (string_pendulum.py): its own, fewer settings
        from ..variants.string_pendulum import check_string_settings

        try:
            check_string_settings(sim.method)
        except InvalidInputError as e:
            raise ScenarioError(source, f"[simulation] {e}") from None
        return
    try:  # the core's own up-front checks (memory of the saved samples, save times), no stepping
        rtol, atol = sim.resolved_tolerances()
        run = RunOptions(
            t0=sim.t0,
            t_end=sim.t_end,
            method=sim.method,
            dt=sim.resolved_dt(),
            rtol=rtol,
            atol=atol,
            project=True,
            save_every=sim.save_every,
            save_times=None if sim.save_at is None else np.asarray(sim.save_at, dtype=np.float64),
        )
        Solver(pendulum.spec, state.pair, run)
    except InvalidInputError as e:
        raise ScenarioError(source, f"[simulation] {e}") from None


def build_spring(spec: ScenarioSpec, source: str) -> tuple[SwingingSpring, State]:
    """The swinging spring (T-7.4): ``length`` is the rest length l₀ [m], ``stiffness`` k [N/m]; an
    angle start lies on the sphere of the equilibrium length l = l₀ + m |g|/k, a Cartesian start is
    taken as given (x [m], v [m/s] anywhere). Methods: rattle → Störmer–Verlet (order 2), rattle4
    → its triple jump (order 4); save_every only. Validated by the core."""
    p, sim, ini = spec.pendulum, spec.simulation, spec.initial
    k = float(p.extras().get("stiffness", _own_params("spring")["stiffness"]["default"]))
    spring = SwingingSpring(k / p.mass, p.length, p.g, p.mass)
    if sim.method not in SPRING_ORDERS:
        raise ScenarioError(
            source,
            f"[simulation] method {sim.method!r} cannot integrate the 'spring' model (it leaves the "
            "sphere): use 'rattle' (Störmer–Verlet, order 2) or 'rattle4' (its triple jump, order 4)",
        )
    if sim.save_at is not None:
        raise ScenarioError(source, "[simulation] save_at is not available for the 'spring' model")
    if ini.project:
        raise ScenarioError(
            source, "[initial] project applies to pendulums on the sphere, not to the 'spring' model"
        )
    if ini.cartesian:
        state = State(np.asarray(ini.x, dtype=np.float64), np.asarray(ini.v, dtype=np.float64))
    else:
        ell = spring.equilibrium_length
        if not (math.isfinite(ell) and ell > 0):
            raise ScenarioError(
                source,
                "[initial] an angle start needs an equilibrium length l = l0 + m |g|/k > 0, "
                f"got {ell!r} m; give a Cartesian start x, v instead",
            )
        state = Pendulum(length=ell, g=p.g, mass=p.mass).state_from_angles(*ini.angles())
    try:  # the core's checks of parameters, start and step, without stepping
        spring_simulate(
            spring.spec, state.pair, RunOptions(dt=sim.resolved_dt(), save_every=int(sim.save_every or 1)), 0
        )
    except InvalidInputError as e:
        raise ScenarioError(source, f"[pendulum] {e}") from None
    return spring, state
