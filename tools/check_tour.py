"""Runs the guided tour (``docs/tour/*.ipynb``) as a new user gets it: a fresh virtual environment
outside the checkout (HOME in a temporary folder), the built wheel installed with the ``tour`` extra by
the README's own line (``pip install "$(ls dist/pendulab-*.whl)[tour]"``, run in bash beside a
``dist/`` that holds the wheel), then every notebook copied into a folder of its own and run from top
to bottom in that environment's kernel (nbclient, from the extra) — not the development ``.venv``.

Each notebook must finish within ``--limit`` seconds (default 20, issue 31), measured from its first
cell to the end of its last (the kernel's start, 2–3 s, is printed apart and not counted); a slower
notebook fails the run with its name, its time and its slowest cell. So does a deprecation a notebook
teaches (as pytest's warnings-as-errors would, and test_tour.py does in the development environment): a
``DeprecationWarning``, ``PendingDeprecationWarning`` or ``FutureWarning`` raised for a cell's code or
for pendulab's (:data:`WATCH`, run first in the kernel) names the cell, its line and the warning; one
that another library raises for its own code is only shown. Every notebook is run and reported
before the verdict, so one run names every failure. What is compared with the limit is the wall time,
unless the machine is busier than its CPUs (load average, ``os.getloadavg``, above the CPU count, before
or after the notebook): then the wall time measures the other work, and the kernel's CPU time (all its
threads, and its child processes that ended, read by a cell added before the first and after the last)
is compared instead (``--measure`` chooses). Both are printed, with the load.

Nothing here reads the checkout except README.md, the notebooks and the wheel. pip's download cache is
the user's own (``~/.cache/pip``), so a second run installs from it.
Usage: python3 tools/check_tour.py [DIST_DIR] [--limit SECONDS] [--only NAME ...]
(``make test-tour-wheel`` after ``make wheel``; ``make test`` runs it).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]
TOUR = REPO / "docs" / "tour"
INSTALL_TIMEOUT = 900.0  # s, the README's install line (pip, from a warm cache about a minute)
CELL_TIMEOUT = 60  # s, one cell (nbclient stops the notebook there)
INSTALL_LINE = 'pip install "$(ls dist/pendulab-*.whl)[tour]"'
# Run first in the kernel (in the cell that reads the CPU time before the notebook's first): warnings are
# shown (deprecations too), and a deprecation raised for a cell's code (where a deprecation's stacklevel
# points) or for pendulab's also prints a line starting with DEPRECATED (on stderr, in the cell's
# output), which fails the notebook (test_tour.py uses the same two).
DEPRECATED = "pendulab-docs deprecated:"
WATCH = f"""
import os as _os, sys as _sys, warnings as _warnings
import pendulab as _pendulab

def _watch(show, package, cells):
    def record(message, category, filename, lineno, file=None, line=None):
        show(message, category, filename, lineno, file, line)
        own = filename.startswith(package) or _os.path.dirname(filename) == cells
        if own and issubclass(category, (DeprecationWarning, PendingDeprecationWarning, FutureWarning)):
            print("{DEPRECATED}", f"line {{lineno}}: {{category.__name__}}: {{message}}", file=_sys.stderr)
    return record

for _category in (DeprecationWarning, PendingDeprecationWarning, FutureWarning):  # shown, not ignored
    _warnings.filterwarnings("default", category=_category)
_warnings.showwarning = _watch(
    _warnings.showwarning,
    _os.path.dirname(_pendulab.__file__) + _os.sep,
    _os.path.dirname(get_ipython().compile.get_code_name("", "", 0)),
)
del _watch, _category
"""
WORDS = {"wall": "(wall time)", "cpu": "(the kernel's CPU time: the machine is busier than its CPUs)"}

# Run by the fresh environment's python: one notebook, timed cell by cell; prints one JSON line.
RUNNER = r"""
import json, sys, time
import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

path, work, cell_timeout = sys.argv[1], sys.argv[2], float(sys.argv[3])
watch, marker = sys.argv[4], sys.argv[5]  # WATCH and DEPRECATED
nb = nbformat.read(path, as_version=4)
# the kernel's CPU time (all its threads, and its children that have ended: a Dask cluster's workers)
# read by a cell before the notebook's first and one after its last; the first also runs WATCH
PROBE = ("import resource as _r\n"
         "print(sum(getattr(_r.getrusage(w), f) for w in (_r.RUSAGE_SELF, _r.RUSAGE_CHILDREN) "
         "for f in ('ru_utime', 'ru_stime')))")
