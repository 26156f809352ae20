"""Crane scenario files (TOML; docs/cranes.md "Crane files"): ``[crane]`` (rope [m], masses [kg],
rigging [m], damping [1/s], g [m/s²]), optional ``[move]`` (a straight pivot move: distance [m], v_max
[m/s], a_max [m/s²], j_max [m/s³], direction, t_start [s]), ``[shaper]`` (kind, and the design as
omega [rad/s] or rope [m]; default the crane's lowest sway mode), ``[hoist]`` (t [s], length [m]),
``[wind]`` (the :class:`~pendulab.crane.system.Wind` fields) and ``[simulation]`` (t_end, dt [s],
sway and rigging_sway [rad], rtol, atol). Unknown keys, wrong types, NaN/inf are errors naming the
key; files above 1 MiB are refused. ``pendulab crane run FILE`` runs one.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from .._core import InvalidInputError
from .paths import Gantry, move
from .paths import Path as CranePath
from .shaper import Shaper, shaper
from .system import Crane, CraneRun, Hoist, Wind

MAX_BYTES = 1 << 20

_Pos = Annotated[float, Field(gt=0, le=1e6)]
_NonNeg = Annotated[float, Field(ge=0, le=1e6)]
_Vec3 = Annotated[list[float], Field(min_length=3, max_length=3)]


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


class _CraneSec(_Section):
    rope: _Pos
    payload_mass: _Pos = 1000.0
    hook_mass: _Pos | None = None
    rigging: _Pos | None = None
    damping: _NonNeg = 0.0
    g: Annotated[float, Field(gt=0, le=1e3)] = 9.81


class _MoveSec(_Section):
    distance: Annotated[float, Field(ge=-1e5, le=1e5)]
    v_max: _Pos
    a_max: _Pos
    j_max: _Pos | None = None
    direction: _Vec3 = [1.0, 0.0, 0.0]
    t_start: _NonNeg = 0.0


class _ShaperSec(_Section):
    kind: str
    omega: _Pos | None = None
    rope: _Pos | None = None
    damping: Annotated[float, Field(ge=0, lt=1)] = 0.0
    tolerance: Annotated[float, Field(gt=0, lt=1)] = 0.05


class _HoistSec(_Section):
    t: Annotated[list[float], Field(min_length=2, max_length=100_000)]
    length: Annotated[list[float], Field(min_length=2, max_length=100_000)]


class _WindSec(_Section):
    velocity: _Vec3 = [0.0, 0.0, 0.0]
    area: _NonNeg = 0.0
    drag_coefficient: _NonNeg = 1.2
    air_density: _NonNeg = 1.225
    gust: _Vec3 = [0.0, 0.0, 0.0]
    gust_start: float = 0.0
    gust_duration: _Pos = 1.0
    hook_area: _NonNeg = 0.0
    hook_drag_coefficient: _NonNeg = 1.2
    turbulence: _NonNeg = 0.0
    turbulence_scale: _Pos = 50.0
    turbulence_modes: Annotated[int, Field(ge=8, le=4096)] = 64
    seed: Annotated[int, Field(ge=0, le=2**63 - 1)] = 0


class _SimSec(_Section):
    t_end: Annotated[float, Field(gt=0, le=1e6)]
    dt: _Pos = 0.02
    sway: Annotated[list[float], Field(min_length=2, max_length=2)] = [0.0, 0.0]
    rigging_sway: Annotated[list[float], Field(min_length=2, max_length=2)] | None = None
    rtol: Annotated[float, Field(ge=1e-14, le=1e-3)] = 1e-10
    atol: Annotated[float, Field(gt=0, le=1.0)] = 1e-10


class _File(_Section):
    crane: _CraneSec
    simulation: _SimSec
    move: _MoveSec | None = None
    shaper: _ShaperSec | None = None
    hoist: _HoistSec | None = None
    wind: _WindSec | None = None
    title: str = ""


@dataclass(frozen=True)
class CraneScenario:
    """A loaded crane file: the ``crane``, its ``shaper`` (or None), the simulation settings and
    the ``move_end`` time [s] (the pivot stops then; 0 without a move)."""

    crane: Crane
    shaper: Shaper | None
    t_end: float
    dt: float
    sway: tuple[float, float]
    rigging_sway: tuple[float, float] | None
    rtol: float
    atol: float
    move_end: float
    title: str

    def run(self) -> CraneRun:
        """Simulates the file's crane (:meth:`Crane.simulate`)."""
        return self.crane.simulate(
            self.t_end, self.sway, self.rigging_sway, dt=self.dt, rtol=self.rtol, atol=self.atol
        )


