"""The crane's tables of a scenario file (docs/scenarios.md "Cranes", docs/cranes.md "Crane files"):
a file with ``[crane]`` describes a crane instead of a pendulum — ``[crane]`` (rope [m], masses [kg],
rigging [m], damping [1/s], g [m/s²]), optional ``[move]`` (a straight pivot move: distance [m],
v_max [m/s], a_max [m/s²], j_max [m/s³], direction, t_start [s]), ``[shaper]`` (kind, and the design
as omega [rad/s] or rope [m]), ``[hoist]`` (t [s], length [m]), ``[wind]`` (velocity [m/s], areas
[m²], drag coefficients, air density [kg/m³], gust [m/s], gust start and duration [s], turbulence
[m/s], its scale [m], modes, seed) and ``[simulation]`` (t_end, dt [s], sway and rigging_sway [rad],
rtol, atol).

Only the tables: pydantic models that refuse unknown keys, wrong types, NaN/inf and values out of
range, with the allowed values (and units) in each field's description, which the error messages of
:mod:`pendulab.scenario.errors` quote. Building the crane from them is :mod:`pendulab.crane.scenario`.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import AliasChoices, BaseModel, ConfigDict, Field, model_validator

from .._numbers import shown
from ..validate import LONGEST, LONGEST_TEXT, SHORTEST, SHORTEST_TEXT
from .table_base import _show

CRANE_SECTIONS = ("crane", "move", "shaper", "hoist", "wind", "simulation")
"""The crane file's tables, in the order :meth:`Scenario.to_toml` writes them."""

OLD_SPACING_KEY = "dt"
"""The older name of ``[simulation] output_spacing`` in a crane's file (read as it)."""

_Vec3 = Annotated[list[float], Field(min_length=3, max_length=3)]


def _pos(description: str, default: Any = ..., le: float = 1e6) -> Any:
    return Field(default, gt=0, le=le, description=f"{description}, > 0 and <= {shown(le)}")


def _rope(description: str, default: Any = ...) -> Any:
    """A rope length [m]: a pendulum's length range, [:data:`SHORTEST`, :data:`LONGEST`]."""
    return Field(
        default,
        ge=SHORTEST,
        le=LONGEST,
        description=f"{description}, >= {SHORTEST_TEXT} and <= {LONGEST_TEXT}",
    )


def _nonneg(description: str, default: Any = 0.0) -> Any:
    return Field(default, ge=0, le=1e6, description=f"{description}, >= 0 and <= 1e6")


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


class CraneSection(_Section):
    """``[crane]``: the rope, the load (and a hook on rigging), damping and gravity."""

    rope: float = _rope("rope length at t = 0 in m")
    payload_mass: float = _pos("payload mass in kg", 1000.0)
    hook_mass: float | None = _pos("hook mass in kg (with rigging: hook + payload)", None)
    rigging: float | None = _rope("rigging length hook to payload in m (with hook_mass)", None)
    damping: float = _nonneg("linear damping of the sway in 1/s")
    g: float = _pos("gravitational acceleration in m/s²", 9.81, le=1e3)


class MoveSection(_Section):
    """``[move]``: a straight, acceleration- (or jerk-) limited pivot move."""

    distance: float = Field(ge=-1e5, le=1e5, description="distance of the move in m, within ±1e5")
    v_max: float = _pos("speed limit in m/s")
    a_max: float = _pos("acceleration limit in m/s²")
    j_max: float | None = _pos("jerk limit in m/s³ (optional)", None)
    direction: _Vec3 = Field([1.0, 0.0, 0.0], description="direction of the move, 3 numbers (normalised)")
    t_start: float = _nonneg("start of the move in s")


class ShaperSection(_Section):
    """``[shaper]``: the command shaper applied to the move."""

    kind: str = Field(description="a shaper kind: zv, zvd, zvdd, ei, 2hump_ei (docs/cranes.md)")
    omega: float | None = _pos("design frequency in rad/s (or rope)", None)
    rope: float | None = _rope("design rope length in m (or omega); default: the crane's lowest mode", None)
    damping: float = Field(0.0, ge=0, lt=1, description="design damping ratio, in [0, 1)")
    tolerance: float = Field(0.05, gt=0, lt=1, description="EI tolerance V, in (0, 1)")


