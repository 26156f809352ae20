"""A trajectory as tables: its columns with SI units (what the CSV, Parquet and NetCDF writers of
:mod:`pendulab.io` take), the metadata every output file carries, and the ``xarray.Dataset``.

Columns: ``t`` [s], ``x``, ``y``, ``z`` [m], ``vx``, ``vy``, ``vz`` [m/s], ``energy`` [J] and ``j3``
[kg m²/s] (T-2.6), ``tension`` [N] (T-2.3), ``constraint_error`` (|x| − l)/l [1], ``tangency`` x·v
[m²/s]; for the real-pendulum models (docs/theory.md §7) ``power`` [W] and ``power_balance_residual``
[J] (T-7.1), a moving pivot's ``pivot_x/y/z`` [m], the slewing crane's ``boom_*`` [m], the string's
``taut`` and ``energy_lost`` [J], and the error estimates ``err_x*`` [m], ``err_v*`` [m/s].

The functions take a finished :class:`pendulab.Trajectory` (duck-typed, as :mod:`pendulab.overview`
does: this module sits below the class, which calls it).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from .. import io
from ..model import Pendulum, models

UNITS = {
    "t": "s",
    "x": "m",
    "v": "m/s",
    "energy": "J",
    "j3": "kg m^2/s",
    "tension": "N",
    "radius_error": "m",
    "constraint_error": "1",
    "tangency": "m^2/s",
    "power": "W",
    "power_balance_residual": "J",
    "pivot": "m",
    "boom": "m",
    "taut": "1",
    "err_x_est": "m",
    "err_v_est": "m/s",
    "err_x": "m",
    "err_v": "m/s",
}


def param_units(pendulum: Pendulum) -> dict[str, str]:
    """Units of the pendulum's parameters: length, mass, g and the model's own (registry)."""
    spec = next(m for m in models() if m["name"] == pendulum.model)
    return {p["name"]: p["unit"] for p in spec["params"]}


def event_records(events: dict[str, Any] | None) -> list[dict[str, Any]]:
    """The string model's events as JSON-ready records (t [s], kind, energy_lost [J])."""
    ev = events or {}
    return [
        {"t": float(t), "kind": str(k), "energy_lost": float(e)}
        for t, k, e in zip(ev.get("t", []), ev.get("kind", []), ev.get("energy_lost", []), strict=True)
    ]


def metadata(tr: Any) -> dict[str, Any]:
    """Parameters, method, options, counters and units (what every output file carries)."""
    return {
        "software": "pendulab",
        "pendulum": tr.pendulum.params(),
        "method": tr.method,
        "options": tr.options,
        "stats": tr.stats,
        "interrupted": tr.interrupted,
        **({"events": event_records(tr.events)} if tr.events is not None else {}),
        **({"error_estimate": tr.error_estimate.describe()} if tr.error_estimate else {}),
        **({"error": tr.error.describe()} if tr.error else {}),
        "units": UNITS | param_units(tr.pendulum),
        "conventions": "SI units, z up, gravity along -z for g > 0, theta from the downward vertical",
    }


def columns(tr: Any) -> dict[str, tuple[str, npt.NDArray[np.float64]]]:
    """Flat columns name -> (unit, values) for tabular files. Models other than the ideal pendulum
    add ``power`` [W] and ``power_balance_residual`` [J], a moving pivot ``pivot_x/y/z`` [m]."""
    cols: dict[str, tuple[str, npt.NDArray[np.float64]]] = {"t": ("s", tr.t)}
    for k, axis in enumerate("xyz"):
        cols[axis] = ("m", tr.x[:, k])
    for k, axis in enumerate("xyz"):
        cols[f"v{axis}"] = ("m/s", tr.v[:, k])
    for name in ("energy", "j3", "tension", "constraint_error", "tangency"):
        cols[name] = (UNITS[name], getattr(tr, name))
    if not tr.pendulum.is_ideal and tr.taut is None:
        for name in ("power", "power_balance_residual"):
            cols[name] = (UNITS[name], getattr(tr, name))
    if tr.pivot is not None:
        for k, axis in enumerate("xyz"):
            cols[f"pivot_{axis}"] = ("m", tr.pivot[:, k])
    if tr.boom is not None:
        for k, axis in enumerate(("radial", "tangential", "vertical")):
            cols[f"boom_{axis}"] = ("m", tr.boom[:, k])
    if tr.taut is not None:
        cols["taut"] = ("1", tr.taut.astype(np.float64))
        cols["energy_lost"] = ("J", tr.energy_lost)
    for suffix, err in (("_est", tr.error_estimate), ("", tr.error)):
        if err is not None:
            cols[f"err_x{suffix}"] = ("m", err.position)
            cols[f"err_v{suffix}"] = ("m/s", err.velocity)
    return cols


def dataset(tr: Any) -> Any:
    """An ``xarray.Dataset`` with dims (time, axis), units as attributes, metadata in ``attrs``."""
    import json

    xr = io._require("xarray")
    extra: dict[str, Any] = {}
    if not tr.pendulum.is_ideal and tr.taut is None:
        power = {"units": "W", "long_name": "power of the non-conservative forces"}
        extra["power"] = ("time", tr.power, power)
        extra["power_balance_residual"] = (
            "time",
            tr.power_balance_residual,
            {"units": "J", "long_name": "E(t) - E(0) - integral of P dt (trapezoid)"},
        )
    if tr.pivot is not None:
        extra["pivot"] = (("time", "axis"), tr.pivot, {"units": "m", "long_name": "pivot position"})
    if tr.boom is not None:
        extra["boom"] = (("time", "axis"), tr.boom, {"units": "m", "long_name": "x in the boom frame"})
    if tr.taut is not None:
        extra["taut"] = ("time", tr.taut.astype(np.int8), {"units": "1", "long_name": "string taut"})
        extra["energy_lost"] = ("time", tr.energy_lost, {"units": "J", "long_name": "lost in snaps"})
    for suffix, err, what in (("_est", tr.error_estimate, "estimated"), ("", tr.error, "true")):
        if err is not None:
            extra[f"err_x{suffix}"] = (
                "time",
                err.position,
                {"units": "m", "long_name": f"{what} position error"},
            )
            extra[f"err_v{suffix}"] = (
                "time",
                err.velocity,
                {"units": "m/s", "long_name": f"{what} velocity error"},
            )
    ds = xr.Dataset(
        {
            "x": (("time", "axis"), tr.x, {"units": "m", "long_name": "bob position"}),
            "v": (("time", "axis"), tr.v, {"units": "m/s", "long_name": "bob velocity"}),
            "energy": ("time", tr.energy, {"units": "J"}),
            "j3": ("time", tr.j3, {"units": "kg m^2/s", "long_name": "vertical angular momentum"}),
            "tension": ("time", tr.tension, {"units": "N"}),
            "constraint_error": ("time", tr.constraint_error, {"units": "1", "long_name": "(|x|-l)/l"}),
            "tangency": ("time", tr.tangency, {"units": "m^2/s", "long_name": "x.v"}),
            **extra,
        },
        coords={"time": ("time", tr.t, {"units": "s"}), "axis": ["x", "y", "z"]},
        attrs={"pendulab": json.dumps(tr.metadata(), sort_keys=True)},
    )
    return ds
