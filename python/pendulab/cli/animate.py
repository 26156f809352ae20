"""``pendulab animate``: a scenario as a movie (MP4, WebM or GIF), integrated or, with ``--exact``,
from the exact solution (every frame exact, docs/theory.md §4). Registered on :data:`pendulab.cli.app`;
SI units (times in s), exit code 0 on success, 2 on a user error (one ``error: …`` line), 130 on
Ctrl-C (no file is left behind: the movie is renamed into place only when complete). Options and
panels: ``docs/animate.md``; the command: ``docs/cli.md``.
"""

from __future__ import annotations

import os
import warnings
from pathlib import Path
from typing import Annotated

import typer

from ..animate.clock import check_fps, make_clock
from ..animate.encode import check_size, check_work, fit_gif, format_of, gif_fps, parse_size
from ..animate.layout import boxes, panel_names
from ..animate.movie import SPHERE_PANELS, Movie, MovieSettings
from ..scenario import ScenarioError, load_scenario
from ..theory.exact import exact
from ..trajectory import Trajectory
from ..variants.spring import SpringTrajectory
from .common import EXIT_INTERRUPTED, _fail, _say, _scenario_file, _user_errors, app


def _check_movie_path(typed: str) -> str:
    """The format of --out, and that its directory can be written (before any work); named as typed."""
    fmt = format_of(typed)
    out = Path(typed)
    if out.is_dir():
        _fail(f"--out {typed!r} is a directory; give a file name ending in .mp4, .webm or .gif")
    parent = out.resolve().parent
    while not parent.exists():
        parent = parent.parent
    if not parent.is_dir() or not os.access(parent, os.W_OK | os.X_OK):
        _fail(f"--out {typed!r}: cannot write to the directory {str(parent)!r}")
    return fmt


def _report(movie: Movie, out: str) -> str:
    """What was written, the movie named ``out`` as typed."""
    w, h = movie.size
    return (
        f"wrote {out}: {movie.frames} frames, {movie.duration:.3g} s at {movie.fps:.3g} frames/s, "
        f"{w}x{h}, t = {movie.t_start:g} .. {movie.t_end:.6g} s, {movie.bytes / 1e6:.2f} MB "
        f"({movie.frames_per_second:.0f} frames/s)"
    )