n = len(nb.cells)
nb.cells = [nbformat.v4.new_code_cell(watch + PROBE)] + nb.cells + [nbformat.v4.new_code_cell(PROBE)]
marks = {}
def started(cell, cell_index, **_):
    marks[cell_index] = time.perf_counter()
def done(cell, cell_index, **_):
    marks[("end", cell_index)] = time.perf_counter()
client = NotebookClient(nb, timeout=cell_timeout, kernel_name="python3",
                        resources={"metadata": {"path": work}},
                        on_cell_start=started, on_cell_executed=done)
t0 = time.perf_counter()
error = None
try:
    client.execute()
except CellExecutionError as e:
    error = str(e)[-3000:]
except Exception as e:  # a timeout, a dead kernel: named, not a traceback of nbclient
    error = f"{type(e).__name__}: {e}"[-3000:]
t1 = time.perf_counter()
taught = [f"cell {i}, {line.removeprefix(marker).strip()}" for i, cell in enumerate(nb.cells[1 : n + 1], 1)
          for out in cell.get("outputs", []) if out.get("name") == "stderr"
          for line in out.get("text", "").splitlines() if line.startswith(marker)]
if taught:
    said = "uses what is deprecated (write what the warning says):\n" + "\n".join(taught)
    error = said if error is None else f"{error}\n{said}"
cells = {i: marks[("end", i)] - marks[i] for i in range(1, n + 1) if i in marks and ("end", i) in marks}
first, last = marks.get(1, t1), marks.get(("end", n), t1)
def cpu(cell):  # its stdout (a warning the first cell shows goes to stderr)
    try:
        return float(next(o for o in cell.outputs if o.get("name") == "stdout")["text"])
    except (StopIteration, KeyError, ValueError):
        return float("nan")
slow = max(cells, key=cells.get) if cells else None
print(json.dumps({"seconds": last - first, "cpu": cpu(nb.cells[-1]) - cpu(nb.cells[0]),
                  "kernel_start": marks.get(0, t1) - t0, "error": error,
                  "slowest_cell": None if slow is None else slow - 1,
                  "slowest_seconds": cells.get(slow, 0.0)}))
"""


def say(msg: str) -> None:
    print(f"check_tour: {msg}", flush=True)


def install(wheel: Path, tmp: Path, env: dict[str, str]) -> Path:
    """The README's install line in a fresh environment; returns the environment."""
    readme = (REPO / "README.md").read_text(encoding="utf-8")
    if INSTALL_LINE not in readme:
        sys.exit(f"check_tour: README.md no longer says {INSTALL_LINE!r}: update this script with it")
    home, src = tmp / "home", tmp / "src"
    (src / "dist").mkdir(parents=True)
    home.mkdir()
    (src / "dist" / wheel.name).symlink_to(wheel)
    venv = home / "pendulab-tour"
    script = f"set -e\npython3 -m venv {venv}\n. {venv}/bin/activate\n{INSTALL_LINE}\n"
    t0 = time.perf_counter()
    p = subprocess.run(
        ["bash", "-c", script],
        cwd=src,
        env={**env, "HOME": str(home)},
        capture_output=True,
        text=True,
        timeout=INSTALL_TIMEOUT,
        check=False,
    )
    if p.returncode != 0:
        sys.exit(
            f"check_tour: FAILED: {INSTALL_LINE} in a fresh environment:\n"
            f"{p.stdout[-3000:]}\n{p.stderr[-3000:]}"
        )
    say(f"ok ({time.perf_counter() - t0:.1f} s): python3 -m venv, then {INSTALL_LINE}")
    return venv


