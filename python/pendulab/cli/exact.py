"""The ``pendulab`` commands of the exact solution (docs/theory.md §3–6): ``exact``, ``phases``, ``em-map``,
``reduced``, and ``plot`` (a scenario's path on the sphere, its top view, or its phase split).
Registered on :data:`pendulab.cli.app`; same conventions: SI units (times in s, E in J,
J₃ in kg m²/s, angles in rad), exit code 0 on success, 2 on a user error (one ``error: …`` line),
130 on Ctrl-C. Described in ``docs/cli.md`` and ``docs/exact.md``.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from .._core import InvalidInputError
from ..scenario import Scenario, load_scenario
from ..simulation import simulate
from ..theory.advance import measured_azimuth_advance
from ..theory.em_map import em_map
from ..theory.exact import ExactSolution, exact
from ..trajectory import Trajectory
from ..validate import show
from .common import (
    IMAGE_SUFFIXES,
    _check_image,
    _check_output,
    _fail,
    _say,
    _scenario_file,
    _user_errors,
    app,
)

MAX_TIMES = 20_000_000
"""Most times ``pendulab exact --t`` accepts (~1 GB of states)."""

PLOT_KINDS = ("both", "sphere", "top", "phases")
"""What ``pendulab plot --kind`` draws."""

PLOT_SAMPLES_PER_PERIOD = 400
"""Exact states per z-period that ``pendulab plot --exact`` draws (at least 2001, at most 200001)."""

_SCENARIO = typer.Argument(
    metavar="SCENARIO",
    help="Scenario file (TOML; see docs/scenarios.md) or the name of a shipped example (rosette, ...).",
    show_default=False,
)
_IMAGE_OUT = typer.Option(  # taken as str, not Path: the messages name the file as typed (./a.png)
    "--out", "-o", metavar="FILE", help="Image file (.png, .svg, .pdf).", show_default=False
)


def parse_times(spec: str) -> np.ndarray:
    """Times [s] from ``START:STOP:STEP``: START, START + STEP, … up to STOP (included when it is on the
    grid to 1e-9 of a step). STEP may be negative for STOP < START; a single number T means just t = T."""
    parts = spec.split(":")
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise InvalidInputError(f"--t {show(spec)}: expected START:STOP:STEP in s, e.g. 0:100:0.01") from None
    if len(values) == 1:
        values = [values[0], values[0], 1.0]
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        raise InvalidInputError(f"--t {show(spec)}: expected three finite numbers START:STOP:STEP in s")
    start, stop, step = values
    if step == 0.0 or (stop - start) * step < 0.0:
        raise InvalidInputError(
            f"--t {show(spec)}: STEP = {step:g} s must be non-zero and lead from START = {start:g} "
            f"to STOP = {stop:g}"
        )
    span = (stop - start) / step  # may overflow to inf: compared before it is rounded
    if not span < MAX_TIMES:
        raise InvalidInputError(
            f"--t {show(spec)} gives {span + 1:.3g} times; at most {MAX_TIMES} (use a larger STEP)"
        )
    n = math.floor(span + 1e-9) + 1
    return start + step * np.arange(n, dtype=np.float64)


def _solution(sc: Scenario) -> ExactSolution:
    return exact(sc.pendulum(), sc.initial_state())


@app.command(
    "exact", short_help="The exact solution of a scenario: summary; states at given times to a file."
)
def exact_cmd(
    scenario: Annotated[str, _SCENARIO],
    t: Annotated[
        str | None,
        typer.Option(
            "--t",
            metavar="START:STOP:STEP",
            help="Times in s (default: the scenario's t0 .. t_end in 1000 steps). Any t costs the same.",
            show_default=False,
        ),
    ] = None,
    out: Annotated[
        str | None,  # not Path: the messages name the file as typed (./out.csv, not out.csv)
        typer.Option(
            "--out",
            "-o",
            metavar="FILE",
            help="Write the states to this file (.csv, .parquet or .nc).",
            show_default=False,
        ),
    ] = None,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing but errors.")] = False,
) -> None:
    """The exact solution through the scenario's start (docs/theory.md §4): print the kind of motion, turning
    heights [m], z-period [s] and azimuthal advance per z-period [rad]; write the states at the times
    --t to --out. The scenario's [simulation] settings are not used (except t0, t_end for the default)."""
    with _user_errors():
        if out is not None:
            _check_output(out)
        sc = load_scenario(_scenario_file(scenario))
        if t is None:
            sim = sc._pendulum_spec().simulation
            times = np.linspace(sim.t0, sim.t_end, 1001)
        else:
            times = parse_times(t)
        sol = _solution(sc)
        tr = sol.trajectory(times)
        if not quiet:
            _say(f"exact solution of {scenario}" + (f": {sc.title}" if sc.title else ""))
            _say(sol.summary())
            _say(f"span:     t = {times[0]:g} .. {times[-1]:g} s, {len(times)} times")
        if out is not None:
            tr.save(out)
            if not quiet:
                _say(f"wrote {out} ({len(tr)} samples)")


