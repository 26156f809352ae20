"""``pendulab fit``: the pendulum that best explains measured data (docs/fit.md). Reads a CSV file,
prints the report (parameters ± standard errors, what the data do not determine, χ²), writes the fitted
scenario (TOML, which ``pendulab run`` and the lab accept) and optionally a figure. SI units; exit code
0 on success, 2 on a user error (one ``error: …`` line), 130 on Ctrl-C.

``--sigma`` is the noise of one measured value in its kind's SI unit: one number for every kind, or
``KIND=VALUE`` per kind (repeatable): positions, horizontal [m]; angles, planar_angle (or angle)
[rad]; specific_force [m/s²]; angular_speed [rad/s].

``--time-limit`` bounds the whole fit, as pl.fit's ``time_limit`` [s]: a number of seconds, or
``none`` (the default: no limit)."""

from __future__ import annotations

import contextlib
import math
import warnings
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer

from .._core import InvalidInputError
from ..fitting import fit
from ..fitting.problem import FITTABLE_MODELS, model_params
from ..fitting.table import read_table_notes
from ..model import Pendulum
from ..model.registry import not_of_model, refused
from ..variants.spring import SwingingSpring
from .common import _as_typed, _check_image, _fail, _say, _user_errors, app

SIGMA_KINDS = {
    "positions": "positions",
    "horizontal": "horizontal",
    "angles": "angles",
    "planar_angle": "planar_angle",
    "angle": "planar_angle",
    "specific_force": "specific_force",
    "f": "specific_force",
    "angular_speed": "angular_speed",
    "w": "angular_speed",
}
"""``--sigma KIND=VALUE``: the names of the data kinds (and the column names that stand for them)."""


def _sigma(items: list[str] | None, kinds: list[str]) -> float | dict[str, float] | None:
    """``--sigma`` as pl.fit takes it: None, one number, or kind → number (each positive, finite)."""
    if not items:
        return None
    if len(items) == 1 and "=" not in items[0]:
        return _positive(items[0], "--sigma")
    out: dict[str, float] = {}
    for item in items:
        name, sep, text = item.partition("=")
        kind = SIGMA_KINDS.get(name.strip().lower())
        if not sep or kind is None:
            _fail(
                f"--sigma {item[:60]!r}: give one number, or KIND=VALUE per kind with KIND one of "
                f"{', '.join(SIGMA_KINDS)}"
            )
        if kind not in kinds:
            _fail(f"--sigma {item[:60]!r}: the file has no {kind} data (it has {', '.join(kinds)})")
        if kind in out:
            _fail(f"--sigma: {kind} given twice")
        out[kind] = _positive(text, f"--sigma {name.strip()}")
    return out


def _positive(text: str, what: str) -> float:
    value = _number(text, what)
    if not value > 0.0 or value < 1e-100 or value > 1e100:
        _fail(f"{what}: {text.strip()[:40]!r} must be a positive number in [1e-100, 1e100] (SI units)")
    return value


@contextlib.contextmanager
def _numeric_failures() -> Iterator[None]:
    """A numerical failure inside the fit (LAPACK's SVD, an overflow) as one ``error:`` line naming
    it and what to try, not a traceback: the data reached the fit but it cannot work with them."""
    try:
        yield
    except (np.linalg.LinAlgError, ZeroDivisionError, OverflowError, FloatingPointError) as e:
        _fail(
            f"the fit failed on these data ({type(e).__name__}: {' '.join(str(e).split())[:120]}); check "
            "that they show a swing (not a bob at rest, constant or pure noise), try fewer unknowns "
            "(--fit) or give --sigma"
        )


