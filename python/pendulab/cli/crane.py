"""``pendulab crane …``: command shapers and crane moves from the command line (docs/cranes.md,
docs/cli.md; docs/theory.md §11). Subcommands: ``shaper`` (the impulse table and insensitivity of a
shaper), ``sensitivity`` (V(ω/ω₀) of shapers: a table, or a plot with --plot), ``residual`` (a move's
residual sway with and without a shaper, simulated in the nonlinear crane model). SI units (m, s,
rad/s, kg); exit code 0 on success, 2 on a user error (one ``error: …`` line), 130 on Ctrl-C.
``pendulab.crane`` (SciPy) is imported only when a crane command runs.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer

from .._core import InvalidInputError
from .common import _check_image, _check_output, _fail, _say, _user_errors, app

crane_app = typer.Typer(
    help="Cranes: command shapers, their sensitivity, a move's residual sway (docs/cranes.md).",
    no_args_is_help=True,
)
app.add_typer(
    crane_app, name="crane", short_help="Cranes: shapers, sensitivity, residual sway, grids, crane files."
)

_KIND_HELP = "Shaper kind: zv, zvd, zvdd, ei, 2hump_ei."
_G = 9.81


def _omega(omega: float | None, rope: float | None, g: float) -> float:
    if (omega is None) == (rope is None):
        _fail("give the design frequency as --omega [rad/s] or as --rope [m] (ω = √(g/l)), one of them")
    if rope is not None:
        if not (math.isfinite(rope) and rope > 0 and math.isfinite(g) and g > 0):
            raise InvalidInputError(f"--rope {rope!r} m and --g {g!r} m/s² must be > 0")
        return math.sqrt(g / rope)
    assert omega is not None
    return omega


@crane_app.command("shaper", short_help="A shaper's impulses (t_i [s], A_i) and its insensitivity.")
def shaper_cmd(
    kind: Annotated[str, typer.Argument(help=_KIND_HELP, show_default=False)],
    omega: Annotated[float | None, typer.Option(help="Design angular frequency [rad/s].")] = None,
    rope: Annotated[float | None, typer.Option(help="Or: rope length [m], ω = √(g/l).")] = None,
    g: Annotated[float, typer.Option(help="Gravity [m/s²] (with --rope).")] = _G,
    damping: Annotated[float, typer.Option(help="Damping ratio ζ of the mode (0 ≤ ζ < 1).")] = 0.0,
    tolerance: Annotated[float, typer.Option(help="V_tol of the EI kinds (a fraction).")] = 0.05,
) -> None:
    """Prints the impulse times [s] and amplitudes of the shaper, its length and its insensitivity:
    the width of the band of ω/ω₀ where V ≤ 5 % (T-11.1, T-11.2)."""
    with _user_errors():
        from .. import crane

        w = _omega(omega, rope, g)
        s = crane.shaper(kind, omega=w, damping=damping, tolerance=tolerance)
        _say(f"{s.kind.upper()} shaper for ω = {w:.6g} rad/s, ζ = {damping:g}")
        _say(f"{'i':>3} {'t_i [s]':>12} {'A_i':>12}")
        for i, (t, a) in enumerate(s.table(), 1):
            _say(f"{i:>3} {t:>12.6f} {a:>12.8f}")
        width = crane.insensitivity(s, 0.05, damping)
        _say(f"duration {s.duration:.6g} s; insensitivity (V ≤ 5 %) {width:.4f} ω₀")


@crane_app.command("sensitivity", short_help="V(ω/ω₀) of shapers: a table, or a plot (--plot).")
def sensitivity_cmd(
    kinds: Annotated[list[str], typer.Argument(metavar="KIND", help=_KIND_HELP, show_default=False)],
    damping: Annotated[float, typer.Option(help="Damping ratio ζ (design and plant).")] = 0.0,
    tolerance: Annotated[float, typer.Option(help="V_tol of the EI kinds (a fraction).")] = 0.05,
    lo: Annotated[float, typer.Option(help="Smallest ω/ω₀.")] = 0.5,
    hi: Annotated[float, typer.Option(help="Largest ω/ω₀.")] = 1.5,
    points: Annotated[int, typer.Option(min=2, max=100_001, help="Rows of the table.")] = 11,
    plot: Annotated[  # str, not Path: named as typed in the messages (./v.png, not v.png)
        str | None, typer.Option(metavar="FILE", help="Write the curves to this image (.png/.svg/.pdf).")
    ] = None,
) -> None:
    """The residual vibration V [%] of each shaper kind against ω/ω₀ (T-11.1)."""
    with _user_errors():
        from .. import crane

        if not (0 < lo < hi and math.isfinite(hi)):
            raise InvalidInputError(f"--lo {lo!r} and --hi {hi!r}: need 0 < lo < hi")
        if plot is not None:
            _check_image("--plot", plot)
        shapers = [crane.shaper(k, omega=1.0, damping=damping, tolerance=tolerance) for k in kinds]
        x = np.linspace(lo, hi, points)
        _say("ω/ω₀   " + "".join(f"{s.kind.upper():>10}" for s in shapers) + "   (V [%])")
        for xi in x:
            row = "".join(f"{100 * crane.residual_vibration(s, [xi], damping)[0]:>10.3f}" for s in shapers)
            _say(f"{xi:<7.4f}{row}")
        if plot is not None:
            from ..crane.plot import plot_sensitivity
            from ..plot import save_figure

            save_figure(plot_sensitivity(shapers, (lo, hi), damping, tolerance), plot)
            _say(f"wrote {plot}")


@crane_app.command("residual", short_help="A move's residual sway, with and without a shaper.")
def residual_cmd(
    distance: Annotated[float, typer.Option(help="Move distance [m] (along x).")] = 5.0,
    v_max: Annotated[float, typer.Option(help="Speed limit [m/s].")] = 0.5,
    a_max: Annotated[float, typer.Option(help="Acceleration limit [m/s²].")] = 0.5,
    j_max: Annotated[float | None, typer.Option(help="Jerk limit [m/s³] (default: none).")] = None,
    rope: Annotated[float, typer.Option(help="Rope length [m].")] = 10.0,
    payload_mass: Annotated[float, typer.Option(help="Payload mass [kg].")] = 1000.0,
    hook_mass: Annotated[float | None, typer.Option(help="Hook mass [kg] (with --rigging).")] = None,
    rigging: Annotated[float | None, typer.Option(help="Rigging length [m] (with --hook-mass).")] = None,
    shaper: Annotated[str, typer.Option(help=_KIND_HELP)] = "zvd",
    design_rope: Annotated[
        float | None, typer.Option(help="Rope length [m] the shaper is designed for (default --rope).")
    ] = None,
    g: Annotated[float, typer.Option(help="Gravity [m/s²].")] = _G,
    settle: Annotated[
        float, typer.Option(help="Time after the move [s] over which the sway is measured.")
    ] = 30.0,
    plot: Annotated[
        str | None, typer.Option(metavar="FILE", help="Write sway vs time (shaped, unshaped) to this image.")
    ] = None,
) -> None:
    """Simulates the move unshaped and shaped (the shaper designed for the lowest sway mode of the
    design rope) in the nonlinear crane model and prints the residual sway amplitude of the payload
    [m] after the move, their ratio, and the shaper's predicted V at the true lowest mode."""
    with _user_errors():
        from .. import crane

        if plot is not None:
            _check_image("--plot", plot)
        settle = float(settle)
        if not (math.isfinite(settle) and 0 < settle <= 3600):
            raise InvalidInputError(f"--settle {settle!r}: a time in (0, 3600] s")
        c0 = crane.Crane(rope=rope, payload_mass=payload_mass, hook_mass=hook_mass, rigging=rigging, g=g)
        w_true = float(c0.modes()[0])
        w_design = float(c0.modes(rope=design_rope)[0]) if design_rope is not None else w_true
        s = crane.shaper(shaper, omega=w_design)
        runs = {}
        amps = {}
        for label, sh in (("unshaped", None), (s.kind.upper(), s)):
            path = crane.move(distance, v_max, a_max, j_max=j_max, shaper=sh, t_start=1.0)
            c = crane.Crane(
                rope=rope, pivot=path, payload_mass=payload_mass, hook_mass=hook_mass, rigging=rigging, g=g
            )
            run = c.simulate(t_end=path.t_end + settle, output_spacing=0.02)
            after = run.t > path.t_end
            off = run.offset()[after]
            amps[label] = float(np.max(np.hypot(off[:, 0], off[:, 1])))
            runs[label] = run
            _say(f"{label:>9}: move ends at {path.t_end:8.3f} s; residual sway {amps[label]:.5g} m")
        ratio = amps[s.kind.upper()] / amps["unshaped"]
        predicted = crane.residual_vibration(s, [w_true])[0]
        modes = ", ".join(f"{m:.5g}" for m in c0.modes())
        _say(f"ratio {ratio:.4g} (the shaper's V at ω = {w_true:.5g} rad/s: {predicted:.4g})")
        _say(f"sway modes {modes} rad/s")
        if plot is not None:
            from ..crane.plot import plot_sway
            from ..plot import save_figure

            save_figure(plot_sway(runs), plot)
            _say(f"wrote {plot}")


