"""One chunk of a sweep, and what it computes: the quantities (``QUANTITIES``, SI units), the settings
that are not points (``SweepSpec``), the fingerprint that makes resuming safe, and ``compute_chunk`` —
a pure function of a ``ChunkTask`` that the thread pool and the Dask workers run. The exact
quantities (rotation number T-4.5, z-period) come from the exact solution; the simulated ones from
one ensemble run per chunk (``simulate_ensemble``'s kernel, with the sweep's method, RATTLE or one of
its compositions, and its arithmetic, ``"fused"`` or ``"unfused"``, resolved once, and checked to be of
the version of its bits the sweep records), so every point is computed independently of the chunking,
the backend and the CPU, bit for bit. Each chunk's result carries what it ran (``RAN``, checked by
``sweeps/workers.py`` in the calling process), so that an older worker that ignores a setting is caught.
"""

from __future__ import annotations

import hashlib
import json
import math
import threading
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, fields
from typing import Any

import numpy as np

from .. import validate as limits
from .._core import (
    EnsembleRun,
    EnsembleSpec,
    ExactSolution,
    InvalidInputError,
    ModelSpec,
    RunOptions,
    arithmetic_version,
    rotation_numbers,
    state_from_angles,
)
from ..ensemble.run import SUBSTEPS, max_sway, model_damping
from ..integrators import check_arithmetic, method_names, unknown_method
from ..model import FloatArray, Pendulum
from .design import AXES, AXIS_LIMITS, INITIAL_AXES, Design, check_axis_name

QUANTITIES: dict[str, dict[str, str]] = {
    "final_state": {"x": "m", "y": "m", "z": "m", "vx": "m/s", "vy": "m/s", "vz": "m/s"},
    "rotation_number": {"rotation_number": "1"},
    "period": {"period": "s"},
    "max_sway": {"max_sway": "rad"},
    "energy_drift": {"energy_drift": "1"},
    "settle_time": {"settle_time": "s"},
}
"""Quantity name → the result columns it makes, with their units."""

SIMULATED = ("final_state", "max_sway", "energy_drift", "settle_time")
"""The quantities that integrate (RATTLE or a composition of it to t_end); the others come from the exact
solution."""

METHODS = tuple(SUBSTEPS)
"""The sweep's integrators (``method``): ``simulate_ensemble``'s vectorised ones, RATTLE and its
compositions of order 4, 6 and 8."""


RAN = "_pendulab_ran"
"""The key of a chunk's result under which its worker echoes what it ran (:func:`ran`): not a column;
the calling process checks and removes it (``sweeps/workers.py``)."""


class _Cancelled(Exception):
    """A chunk stopped because the sweep was interrupted (never written)."""


def _bad(message: str) -> InvalidInputError:
    return InvalidInputError(message)


# --- what to compute -----------------------------------------------------------------------------


@dataclass(frozen=True)
class SweepSpec:
    """Everything but the points: the quantities, the pendulum (l [m], g [m/s²], m [kg]) used where
        the design does not vary length or g, the fixed initial conditions (``fixed``: axis → value; 0
        for those not given), for simulated quantities ``t_end`` [s] and ``dt`` [s], the linear damping
        c [1/s] where the design does not vary it, for ``settle_time`` the ``settle_angle`` [rad], and for
        simulated quantities the RATTLE ``arithmetic`` (``"fused"`` or ``"unfused"``, resolved once when
        the sweep is set up, so that every chunk, on any worker, uses the same; None for exact ones) and
        ``arithmetic_version``, the version of that arithmetic's bits (``_core.arithmetic_version``; None
        in the record of a sweep written before versions were recorded, ``sweeps/resume.py``), and
    ``method``, the integrator of simulated quantities (one of :data:`METHODS`; None for exact ones, and
    in the record of a sweep written before methods were recorded, which ran RATTLE)."""

    quantities: tuple[str, ...]
    length: float
    g: float
    mass: float
    fixed: dict[str, float]
    t_end: float | None = None
    dt: float | None = None
    damping: float = 0.0
    settle_angle: float | None = None
    arithmetic: str | None = None
    arithmetic_version: int | None = None
    method: str | None = None

    @property
    def simulated(self) -> bool:
        return any(q in SIMULATED for q in self.quantities)

    @property
    def substeps(self) -> int:
        """RATTLE sub-steps per step of the method (1 for RATTLE; ``SUBSTEPS`` of ``ensemble/run.py``)."""
        return SUBSTEPS[self.method or "rattle"]

    @property
    def steps(self) -> int:
        return 0 if not self.simulated else round(float(self.t_end or 0.0) / float(self.dt or 1.0))

    def output_units(self) -> dict[str, str]:
        """The quantity columns with their units, in order."""
        return {c: u for q in self.quantities for c, u in QUANTITIES[q].items()}

    def describe(self) -> dict[str, Any]:
        d = asdict(self) | {"quantities": list(self.quantities)}
        # settings at their defaults are left out, so that sweeps written before they existed resume
        for key, default in (
            ("damping", 0.0),
            ("settle_angle", None),
            ("arithmetic", None),
            ("arithmetic_version", None),
            ("method", None),
        ):
            if d[key] == default:
                del d[key]
        return d


