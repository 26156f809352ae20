"""Column names and units of measured-data files, as video-analysis tools and phone sensor apps write
them: a header cell is a name and an optional unit, ``x (cm)``, ``Time [s]``,
``Acceleration x (m/s^2)``, ``Gyroscope z (rad/s)``.

Names map to the data kinds of :func:`pendulab.fit` (``t``, ``x``, ``y``, ``z``, ``theta``, ``phi``,
``angle``, ``specific_force``, ``angular_speed``) or to vector components (``ax``, ``ay``, ``az``: the
accelerometer, which measures the specific force a − g⃗ [m/s²]; ``wx``, ``wy``, ``wz``: the gyroscope
[rad/s]) whose magnitudes the table reader forms. A unit is converted to SI (cm, mm → m; ms → s;
deg → rad; deg/s → rad/s; g₀ = 9.80665 m/s² → m/s²); a unit that does not fit the column's quantity,
pixels, or a phone's "linear acceleration" (gravity removed: not the specific force) is an error
naming the column and what is allowed.

Header cells as the common lab programs write them: ``x (cm)`` and ``Time [s]`` (video analysis,
phyphox), ``t / s`` (Cassy, the ISO 80000 quantity / unit form), ``Latest: Time (s)`` and
``Run 1: Angle (°)`` (Logger Pro and Graphical Analysis: the run's name before a colon), phyphox'
``Absolute acceleration (m/s^2)`` and the gyroscope's ``Absolute (rad/s)``. Cells are split by
``str`` methods, not a regular expression over the whole cell: linear time whatever the cell holds.
"""

from __future__ import annotations

import math
import re

from .keyed import KeyedInputError

#: The physical quantity of each column name.
QUANTITY = {
    "t": "time",
    "x": "length",
    "y": "length",
    "z": "length",
    "theta": "angle",
    "phi": "angle",
    "angle": "angle",
    "specific_force": "acceleration",
    "ax": "acceleration",
    "ay": "acceleration",
    "az": "acceleration",
    "angular_speed": "angular rate",
    "wx": "angular rate",
    "wy": "angular rate",
    "wz": "angular rate",
}

#: Units accepted per quantity and their factor to SI (standard gravity g₀ = 9.80665 m/s², CGPM 1901).
UNITS: dict[str, dict[str, float]] = {
    "time": {"s": 1.0, "sec": 1.0, "seconds": 1.0, "ms": 1e-3, "us": 1e-6, "µs": 1e-6, "min": 60.0},
    "length": {"m": 1.0, "meters": 1.0, "metres": 1.0, "cm": 1e-2, "mm": 1e-3, "km": 1e3},
    "angle": {
        "rad": 1.0,
        "deg": math.pi / 180.0,
        "°": math.pi / 180.0,
        "degree": math.pi / 180.0,
        "degrees": math.pi / 180.0,
    },
    "acceleration": {"m/s^2": 1.0, "m/s²": 1.0, "m/s2": 1.0, "ms^-2": 1.0, "m s^-2": 1.0, "g": 9.80665},
    "angular rate": {
        "rad/s": 1.0,
        "1/s": 1.0,
        "deg/s": math.pi / 180.0,
        "°/s": math.pi / 180.0,
        "dps": math.pi / 180.0,
    },
}

ALIASES = {
    "time": "t",
    "t_s": "t",
    "timestamp": "t",
    "f": "specific_force",
    "absolute acceleration": "specific_force",
    "w": "angular_speed",
    "omega": "angular_speed",
    "planar_angle": "angle",
    "α": "angle",
    "θ": "theta",
    "φ": "phi",
    "-": "-",
}

_COMPONENT = re.compile(
    r"^(?:(?P<acc>acceleration|accel|acc|a)|(?P<gf>gf)|(?P<gyro>gyroscope|gyro|angular velocity|omega|w))"
    r"[ _]?(?P<axis>[xyz])$"
)
MAX_NAME = 200
"""The longest column name looked up [characters]; longer names are unknown columns."""


