"""Sweep files: a small TOML format for ``pendulab sweep`` (described in ``docs/sweeps.md``).

::

    title = "Rotation number over the start's polar angle and azimuthal rate"
    quantity = "rotation_number"           # or a list: ["max_sway", "energy_drift"]

    [pendulum]                             # the ideal pendulum (defaults: 1 m, 9.81 m/s^2, 1 kg)
    length = 1.0                           # m
    g = 9.81                               # m/s^2
    damping = 0.0                          # 1/s, linear damping (simulated quantities only)

    [grid]                                 # full factorial; or [random] (n, seed, method, ranges)
    theta0 = { start = 0.1, stop = 3.0, num = 100 }    # rad: 100 values, ends included
    phi_dot0 = [-2.0, -1.0, 1.0, 2.0]                  # rad/s: explicit values

    [fixed]                                # initial conditions that are not axes (default 0)
    theta_dot0 = 0.0                       # rad/s

    [simulation]                           # needed by final_state, max_sway, energy_drift, settle_time
    t_end = 20.0                           # s
    dt = 1e-3                              # s
    settle_angle = 0.01                    # rad, needed by settle_time
    arithmetic = "auto"                    # RATTLE's multiply-adds: "auto", "unfused" or "fused"
    method = "rattle"                      # or "rattle4", "rattle6", "rattle8" (order 4, 6, 8)

    [run]                                  # optional; the command line overrides these
    chunk_size = 2000
    backend = "threads"                    # or "dask"
    workers = 2
    scheduler = "tcp://10.0.0.5:8786"      # a Dask scheduler (implies backend = "dask")

Everything is checked when the file is loaded; a problem raises :class:`SweepFileError` naming the
file, the key, the bad value and what is allowed.
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator
from pydantic_core import ErrorDetails

from .._core import InvalidInputError
from ..model import Pendulum
from ..scenario import ScenarioError
from ..scenario.errors import merge_typos
from ..scenario.schema import (
    _show,  # a value as it looks in TOML, as scenario errors show it
    printable,
)
from ..validate import MAX_SAMPLES, did_you_mean, parse_toml, read_file_capped
from . import design as sweep_design
from .compute import QUANTITIES, make_spec
from .design import Design
from .run import check_work

MAX_AXIS_VALUES = 10_000_000


class SweepFileError(ScenarioError):
    """A sweep file cannot be used: ``source`` the file, ``problems`` one message per problem (each
    naming the key, the bad value and what is allowed), ``line`` for TOML syntax errors."""


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=False)


class PendulumTable(_Strict):
    length: float = Field(1.0, gt=0, allow_inf_nan=False, description="rod length in m, > 0")
    g: float = Field(9.81, allow_inf_nan=False, description="gravity in m/s^2, any finite value")
    mass: float = Field(1.0, gt=0, allow_inf_nan=False, description="bob mass in kg, > 0")
    damping: float = Field(0.0, ge=0, allow_inf_nan=False, description="linear damping in 1/s, >= 0")


class RandomTable(_Strict):
    n: int = Field(ge=1, le=MAX_SAMPLES, description="number of points, >= 1")  # as pl.sweep takes
    seed: int = Field(0, ge=0, description="seed of NumPy's default_rng, >= 0")
    method: Literal["uniform", "lhs"] = Field("uniform", description='"uniform" or "lhs"')
    ranges: dict[str, tuple[float, float]] = Field(description="axis = [lo, hi] in the axis's unit")


class SimulationTable(_Strict):
    t_end: float = Field(gt=0, allow_inf_nan=False, description="end time in s, > 0, a multiple of dt")
    dt: float = Field(1e-3, gt=0, allow_inf_nan=False, description="RATTLE step in s, > 0")
    settle_angle: float | None = Field(
        None, gt=0, lt=3.141592653589793, allow_inf_nan=False, description="sway angle in rad, in (0, pi)"
    )
    # any value here: make_spec checks it (check_arithmetic, as pl.sweep does) and names what is allowed
    arithmetic: Any = Field("auto", description='RATTLE multiply-adds: "auto", "unfused" or "fused"')
    # likewise: make_spec checks it (check_method) and names what is allowed
    method: Any = Field("rattle", description='"rattle" or its compositions "rattle4", "rattle6", "rattle8"')


class RunTable(_Strict):
    chunk_size: int | None = Field(None, ge=1, description="points per chunk, >= 1")
    backend: Literal["threads", "dask"] | None = Field(None, description='"threads" or "dask"')
    workers: int | None = Field(None, ge=1, le=1024, description="threads or LocalCluster workers")
    scheduler: str | None = Field(None, description="a Dask scheduler address, tcp://HOST:8786")


class SweepSpecFile(_Strict):
    title: str = ""
    quantity: str | list[str] = Field(description=f"one of {', '.join(QUANTITIES)}, or a list of them")
    pendulum: PendulumTable = Field(default_factory=PendulumTable)
    grid: dict[str, Any] | None = None
    random: RandomTable | None = None
    fixed: dict[str, float] = Field(default_factory=dict)
    simulation: SimulationTable | None = None
    run: RunTable = Field(default_factory=RunTable)

    @field_validator("title")
    @classmethod
    def _printable(cls, value: str) -> str:
        return printable(value, "title", one_line=True)  # printed by `pendulab sweep`

    @model_validator(mode="after")
    def _one_design(self) -> SweepSpecFile:
        if (self.grid is None) == (self.random is None):
            raise ValueError("give exactly one of the tables [grid] and [random]")
        return self


@dataclass(frozen=True)
class SweepFile:
    """A validated sweep file: ``design``, ``quantities``, ``pendulum``, ``fixed``, the simulation's
    ``t_end`` and ``dt`` [s] (None for exact quantities), its ``arithmetic`` (default "auto") and
    ``method`` (default "rattle"), the ``[run]`` settings and the ``title``."""

    spec: SweepSpecFile
    design: Design
    pendulum: Pendulum
    source: str

    @property
    def title(self) -> str:
        return self.spec.title

    def sweep_kwargs(
        self,
        *,
        workers: int | None = None,
        scheduler: str | None = None,
        backend: str | None = None,
        chunk_size: int | None = None,
        arithmetic: str | None = None,
        method: str | None = None,
    ) -> dict[str, Any]:
        """The keywords of :func:`pendulab.sweep` this file sets (not out, resume, progress), with the
        ``[run]`` settings and ``[simulation] arithmetic`` and ``method`` overridden where given
        (``pendulab sweep``'s options; ``arithmetic`` and ``method`` are checked by
        :func:`pendulab.sweep`): a scheduler implies the dask
        backend and replaces the file's workers; workers given alone replace its scheduler."""
        kwargs = self._file_kwargs()
        for key, value in (
            ("arithmetic", arithmetic),
            ("method", method),
            ("workers", workers),
            ("scheduler", scheduler),
            ("backend", backend),
            ("chunk_size", chunk_size),
        ):
            if value is not None:
                kwargs[key] = value
        if scheduler is not None and backend is None:
            kwargs["backend"] = "dask"
        if workers is not None and scheduler is None:
            kwargs["scheduler"] = None
        if kwargs["scheduler"] is not None:
            kwargs["workers"] = None
        return kwargs

    def _file_kwargs(self) -> dict[str, Any]:
        sim, run = self.spec.simulation, self.spec.run
        return {
            "quantity": self.spec.quantity,
            "pendulum": self.pendulum,
            "fixed": self.spec.fixed,
            "t_end": None if sim is None else sim.t_end,
            "dt": None if sim is None else sim.dt,
            "settle_angle": None if sim is None else sim.settle_angle,
            "arithmetic": "auto" if sim is None else sim.arithmetic,
            "method": "rattle" if sim is None else sim.method,
            "chunk_size": run.chunk_size,
            "backend": run.backend,
            "workers": run.workers,
            "scheduler": run.scheduler,
        }