class HoistSection(_Section):
    """``[hoist]``: the rope length through time (piecewise, smooth between the given points)."""

    t: list[float] = Field(min_length=2, max_length=100_000, description="times in s, increasing (2 to 1e5)")
    length: list[Annotated[float, Field(ge=SHORTEST, le=LONGEST)]] = Field(
        min_length=2,
        max_length=100_000,
        description=f"rope lengths in m at those times, >= {SHORTEST_TEXT} and <= {LONGEST_TEXT}",
    )


class WindSection(_Section):
    """``[wind]``: steady wind, a (1 − cos) gust and seeded turbulence, as drag on the load."""

    velocity: _Vec3 = Field([0.0, 0.0, 0.0], description="steady wind velocity in m/s, 3 numbers")
    area: float = _nonneg("payload's area facing the wind in m²")
    drag_coefficient: float = _nonneg("payload's drag coefficient", 1.2)
    air_density: float = _nonneg("air density in kg/m³", 1.225)
    gust: _Vec3 = Field([0.0, 0.0, 0.0], description="gust's peak velocity in m/s, 3 numbers")
    gust_start: float = Field(0.0, ge=-1e6, le=1e6, description="gust start in s")
    gust_duration: float = _pos("gust duration in s", 1.0)
    hook_area: float = _nonneg("hook's area facing the wind in m²")
    hook_drag_coefficient: float = _nonneg("hook's drag coefficient", 1.2)
    turbulence: float = _nonneg("turbulence intensity σ in m/s")
    turbulence_scale: float = _pos("turbulence length scale in m", 50.0)
    turbulence_modes: int = Field(64, ge=8, le=4096, description="number of turbulence modes, 8 to 4096")
    seed: int = Field(0, ge=0, le=2**63 - 1, description="turbulence seed, an integer >= 0")


class CraneSimulationSection(_Section):
    """``[simulation]`` of a crane: the run's end, the spacing of its output rows and the start sway.
    ``output_spacing`` was ``dt`` (the crane's DOP853 chooses its own steps, so it is no step): a file
    with ``dt`` is read as before; one with both keys is refused naming both."""

    t_end: float = _pos("end time in s")
    output_spacing: float = Field(
        0.02,
        gt=0,
        le=1e6,
        validation_alias=AliasChoices("output_spacing", OLD_SPACING_KEY),
        description="time between output rows in s, > 0 and <= 1e6 (DOP853 chooses its own steps)",
    )
    sway: list[float] = Field(
        [0.0, 0.0], min_length=2, max_length=2, description="start sway of the rope [θ, φ] in rad"
    )
    rigging_sway: list[float] | None = Field(
        None, min_length=2, max_length=2, description="start sway of the rigging [θ, φ] in rad"
    )
    rtol: float = Field(1e-10, ge=1e-14, le=1e-3, description="relative tolerance, in [1e-14, 1e-3]")
    atol: float = Field(1e-10, gt=0, le=1.0, description="absolute tolerance, in (0, 1]")

    @model_validator(mode="before")
    @classmethod
    def _one_spacing(cls, data: Any) -> Any:
        if isinstance(data, dict) and "output_spacing" in data and OLD_SPACING_KEY in data:
            new, old = _show(data["output_spacing"]), _show(data[OLD_SPACING_KEY])
            raise ValueError(
                f"output_spacing = {new} and dt = {old} both given: dt is the older name of "
                "output_spacing (the time between output rows in s); keep one"
            )
        return data


class CraneSpec(_Section):
    """A crane file: ``title``, ``description`` and the tables of the module doc."""

    title: str | None = Field(None, description="a one-line title (string, optional)")
    description: str | None = Field(None, description="free text (string, optional)")
    crane: CraneSection = Field(description="the table [crane]")
    simulation: CraneSimulationSection = Field(description="the table [simulation]")
    move: MoveSection | None = Field(None, description="the table [move]")
    shaper: ShaperSection | None = Field(None, description="the table [shaper]")
    hoist: HoistSection | None = Field(None, description="the table [hoist]")
    wind: WindSection | None = Field(None, description="the table [wind]")


def is_crane(data: Any) -> bool:
    """True when the parsed file has a ``[crane]`` table (then it describes a crane, not a pendulum)."""
    return isinstance(data, dict) and "crane" in data
