"""The ``pendulab`` commands about scenario files and the registries: ``run`` (a scenario file: print
a summary, write the trajectory), ``validate``, ``scenarios``, ``methods``, ``models``.

Units are SI throughout: --dt and --t-end in s, --atol in m and m/s. Exit codes: 0 success; 2 a
user error (bad scenario file, option, output path), reported as one line ``error: …`` on stderr
without a traceback; 130 interrupted by Ctrl-C (``run`` still writes what was computed). The
commands and options are described in ``docs/cli.md``.
"""

from __future__ import annotations

import contextlib
import json
import math
import warnings
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from .._core import InvalidInputError
from ..integrators import methods as method_table
from ..model import models as model_table
from ..scenario import RunOverrides, Scenario, ScenarioError, load_scenario
from ..scenario.examples import scenario_files, sweep_files
from ..trajectory import Trajectory
from ..trajectory.report import nth
from ..variants.spring import SpringTrajectory
from .common import (
    EXIT_INTERRUPTED,
    EXIT_USER_ERROR,
    _check_output,
    _describe,
    _fail,
    _say,
    _scenario_file,
    _user_errors,
    app,
)
from .crane import report

if TYPE_CHECKING:
    from .._core import ModelInfo, ParamSpec


def _settings(sc: Scenario) -> str:
    sim = sc._pendulum_spec().simulation
    step = f"dt = {sim.dt:g} s" if sim.dt is not None else "dt = default"
    if sim.is_adaptive():
        rtol, atol = sim.resolved_tolerances()
        step = f"rtol = {rtol:g}, atol = {atol:g}" + (f", initial dt = {sim.dt:g} s" if sim.dt else "")
    elif sim.dt is None:
        step = f"dt = {sim.resolved_dt():g} s"
    n = sc.expected_samples()
    # an adaptive run without save_at: its steps, so the number of samples, are known only afterwards
    saved = f"{n} samples" if n is not None else f"every {nth(sim.save_every or 1)}accepted step"
    return f"{sim.method}, {step}, t = {sim.t0:g} .. {sim.t_end:g} s, saving {saved}"


@app.command(short_help="Run a scenario file; print a summary, write the trajectory.")
def run(
    scenario: Annotated[
        str,  # not Path: typer would normalise ./x.toml to x.toml, and the messages name it as typed
        typer.Argument(
            metavar="SCENARIO",
            help="Scenario file (TOML; see docs/scenarios.md) or the name of a shipped example "
            "(`pendulab scenarios`), e.g. rosette.",
            show_default=False,
        ),
    ],
    out: Annotated[
        str | None,  # not Path: the messages name the file as typed (./out.csv, not out.csv)
        typer.Option(
            "--out",
            "-o",
            metavar="FILE",
            help="Write the trajectory to this file; the format comes from the suffix: "
            ".csv, .parquet or .nc. Checked before the run.",
            show_default=False,
        ),
    ] = None,
    method: Annotated[
        str | None,
        typer.Option(
            help="Integrator (see `pendulab methods`); replaces the file's method.", show_default=False
        ),
    ] = None,
    dt: Annotated[
        float | None,
        typer.Option(
            help="Step size in s (> 0); replaces the file's dt (a crane file's output_spacing).",
            show_default=False,
        ),
    ] = None,
    t_end: Annotated[
        float | None,
        typer.Option("--t-end", help="End time in s; replaces the file's t_end.", show_default=False),
    ] = None,
    save_every: Annotated[
        int | None,
        typer.Option(
            "--save-every",
            help="Keep every N-th step (N >= 1) and the first and last state; replaces save_every/save_at.",
            show_default=False,
        ),
    ] = None,
    rtol: Annotated[
        float | None,
        typer.Option(help="Relative tolerance of adaptive methods (dop853).", show_default=False),
    ] = None,
    atol: Annotated[
        float | None,
        typer.Option(help="Absolute tolerance of adaptive methods, in m and m/s.", show_default=False),
    ] = None,
    progress: Annotated[
        bool | None,
        typer.Option(
            "--progress/--no-progress",
            help="Show a progress bar on stderr (default: only for runs of more than 5 million steps).",
            show_default=False,
        ),
    ] = None,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing but errors.")] = False,
) -> None:
    """Run a scenario: print a summary (energy, J3 and constraint errors) and optionally write the
    trajectory. Ctrl-C stops the run, writes what was computed and exits with code 130."""
    with _user_errors():
        if out is not None:
            _check_output(out)
        overrides = RunOverrides(
            method=method, dt=dt, t_end=t_end, save_every=save_every, rtol=rtol, atol=atol
        )
        sc = load_scenario(scenario).with_overrides(overrides)  # its messages name the file as typed
        if sc.is_crane:  # a [crane] file: the crane's run and report (pendulab crane run)
            if out is not None and Path(out).suffix.lower() != ".csv":
                _fail(f"--out {out!r}: crane runs are written as .csv")
            if not quiet:
                _say(f"running {scenario}" + (f": {sc.title}" if sc.title else ""), err=True)
            report(sc.crane(), str(scenario), out, quiet=quiet)
            return
        projection = sc.initial_state().projection
        if not quiet:
            _say(f"running {scenario}" + (f": {sc.title}" if sc.title else ""), err=True)
            _say(f"  {_settings(sc)}", err=True)
            if projection is not None:
                _say(
                    f"  projected the start onto TS²: moved x by {projection[0]:.3g} m, "
                    f"v by {projection[1]:.3g} m/s",
                    err=True,
                )
        with warnings.catch_warnings():
            # The interruption is reported below, from Trajectory.interrupted.
            warnings.filterwarnings("ignore", message="simulation interrupted", category=RuntimeWarning)
            tr = sc.run(progress=progress)
        assert isinstance(tr, Trajectory | SpringTrajectory), "a crane's file was reported above"
        if not quiet:
            _say(tr.summary())
        if out is not None:
            tr.save(out)
            if not quiet:
                _say(f"wrote {out} ({len(tr)} samples)")
    if tr.interrupted:
        written = (
            f"wrote the {len(tr)} samples computed so far to {out}" if out is not None else "nothing written"
        )
        _say(f"interrupted (Ctrl-C) at t = {tr.t[-1]:g} s; {written}", err=True)
        raise typer.Exit(EXIT_INTERRUPTED)