def split_unit(cell: str) -> tuple[str, str | None]:
    """``'x (cm)'`` → (``'x'``, ``'cm'``); ``'t / s'`` → (``'t'``, ``'s'``); ``'t'`` → (``'t'``,
    None). The unit is the text in the last pair of brackets that ends the cell, else the text after
    the first `` / ``."""
    s = cell.strip()
    if s[-1:] in (")", "]"):
        i = max(s.rfind("("), s.rfind("["))
        inner = s[i + 1 : -1]
        if i >= 0 and ")" not in inner and "]" not in inner:
            return s[:i].strip(), inner.strip()
    name, sep, unit = s.partition(" / ")
    if sep and name.strip() and unit.strip():
        return name.strip(), unit.strip()
    return s, None


def drop_run(cell: str) -> str:
    """A Logger Pro / Graphical Analysis header cell without its run's name: ``'Latest: Time (s)'``
    → ``'Time (s)'`` (the colon must come before any unit bracket)."""
    head, sep, rest = cell.partition(":")
    if sep and rest.strip() and "(" not in head and "[" not in head:
        return rest.strip()
    return cell


def column(cell: str, where: str) -> tuple[str, float]:
    """The data kind or component a header cell names and the factor to SI of its values: ``'x (cm)'``
    → (``'x'``, 0.01). Physics Toolbox's g-force columns ``gFx``, ``gFy``, ``gFz`` (the specific force
    in units of g₀) are accelerometer components in g unless a unit says otherwise."""
    raw, unit = split_unit(drop_run(cell))
    if len(raw) > MAX_NAME:
        return raw[:MAX_NAME].lower(), 1.0  # an unknown column (ignored or refused by the caller)
    name = column_name(raw, where)
    implied = "g" if re.fullmatch(r"gf[ _]?[xyz]|tgf", " ".join(raw.lower().split())) else None
    if name == "tgf":
        name = "specific_force"
    if name == "absolute" and unit is not None:  # phyphox: the magnitude, named by its unit
        u = unit.strip().lower().replace(" ", "")
        name = "angular_speed" if u in UNITS["angular rate"] else "specific_force"
    return name, to_si(name, unit if unit is not None else implied, where)


def column_name(raw: str, where: str) -> str:
    """The data kind or component a header cell names (unknown names come back lower-cased, for the
    caller to ignore or refuse)."""
    text = " ".join(raw.strip().lower().replace("_", " ").split())
    if "linear acceleration" in text or "linear acc" in text:
        raise KeyedInputError(
            f"{where}: column {raw!r} is a linear acceleration (the phone removed gravity); the fit needs "
            "the accelerometer with gravity, |a - g| (e.g. phyphox 'Acceleration with g')",
            "data_linear_acceleration",
            file=where,
            column=raw,
        )
    compact = text.replace(" ", "_")
    if compact in QUANTITY:
        return compact
    if text in ALIASES or compact in ALIASES:
        return ALIASES.get(text, ALIASES.get(compact, text))
    m = _COMPONENT.match(text)
    if m is not None:
        return ("w" if m["gyro"] else "a") + m["axis"]
    return text


def is_unit(text: str) -> bool:
    """Whether ``text`` is one of the units of :data:`UNITS` (a line of units: Vernier's format)."""
    u = text.strip().lower().replace(" ", "")
    return any(u in table for table in UNITS.values())


def to_si(name: str, unit: str | None, where: str) -> float:
    """The factor that takes the column ``name`` in ``unit`` to SI (1 when no unit is given)."""
    if unit is None or name not in QUANTITY:
        return 1.0
    u = unit.strip().lower().replace(" ", "")
    if u in ("px", "pixel", "pixels", "pix"):
        raise KeyedInputError(
            f"{where}: column {name!r} is in pixels; scale it to metres first (a ruler of known length "
            "in the video gives metres per pixel)",
            "data_pixels",
            file=where,
            column=name,
        )
    quantity = QUANTITY[name]
    table = UNITS[quantity]
    if u in table:
        return table[u]
    raise KeyedInputError(
        f"{where}: column {name!r} has the unit {unit!r}; a {quantity} is given in one of {', '.join(table)}",
        "data_bad_unit",
        file=where,
        column=name,
        unit=unit,
        allowed=", ".join(table),
    )