def _number(text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        _fail(f"{what}: {text[:40]!r} is not a number")
    if not math.isfinite(value):
        _fail(f"{what}: {text!r} must be finite")
    return value


def _time_limit(text: str) -> float | None:
    """``--time-limit`` as pl.fit takes it: None for ``none``, else seconds in (0, 1e9)."""
    if text.strip().lower() == "none":
        return None
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not 0.0 < value < 1e9:
        _fail(f"--time-limit {text[:40]!r}: give a number of seconds > 0 and < 1e9, or none for no limit")
    return value


def _need_scipy() -> None:
    """pl.fit's least_squares: SciPy is an extra (``fit``, ``lab``), not a base dependency."""
    try:
        import scipy.optimize  # noqa: F401
    except ImportError:
        _fail("pendulab fit needs SciPy: pip install 'pendulab[fit]' (or scipy>=1.11)")


class _AsTyped:
    """A ``--param`` value in a message as the user typed it (``1``, not ``1.0``; ``2e-3``, not
    ``0.002``); text that is not a number quoted."""

    def __init__(self, text: str) -> None:
        self.text = text.strip()

    def __repr__(self) -> str:
        try:
            float(self.text)
        except ValueError:
            return repr(self.text[:60])
        return self.text[:60]


def _params(
    model: str, own: Mapping[str, Mapping[str, Any]], items: list[str]
) -> tuple[dict[str, float], dict[str, str]]:
    """The values of ``--param NAME=VALUE`` by name (floats, for the fit) and their texts as typed (for
    the messages and the report); unknown names all refused at once, in the words of ``pl.Pendulum``
    (each with its did-you-mean, then the model's parameters ``own``), a value outside its parameter's
    range refused naming the value as typed and the range (SI units)."""
    values: dict[str, float] = {}
    typed: dict[str, str] = {}
    unknown: dict[str, object] = {}
    for item in items:
        name, sep, text = item.partition("=")
        name = name.strip()
        if not sep:
            _fail(f"--param {item!r}: give NAME=VALUE with NAME one of {', '.join(own)}")
        if name not in own:
            unknown[name] = _AsTyped(text)
            continue
        spec = own[name]
        why = "not a number"
        try:
            value = float(text)
            why = "out of range" if math.isfinite(value) else "not a finite number"
        except ValueError:
            value = math.nan
        if not spec["min"] <= value <= spec["max"]:
            shown = f"{name}={text.strip()[:40]}"
            _fail(f"--param {shown}: {why}; allowed: {spec['allowed']} ({spec['label']})")
        values[name], typed[name] = value, text.strip()
    if unknown:
        _fail(f"--param: {refused(unknown, not_of_model(model, list(unknown), list(own)))}")
    return values, typed


def _typed_in_report(report: str, typed: Mapping[str, str]) -> str:
    """The report with the held values given by ``--param`` shown as typed on its ``fixed:`` line
    (``length = 1.50 m``, not ``length = 1.5 m``); the fit computed with the parsed numbers."""
    lines = report.split("\n")
    for i, line in enumerate(lines):
        if line.startswith("  fixed: "):
            entries = line.removeprefix("  fixed: ").split(", ")
            for j, entry in enumerate(entries):
                name, sep, rest = entry.partition(" = ")
                if sep and name in typed:
                    unit = rest.partition(" ")[2]
                    entries[j] = f"{name} = {typed[name]}" + (f" {unit}" if unit else "")
            lines[i] = "  fixed: " + ", ".join(entries)
    return "\n".join(lines)


@app.command("fit", short_help="Fit length, g, damping and the start to measured data (CSV).")
def fit_cmd(
    data: Annotated[  # str, not Path: the messages name the file as typed (./x.csv, not x.csv)
        str,
        typer.Argument(
            metavar="DATA",
            help="CSV file of measurements (SI units), or a shipped data set: example:filmed_swing.",
        ),
    ],
    model: Annotated[str, typer.Option(help=f"Model: {', '.join(FITTABLE_MODELS)}.")] = "ideal",
    fit_names: Annotated[
        str, typer.Option("--fit", help="Parameters to fit, comma separated (e.g. length,g,damping,pivot).")
    ] = "length,g",
    columns: Annotated[
        str | None,
        typer.Option(help="The file's column names in order (e.g. t,x,y,z); default its header row."),
    ] = None,
    sigma: Annotated[
        list[str] | None,
        typer.Option(
            metavar="VALUE|KIND=VALUE",
            help="Noise of one measured value (SI): a number, or KIND=VALUE per data kind (repeatable, "
            "e.g. positions=0.002, angle=0.01); default: from the residual.",
        ),
    ] = None,
    param: Annotated[
        list[str] | None,
        typer.Option(
            "--param",
            metavar="NAME=VALUE",
            help="Start or fixed value of a model parameter, NAME=VALUE (SI), repeatable.",
        ),
    ] = None,
    pivot: Annotated[
        str | None,
        typer.Option(metavar="X,Y,Z", help="Known pivot position in the data's frame, x,y,z in m."),
    ] = None,
    loss: Annotated[
        str, typer.Option(help="linear, or a robust loss: soft_l1, huber, cauchy, arctan.")
    ] = "linear",
    out: Annotated[  # str, not Path: the messages name the files as typed (./fit.toml, not fit.toml)
        str | None, typer.Option("--out", "-o", metavar="FILE", help="Write the fitted scenario (TOML) here.")
    ] = None,
    plot: Annotated[
        str | None,
        typer.Option(metavar="FILE", help="Save the data-and-fit figure here (.png, .svg, .pdf)."),
    ] = None,
    time_limit: Annotated[
        str,
        typer.Option(
            "--time-limit",
            metavar="SECONDS",
            help="Bound the whole fit (checking the data, search, error bars) to this many seconds, or none.",
        ),
    ] = "none",
) -> None:
    """Fit a pendulum to measured data and print the report. Column names: t [s]; x, y, z [m] (or x, z
    seen along y, or x, y seen from above); theta, phi [rad]; angle [rad] (a planar swing);
    specific_force [m/s^2]; angular_speed [rad/s]. Exports of Tracker, Logger Pro, phyphox, Cassy and
    Excel are read as they are (docs/fit.md)."""
    with _user_errors():
        _need_scipy()
        limit = _time_limit(time_limit)
        if out is not None and Path(out).suffix.lower() != ".toml":
            _fail(f"--out {out!r}: the fitted scenario is written as TOML; give a name ending in .toml")
        if out is not None and not Path(out).resolve().parent.is_dir():  # checked before the fit, as --plot
            folder = str(Path(out).resolve().parent)
            _fail(f"--out {out!r}: the directory {folder!r} does not exist; create it first")
        if plot is not None:
            _check_image("--plot", plot)
        if model not in FITTABLE_MODELS:
            raise InvalidInputError(f"--model {model!r}: use one of {', '.join(FITTABLE_MODELS)}")
        own = model_params(model)
        values, typed = _params(model, own, param or [])
        base = {k: values.pop(k) for k in ("length", "g", "mass") if k in values}
        pendulum: Pendulum | SwingingSpring
        if model == "spring":  # length: the rest length l0; stiffness k [N/m]
            full = {n: float(spec["default"]) for n, spec in own.items()} | base | values
            k_over_m = full["stiffness"] / full["mass"]
            pendulum = SwingingSpring(k_over_m, full["length"], full["g"], full["mass"])
        else:
            # **base (l, g, m) and **values (own parameters): floats by name, no model/force/pivot_samples
            pendulum = Pendulum(**base, model=model, **values)  # type: ignore[arg-type]
        names = [c.strip() for c in columns.split(",")] if columns else None
        kwargs, notes = read_table_notes(_as_typed(data, "data"), names)
        for note in notes:
            _say(f"data: {note}", err=True)
        kinds = [k for k in kwargs if k != "t"]
        sigmas = _sigma(sigma, kinds)
        where = None
        if pivot is not None:
            parts = pivot.split(",")
            if len(parts) != 3:
                _fail(f"--pivot {pivot!r}: give x,y,z in m")
            where = [_number(c, "--pivot") for c in parts]
        with warnings.catch_warnings(record=True) as caught, _numeric_failures():
            warnings.simplefilter("always")
            res = fit(
                pendulum=pendulum,
                fit=fit_names,
                sigma=sigmas,
                loss=loss,
                pivot=where,
                progress=None,
                time_limit=limit,
                **kwargs,
            )
        for w in caught:
            _say(f"warning: {w.message}", err=True)
        _say(_typed_in_report(res.report(), typed))
        if out is not None:
            res.save(out)
            _say(f"wrote {out}")
        if plot is not None:
            res.plot(plot)
            _say(f"wrote {plot}")