def _quantities(quantity: str | Sequence[str]) -> tuple[str, ...]:
    names = [quantity] if isinstance(quantity, str) else list(quantity)
    if not names:
        raise _bad(f"give at least one quantity: {', '.join(QUANTITIES)}")
    for q in names:
        if not isinstance(q, str) or q not in QUANTITIES:
            did = limits.did_you_mean(q, QUANTITIES)
            raise _bad(f"unknown quantity {limits.show(q)}{did}; the quantities are {', '.join(QUANTITIES)}")
    return tuple(q for q in QUANTITIES if q in names)  # canonical order, no duplicates


def make_spec(
    design: Design,
    quantity: str | Sequence[str],
    pendulum: Pendulum | None = None,
    fixed: Mapping[str, float] | None = None,
    t_end: float | None = None,
    dt: float | None = None,
    settle_angle: float | None = None,
    arithmetic: Any = "auto",
    method: Any = "rattle",
) -> SweepSpec:
    """Checks and collects the settings of a sweep over ``design`` (see :func:`sweep`); ``arithmetic``
    (``"auto"``, ``"unfused"``, ``"fused"``) is resolved here, as ``simulate_ensemble`` resolves it;
    ``method`` is one of :data:`METHODS`."""
    quantities = _quantities(quantity)
    method = check_method(method)  # both checked even where nothing integrates
    resolved = check_arithmetic(arithmetic, method)
    p = Pendulum() if pendulum is None else pendulum
    if not isinstance(p, Pendulum):
        raise _bad(f"pendulum must be a pendulab.Pendulum, got {type(p).__name__}")
    try:
        damping = model_damping(p)
    except InvalidInputError:
        raise _bad(
            f"sweeps run the ideal pendulum, optionally with linear damping (exact solution, ensemble "
            f"kernel), not {p!r}"
        ) from None
    exact = [q for q in quantities if q not in SIMULATED]
    if exact and (damping != 0.0 or "damping" in design.names):
        raise _bad(
            f"{', '.join(exact)} come from the exact solution of the undamped pendulum: "
            "remove the damping or compute simulated quantities only"
        )
    if "settle_time" in quantities:
        if settle_angle is None:
            raise _bad("settle_time needs settle_angle [rad]: the sway angle that counts as settled")
        if not (
            isinstance(settle_angle, int | float)
            and not isinstance(settle_angle, bool)
            and 0 < settle_angle < math.pi
        ):
            raise _bad(f"settle_angle = {limits.show(settle_angle)} must be a sway angle in (0, π) rad")
        settle_angle = float(settle_angle)
    else:
        settle_angle = None
    fixed_values: dict[str, float] = {}
    for name, value in (fixed or {}).items():
        check_axis_name(name, "fixed value")
        if name not in INITIAL_AXES:
            raise _bad(
                f"fixed {limits.show(name)}: set length and g on the pendulum; "
                f"fixed takes {', '.join(INITIAL_AXES)}"
            )
        if name in design.names:
            raise _bad(f"{limits.show(name)} is both an axis of the design and a fixed value")
        fixed_values[name] = limits.number(f"fixed {name}", value, AXIS_LIMITS[name])
    for name in INITIAL_AXES:
        if name not in design.names:
            fixed_values.setdefault(name, 0.0)
    if any(q in SIMULATED for q in quantities):
        dt = 1e-3 if dt is None else dt
        sim = [q for q in quantities if q in SIMULATED]
        if t_end is None:
            verb = "integrates" if len(sim) == 1 else "integrate"
            raise _bad(f"{', '.join(sim)} {verb}: give t_end [s] (and dt [s])")
        dt = limits.number("dt", dt, "dt")
        t_end = limits.number("t_end", t_end, "time", positive=True)
        limits.planned_work(t_end, dt, 1, "point", method, SUBSTEPS[method])  # one point's RATTLE steps
        steps = round(t_end / dt)
        if not (math.isfinite(t_end) and t_end > 0 and abs(steps * dt - t_end) <= 1e-9 * t_end):
            raise _bad(
                f"t_end = {limits.show(t_end)} s must be > 0 and a multiple of dt = {limits.show(dt)} s"
            )
        t_end, dt = float(t_end), float(dt)
        arith: str | None = resolved
        used: str | None = method
    else:
        t_end = dt = arith = used = None  # not used: not part of what the results depend on
    version = None if arith is None else arithmetic_version(arith)
    settings = (dict(sorted(fixed_values.items())), t_end, dt, damping, settle_angle, arith, version, used)
    return SweepSpec(quantities, p.length, p.g, p.mass, *settings)


