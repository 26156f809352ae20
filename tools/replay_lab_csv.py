"""Replays a CSV the lab exported (*Share and export* → CSV; docs/web.md) with the Python package.

The file is read as every Pendulab CSV is (README, "Reading a CSV back"): the metadata by
``pendulab.io.read_metadata`` (the JSON after ``metadata (JSON): `` on the first line), the numbers by
``np.loadtxt(..., skiprows=2)``. Then
``pl.simulate(pl.Pendulum(**meta["pendulum"]), start, method=..., dt=..., t0=..., save_every=1,
arithmetic=meta["options"]["arithmetic"])`` must give the file's states x, v bit for bit at its times (each a
whole number of steps of dt after t0: docs/lab.md, "Against the Python package"), from the header's
``start`` (the first row's state). One fixed-step method only: DOP853 in the lab lands on the ticks'
times, so its steps are not those of one ``pl.simulate``, and a run whose method changed (the header's
``method_changes``) is refused.

Usage: ``python tools/replay_lab_csv.py FILE.csv``; prints what was replayed, exits 1 naming the first
row that differs, 2 with one line ``error: FILE: ...`` for a file it cannot replay (missing, not a lab
CSV, metadata without what a replay needs, a run it does not replay). ``web/tests/e2e/lab_file.mjs``
runs it on the one-file lab's downloads, ``python/tests/test_lab_csv.py`` on downloads kept in
``python/tests/data/lab/``.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import numpy as np
import pendulab as pl
from pendulab.io import read_metadata

PREFIX = "# pendulab lab trajectory; metadata (JSON): "
COLUMNS = ["t [s]", "x1 [m]", "x2 [m]", "x3 [m]", "v1 [m/s]", "v2 [m/s]", "v3 [m/s]"]
NEEDED: dict[str, type] = {
    "method": str,
    "adaptive": bool,
    "method_changes": list,
    "pendulum": dict,
    "options": dict,
    "start": dict,
}
"""The metadata a replay reads, with their JSON types (a file without them is refused, naming them)."""


def read(path: str | Path) -> tuple[dict[str, Any], list[str], np.ndarray]:
    """The metadata, the column names and the numbers (one row per frame) of a lab CSV."""
    with open(path, encoding="utf-8") as f:
        first, names = f.readline(), f.readline().rstrip("\n").split(",")
    if not first.startswith(PREFIX):
        raise ValueError(f"{path}: the first line is not the lab's metadata line {PREFIX!r}: {first[:80]!r}")
    meta = read_metadata(path)
    missing = [key for key in NEEDED if not isinstance(meta.get(key), NEEDED[key])]
    for table, keys in (("options", ("t0", "arithmetic")), ("start", ("x", "v"))):
        if table not in missing:
            missing += [f"{table}.{k}" for k in keys if k not in meta[table]]
    if missing:
        raise ValueError(f"{path}: the metadata lack what a replay needs: {', '.join(missing)}")
    if names[: len(COLUMNS)] != COLUMNS:
        raise ValueError(f"{path}: the columns begin {names[: len(COLUMNS)]}, not {COLUMNS}")
    try:
        data = np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)
    except ValueError as e:
        raise ValueError(f"{path}: the rows are not numbers ({' '.join(str(e).split())})") from None
    if data.shape[0] == 0 or data.shape[1] < len(COLUMNS):
        raise ValueError(f"{path}: {data.shape[0]} rows of {data.shape[1]} numbers, no states to replay")
    return meta, names, data


def replay(path: str | Path, arithmetic: str | None = None) -> dict[str, Any]:
    """Simulates the run the CSV at ``path`` names (with ``arithmetic``, default the file's) and compares
    the states: the rows, the time span, and how many rows differ from it in x or v (``differ``, 0 when
    the file is reproduced bit for bit) with the first such time."""
    meta, _, data = read(path)
    opts, start = meta["options"], meta["start"]
    if meta["method_changes"]:
        change = meta["method_changes"][0]
        raise ValueError(
            f"{path}: the method changed at t = {change['t']} s to {change['method']} "
            f"(dt = {change['dt']} s) in the run: one pl.simulate replays one method"
        )
    if meta["adaptive"]:
        raise ValueError(f"{path}: method {meta['method']!r} is adaptive: its steps are the lab's own")
    dt, t0 = float(opts["dt"]), float(opts["t0"])
    t = data[:, 0]
    k = np.rint((t - t0) / dt).astype(np.int64)
    if k.min() < 0 or np.any(np.abs(t0 + k * dt - t) > 1e-6 * dt):
        raise ValueError(f"{path}: the times are not whole steps of dt = {dt} s after t0 = {t0} s")
    try:
        pendulum = pl.Pendulum(**meta["pendulum"])
    except TypeError as e:  # a key that is not a parameter
        raise ValueError(f"{path}: the metadata's pendulum {meta['pendulum']} is not one: {e}") from None
    tr = pl.simulate(
        pendulum,
        pl.State(np.array(start["x"], dtype=float), np.array(start["v"], dtype=float)),
        t0 + int(k.max()) * dt,
        method=meta["method"],
        dt=dt,
        t0=t0,
        save_every=1,
        arithmetic=arithmetic or opts["arithmetic"],
    )
    if len(tr.t) <= k.max():
        raise ValueError(f"{path}: pl.simulate gave {len(tr.t)} states, the file needs step {k.max()}")
    same = np.all(tr.x[k] == data[:, 1:4], axis=1) & np.all(tr.v[k] == data[:, 4:7], axis=1)
    bad = np.flatnonzero(~same)
    return {
        "rows": len(t),
        "t": (float(t[0]), float(t[-1])),
        "arithmetic": arithmetic or opts["arithmetic"],
        "differ": len(bad),
        "first_differ": float(t[bad[0]]) if len(bad) else None,
        "largest": float(np.max(np.abs(tr.x[k] - data[:, 1:4]))),
    }


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print(__doc__.split("\n\n")[-1], file=sys.stderr)
        return 2
    path = argv[0]
    try:
        meta, _, _ = read(path)
        got = replay(path)
        fused = replay(path, "fused")
    except OSError as e:  # missing, a directory, no permission
        print(f"error: {path}: cannot read: {e.strerror or e}", file=sys.stderr)
        return 2
    except (ValueError, pl.IntegrationError) as e:  # InvalidInputError is a ValueError
        text = " ".join(str(e).split())
        print(f"error: {text if text.startswith(path) else f'{path}: {text}'}", file=sys.stderr)
        return 2
    print(
        f"{argv[0]}: {got['rows']} rows, t {got['t'][0]} .. {got['t'][1]} s, {meta['pendulum']['model']}, "
        f"{meta['method']}, dt {meta['options']['dt']} s: {got['differ']} differ from "
        f"pl.simulate(arithmetic={got['arithmetic']!r}) (with 'fused': {fused['differ']}, "
        f"largest {fused['largest']:.1e} m)"
    )
    if got["differ"]:
        print(f"first at t = {got['first_differ']} s, largest {got['largest']:.3e} m", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