@crane_app.command("run", short_help="Run a crane file ([crane], [move], [shaper], [hoist], [wind], ...).")
def run_cmd(
    file: Annotated[  # str, not Path: the messages name the file as typed (./x.toml, not x.toml)
        str, typer.Argument(help="Crane file (TOML; docs/cranes.md 'Crane files').", show_default=False)
    ],
    out: Annotated[
        str | None, typer.Option("--out", "-o", metavar="FILE", help="Write the run to this .csv file.")
    ] = None,
    plot: Annotated[
        str | None, typer.Option(metavar="FILE", help="Write sway vs time to this image.")
    ] = None,
) -> None:
    """Runs the crane of FILE and prints its sway modes [rad/s], the residual sway after the move [m],
    the largest rope tension [N] and the energy balance E − E₀ − ΣW [J]; --out writes t [s], pivot,
    hook, payload [m], rope [m], tensions [N], energy and works [J] as CSV."""
    with _user_errors():
        from ..crane.scenario import load

        if out is not None:
            if Path(out).suffix.lower() != ".csv":
                _fail(f"--out {out!r}: crane runs are written as .csv")
            _check_output(out)
        if plot is not None:
            _check_image("--plot", plot)
        if not Path(file).exists() or Path(file).is_dir():
            what = "a directory, not a crane file" if Path(file).is_dir() else "No such file"
            _fail(f"{file}: {what}; give a crane file: TOML with [crane] and [simulation] (docs/cranes.md)")
        sc = load(file)
        report(sc, file, out, plot)