def check_method(method: Any) -> str:
    """``method`` if it is one of :data:`METHODS`, else an ``InvalidInputError`` naming it and them; a
    name no integrator has gets the message of every entry point (the nearest name, the same but for
    case first, and the registered ones: :func:`~pendulab.integrators.unknown_method`)."""
    if isinstance(method, str) and method not in method_names():
        raise _bad(unknown_method(method))
    if not isinstance(method, str) or method not in SUBSTEPS:
        raise _bad(
            f"method = {limits.show(method)}: sweeps integrate with {', '.join(map(repr, METHODS))} "
            "(RATTLE or its symmetric compositions of order 4, 6, 8, as pl.simulate_ensemble)"
        )
    return method


def fingerprint(design: Design, spec: SweepSpec) -> str:
    """SHA-256 of the points and the settings: equal prints, equal results (the key of resuming)."""
    text = json.dumps({"design": design.fingerprint(), "spec": spec.describe()}, sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()


# --- one chunk -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class ChunkTask:
    """Chunk ``index``: points ``start`` … ``stop − 1`` with their design values ``inputs``."""

    index: int
    start: int
    stop: int
    inputs: dict[str, FloatArray]
    spec: SweepSpec


def _full(task: ChunkTask) -> dict[str, FloatArray]:
    m, s = task.stop - task.start, task.spec
    base = {"length": s.length, "g": s.g, "damping": s.damping, **s.fixed}
    return {k: np.asarray(task.inputs[k]) if k in task.inputs else np.full(m, float(base[k])) for k in AXES}


def _states(c: dict[str, FloatArray], mass: float) -> tuple[FloatArray, FloatArray]:
    """(x, v) of every point, by the same core call as ``Pendulum.state_from_angles``."""
    m = len(c["theta0"])
    x, v = np.empty((m, 3)), np.empty((m, 3))
    for i in range(m):
        angles = [float(c[k][i]) for k in ("theta0", "phi0", "theta_dot0", "phi_dot0")]
        x[i], v[i] = state_from_angles(_point(c, int(i), mass), angles)
    return x, v


def _point(c: dict[str, FloatArray], i: int, mass: float) -> ModelSpec:
    """The ideal pendulum of point ``i`` (its l [m] and g [m/s²], the sweep's m [kg])."""
    return ModelSpec(float(c["length"][i]), mass, float(c["g"][i]))


def _rotation_numbers(c: dict[str, FloatArray], mass: float) -> FloatArray:
    """W from ε = E/(m|g|l) and j = J₃/(m l² ω₀), computed from the angles; the few points the
    vectorised map leaves NaN with J₃ ≠ 0 (on the conical boundary, to rounding) go through the exact
    solution itself, as ``pl.exact(p, s).rotation_number`` does."""
    th, thd, phd, length, g = c["theta0"], c["theta_dot0"], c["phi_dot0"], c["length"], c["g"]
    s2 = np.sin(th) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        omega0 = np.sqrt(np.abs(g) / length)
        eps = (0.5 * length * (thd**2 + s2 * phd**2) - g * np.cos(th)) / np.abs(g)
        j = s2 * phd / omega0
    ok = (g != 0.0) & np.isfinite(eps) & np.isfinite(j)
    w = np.full(len(th), np.nan)
    w[ok] = rotation_numbers(np.ascontiguousarray(eps[ok]), np.ascontiguousarray(j[ok]))
    for i in np.flatnonzero(ok & np.isnan(w) & (j != 0.0)):
        one = {k: a[i : i + 1] for k, a in c.items()}
        x, v = _states(one, mass)
        adv = ExactSolution(_point(c, int(i), mass), (x[0], v[0])).azimuth_advance
        w[i] = np.nan if adv is None else adv / (2.0 * math.pi)
    return w


def _periods(c: dict[str, FloatArray], mass: float) -> FloatArray:
    x, v = _states(c, mass)
    out = np.empty(len(x))
    for i in range(len(x)):
        tz = ExactSolution(_point(c, int(i), mass), (x[i], v[i])).period_z
        out[i] = np.nan if tz is None else tz
    return out


def _integration(spec: SweepSpec) -> tuple[str, str, int]:
    """The method (RATTLE for a SweepSpec made without one), the arithmetic (the sweep's, resolved
    once by make_spec, so that every point is simulate_ensemble's trajectory with it bit for bit on any
    CPU; "auto" here only for a SweepSpec made without one) and its version that a chunk runs."""
    arithmetic = spec.arithmetic or check_arithmetic("auto", "rattle")
    return spec.method or "rattle", arithmetic, arithmetic_version(arithmetic)


def ran(spec: SweepSpec) -> dict[str, Any]:
    """What a chunk of ``spec`` runs here, as its result echoes it (:data:`RAN`): the settings this
    pendulab honours (``honours``, the fields of its SweepSpec), and for simulated quantities the
    method, arithmetic and arithmetic version it integrates with (None for exact ones)."""
    method, arithmetic, version = _integration(spec) if spec.simulated else (None, None, None)
    honours = [f.name for f in fields(SweepSpec)]
    return {"honours": honours, "method": method, "arithmetic": arithmetic, "arithmetic_version": version}


def _simulate(
    c: dict[str, FloatArray], spec: SweepSpec, cancel: threading.Event | None
) -> dict[str, FloatArray]:
    x, v = _states(c, spec.mass)
    length, g = np.ascontiguousarray(c["length"]), np.ascontiguousarray(c["g"])
    need_summary = "max_sway" in spec.quantities or "energy_drift" in spec.quantities
    damping = np.ascontiguousarray(c["damping"])
    dt, settle = float(spec.dt or 0.0), spec.settle_angle
    models = EnsembleSpec(length, g, damping)
    method, arithmetic, here = _integration(spec)
    if spec.arithmetic_version is not None and spec.arithmetic_version != here:
        raise _bad(  # a Dask worker with another pendulab build would compute other bits
            f"this pendulab's {arithmetic} arithmetic is of version {here}, the sweep's of version "
            f"{spec.arithmetic_version}: run every worker with the pendulab that set the sweep up"
        )
    options = RunOptions(method=method, dt=dt, arithmetic=arithmetic)
    run = EnsembleRun(models, x, v, options, spec.steps, need_summary, settle)
    # wait returns the moment the chunk is done; a cancel is seen within 20 ms
    while not run.wait(0.02):
        if cancel is not None and cancel.is_set():
            run.cancel()
            run.result()
            raise _Cancelled
    res = run.result()
    if res["cancelled"]:  # pragma: no cover - only a cancel above stops it
        raise _Cancelled
    out: dict[str, FloatArray] = {}
    if "final_state" in spec.quantities:
        xf, vf = res["x"][:, -1, :], res["v"][:, -1, :]
        for k, name in enumerate(("x", "y", "z")):
            out[name] = np.ascontiguousarray(xf[:, k])
            out["v" + name] = np.ascontiguousarray(vf[:, k])
    if "max_sway" in spec.quantities:
        out["max_sway"] = max_sway(res["z_min"], res["z_max"], g, length)
    if "settle_time" in spec.quantities:
        out["settle_time"] = res["settle_time"]
    if "energy_drift" in spec.quantities:
        scale = np.abs(g) * length
        scale = np.where(g != 0.0, scale, 0.5 * np.einsum("ij,ij->i", v, v))
        with np.errstate(divide="ignore", invalid="ignore"):
            out["energy_drift"] = np.where(scale > 0, (res["e_max"] - res["e_min"]) / scale, np.nan)
    return out


def compute_chunk(task: ChunkTask, cancel: threading.Event | None = None) -> dict[str, Any]:
    """The result columns of one chunk: ``point`` (int64), the design's axes, then the quantity columns
    (float64), one row per point, and under :data:`RAN` what it ran (:func:`ran`; not a column). Pure:
    the same task gives the same numbers anywhere (it is what the thread pool and the Dask workers
    run). ``cancel`` stops a simulation within ~1024 steps."""
    spec = task.spec
    c = _full(task)
    out: dict[str, Any] = {"point": np.arange(task.start, task.stop, dtype=np.int64)}
    out.update({k: np.asarray(v, dtype=np.float64) for k, v in task.inputs.items()})
    sim = _simulate(c, spec, cancel) if spec.simulated else {}
    for q in spec.quantities:
        if q == "rotation_number":
            out[q] = _rotation_numbers(c, spec.mass)
        elif q == "period":
            out[q] = _periods(c, spec.mass)
        else:
            out.update({k: sim[k] for k in QUANTITIES[q]})
    out[RAN] = ran(spec)
    return out