@app.command(short_help="Azimuthal advance per z-period: exact, its dynamic/geometric split, measured.")
def phases(
    scenario: Annotated[str, _SCENARIO],
    periods: Annotated[
        int, typer.Option(min=1, max=10_000, help="z-periods of the RATTLE8 run that measures the advance.")
    ] = 5,
    dt: Annotated[
        float | None,
        typer.Option(
            help="RATTLE8 step in s (default: the smaller of 2e-3 s and T_z/500).", show_default=False
        ),
    ] = None,
    plot: Annotated[
        str | None,  # named as typed, as --out
        typer.Option(
            "--plot",
            metavar="FILE",
            help="Also draw the split and the reduced orbit to this image (.png, .svg, .pdf).",
            show_default=False,
        ),
    ] = None,
) -> None:
    """Δφ per z-period from T-4.5, its dynamic and geometric parts (T-5.1), their sum and the difference,
    and Δφ measured from a RATTLE8 simulation of a few z-periods (between upward crossings of the mid
    height, located by interpolation; see pendulab.theory.advance). --plot draws the split as bars and the
    reduced orbit in the (z, p_z) plane with its area shaded.
    Needs an orbit with J3 != 0 (kind generic or conical)."""
    with _user_errors():
        if plot is not None:
            _check_image("--plot", plot)
        if dt is not None and not (math.isfinite(dt) and dt > 0.0):
            _fail(f"--dt {dt!r} must be a finite step > 0 s")
        sc = load_scenario(_scenario_file(scenario))
        sol = _solution(sc)
        ph = sol.phases()
        tz = sol.period_z
        _say(f"phases of {scenario}" + (f": {sc.title}" if sc.title else "") + f"  (kind {sol.kind})")
        _row("z-period T_z", f"{tz:.15g} s")
        _row("rotation number W = dphi/2pi", f"{ph.total / (2 * math.pi):.15g}")
        _row("dphi (T-4.5)", f"{ph.total:.15g} rad")
        _row("dphi_dyn = 2 T_z <K>/J3 (T-5.1)", f"{ph.dynamic:.15g} rad")
        _row("dphi_geom = -area/J3 (T-5.1)", f"{ph.geometric:.15g} rad")
        _row("dphi_dyn + dphi_geom", f"{ph.sum:.15g} rad")
        _row("dphi - (dphi_dyn + dphi_geom)", f"{ph.difference:.3e} rad")
        if sol.kind == "conical":
            _say("  measured: skipped (a conical orbit has constant height: no z-period to measure over)")
        else:
            _measure(sc, ph.total, tz, periods, dt)
        if plot is not None:
            from ..plot import plot_phases

            plot_phases({Path(scenario).stem: sol}, plot)
            _say(f"wrote {plot}")


def _measure(sc: Scenario, total: float, tz: float | None, periods: int, dt: float | None) -> None:
    """Prints Δφ measured from a RATTLE8 run of ``periods`` z-periods and its difference from ``total``."""
    if tz is None or not math.isfinite(tz):
        _fail(f"the z-period is {tz}; cannot simulate whole periods")
    step = dt if dt is not None else min(2e-3, tz / 500.0)
    if not (math.isfinite(step) and step > 0.0):
        _fail(f"--dt {step!r} must be a finite step > 0 s")
    t_end = (periods + 1.05) * tz
    if t_end / step > 5e7:
        _fail(f"{periods} periods of {tz:g} s at dt = {step:g} s are {t_end / step:.3g} steps; at most 5e7")
    tr = simulate(sc.pendulum(), sc.initial_state(), t_end, method="rattle8", dt=step)
    m = measured_azimuth_advance(tr)
    n = len(m.per_period)
    _row(f"measured (rattle8, dt {step:g} s, {n} periods)", f"{m.delta_phi:.15g} rad")
    _row("measured - dphi", f"{m.delta_phi - total:.3e} rad")