def report(sc: Any, name: str, out: str | None = None, plot: str | None = None, quiet: bool = False) -> None:
    """Runs the crane scenario ``sc`` (``pendulab.crane.scenario.CraneScenario``) and prints its
    modes [rad/s], residual sway [m], largest tension [N] and energy balance [J]; writes ``out``
    (.csv) and ``plot`` (an image) when given, named as typed (``pendulab crane run`` and
    ``pendulab run``). ``quiet`` (``pendulab run -q``) prints nothing."""

    def say(text: str) -> None:
        if not quiet:
            _say(text)

    run = sc.run()
    modes = ", ".join(f"{m:.5g}" for m in sc.crane.modes())
    say(f"{sc.title or name}: sway modes {modes} rad/s; shaper {sc.shaper.kind if sc.shaper else 'none'}")
    after = run.t >= sc.move_end
    sway = float(np.hypot(*run.offset()[after].T).max())
    say(f"largest sway after the move (t >= {sc.move_end:.3f} s): {sway:.5g} m")
    balance = np.abs(run.energy_residual()).max()
    say(f"largest rope tension {run.tension[:, 0].max():.6g} N; E - E0 - W max {balance:.3g} J")
    if out is not None:
        _write_csv(sc, run, out)
        say(f"wrote {out}")
    if plot is not None:
        from ..crane.plot import plot_sway
        from ..plot import save_figure

        save_figure(plot_sway({"run": run}, t_marks=[sc.move_end] if sc.move_end else []), plot)
        say(f"wrote {plot}")