def run_notebook(py: str, path: Path, env: dict[str, str]) -> dict[str, Any]:
    """The notebook ``path`` run by :data:`RUNNER` in ``py``'s environment, in its folder: its times,
    slowest cell and ``error`` (None, or what failed: a cell, a timeout, a deprecation it teaches)."""
    p = subprocess.run(
        [py, "-c", RUNNER, str(path), str(path.parent), str(CELL_TIMEOUT), WATCH, DEPRECATED],
        cwd=path.parent,
        env=env,
        capture_output=True,
        text=True,
        timeout=30 * CELL_TIMEOUT,
        check=False,
    )
    lines = [line for line in p.stdout.splitlines() if line.startswith("{")]
    if p.returncode != 0 or not lines:
        nan = float("nan")
        return {"seconds": nan, "cpu": nan, "kernel_start": nan, "error": p.stderr[-3000:] or "no result"}
    out: dict[str, Any] = json.loads(lines[-1])
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dist", nargs="?", type=Path, default=REPO / "dist")
    ap.add_argument("--limit", type=float, default=20.0, help="seconds one notebook may take (default 20)")
    ap.add_argument("--only", nargs="*", default=[], help="run only notebooks whose names contain these")
    ap.add_argument(
        "--measure",
        choices=("auto", "wall", "cpu"),
        default="auto",
        help="what is compared with the limit: wall time, the kernel's CPU time, or auto (default): wall "
        "time, CPU time when the load average exceeds the CPU count",
    )
    args = ap.parse_args()
    wheels = sorted(args.dist.glob("pendulab-*.whl"))
    if len(wheels) != 1:
        sys.exit(
            f"check_tour: expected one pendulab wheel in {args.dist}, found {len(wheels)}: run make wheel"
        )
    notebooks = sorted(TOUR.glob("*.ipynb"))
    if args.only:
        notebooks = [nb for nb in notebooks if any(w in nb.name for w in args.only)]
    if not notebooks:
        sys.exit(f"check_tour: no notebooks in {TOUR}")
    t_start = time.perf_counter()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME")}
    env.setdefault("PIP_CACHE_DIR", str(Path.home() / ".cache" / "pip"))
    env.update(PYTHONUNBUFFERED="1", MPLBACKEND="Agg", PYTHONHASHSEED="0")
    with tempfile.TemporaryDirectory(prefix="pendulab-tour-") as tmp_name:
        tmp = Path(tmp_name)
        venv = install(wheels[0].resolve(), tmp, env)
        env["HOME"] = str(tmp / "home")  # no kernel or configuration of the user's own
        env["JUPYTER_PLATFORM_DIRS"] = "1"
        env["PATH"] = f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}"
        py = str(venv / "bin" / "python")
        results = []
        cpus = os.cpu_count() or 1
        for nb in notebooks:
            work = tmp / "work" / nb.stem
            work.mkdir(parents=True)
            shutil.copy2(nb, work / nb.name)
            load = os.getloadavg()[0]
            r = run_notebook(py, work / nb.name, env)
            load = max(load, os.getloadavg()[0])
            by = args.measure if args.measure != "auto" else ("cpu" if load > cpus else "wall")
            r |= {"name": nb.name, "load": load, "by": by, "time": r["cpu"] if by == "cpu" else r["seconds"]}
            results.append(r)
            verdict = "FAIL" if r["error"] else ("SLOW" if not r["time"] <= args.limit else "ok  ")
            say(
                f"{verdict} {nb.name}: {r['time']:.1f} s {WORDS[by]} (wall {r['seconds']:.1f} s, CPU "
                f"{r['cpu']:.1f} s, kernel start {r['kernel_start']:.1f} s, slowest cell "
                f"{r.get('slowest_cell')}: {r.get('slowest_seconds', 0.0):.1f} s; load {load:.1f})"
            )
    problems = [f"{r['name']} failed:\n{r['error']}" for r in results if r["error"]]
    problems += [
        f"{r['name']} took {r['time']:.1f} s {WORDS[r['by']]}, over the {args.limit:g} s limit (slowest cell "
        f"{r.get('slowest_cell')}: {r.get('slowest_seconds', 0):.1f} s wall; load average {r['load']:.1f} on "
        f"{cpus} CPUs)"
        for r in results
        if not r["error"] and not r["time"] <= args.limit
    ]
    total = sum(r["seconds"] for r in results if r["seconds"] == r["seconds"])  # nan: not run
    summary = {
        "notebooks": len(results),
        "tour_seconds": round(total, 1),
        "all_seconds": round(time.perf_counter() - t_start, 1),
    }
    say(json.dumps(summary))
    if problems:
        sys.exit("check_tour: FAILED:\n" + "\n".join(problems))


if __name__ == "__main__":
    main()
