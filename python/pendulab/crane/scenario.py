"""Crane scenario files (TOML; docs/cranes.md "Crane files"): ``[crane]`` (rope [m], masses [kg],
rigging [m], damping [1/s], g [m/s²]), optional ``[move]`` (a straight pivot move: distance [m], v_max
[m/s], a_max [m/s²], j_max [m/s³], direction, t_start [s]), ``[shaper]`` (kind, and the design as
omega [rad/s] or rope [m]; default the crane's lowest sway mode), ``[hoist]`` (t [s], length [m]),
``[wind]`` (the :class:`~pendulab.crane.system.Wind` fields) and ``[simulation]`` (t_end [s],
output_spacing [s]: the time between output rows — ``dt`` in older files, still read —, sway and
rigging_sway [rad], rtol, atol). Unknown keys, wrong types, NaN/inf are errors naming the
key; files above 1 MiB are refused. ``pendulab crane run FILE`` runs one. The tables are those of a
scenario file with ``[crane]`` (:mod:`pendulab.scenario.crane_schema`): ``pl.load_scenario``,
``pendulab run`` and ``pendulab validate`` read the same files, building the crane with
:func:`from_spec`.
"""

from __future__ import annotations

import math
import os
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from .._core import InvalidInputError
from ..scenario.crane_schema import CraneSpec
from ..scenario.errors import EMPTY_FILE, describe, file_problems
from ..validate import parse_toml
from .hoist import Hoist
from .paths import Gantry, move
from .paths import Path as CranePath
from .shaper import Shaper, shaper
from .system import Crane, CraneRun, Wind

MAX_BYTES = 1 << 20


@dataclass(frozen=True)
class CraneScenario:
    """A loaded crane file: the ``crane``, its ``shaper`` (or None), the simulation settings (t_end,
    output_spacing [s], sway, rigging_sway [rad], rtol, atol) and the ``move_end`` time [s] (the
    pivot stops then; 0 without a move)."""

    crane: Crane
    shaper: Shaper | None
    t_end: float
    output_spacing: float
    sway: tuple[float, float]
    rigging_sway: tuple[float, float] | None
    rtol: float
    atol: float
    move_end: float
    title: str
    spec: CraneSpec | None = None

    def run(self) -> CraneRun:
        """Simulates the file's crane (:meth:`Crane.simulate`)."""
        return self.crane.simulate(
            self.t_end,
            self.sway,
            self.rigging_sway,
            output_spacing=self.output_spacing,
            rtol=self.rtol,
            atol=self.atol,
        )

    def metadata(self, run: CraneRun | None = None) -> dict[str, Any]:
        """What a crane run's file carries (its CSV's ``#`` line, as a trajectory's): the file's
        settings with their defaults (``file``: the tables of the module doc), the shaper's impulses
        (times [s], amplitudes), the sway modes [rad/s], the move's end [s], the steps taken and the
        units of the columns and numbers."""
        c = self.crane
        spec = None if self.spec is None else self.spec.model_dump(mode="json", exclude_none=True)
        shaper_info = None
        if self.shaper is not None:
            sh = self.shaper
            design = {"omega": sh.omega, "damping": sh.damping, "tolerance": sh.tolerance}
            shaper_info = {"kind": sh.kind, "times": sh.times.tolist(), "amplitudes": sh.amplitudes.tolist()}
            shaper_info |= {k: v for k, v in design.items() if math.isfinite(v)}
        units = {"modes": "rad/s", "move_end": "s", "shaper.times": "s", "shaper.omega": "rad/s"}
        if spec is not None:
            units |= {"file.simulation.output_spacing": "s"}
        if run is not None:
            units |= {name: unit for name, (unit, _) in run.columns().items()}
        return {
            "software": "pendulab",
            "title": self.title,
            "file": None if spec is None else file_settings(spec),
            "shaper": shaper_info,
            "modes": c.modes().tolist(),
            "move_end": self.move_end,
            **({"steps": run.steps} if run is not None else {}),
            "units": units,
            "conventions": "SI units, z up, gravity along -z for g > 0",
        }