def _write_csv(sc: Any, run: object, out: str) -> None:
    """The run as CSV: the ``#`` metadata line of every Pendulab CSV (the crane file's settings, the
    shaper's impulses, the sway modes, units), the column names with units, one row per sample."""
    from ..crane.system import CraneRun
    from ..io import write_columns_csv

    assert isinstance(run, CraneRun)
    write_columns_csv(out, "crane run", sc.metadata(run), run.columns())


def _span(option: str, spec: str, geometric: bool) -> np.ndarray:
    """START:STOP:N → N values (linear, or geometric for ratios)."""
    parts = spec.split(":")
    try:
        lo, hi, n = float(parts[0]), float(parts[1]), int(parts[2])
    except (ValueError, IndexError):
        raise InvalidInputError(f"{option} {spec!r}: expected START:STOP:N, e.g. 5:30:50") from None
    if len(parts) != 3 or not (math.isfinite(lo) and math.isfinite(hi) and 0 < lo <= hi and 1 <= n <= 10_000):
        raise InvalidInputError(f"{option} {spec!r}: need 0 < START <= STOP and 1 <= N <= 10000")
    return np.geomspace(lo, hi, n) if geometric else np.linspace(lo, hi, n)


@crane_app.command("grid", short_help="Residual sway over rope lengths x payload ratios x shapers.")
def grid_cmd(
    ropes: Annotated[str, typer.Option(help="Rope lengths START:STOP:N [m] (linear).")] = "5:30:20",
    ratios: Annotated[
        str, typer.Option(help="Payload/hook mass ratios START:STOP:N (geometric).")
    ] = "1:30:10",
    shapers: Annotated[
        str, typer.Option(help="Comma-separated kinds; 'none' for unshaped.")
    ] = "none,zv,zvd,ei",
    design_rope: Annotated[float | None, typer.Option(help="Rope [m] the shapers are designed for.")] = None,
    distance: Annotated[float, typer.Option(help="Move distance [m].")] = 5.0,
    v_max: Annotated[float, typer.Option(help="Speed limit [m/s].")] = 0.5,
    a_max: Annotated[float, typer.Option(help="Acceleration limit [m/s²].")] = 0.5,
    j_max: Annotated[float | None, typer.Option(help="Jerk limit [m/s³].")] = None,
    hook_mass: Annotated[float, typer.Option(help="Hook mass [kg].")] = 100.0,
    rigging: Annotated[float, typer.Option(help="Rigging length [m].")] = 2.0,
    g: Annotated[float, typer.Option(help="Gravity [m/s²].")] = _G,
    settle: Annotated[
        float, typer.Option(help="Time after the move [s] over which the sway is measured.")
    ] = 20.0,
    out: Annotated[
        str | None, typer.Option("--out", "-o", metavar="FILE", help="Write the grid to this .csv file.")
    ] = None,
    plot: Annotated[str | None, typer.Option(metavar="FILE", help="Write the chart to this image.")] = None,
) -> None:
    """Simulates every rope length × payload ratio × shaper (hook + payload cranes in the core, in
    parallel) and prints the median and largest residual sway [m] per shaper; --out writes every case
    (shaper, rope [m], ratio, sway [m]) as CSV, --plot the chart (docs/cranes.md "A grid of cases")."""
    with _user_errors():
        import time

        from .. import crane

        if out is not None:
            if Path(out).suffix.lower() != ".csv":
                _fail(f"--out {out!r}: the grid is written as .csv")
            _check_output(out)
        if plot is not None:
            _check_image("--plot", plot)
        lr, rr = _span("--ropes", ropes, False), _span("--ratios", ratios, True)
        design = design_rope if design_rope is not None else 0.5 * (lr[0] + lr[-1])
        probe = crane.Crane(
            rope=design,
            payload_mass=hook_mass * float(np.median(rr)),
            hook_mass=hook_mass,
            rigging=rigging,
            g=g,
        )
        w = float(probe.modes()[0])
        kinds = [k.strip().lower() for k in shapers.split(",") if k.strip()]
        shs = [None if k == "none" else crane.shaper(k, omega=w) for k in kinds]
        t0 = time.perf_counter()
        res = crane.residual_grid(lr, rr, shs, distance, v_max, a_max, j_max, hook_mass, rigging, g, settle)
        elapsed = time.perf_counter() - t0
        _say(f"{res.sway.size} runs in {elapsed:.2f} s; shapers designed for ω = {w:.5g} rad/s")
        for i, label in enumerate(res.labels):
            _say(f"{label:>9}: median {np.median(res.sway[i]):.4g} m, largest {res.sway[i].max():.4g} m")
        if out is not None:
            settings = {"ropes": ropes, "ratios": ratios, "shapers": kinds, "design_rope": design}
            settings |= {"distance": distance, "v_max": v_max, "a_max": a_max, "j_max": j_max}
            settings |= {"hook_mass": hook_mass, "rigging": rigging, "g": g, "settle": settle}
            settings |= {"sample_spacing": res.output_spacing, "rtol": res.rtol, "atol": res.atol}
            _write_grid_csv(out, res, settings, w, [s for s in shs if s is not None])
            _say(f"wrote {out}")
        if plot is not None:
            from ..crane.plot import plot_grid
            from ..plot import save_figure

            save_figure(plot_grid(res), plot)
            _say(f"wrote {plot}")


