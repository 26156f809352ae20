"""``pendulab sweep``: run a sweep file (``docs/sweeps.md``) on threads or Dask, chunk by chunk into
Parquet, resumable. Registered on :data:`pendulab.cli.app`; the same conventions: SI units, exit code 0
on success, 2 on a user error (one ``error: …`` line), 130 on Ctrl-C (the finished chunks are kept;
``--resume`` computes the rest).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer

from .._core import InvalidInputError
from ..integrators import check_arithmetic
from ..sweeps.compute import METHODS, check_method
from ..sweeps.file import SweepFile, load_sweep_file
from ..sweeps.results import MANIFEST
from ..sweeps.resume import ResumeConflict
from ..sweeps.run import BACKENDS, sweep
from .common import EXIT_INTERRUPTED, _fail, _say, _sweep_file, _user_errors, app

_SWEEP = typer.Argument(
    metavar="SWEEP",
    help="Sweep file (TOML; see docs/sweeps.md) or the name of a shipped example (`pendulab scenarios`).",
    show_default=False,
)


def _plan(sf: SweepFile, kwargs: dict[str, Any]) -> str:
    d = sf.design
    if d.kind == "grid":
        points = f"grid {' x '.join(str(s) for s in d.shape)} ({', '.join(d.names)})"
    else:
        points = f"{d.kind} design over {', '.join(d.names)}"
        if d.kind == "random":
            points += f" (seed {d.info['seed']}, {d.info['method']})"
    q = kwargs["quantity"]
    what = q if isinstance(q, str) else ", ".join(str(x) for x in q)
    method = "RATTLE" if kwargs["method"] == "rattle" else kwargs["method"]
    sim = f"; {method} to t = {kwargs['t_end']:g} s, dt = {kwargs['dt']:g} s" if kwargs["t_end"] else ""
    return f"  {d.n} points: {points} -> {what}{sim}"


def _chunks(n: int, chunks: int, size: int) -> str:
    """'1 chunk of 2 points', '3 chunks of 4 points (the last of 2)': the chunks as they are, not the
    chunk size asked for (the default, 100 000 points, for a sweep of 2)."""
    full = min(size, n)
    last = n - (chunks - 1) * size
    text = f"{chunks} chunk{'s' if chunks != 1 else ''} of {full} point{'s' if full != 1 else ''}"
    return text + (f" (the last of {last})" if chunks > 1 and last != full else "")


def _done_so_far(out: Path) -> str:
    """'k of n chunks' from the manifest beside or in ``out`` ('' if there is none)."""
    for directory in (out, out.parent / f".{out.name}.chunks"):
        path = directory / MANIFEST
        if path.is_file():
            try:
                m = json.loads(path.read_text())
                return f"{len(m['chunks_done'])} of {m['n_chunks']} chunks are in {directory}"
            except (OSError, ValueError, KeyError):  # pragma: no cover - a damaged manifest
                return ""
    return ""


@app.command("sweep", short_help="Run a sweep file: a quantity over a grid or random design, to Parquet.")
def sweep_cmd(
    sweep_file: Annotated[str, _SWEEP],  # str: named as typed (./x.toml)
    out: Annotated[
        str,  # not Path: the messages name it as typed (./runs, not runs)
        typer.Option(
            "--out",
            "-o",
            metavar="PATH",
            help="A directory (one Parquet file per chunk + _manifest.json) or a FILE.parquet.",
            show_default=False,
        ),
    ],
    workers: Annotated[
        int | None,
        typer.Option(min=1, max=1024, help="Threads (or LocalCluster workers with --backend dask)."),
    ] = None,
    scheduler: Annotated[
        str | None,
        typer.Option(metavar="tcp://HOST:8786", help="Run on this Dask scheduler.", show_default=False),
    ] = None,
    backend: Annotated[
        str | None,
        typer.Option(
            metavar="|".join(BACKENDS), help="Where chunks run (default: the file's, else threads)."
        ),
    ] = None,
    chunk_size: Annotated[
        int | None,
        typer.Option("--chunk-size", min=1, help="Points per chunk (default: the file's or auto)."),
    ] = None,
    arithmetic: Annotated[
        str | None,
        typer.Option(
            metavar="auto|unfused|fused",
            help="RATTLE's multiply-adds (default: the file's [simulation] arithmetic, else auto; "
            "with --resume, auto takes the recorded one).",
            show_default=False,
        ),
    ] = None,
    method: Annotated[
        str | None,
        typer.Option(
            metavar="|".join(METHODS),
            help="RATTLE or its compositions of order 4, 6, 8 (default: the file's [simulation] method, "
            "else rattle).",
            show_default=False,
        ),
    ] = None,
    resume: Annotated[
        bool, typer.Option("--resume", help="Continue the sweep in --out: skip the chunks already written.")
    ] = False,
    progress: Annotated[
        bool | None,
        typer.Option(
            "--progress/--no-progress", help="Progress bar over chunks on stderr.", show_default=False
        ),
    ] = None,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing but errors.")] = False,
) -> None:
    """Computes the sweep file's quantity at every point of its [grid] or [random] design, in chunks on
    a thread pool (default) or Dask (--backend dask: a LocalCluster of --workers processes; --scheduler:
    a running cluster), writing each chunk to --out as it finishes. Prints the plan, then per result
    column its range and NaN count. Ctrl-C keeps the finished chunks; --resume does the rest.
    --arithmetic and --method override the file's [simulation] arithmetic and method, as the other
    options its [run] table."""
    with _user_errors():
        if workers is not None and scheduler is not None:
            _fail("--workers and --scheduler exclude each other (the scheduler's cluster has its workers)")
        if backend is not None and backend not in BACKENDS:
            _fail(f"--backend {backend!r}: use one of {', '.join(BACKENDS)}")
        if arithmetic is not None:
            try:
                check_arithmetic(arithmetic, "rattle")  # pl.sweep's check, here before the file is read
            except InvalidInputError as e:
                _fail(f"--arithmetic: {e}")
        if method is not None:
            try:
                check_method(method)  # pl.sweep's check, here before the file is read
            except InvalidInputError as e:
                _fail(f"--method: {e}")
        sf = load_sweep_file(_sweep_file(sweep_file))
        kwargs = sf.sweep_kwargs(
            workers=workers,
            scheduler=scheduler,
            backend=backend,
            chunk_size=chunk_size,
            arithmetic=arithmetic,
            method=method,
        )
        if not quiet:
            _say(f"sweep {sweep_file}" + (f": {sf.title}" if sf.title else ""), err=True)
            _say(_plan(sf, kwargs), err=True)
        try:
            show = False if quiet else progress
            res = sweep(sf.design, out=out, resume=resume, progress=show, **kwargs)
        except ResumeConflict as e:  # the fix spelled as this command's options
            _fail(e.for_cli())
        except KeyboardInterrupt:
            where = _done_so_far(Path(out))
            _fail(
                f"interrupted (Ctrl-C){': ' + where if where else ''}; run again with --resume to finish",
                EXIT_INTERRUPTED,
            )
        if quiet:
            return
        st = res.stats
        used = res.metadata["spec"].get("arithmetic")  # resolved; none for exact quantities only
        _say(
            f"{_chunks(len(res), st['chunks'], st['chunk_size'])}: computed {st['computed']}, "
            f"skipped {st['skipped']} (already in --out); {st['backend']}, {st['seconds']:.3g} s"
            + (f"; arithmetic {used}" if used else "")
        )
        for name, unit in res.units.items():
            if name == "point" or name in sf.design.names:
                continue
            col = res[name]
            finite = col[np.isfinite(col)]
            span = f"{finite.min():.9g} .. {finite.max():.9g}" if finite.size else "no finite values"
            _say(f"  {name} [{unit}]: {span}, NaN {int(np.isnan(col).sum())}, inf {int(np.isinf(col).sum())}")
        _say(f"wrote {out} ({len(res)} rows)")