def _mark(flag: bool) -> str:
    return "yes" if flag else "-"


@app.command(short_help="List the integrators with order and properties.")
def methods(
    as_json: Annotated[
        bool, typer.Option("--json", help="Print the table as JSON (a list of objects).")
    ] = False,
) -> None:
    """List the integrators with their order and structural properties."""
    table = method_table()
    if as_json:
        _say(json.dumps(table, indent=2))
        return
    header = ("name", "order", "symplectic", "keeps TS2", "keeps J3", "adaptive", "dense", "summary")
    rows = [
        (
            m["name"] + (" (default)" if m["default"] else ""),
            str(m["order"]),
            _mark(m["symplectic"]),
            _mark(m["preserves_ts2"]),
            _mark(m["preserves_j3"]),
            _mark(m["adaptive"]),
            _mark(m["dense_output"]),
            m["summary"],
        )
        for m in table
    ]
    widths = [max(len(r[k]) for r in (header, *rows)) for k in range(len(header) - 1)]
    for r in (header, *rows):
        _say("  ".join(c.ljust(w) for c, w in zip(r, widths, strict=False)) + "  " + r[-1])


def _json_number(value: float) -> float | None:
    """JSON has no infinity: an unbounded limit is written as null."""
    return value if math.isfinite(value) else None


