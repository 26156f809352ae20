"""How a scenario shows and writes itself: TOML text that reads back to an equal scenario (floats by
their shortest repr, strings JSON-escaped, the unit of every dimensioned key as a comment: lengths [m],
masses [kg], g [m/s²], angles [rad] or ``*_deg`` [degrees], rates [rad/s], times [s]), the one-line
``repr`` and the rows of the HTML table (notebooks). :class:`pendulab.scenario.Scenario` calls these
with its validated settings; nothing here validates or runs.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from .._core import __version__
from ..display import Row, number, with_unit
from ..model import State
from .crane_schema import CRANE_SECTIONS, CraneSpec
from .schema import SECTIONS, UNITS, ScenarioSpec, _degree_keys, _own_params


def _toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return repr(value)  # shortest repr: reads back to the same float
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False).replace("\x7f", "\\u007f")
    if isinstance(value, list):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(f"cannot write {value!r} to TOML")


def toml_text(spec: ScenarioSpec | CraneSpec, data: dict[str, Any]) -> str:
    """The TOML text of a scenario's settings ``data`` (:meth:`Scenario.to_dict`): a header line, the
    title and description, each table with the unit of every dimensioned key as a comment (degrees for
    the ``_deg`` keys; :data:`UNITS` and the model's own units from the registry)."""
    if isinstance(spec, CraneSpec):
        lines = [f"# Pendulab crane scenario (pendulab {__version__}); SI units (docs/scenarios.md, Cranes)"]
        lines += [f"{k} = {_toml_value(data[k])}" for k in ("title", "description") if k in data]
        for section in CRANE_SECTIONS:
            if section in data:
                lines += ["", f"[{section}]"]
                lines += [f"{key} = {_toml_value(value)}" for key, value in data[section].items()]
        return "\n".join(lines) + "\n"
    model = spec.pendulum.model
    units = {section: dict(table) for section, table in UNITS.items()}
    units["pendulum"] |= {k: p["unit"] for k, p in _own_params(model).items() if p["unit"] != "1"}
    units["pendulum"] |= dict.fromkeys(_degree_keys(model), "degrees")
    lines = [f"# Pendulab scenario (pendulab {__version__}); SI units, angles *_deg in degrees"]
    lines += [f"{k} = {_toml_value(data[k])}" for k in ("title", "description") if k in data]
    for section in SECTIONS:
        lines += ["", f"[{section}]"]
        for key, value in data[section].items():
            unit = units[section].get(key)
            entry = f"{key} = {_toml_value(value)}"
            lines.append(f"{entry:<24}  # {unit}" if unit else entry)
    return "\n".join(lines) + "\n"


def scenario_repr(spec: ScenarioSpec | CraneSpec, state: State | None, source: str) -> str:
    """``repr(Scenario)``: the file's name, the model and its parameters, l [m], m [kg], g [m/s²], θ₀, φ₀
    [°], the method, step [s] and time span [s] (a crane: rope [m], payload [kg], hoist, shaper)."""
    name = Path(source).name if source and not source.startswith("<") else source
    if isinstance(spec, CraneSpec):
        c = spec.crane
        return (
            f"Scenario({name!r}: crane, rope={number(c.rope)} m, payload={number(c.payload_mass)} kg"
            f"{', hoisted' if spec.hoist else ''}"
            f"{', shaper ' + spec.shaper.kind if spec.shaper else ''}; "
            f"t=0…{number(spec.simulation.t_end)} s)"
        )
    assert state is not None
    p, sim = spec.pendulum, spec.simulation
    theta, phi = state.angles_deg()
    step = "adaptive" if sim.is_adaptive() else f"dt={number(sim.resolved_dt())} s"
    params = "".join(f", {k}={number(v)}" for k, v in p.params.items() if isinstance(v, int | float))
    return (
        f"Scenario({name!r}: {p.model}{params}, l={number(p.length)} m, m={number(p.mass)} kg, "
        f"g={number(p.g)} m/s², θ₀={number(theta)}°, φ₀={number(phi)}°; {sim.method}, {step}, "
        f"t={number(sim.t0)}…{number(sim.t_end)} s)"
    )


def summary_rows(spec: ScenarioSpec | CraneSpec, state: State | None, crane: Any) -> list[Row]:
    """The rows of the scenario's HTML table (name, value, unit): the model and its parameters, l [m],
    m [kg], g [m/s²], the start θ, φ [°], method, step [s], time span [s]; a crane's own rows."""
    if isinstance(spec, CraneSpec):
        return _crane_rows(spec, crane)
    assert state is not None
    p, sim = spec.pendulum, spec.simulation
    theta, phi = state.angles_deg()
    step = "adaptive" if sim.is_adaptive() else with_unit(sim.resolved_dt(), "s")
    rows: list[Row] = [
        ("model", p.model, ""),
        *((k, v if isinstance(v, int | float) else repr(v), "") for k, v in p.params.items()),
        ("length l", p.length, "m"),
        ("mass m", p.mass, "kg"),
        ("gravity g", p.g, "m/s²"),
        ("start θ, φ", f"{number(theta)}, {number(phi)}", "°"),
        ("method", sim.method, ""),
        ("step dt", step, ""),
        ("time span t0 … t_end", f"{number(sim.t0)} … {number(sim.t_end)}", "s"),
    ]
    return rows


def _crane_rows(spec: CraneSpec, crane: Any) -> list[Row]:
    """The crane's rows: rope [m], payload [kg], sway modes [rad/s], shaper, hoist, time span [s]."""
    c, sim = crane, spec.simulation
    return [
        ("crane: rope", spec.crane.rope, "m"),
        ("payload mass", spec.crane.payload_mass, "kg"),
        ("sway modes", ", ".join(number(float(w)) for w in c.crane.modes()), "rad/s"),
        ("shaper", c.shaper.kind if c.shaper is not None else "none", ""),
        ("hoist", "yes" if spec.hoist is not None else "no", ""),
        ("time span 0 … t_end", f"0 … {number(sim.t_end)}", "s"),
    ]
