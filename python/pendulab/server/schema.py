"""``GET /api/schema``: what the page builds its controls from (docs/web.md).

The parameters, their units, defaults and hard limits come from the core's model registry
(``pendulab.models()``); this module adds only what a control needs beyond that: the span of a slider
(``ui_min`` … ``ui_max``) and its ``step``. The live limits of length, mass and g are the server's own
(:data:`pendulab.server.protocol.LIMITS`, narrower than the core's); a model's own parameters keep the
core's limits (``min``/``max``, null for none). Units SI throughout.
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING, Any

from .._core import __version__
from ..integrators import methods
from .protocol import COMMAND_TYPES, FRAME_FIELDS, FRAME_UNITS, LIMITS, MODEL_SPECS, RECORD_BYTES, own_params

if TYPE_CHECKING:
    from .._core import ParamSpec

TICK_HZ = 60.0
"""Frames per second sent to each client while running."""

_PI = math.pi
SLIDERS: dict[str, tuple[float, float, float]] = {
    # name: (ui_min, ui_max, step) of the slider; the value may go beyond with the number box
    "damping": (0.0, 2.0, 0.001),
    "drag": (0.0, 5.0, 0.01),
    "forcing_amplitude": (0.0, 30.0, 0.01),
    "forcing_omega": (0.0, 20.0, 0.01),
    "forcing_phase": (-_PI, _PI, 0.01),
    "forcing_x": (-1.0, 1.0, 0.01),
    "forcing_y": (-1.0, 1.0, 0.01),
    "forcing_z": (-1.0, 1.0, 0.01),
    "gravity_x": (-1.0, 1.0, 0.01),
    "gravity_y": (-1.0, 1.0, 0.01),
    "gravity_z": (-1.0, 1.0, 0.01),
    "frame_rate": (0.0, 1.0, 1e-4),
    "latitude": (-_PI / 2, _PI / 2, 0.001),
    "radius": (0.0, 10.0, 0.01),
    "rate": (-2.0, 2.0, 0.001),
    "height": (-5.0, 5.0, 0.01),
    "amplitude": (0.0, 0.3, 0.001),
    "frequency": (0.0, 400.0, 0.1),
    "stiffness": (1.0, 200.0, 0.01),
    "restitution": (0.0, 1.0, 0.01),
}
"""Slider spans of the models' own parameters (SI units). A parameter missing here gets a span from
its default (see :func:`_slider`), so a new model in the core shows up without a change here."""


def _finite(v: float) -> float | None:
    return float(v) if math.isfinite(v) else None


def _slider(p: ParamSpec) -> tuple[float, float, float]:
    if p["name"] in SLIDERS:
        return SLIDERS[p["name"]]
    d = float(p["default"])
    span = max(abs(d), 1.0)
    lo = float(p["min"]) if math.isfinite(p["min"]) else d - 2 * span
    hi = float(p["max"]) if math.isfinite(p["max"]) else d + 2 * span
    return lo, hi, (hi - lo) / 1000


def _lab_allowed(allowed: str, lo: float, hi: float) -> str:
    """The registry's words for a parameter's values with its range replaced by the lab's narrower one:
    `a number in [1e-6, 1e4] m` → `a number in [0.001, 1000] m` (a refusal said both ranges, the core's
    one allowing the refused value: `length = 5000 is not allowed: a number in [1e-6, 1e4] m
    (0.001 … 1000 m)`)."""
    lab = f"[{lo:g}, {hi:g}]"
    said, n = re.subn(r"\[[^\]]*\]", lab, allowed, count=1)
    return said if n == 1 else f"{allowed}; in the lab {lab}"


def param_schema(p: ParamSpec) -> dict[str, Any]:
    """One parameter for the page: name, label (the words a student reads), unit (SI), description (one
    line of help), allowed (in words: the range min … max), default, the hard
    limits min/max (null: none) and the slider's ui_min, ui_max, step."""
    lo: float | None
    hi: float | None
    allowed = p["allowed"]
    if p["name"] in LIMITS:
        lim = LIMITS[p["name"]]
        lo, hi, ui = lim["min"], lim["max"], (lim["ui_min"], lim["ui_max"], lim["step"])
        allowed = _lab_allowed(allowed, lo, hi)
    else:
        lo, hi, ui = _finite(p["min"]), _finite(p["max"]), _slider(p)
    return {
        "name": p["name"],
        "label": p["label"],
        "unit": p["unit"],
        "description": p["description"],
        "allowed": allowed,
        "default": p["default"],
        "min": lo,
        "max": hi,
        "ui_min": ui[0],
        "ui_max": ui[1],
        "step": ui[2],
    }


def schema() -> dict[str, Any]:
    """What the page builds its controls from: the shared parameters (length, mass, g) with units and
    limits, every model of the registry with its own parameters, the controls, the methods, the frame
    layout, the command types and the tick rate."""
    ideal = MODEL_SPECS["ideal"]
    controls = {
        "dt": {"unit": "s", "description": "step size of fixed-step methods", **LIMITS["dt"]},
        "time_scale": {"unit": "1", "description": "simulated seconds per second", **LIMITS["time_scale"]},
        "step_n": {"unit": "steps", "description": "steps taken by one 'step' command", **LIMITS["step_n"]},
    }
    return {
        "version": __version__,
        "model": {
            "name": "ideal",
            "label": ideal["label"],
            "summary": ideal["summary"],
            "params": [param_schema(p) for p in ideal["params"]],
        },
        "models": [
            {
                "name": name,
                "label": m["label"],
                "summary": m["summary"],
                "params": [param_schema(p) for p in own_params(name)],
            }
            for name, m in MODEL_SPECS.items()
        ],
        "controls": controls,
        "methods": [dict(m) for m in methods()],
        "frame": {
            "fields": list(FRAME_FIELDS),
            "units": list(FRAME_UNITS),
            "dtype": "float64",
            "byte_order": "little",
            "record_bytes": RECORD_BYTES,
        },
        "commands": list(COMMAND_TYPES),
        "tick_hz": TICK_HZ,
    }