@app.command(short_help="List the models with their parameters, units, defaults and limits.")
def models(
    name: Annotated[
        str | None,
        typer.Argument(metavar="MODEL", help="Show only this model.", show_default=False),
    ] = None,
    as_json: Annotated[
        bool, typer.Option("--json", help="Print the registry as JSON (a list of objects; no limit: null).")
    ] = False,
) -> None:
    """List the pendulum models (docs/theory.md §7) and their parameters: SI unit, default, allowed values
    and meaning, as scenario files (keys of [pendulum]) and pendulab.Pendulum(model=..., **params)
    take them. Every model has length [m], mass [kg] and g [m/s^2]."""
    with _user_errors():
        table = model_table()
        if name is not None:
            table = [m for m in table if m["name"] == name]
            if not table:
                names = ", ".join(m["name"] for m in model_table())
                raise InvalidInputError(f"unknown model {name!r}; available: {names}")
    if as_json:
        plain = [
            {
                **m,
                "params": [
                    {**p, "min": _json_number(p["min"]), "max": _json_number(p["max"])} for p in m["params"]
                ],
            }
            for m in table
        ]
        _say(json.dumps(plain, indent=2, ensure_ascii=False, allow_nan=False))
        return
    common = ("length", "mass", "g")
    if name is None:
        shared = [p for p in table[0]["params"] if p["name"] in common]
        _say(
            "every model: "
            + ", ".join(f"{p['name']} [{p['unit']}] (default {p['default']:g})" for p in shared)
        )
    for i, m in enumerate(table):
        if name is None or i > 0:
            _say("")
        batch = (
            ""
            if m.get("interactive", True)
            else "  [own stepper: pendulab run and the lab]"
            if m["name"] in ("spring", "string")
            else "  [not interactive (no live stepper): pendulab run]"
        )
        _say(f"{m['name']}: {m['label']} — {m['summary']}{batch}")
        own = [p for p in m["params"] if name is not None or p["name"] not in common or _own_sense(p, table)]
        if not own:
            _say("    (no parameters of its own)")
        rows = [(p["name"], f"[{p['unit']}]", f"default {p['default']:g}", p) for p in own]
        widths = [max((len(r[k]) for r in rows), default=0) for k in range(3)]
        for *cells, p in rows:
            head = "  ".join(c.ljust(w) for c, w in zip(cells, widths, strict=True))
            _say(f"    {head}  {p['label']}: {p['description']}; {p['allowed']}")
    degrees = [f"{p['name']}_deg" for m in table for p in m["params"] if p["unit"] == "rad"]
    if degrees:
        _say("")
        _say(f"Scenario files take an angle in rad also in degrees as <name>_deg ({', '.join(degrees)}).")


def _own_sense(param: ParamSpec, table: list[ModelInfo]) -> bool:
    """True when a shared parameter means something else in this model (the spring's length is its
    rest length l₀): listed with the model's own then."""
    first = next(p for p in table[0]["params"] if p["name"] == param["name"])
    return param["description"] != first["description"]


@app.command(short_help="Check scenario files without running them.")
def validate(
    scenarios: Annotated[
        list[str],  # not Path: the messages name each file as typed (./x.toml, not x.toml)
        typer.Argument(
            metavar="SCENARIO",
            help="Scenario files (TOML) or names of shipped examples to check.",
            show_default=False,
        ),
    ],
) -> None:
    """Check scenario files without running them: print OK or every problem; exit code 2 if any is bad."""
    bad = 0
    for path in scenarios:
        try:
            sc = load_scenario(_scenario_file(path))
        except ScenarioError as e:
            bad += 1
            for problem in e.problems:
                _say(f"error: {e.location}: {problem}", err=True)
        except OSError as e:
            bad += 1
            _say(f"error: {_describe(e)}", err=True)
        else:
            _say(f"{path}: OK" + (f" ({sc.title})" if sc.title else ""))
    if bad:
        raise typer.Exit(EXIT_USER_ERROR)


@app.command(short_help="List the example scenarios and sweeps shipped with the package.")
def scenarios() -> None:
    """List the example scenarios (run one by name: `pendulab run rosette`) and sweeps (`pendulab sweep
    rotation_number`) shipped inside the package, with their titles and files."""
    files = scenario_files()
    if not files:
        _fail("no example scenarios found: the package's examples/ folder is missing (a broken install?)")
    width = max(map(len, [*files, *sweep_files()]))
    for name, path in files.items():
        try:
            title = load_scenario(path).title or ""
        except (ScenarioError, OSError) as e:
            title = f"INVALID: {_describe(e)}"
        _say(f"{name.ljust(width)}  {title}  ({_display(path)})")
    sweeps = sweep_files()
    if sweeps:
        _say("")
        _say("Example sweeps (pendulab sweep NAME --out FILE.parquet):")
        for name, path in sweeps.items():
            _say(f"{name.ljust(width)}  {_sweep_title(path)}  ({_display(path)})")


def _sweep_title(path: Path) -> str:
    """The first line of a sweep file's leading comment (sweep files have no title key)."""
    with contextlib.suppress(OSError, UnicodeDecodeError):
        for line in path.read_text(encoding="utf-8").splitlines():
            if line.startswith("#"):
                return line.lstrip("# ").split(":")[0].strip()
            if line.strip():
                break
    return ""


def _display(path: Path) -> str:
    with contextlib.suppress(ValueError):
        return str(path.relative_to(Path.cwd()))
    return str(path)
