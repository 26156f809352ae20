"""Every numeric argument of the crane's Python API refuses a bad value — a string, None (where None is
not "not given"), a bool, a complex number, an array where one number belongs, NaN, ±inf, a negative
number where none is allowed, a non-integer where an integer is — with an InvalidInputError
``invalid <name> = <value>: <allowed>`` naming the argument, the value and what is allowed (never a
bare ValueError or TypeError, never a NaN carried into a result). A string as ``output_spacing`` gave
"could not convert string to float" in Crane.simulate and a TypeError in residual_grid."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from pendulab import InvalidInputError, crane
from pendulab.crane.plot import plot_sensitivity, plot_sway
from pendulab.validate import show

NAN, INF = math.nan, math.inf
# what no number argument takes; None only where it is not "not given"
REAL = ["1.0", True, 1j, np.array([1.0, 2.0]), NAN, INF, -INF]
ARRAY = ["1.0", None, True, 1j, NAN, INF, -INF]
INTEGER = ["8", None, True, 1j, NAN, INF, 8.5]

ZV = crane.shaper("zv", omega=1.0)
PROFILE = crane.profile(2.0, 0.5, 0.5)
MOVE = crane.move(2.0, 0.5, 0.5)
SAMPLED = crane.Sampled(np.arange(5.0), np.zeros((5, 3)))
HOIST = crane.Hoist([0.0, 1.0], [5.0, 4.0])
CRANE = crane.Crane(rope=5.0, pivot=MOVE)
HOOKED = crane.Crane(rope=5.0, hook_mass=100.0, rigging=2.0)
WIND = crane.Wind(velocity=(1.0, 0.0, 0.0))
LQR = crane.lqr(rope=5.0)
LQR_RUN = LQR.simulate(1.0, t_end=5.0)
RUN = CRANE.simulate(t_end=1.0, output_spacing=0.5)


def real(none: bool = False, negative: bool = True) -> list[Any]:
    """The bad values of a real number: ``none`` when None is not "not given", ``negative`` when no
    negative number is allowed."""
    return REAL + [None] * none + [-1.0] * negative


def array(negative: bool = False) -> list[Any]:
    return ARRAY + [-1.0] * negative


# (entry point, call(**kw), the valid arguments, {argument: bad values})
ENTRIES: list[tuple[str, Callable[..., Any], dict[str, Any], dict[str, list[Any]]]] = [
    (
        "shaper",
        crane.shaper,
        {"kind": "ei", "omega": 1.0, "damping": 0.0, "tolerance": 0.05},
        {"omega": real(True), "damping": real(True), "tolerance": real(True)},
    ),
    (
        "residual_vibration",
        crane.residual_vibration,
        {"s": ZV, "omega": [0.5, 1.0], "damping": 0.0},
        {"omega": array(True), "damping": real(True)},
    ),
    (
        "insensitivity",
        crane.insensitivity,
        {"s": crane.shaper("zvd", 1.0), "level": 0.05, "damping": 0.0},
        {"level": real(True), "damping": real(True)},
    ),
    (
        "profile",
        crane.profile,
        {"distance": 2.0, "v_max": 0.5, "a_max": 0.5, "j_max": 1.0, "t_start": 0.0, "start": 0.0},
        {
            "distance": real(True, False),
            "v_max": real(True),
            "a_max": real(True),
            "j_max": real(),
            "t_start": real(True, False),
            "start": real(True, False),
        },
    ),
    (
        "move",
        crane.move,
        {"distance": 2.0, "v_max": 0.5, "a_max": 0.5, "direction": (1, 0, 0), "origin": (0, 0, 0)},
        {"distance": real(True, False), "v_max": real(True), "direction": array(), "origin": array()},
    ),
    (
        "Gantry",
        crane.Gantry,
        {"trolley": PROFILE, "origin": (0, 0, 0), "trolley_axis": (1, 0, 0), "bridge_axis": (0, 1, 0)},
        {"origin": array(), "trolley_axis": array(), "bridge_axis": array()},
    ),
    (
        "Tower",
        crane.Tower,
        {"slew": 0.5, "radius": 10.0, "height": 20.0},
        {"slew": real(True, False), "radius": real(False, False), "height": real(True, False)},
    ),
    (
        "Tower(luff)",
        crane.Tower,
        {"slew": 0.5, "height": 20.0, "luff": 0.3, "boom": 30.0},
        {"luff": real(False, False), "boom": real()},
    ),
    (
        "Sampled",
        crane.Sampled,
        {"times": np.arange(5.0), "positions": np.zeros((5, 3))},
        {"times": array(), "positions": array()},
    ),
    ("Hoist", crane.Hoist, {"t": [0.0, 1.0], "length": [5.0, 4.0]}, {"t": array(), "length": array(True)}),
    ("Hoist.length", HOIST.length, {"t": 0.5}, {"t": array()}),
    ("Path.position", MOVE.position, {"t": 0.5}, {"t": array()}),
    ("Path.velocity", MOVE.velocity, {"t": 0.5}, {"t": array()}),
    ("Path.acceleration", MOVE.acceleration, {"t": 0.5}, {"t": array()}),
    ("Sampled.position", SAMPLED.position, {"t": 0.5}, {"t": array()}),
    ("Profile.position", PROFILE.position, {"t": 0.5}, {"t": array()}),
    ("Profile.velocity", PROFILE.velocity, {"t": 0.5}, {"t": array()}),
    ("Profile.acceleration", PROFILE.acceleration, {"t": 0.5}, {"t": array()}),
    (
        "Path.knots",
        MOVE.knots,
        {"t0": 0.0, "t1": 5.0, "spacing": 0.05},
        {"t0": real(True, False), "t1": real(True), "spacing": real()},
    ),
    ("Path.knots(dt=)", MOVE.knots, {"t0": 0.0, "t1": 5.0}, {"dt": real()}),
    ("Sampled.knots", SAMPLED.knots, {"t0": 0.0, "t1": 4.0}, {"t0": real(True, False), "t1": real(True)}),
    (
        "Path.pivot_samples",
        MOVE.pivot_samples,
        {"t_end": 5.0, "spacing": 0.1, "t_start": 0.0},
        {"t_end": real(True), "spacing": real(), "t_start": real(True, False)},
    ),
    ("Path.pivot_samples(dt=)", MOVE.pivot_samples, {"t_end": 5.0}, {"dt": real()}),
    (
        "Wind",
        crane.Wind,
        {},
        {
            "velocity": array(),
            "gust": array(),
            "area": real(True),
            "drag_coefficient": real(True),
            "air_density": real(True),
            "gust_start": real(True, False),
            "gust_duration": real(True),
            "hook_area": real(True),
            "hook_drag_coefficient": real(True),
            "turbulence": real(True),
            "turbulence_scale": real(True),
            "turbulence_modes": [*INTEGER, -64],
            "seed": [*INTEGER, -1],
        },
    ),
    ("Wind.force", WIND.force, {"relative_speed": 2.0}, {"relative_speed": real(True, False)}),
    ("Wind.velocity_at", WIND.velocity_at, {"t": 0.5}, {"t": array()}),
    (
        "Crane",
        crane.Crane,
        {"rope": 5.0, "payload_mass": 1000.0, "hook_mass": 100.0, "rigging": 2.0, "damping": 0.0, "g": 9.81},
        {
            "rope": real(True),
            "payload_mass": real(True),
            "hook_mass": real(),
            "rigging": real(),
            "damping": real(True),
            "g": real(True, False),
        },
    ),
    ("Crane.modes", HOOKED.modes, {"rope": 5.0}, {"rope": real()}),
    (
        "Crane.simulate",
        CRANE.simulate,
        {"t_end": 1.0, "sway": (0.1, 0.0), "rigging_sway": None, "output_spacing": 0.5, "t_start": 0.0},
        {
            "t_end": real(True),
            "sway": array(),
            "rigging_sway": ["1.0", True, 1j, NAN, INF],
            "output_spacing": real(),
            "t_start": real(True, False),
            "rtol": real(True),
            "atol": real(True),
        },
    ),
    ("Crane.simulate(dt=)", CRANE.simulate, {"t_end": 1.0}, {"dt": real()}),
    (
        "residual_grid",
        crane.residual_grid,
        {"ropes": [4.0], "ratios": [2.0], "shapers": [None], "settle": 3.0, "output_spacing": 0.5},
        {
            "ropes": array(True),
            "ratios": array(True),
            "distance": real(True, False),
            "v_max": real(True),
            "a_max": real(True),
            "j_max": real(),
            "hook_mass": real(True),
            "rigging": real(True),
            "g": real(True, False),
            "settle": real(True),
            "output_spacing": real(),
            "rtol": real(True),
            "atol": real(True),
            "workers": [*INTEGER, -1],
            "progress": ["yes", 1, NAN],
        },
    ),
    (
        "residual_grid(dt=)",
        crane.residual_grid,
        {"ropes": [4.0], "ratios": [2.0], "shapers": [None]},
        {"dt": real()},
    ),
    (
        "lqr",
        crane.lqr,
        {"rope": 5.0, "g": 9.81, "q": (1, 1, 10, 1), "r": 1.0, "a_max": 2.0},
        {
            "rope": real(True),
            "g": real(True),
            "q": array(True),
            "r": real(True),
            "a_max": [*REAL[:-2], None, -1.0, -INF],
        },
    ),
    (
        "LQR.simulate",
        LQR.simulate,
        {"distance": 1.0, "t_end": 5.0, "t_start": 0.0, "sway": 0.0},
        {
            "distance": real(True, False),
            "t_end": real(True),
            "t_start": real(True, False),
            "sway": real(True, False),
            "progress": ["yes", 1, NAN],
        },
    ),
    ("LQR.control", LQR.control, {"z": np.zeros(4)}, {"z": array()}),
    ("LQRRun.trolley", LQR_RUN.trolley, {"t": 1.0}, {"t": array()}),
    ("LQRRun.sway", LQR_RUN.sway, {"t": 1.0}, {"t": array()}),
    (
        "rope_range",
        crane.rope_range,
        {"rope_min": 2.0, "rope_max": 8.0, "g": 9.81},
        {"rope_min": real(True), "rope_max": real(True), "g": real(True)},
    ),
    (
        "shaper_for_range",
        crane.shaper_for_range,
        {"omega_min": 1.0, "omega_max": 1.2, "tolerance": 0.05, "ei_tolerance": 0.05},
        {
            "omega_min": real(True),
            "omega_max": real(True),
            "tolerance": real(True),
            "ei_tolerance": real(True),
        },
    ),
    (
        "worst_vibration",
        crane.worst_vibration,
        {"s": ZV, "omega_min": 0.9, "omega_max": 1.1, "damping": 0.0},
        {"omega_min": real(True), "omega_max": real(True), "damping": real(True)},
    ),
    (
        "plot_sensitivity",
        plot_sensitivity,
        {"shapers": [ZV], "ratio": (0.0, 2.0), "damping": 0.0, "tolerance": 0.05},
        {"ratio": array(), "damping": real(True), "tolerance": real()},
    ),
    ("plot_sway", plot_sway, {"runs": {"a": RUN}, "t_marks": [0.5]}, {"t_marks": array()}),
]
CASES = [
    pytest.param(call, base, arg, bad, id=f"{entry}-{arg}-{show(bad)}")
    for entry, call, base, args in ENTRIES
    for arg, bads in args.items()
    for bad in bads
]


def _call(call: Callable[..., Any], kw: dict[str, Any]) -> Any:
    if "dt" in kw:  # the deprecated name warns first (warnings are errors)
        with pytest.warns(DeprecationWarning, match="dt is the older name"):
            return call(**kw)
    return call(**kw)


@pytest.mark.parametrize(("call", "base", "arg", "bad"), CASES)
def test_a_bad_number_is_refused_naming_it(call: Callable[..., Any], base: dict, arg: str, bad: Any) -> None:
    with pytest.raises(InvalidInputError) as caught:
        _call(call, {**base, arg: bad})
    name = f"wind.{arg}" if call is crane.Wind else arg
    shown = re.escape(show(bad))
    # an array's entry is named with its index; what is allowed follows the colon
    assert re.match(
        rf"^invalid {re.escape(name)}(\[\d+\])* = ({shown}|.*{shown}.*): \S", str(caught.value)
    ), str(caught.value)


@pytest.mark.parametrize(("entry", "call", "base"), [pytest.param(*e[:3], id=e[0]) for e in ENTRIES])
def test_the_valid_arguments_are_taken(entry: str, call: Callable[..., Any], base: dict) -> None:
    """The cases above differ from a call that works in the one bad argument only."""
    _call(call, base)