def file_settings(file: dict[str, Any]) -> dict[str, Any]:
    """A crane file's settings as a run's metadata says them (``file``): ``[simulation] output_spacing``
    [s], the spacing of the output rows of an adaptive run (DOP853 chooses its own steps). Older files
    and their runs' metadata said ``dt``: :func:`pendulab.io.read_metadata` reads them through here."""
    sim = file.get("simulation")
    if not (isinstance(sim, dict) and "dt" in sim):
        return file
    sim = {("output_spacing" if k == "dt" else k): v for k, v in sim.items()}
    return file | {"simulation": sim}


class CraneFileError(InvalidInputError):
    """A crane file whose tables do not validate: ``source`` names the file, ``problems`` lists every
    problem (the key, the bad value and what is allowed; unknown keys first). The message shows the
    first :data:`pendulab.scenario.errors.MOST_SHOWN` (five), numbered when several, and says how many
    more there are:
    ``<source>: 7 problems: (1) … (5) … (and 2 more)``. An ``InvalidInputError``, as before."""

    def __init__(self, source: str, problems: list[str]) -> None:
        self.source = source
        self.problems = list(problems)
        super().__init__(f"{source}: {describe(self.problems)}")


def parse(data: dict[str, Any], source: str = "<crane file>") -> CraneScenario:
    """A :class:`CraneScenario` from the parsed TOML ``data``; errors name ``source`` and the key
    (:class:`CraneFileError`, its ``problems`` all of them: the message shows at most five), in the
    words of the pendulum's scenario files (:func:`pendulab.scenario.errors.file_problems`)."""
    try:
        f = CraneSpec.model_validate(data)
    except ValidationError as e:
        raise CraneFileError(source, file_problems(e.errors(), data, CraneSpec)) from None
    return from_spec(f, source)


def from_spec(f: CraneSpec, source: str = "<crane file>") -> CraneScenario:
    """A :class:`CraneScenario` from validated tables (what a scenario file with ``[crane]`` holds,
    :mod:`pendulab.scenario.crane_schema`); ``InvalidInputError`` naming ``source`` when the crane
    cannot be built (a move the limits cannot make, an unknown shaper kind, a bad hoist)."""
    try:
        return _build(f, source)
    except InvalidInputError as e:
        text = str(e)
        raise InvalidInputError(text if text.startswith(source) else f"{source}: {text}") from None


def _build(f: CraneSpec, source: str) -> CraneScenario:
    c = f.crane
    probe = Crane(rope=c.rope, payload_mass=c.payload_mass, hook_mass=c.hook_mass, rigging=c.rigging, g=c.g)
    s = None
    if f.shaper is not None:
        sh = f.shaper
        if sh.omega is not None and sh.rope is not None:
            raise InvalidInputError(f"{source}: [shaper] give omega [rad/s] or rope [m], not both")
        omega = sh.omega if sh.omega is not None else float(probe.modes(rope=sh.rope)[0])
        s = shaper(sh.kind, omega=omega, damping=sh.damping, tolerance=sh.tolerance)
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
        sim.output_spacing,
        (sim.sway[0], sim.sway[1]),
        None if sim.rigging_sway is None else (sim.rigging_sway[0], sim.rigging_sway[1]),
        sim.rtol,
        sim.atol,
        move_end,
        f.title or "",
        f,
    )


def load(path: str | Path) -> CraneScenario:
    """Reads a crane file (module doc); ``InvalidInputError`` naming the file as given (``./x.toml``
    stays ``./x.toml``, as typed on a command line) and the key on bad contents, ``OSError`` naming it
    so if it cannot be read."""
    name = os.fspath(path)
    size = os.stat(name).st_size
    if size > MAX_BYTES:
        raise InvalidInputError(f"{name}: {size} bytes; crane files are at most {MAX_BYTES} bytes")
    try:  # a BOM dropped, nesting checked (deep nesting was a RecursionError), long integers refused
        with open(name, encoding="utf-8") as fh:
            data = parse_toml(fh.read())
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        raise InvalidInputError(f"{name}: not valid TOML: {e}") from None
    except InvalidInputError as e:
        raise InvalidInputError(f"{name}: {e}") from None
    if not data:
        raise CraneFileError(name, [EMPTY_FILE])
    return parse(data, name)