def _key(loc: tuple[int | str, ...]) -> str:
    out = ""
    for part in loc:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


EMPTY_SWEEP_FILE = (
    'nothing in it (an empty file, or only comments): a sweep file has quantity = "..." and one of the '
    "tables [grid] and [random] (docs/sweeps.md)"
)
"""The problem of a sweep file without a key: what such a file holds, not each missing key."""


def _names_at(table: tuple[int | str, ...]) -> list[str]:
    """The keys the table at ``table`` takes (the top level for ``()``)."""
    model: Any = SweepSpecFile
    for part in table:
        model = getattr(model, "model_fields", {}).get(part)
        model = getattr(model, "annotation", None)
    return list(getattr(model, "model_fields", {}))


def _problems(errors: list[ErrorDetails]) -> list[str]:
    """One line per problem, unknown keys first; a typo of a required key is one problem, as in a
    scenario file (``unknown key quantitty (did you mean 'quantity'? so the required quantity is
    missing)``, :func:`~pendulab.scenario.errors.merge_typos`)."""
    return merge_typos(
        errors, problem=_problem, keys_of=_names_at, missing_name=lambda err: _key(tuple(err["loc"]))
    )


def _problem(err: ErrorDetails) -> str:
    loc = tuple(err["loc"])
    key, kind, value = _key(loc), err["type"], err.get("input")
    if kind == "missing":
        return f"{key} is missing"
    if kind == "extra_forbidden":
        names = _names_at(loc[:-1])
        did = did_you_mean(str(loc[-1]), names)
        where = f"[{_key(loc[:-1])}]" if len(loc) > 1 else "the top level"
        return f"unknown key {key}{did}; allowed keys in {where}: {', '.join(names)}"
    msg = str(err.get("ctx", {}).get("error", err["msg"])) if kind == "value_error" else err["msg"]
    msg = msg.replace("Input should be", "must be").replace("Value error, ", "")
    return f"{key} = {_show(value)}: {msg}" if key else msg