def _row(label: str, value: str) -> None:
    _say(f"  {label + ':':<46} {value}")


def _range(name: str, spec: str | None) -> tuple[float, float] | None:
    if spec is None:
        return None
    try:
        lo, hi = (float(v) for v in spec.split(":"))
    except ValueError:
        raise InvalidInputError(f"{name} {spec!r}: expected MIN:MAX") from None
    return lo, hi


def _grid(spec: str) -> tuple[int, int]:
    try:
        nj, ne = (int(v) for v in spec.lower().split("x"))
    except ValueError:
        raise InvalidInputError(f"--grid {spec!r}: expected N_J3xN_E, e.g. 400x400") from None
    return nj, ne


@app.command("em-map", short_help="The energy–momentum map with the rotation number W (image or data).")
def em_map_cmd(
    out: Annotated[
        str,  # named as typed, as --out of run
        typer.Option(
            "--out",
            "-o",
            metavar="FILE",
            help="Image (.png, .svg, .pdf) or data (.nc, .csv: E, J3, W).",
            show_default=False,
        ),
    ],
    grid: Annotated[str, typer.Option(metavar="N_J3xN_E", help="Grid points along J3 and E.")] = "400x400",
    length: Annotated[float, typer.Option(help="Rod length l in m.")] = 1.0,
    g: Annotated[float, typer.Option(help="Gravity g in m/s^2 (g < 0: the mirror image; not 0).")] = 9.81,
    mass: Annotated[float, typer.Option(help="Bob mass m in kg.")] = 1.0,
    j_range: Annotated[
        str | None,
        typer.Option(
            "--j-range",
            metavar="MIN:MAX",
            help="J3 range in kg m^2/s (default ±2.4 m l² ω₀).",
            show_default=False,
        ),
    ] = None,
    e_range: Annotated[
        str | None,
        typer.Option(
            "--e-range",
            metavar="MIN:MAX",
            help="E range in J (default -1.1 .. 2.5 m g l).",
            show_default=False,
        ),
    ] = None,
) -> None:
    """The energy–momentum map (J3, E) of the spherical pendulum (T-6.4): rotation number W as colour,
    the conical boundary, the critical line J3 = 0 with the bottom and the top, and the monodromy loop
    around the top (W changes by ±1). Writes an image or the grid data, by the suffix of --out."""
    from ..model import Pendulum

    with _user_errors():
        suffix = Path(out).suffix.lower()
        if suffix not in (*IMAGE_SUFFIXES, ".nc", ".csv"):
            _fail(
                f"unknown output suffix {suffix!r} in {out!r}; "
                "use .png, .svg, .pdf (image) or .nc, .csv (data)"
            )
        if suffix in IMAGE_SUFFIXES:
            _check_image("--out", out)
        else:
            _check_output(out)
        p = Pendulum(length=length, g=g, mass=mass)
        emm = em_map(p, _range("--j-range", j_range), _range("--e-range", e_range), _grid(grid))
        inside = emm.W[np.isfinite(emm.W)]
        _say(f"energy-momentum map: l = {p.length:g} m, g = {p.g:g} m/s^2, m = {p.mass:g} kg")
        _say(
            f"  grid {len(emm.J3)} x {len(emm.E)}: J3 in [{emm.J3[0]:.6g}, {emm.J3[-1]:.6g}] kg m^2/s, "
            f"E in [{emm.E[0]:.6g}, {emm.E[-1]:.6g}] J"
        )
        if inside.size:
            lo, hi = np.min(np.abs(inside)), np.max(np.abs(inside))
            _say(f"  |W| in [{lo:.6f}, {hi:.6f}] on the {inside.size} grid points inside the image")
        bottom, top = emm.critical_values["bottom"][1], emm.critical_values["top"][1]
        _say(f"  critical values (J3, E): bottom (0, {bottom:.6g} J), top (0, {top:.6g} J)")
        _say(f"  monodromy: W carried once around the top changes by {emm.monodromy():+.12f}")
        if suffix in IMAGE_SUFFIXES:
            from ..plot import plot_em_map

            plot_em_map(emm, out)
        else:
            emm.save(out)
        _say(f"wrote {out}")