def _describe(e: ValidationError) -> str:
    parts = []
    for err in e.errors()[:5]:
        where = ".".join(str(p) for p in err["loc"])
        parts.append(
            f"[{where}]: {err['msg']}" if err["type"] != "extra_forbidden" else f"unknown key {where}"
        )
    return "; ".join(parts)


def parse(data: dict[str, Any], source: str = "<crane file>") -> CraneScenario:
    """A :class:`CraneScenario` from the parsed TOML ``data``; errors name ``source`` and the key."""
    try:
        f = _File.model_validate(data)
    except ValidationError as e:
        raise InvalidInputError(f"{source}: {_describe(e)}") from None
    c = f.crane
    probe = Crane(rope=c.rope, payload_mass=c.payload_mass, hook_mass=c.hook_mass, rigging=c.rigging, g=c.g)
    s = None
    if f.shaper is not None:
        sh = f.shaper
        if sh.omega is not None and sh.rope is not None:
            raise InvalidInputError(f"{source}: [shaper] give omega [rad/s] or rope [m], not both")
        w = sh.omega if sh.omega is not None else float(probe.modes(rope=sh.rope)[0])
        s = shaper(sh.kind, omega=w, damping=sh.damping, tolerance=sh.tolerance)
        if f.move is None:
            raise InvalidInputError(f"{source}: [shaper] needs a [move] to shape")
    path: CranePath = Gantry()
    move_end = 0.0
    if f.move is not None:
        m = f.move
        gantry = move(
            m.distance, m.v_max, m.a_max, j_max=m.j_max, shaper=s, direction=m.direction, t_start=m.t_start
        )
        path, move_end = gantry, gantry.t_end
    hoist = Hoist(f.hoist.t, f.hoist.length) if f.hoist is not None else None
    wind = None
    if f.wind is not None:
        w = f.wind
        kw = w.model_dump()
        kw["velocity"], kw["gust"] = tuple(w.velocity), tuple(w.gust)
        wind = Wind(**kw)
        wind.modes()  # checks the turbulence settings now
    crane_obj = Crane(
        rope=c.rope,
        pivot=path,
        payload_mass=c.payload_mass,
        hook_mass=c.hook_mass,
        rigging=c.rigging,
        wind=wind,
        damping=c.damping,
        g=c.g,
        hoist=hoist,
    )
    sim = f.simulation
    if not all(math.isfinite(a) for a in sim.sway):
        raise InvalidInputError(f"{source}: [simulation] sway must be finite angles [rad]")
    return CraneScenario(
        crane_obj,
        s,
        sim.t_end,
        sim.dt,
        (sim.sway[0], sim.sway[1]),
        None if sim.rigging_sway is None else (sim.rigging_sway[0], sim.rigging_sway[1]),
        sim.rtol,
        sim.atol,
        move_end,
        f.title,
    )


def load(path: str | Path) -> CraneScenario:
    """Reads a crane file (module doc); ``InvalidInputError`` naming the file and key on bad contents,
    ``OSError`` if it cannot be read."""
    p = Path(path)
    size = p.stat().st_size
    if size > MAX_BYTES:
        raise InvalidInputError(f"{p}: {size} bytes; crane files are at most {MAX_BYTES} bytes")
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        raise InvalidInputError(f"{p}: not valid TOML: {e}") from None
    return parse(data, str(p))