def _axis_values(name: str, spec: Any) -> np.ndarray:
    """A [grid] entry: a list of numbers, or {start, stop, num} (num values, both ends included)."""
    if isinstance(spec, dict):
        extra = set(spec) - {"start", "stop", "num"}
        if extra or not {"start", "stop", "num"} <= set(spec):
            raise InvalidInputError(
                f"[grid] {name} = {_show(spec)}: a table needs exactly start, stop (axis unit), num"
            )
        start, stop, num = spec["start"], spec["stop"], spec["num"]
        if isinstance(num, bool) or not isinstance(num, int) or not 1 <= num <= MAX_AXIS_VALUES:
            raise InvalidInputError(
                f"[grid] {name}.num = {num!r}: must be an integer from 1 to {MAX_AXIS_VALUES}"
            )
        if not all(isinstance(v, int | float) and not isinstance(v, bool) for v in (start, stop)):
            raise InvalidInputError(f"[grid] {name}: start and stop must be numbers, got {_show(spec)}")
        return np.linspace(float(start), float(stop), num)
    if isinstance(spec, list):
        if not all(isinstance(v, int | float) and not isinstance(v, bool) for v in spec):
            raise InvalidInputError(f"[grid] {name} = {_show(spec)}: the values must be numbers")
        return np.asarray(spec, dtype=np.float64)
    raise InvalidInputError(
        f"[grid] {name} = {_show(spec)}: give a list of values or {{start, stop, num}} "
        "(a single fixed value goes in [fixed])"
    )


def sweep_file_from_dict(data: dict[str, Any], source: str = "<dict>") -> SweepFile:
    """A sweep file from its parsed TOML (nested dicts); :class:`SweepFileError` if it is not valid."""
    if not data:
        raise SweepFileError(source, EMPTY_SWEEP_FILE)
    try:
        spec = SweepSpecFile.model_validate(data)
    except ValidationError as e:
        raise SweepFileError(source, _problems(e.errors())) from None
    try:
        if spec.grid is not None:
            design = sweep_design.grid({k: _axis_values(k, v) for k, v in spec.grid.items()})
        else:
            assert spec.random is not None
            r = spec.random
            design = sweep_design.random(r.n, r.ranges, r.seed, r.method)
    except InvalidInputError as e:
        section = "[grid]" if spec.grid is not None else "[random]"
        text = str(e)
        raise SweepFileError(source, text if text.startswith(section) else f"{section} {text}") from None
    p = spec.pendulum
    try:
        extra = {"damping": p.damping} if p.damping != 0.0 else {}
        # **extra holds only the model's own float parameters by name (never model/force/pivot_samples)
        pendulum = Pendulum(length=p.length, g=p.g, mass=p.mass, **extra)  # type: ignore[arg-type]
    except InvalidInputError as e:
        raise SweepFileError(source, f"[pendulum] {e}") from None
    sim = spec.simulation
    try:
        sweep_spec = make_spec(
            design,
            spec.quantity,
            pendulum,
            spec.fixed,
            None if sim is None else sim.t_end,
            None if sim is None else sim.dt,
            None if sim is None else sim.settle_angle,
            "auto" if sim is None else sim.arithmetic,
            "rattle" if sim is None else sim.method,
        )
    except InvalidInputError as e:
        text = str(e).replace("give t_end [s] (and dt [s])", "add [simulation] t_end (in s) and dt (in s)")
        if text.startswith(("t_end", "dt", "invalid arithmetic", "method", "one point would take")):
            text = f"[simulation] {text}"
        raise SweepFileError(source, text) from None
    points = "[grid]" if spec.grid is not None else "[random] n"
    try:
        check_work(design, sweep_spec)  # the whole sweep's work, as pl.sweep checks it
    except InvalidInputError as e:
        text = str(e).replace("use fewer points", f"use fewer points ({points})")
        raise SweepFileError(source, text.replace("design = ", f"{points}: ", 1)) from None
    return SweepFile(spec, design, pendulum, source)


def load_sweep_file(path: str | os.PathLike[str]) -> SweepFile:
    """Reads and checks a sweep file (TOML); :class:`SweepFileError` names any problem."""
    source = str(path)
    try:
        text = read_file_capped(path)  # at most 1 MiB, 16 levels of nesting (docs/limits.md)
        data = parse_toml(text)  # over-long integers refused too
    except tomllib.TOMLDecodeError as e:
        raise SweepFileError(source, f"invalid TOML: {e}") from None
    except InvalidInputError as e:
        raise SweepFileError(source, str(e)) from None
    return sweep_file_from_dict(data, source)