@app.command(short_help="Holm's Figure 2 for a scenario: C = 0, the energy plane and the orbit.")
def reduced(
    scenario: Annotated[str, _SCENARIO],
    out: Annotated[str, _IMAGE_OUT],
    periods: Annotated[
        float, typer.Option(min=0.01, max=1000.0, help="z-periods of the orbit to draw.")
    ] = 1.0,
) -> None:
    """The reduced space (docs/theory.md T-3.3, Holm's Figure 2): in (σ1, σ2, σ3) = (z/l, ż/l, |v|²/l²)
    the surface C = 0 of the orbit's J3, the plane H = const and the exact orbit on their intersection."""
    with _user_errors():
        _check_image("--out", out)
        sc = load_scenario(_scenario_file(scenario))
        sol = _solution(sc)
        tz = sol.period_z
        span = (
            periods * tz
            if tz is not None and math.isfinite(tz)
            else sc._pendulum_spec().simulation.t_end - sc._pendulum_spec().simulation.t0
        )
        tr = sol.trajectory(np.linspace(0.0, span, 2001))
        from ..plot import plot_reduced

        plot_reduced(tr, out)
        _say(f"reduced space of {scenario} ({sol.kind}, t = 0 .. {span:.6g} s)")
        _say(f"wrote {out}")


@app.command("plot", short_help="Draw a scenario: its path on the sphere, the top view, or the phase split.")
def plot_cmd(
    scenario: Annotated[str, _SCENARIO],
    out: Annotated[str, _IMAGE_OUT],
    kind: Annotated[
        str,
        typer.Option(
            metavar="|".join(PLOT_KINDS),
            help="both: 3-D and top view side by side; sphere: 3-D; top: the (x, y) rosette; "
            "phases: the T-5.1 split and the reduced orbit.",
        ),
    ] = "both",
    t_end: Annotated[
        float | None,
        typer.Option("--t-end", help="End time in s (default: the scenario's t_end).", show_default=False),
    ] = None,
    use_exact: Annotated[
        bool,
        typer.Option(
            "--exact",
            help=f"Draw the exact solution ({PLOT_SAMPLES_PER_PERIOD} states per z-period) "
            "instead of simulating.",
        ),
    ] = False,
) -> None:
    """Draws the scenario's motion from t0 to t_end: simulated with its [simulation] settings (method,
    dt, tolerances, saving), or with --exact the exact solution (ideal pendulum only). For the ideal
    pendulum the turning heights z1, z2 of the exact solution are drawn as horizontal circles.
    --kind phases draws the dynamic/geometric split of Δφ (T-5.1) instead (needs J3 != 0; --t-end and
    --exact do not apply)."""
    with _user_errors():
        _check_image("--out", out)
        if kind not in PLOT_KINDS:
            _fail(f"--kind {kind!r}: use one of {', '.join(PLOT_KINDS)}")
        sc = load_scenario(_scenario_file(scenario))
        if t_end is not None:
            sc = sc.with_overrides(t_end=t_end)
        from .. import plot as plotting

        if kind == "phases":
            sol = _solution(sc)
            plotting.plot_phases({Path(scenario).stem: sol}, out)
            _say(f"phase split of {scenario} ({sol.kind}): dphi = {sol.phases().total:.15g} rad per z-period")
            _say(f"wrote {out}")
            return
        exact_sol = _solution(sc) if use_exact or sc.pendulum().is_ideal else None
        sim = sc._pendulum_spec().simulation
        if use_exact:
            assert exact_sol is not None
            tz = exact_sol.period_z
            per = tz if tz is not None and math.isfinite(tz) and tz > 0 else sim.t_end - sim.t0
            n = int(min(max(PLOT_SAMPLES_PER_PERIOD * (sim.t_end - sim.t0) / per, 2001), 200_001))
            times = np.linspace(sim.t0, sim.t_end, n)
            # the scenario's start is the state at t0, as for a simulation
            tr = dataclasses.replace(exact_sol.trajectory(times - sim.t0), t=times)
        else:
            run = sc.run()
            assert isinstance(run, Trajectory), "sc.pendulum() above refused a spring and a crane"
            tr = run
        plotting.plot_trajectory(tr, out, exact=exact_sol, kind=kind)
        _say(
            f"{kind} plot of {scenario}"
            + (f": {sc.title}" if sc.title else "")
            + f" ({tr.method}, t = {tr.t[0]:g} .. {tr.t[-1]:g} s, {len(tr)} samples)"
        )
        _say(f"wrote {out}")