GRID_UNITS = {
    "rope": "m",
    "ratio": "1",
    "sway": "m",
    "ropes": "m",
    "design_rope": "m",
    "distance": "m",
    "v_max": "m/s",
    "a_max": "m/s^2",
    "j_max": "m/s^3",
    "hook_mass": "kg",
    "rigging": "m",
    "g": "m/s^2",
    "settle": "s",
    "sample_spacing": "s",
    "design_omega": "rad/s",
    "shapers.times": "s",
}


def _write_grid_csv(out: str, res: Any, settings: dict[str, Any], omega: float, shapers: list[Any]) -> None:
    """The grid as CSV: the ``#`` metadata line of every Pendulab CSV (``# pendulab crane grid; metadata
    (JSON): {...}``: the command's settings, ``ropes`` linear and ``ratios`` geometric START:STOP:N, the
    design ω [rad/s], each shaper's impulses, units), the header ``shaper,rope [m],ratio,sway [m]`` and
    one row per case; numbers as :func:`pendulab.io.csv_number` writes them."""
    from ..io import atomic_path, csv_number

    impulses = {s.kind: {"times": s.times.tolist(), "amplitudes": s.amplitudes.tolist()} for s in shapers}
    meta = {
        "software": "pendulab",
        "settings": settings,
        "design_omega": omega,
        "shapers": impulses,
        "cases": int(res.sway.size),
        "interrupted": bool(res.interrupted),
        "sway": "the payload's largest horizontal distance from the pivot over settle s after the move",
        "ratio": "payload mass / hook mass",
        "units": GRID_UNITS,
        "conventions": "SI units, z up, gravity along -z for g > 0",
    }
    with atomic_path(out) as tmp, open(tmp, "w", encoding="utf-8", newline="") as f:
        f.write(f"# pendulab crane grid; metadata (JSON): {json.dumps(meta, sort_keys=True)}\n")
        f.write("shaper,rope [m],ratio,sway [m]\n")
        for i, label in enumerate(res.labels):
            for j, rope in enumerate(res.ropes):
                for k, ratio in enumerate(res.ratios):
                    numbers = (csv_number(x) for x in (rope, ratio, res.sway[i, j, k]))
                    f.write(",".join((label, *numbers)) + "\n")