@app.command(short_help="Make a movie of a scenario (.mp4, .webm, .gif).")
def animate(
    scenario: Annotated[
        str,  # not Path: the messages name the file as typed (./x.toml, not x.toml)
        typer.Argument(
            metavar="SCENARIO",
            help="Scenario file (TOML) or a shipped example's name (rosette); see docs/scenarios.md.",
            show_default=False,
        ),
    ],
    out: Annotated[
        str,  # not Path: the messages name it as typed (./m.gif, not m.gif)
        typer.Option(
            "--out",
            "-o",
            metavar="FILE",
            help="The movie: .mp4 (H.264), .webm (VP9) or .gif.",
            show_default=False,
        ),
    ],
    exact_: Annotated[
        bool,
        typer.Option(
            "--exact",
            help="Draw the exact solution (ideal pendulum only): every frame exact, nothing integrated; "
            "the movie starts at t = 0 and runs to the scenario's t_end.",
        ),
    ] = False,
    panels: Annotated[str, typer.Option(help="Comma-separated panels: 3d, top, z, reduced, veff.")] = "3d",
    fps: Annotated[
        float | None,
        typer.Option(
            help="Frames per second of video (default 30; GIF: 100/n, at most 50; default 20 or less "
            "to fit).",
            show_default=False,
        ),
    ] = None,
    speed: Annotated[float, typer.Option(help="Simulated seconds per second of video.")] = 1.0,
    duration: Annotated[
        float | None,
        typer.Option(help="Seconds of video (default: the whole run at this speed).", show_default=False),
    ] = None,
    size: Annotated[
        str | None,
        typer.Option(
            help="WIDTHxHEIGHT in pixels (even for .mp4 and .webm; default 1280x720, GIF 640x360).",
            show_default=False,
        ),
    ] = None,
    trail: Annotated[
        float | None,
        typer.Option(
            help="Seconds of fading trail (default: one period 2π√(l/g); 0: none).", show_default=False
        ),
    ] = None,
    vectors: Annotated[bool, typer.Option("--vectors", help="Draw the velocity at the bob.")] = False,
    t_end: Annotated[
        float | None,
        typer.Option("--t-end", help="End time in s; replaces the file's t_end.", show_default=False),
    ] = None,
    progress: Annotated[
        bool | None,
        typer.Option("--progress/--no-progress", help="Progress bars on stderr.", show_default=False),
    ] = None,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing but errors.")] = False,
) -> None:
    """Make a movie of a scenario. Everything is checked before the run (format, size, panels, the
    number of frames); Ctrl-C stops, leaves no file and exits with code 130."""
    with _user_errors():
        note = ""
        fmt = _check_movie_path(out)
        given_size = parse_size(size) if size is not None else None
        sc = load_scenario(_scenario_file(scenario)).with_overrides(t_end=t_end)
        sim = sc._pendulum_spec().simulation
        if fmt == "gif":  # what is not given is chosen to fit a GIF's pixel cap (the speed too)
            chosen = size is None or fps is None
            if duration is None:
                frame_size, fps, speed = fit_gif(sim.t_end - sim.t0, given_size, fps, speed)
            else:
                frame_size, fps, _ = fit_gif(duration * speed, given_size, fps, speed)
            if chosen and not quiet:  # said once everything is checked (not "at -1 frames/s")
                note = f"GIF: {frame_size[0]}x{frame_size[1]} at {fps:.3g} frames/s, speed {speed:g}"
        else:
            frame_size = given_size or (1280, 720)
            fps = 30.0 if fps is None else fps
        check_size(fmt, frame_size)
        names = panel_names(panels, 1)
        boxes(names, *frame_size)
        is_spring = sc._pendulum_spec().pendulum.model == "spring"
        if is_spring and exact_:
            raise ScenarioError(
                str(scenario),
                "--exact draws the exact solution of the ideal pendulum; the 'spring' model has none "
                "(leave out --exact to integrate it)",
            )
        if is_spring and set(names) & set(SPHERE_PANELS):
            raise ScenarioError(
                str(scenario),
                f"--panels {panels}: a swinging spring leaves the sphere and takes the panels 3d, top, z",
            )
        # the movie clock over the run's span: fps, speed, duration and the frame limits, before the run
        span = (0.0, sim.t_end - sim.t0) if exact_ else (sim.t0, sim.t_end)
        clock = make_clock(
            span, fps=gif_fps(check_fps(fps)) if fmt == "gif" else fps, speed=speed, duration=duration
        )
        check_work(fmt, frame_size, clock.frames)
        if note:
            _say(note, err=True)
        settings = MovieSettings(
            fps=fps,
            speed=speed,
            duration=duration,
            panels=panels,
            size=frame_size,
            trail=trail,
            vectors=vectors,
            progress=progress,
        )
        if exact_:
            sol = exact(sc.pendulum(), sc.initial_state())
            if not quiet:
                _say(
                    f"exact solution of {scenario} ({sol.kind}), t = 0 .. {sim.t_end - sim.t0:g} s", err=True
                )
            movie = sol.animate(out, settings, t=(0.0, sim.t_end - sim.t0))
        else:
            if not quiet:
                _say(f"running {scenario} ({sim.method}, t = {sim.t0:g} .. {sim.t_end:g} s)", err=True)
            with warnings.catch_warnings():
                warnings.filterwarnings("ignore", message="simulation interrupted", category=RuntimeWarning)
                tr = sc.run(progress=progress)
            assert isinstance(tr, Trajectory | SpringTrajectory)
            if tr.interrupted:
                _say(f"interrupted (Ctrl-C) at t = {tr.t[-1]:g} s; no movie written", err=True)
                raise typer.Exit(EXIT_INTERRUPTED)
            movie = tr.animate(out, settings)
        if not quiet:
            _say(_report(movie, out))
