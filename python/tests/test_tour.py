"""The guided tour (docs/tour/*.ipynb): every notebook is stored without outputs and runs from top to
bottom in a fresh kernel within its time limit. The notebooks check their own claims with ``assert``
(Newton's law along the motion, the slack height of a string, observed orders, Holm's relations and the
sign of the Nambu flow, T-4.2 against SciPy's elliptic functions, the phase split of T-5.1, monodromy,
Foucault's 31.8 h, an ensemble row against pl.simulate), so a failing claim fails this test.

A notebook added to docs/tour/ is picked up automatically. Each runs in its own temporary directory
(the movies they write go there). This runs them in the development environment (``make test-tour``);
``make test`` leaves ``test_notebook_runs`` out and runs them instead as a user would, in a fresh
environment with the wheel's ``tour`` extra, each within 20 s (``tools/check_tour.py``).
"""

from __future__ import annotations

import os
import re
import sys
import time
import tomllib
from pathlib import Path

import pytest
from conftest import REPO, load_tool

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

TOUR = REPO / "docs" / "tour"
NOTEBOOKS = sorted(TOUR.glob("*.ipynb"))

CELL_TIMEOUT = 60
"""Seconds one cell may take (nbclient stops the notebook after that)."""

NOTEBOOK_LIMIT = 120
"""Seconds one notebook may take in all: twice the one minute each is written for, so that a busy CI
machine does not fail it; they take 7–14 s each on the 2-core reference machine, up to 25 s under
load (docs/tour/index.md)."""


def test_the_tour_has_its_notebooks_and_the_readme_counts_them():
    names = [p.name for p in NOTEBOOKS]
    assert names[:8] == [
        "01_newton_lagrange.ipynb",
        "02_hamiltonian_integrators.ipynb",
        "03_reduction.ipynb",
        "04_exact_solution.ipynb",
        "05_phases.ipynb",
        "06_real_pendulums.ipynb",
        "07_many_trajectories.ipynb",
        "08_fitting.ipynb",
    ]
    words = {7: "Seven", 8: "Eight", 9: "Nine", 10: "Ten", 11: "Eleven", 12: "Twelve"}
    readme = (REPO / "README.md").read_text(encoding="utf-8")
    assert f"{words[len(names)]} Jupyter notebooks in `docs/tour/`" in readme


# third-party modules the notebooks import -> the distribution that brings them
_DISTRIBUTION = {"matplotlib": "matplotlib", "scipy": "scipy", "distributed": "dask", "IPython": "ipykernel"}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_states_its_extra_and_the_extra_has_what_it_imports(path: Path):
    nb = nbformat.read(path, as_version=4)
    top = nb.cells[0]
    assert top.cell_type == "markdown" and "[tour]" in top.source, f"{path.name}: say the extra at the top"
    extra = tomllib.loads((REPO / "python" / "pyproject.toml").read_text())["project"][
        "optional-dependencies"
    ]
    tour = {re.split(r"[\[<>=]", req)[0] for req in extra["tour"]}
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        for module in re.findall(r"^\s*(?:from|import)\s+(\w+)", cell.source, flags=re.M):
            if module in _DISTRIBUTION:
                assert _DISTRIBUTION[module] in tour, (
                    f"{path.name} imports {module}: add it to the tour extra"
                )
        if ".mp4" in cell.source or ".webm" in cell.source:
            assert "imageio-ffmpeg" in tour


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_is_stored_without_outputs(path: Path):
    nb = nbformat.read(path, as_version=4)
    for cell in nb.cells:
        if cell.cell_type == "code":
            assert cell.outputs == [] and cell.execution_count is None, f"{path.name}: clear the outputs"


# Run first, in the kernel (a cell of its own, not stored): warnings are shown (deprecations too), and a
# deprecation raised for a cell's code or for pendulab's prints a line starting with DEPRECATED, which
# fails the notebook (as doc_blocks.no_deprecations does for the pages). The same two as
# tools/check_tour.py, which runs the tour against the wheel.
CHECK_TOUR = load_tool("check_tour")
WATCH, DEPRECATED = CHECK_TOUR.WATCH, CHECK_TOUR.DEPRECATED


def deprecations(nb: nbformat.NotebookNode, folder: Path) -> list[str]:
    """Runs ``nb`` in a fresh kernel in ``folder`` (raises ``CellExecutionError``, with the cell and
    traceback, if a cell fails); returns a line for each deprecation a cell makes (:data:`WATCH`), naming
    the cell (counted from 1) and the warning."""
    nb.cells.insert(0, nbformat.v4.new_code_cell(WATCH))
    client = nbclient.NotebookClient(
        nb, timeout=CELL_TIMEOUT, kernel_name="python3", resources={"metadata": {"path": str(folder)}}
    )
    client.execute()
    return [
        f"cell {i}, {line.removeprefix(DEPRECATED).strip()}"
        for i, cell in enumerate(nb.cells[1:], 1)
        for out in cell.get("outputs", [])
        if out.get("name") == "stderr"
        for line in out.text.splitlines()
        if line.startswith(DEPRECATED)
    ]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path: Path, tmp_path: Path):
    nb = nbformat.read(path, as_version=4)
    start = time.perf_counter()
    found = deprecations(nb, tmp_path)
    seconds = time.perf_counter() - start
    assert not found, f"{path.name} uses what is deprecated (write what the warning says):\n" + "\n".join(
        found
    )
    assert seconds < NOTEBOOK_LIMIT, f"{path.name} took {seconds:.0f} s (limit {NOTEBOOK_LIMIT} s)"


OLD_CALL_CELLS = [
    "import warnings\nfrom pendulab import crane\nc = crane.Crane(10.0)",
    "warnings.warn('shown on purpose', UserWarning)\n"
    "warnings.warn_explicit('theirs', FutureWarning, warnings.__file__, 1)",  # another library's own
    "run = c.simulate(1.0, sway=(0.1, 0.0), dt=0.1)",
]
"""A notebook whose third cell makes a deprecated call (line 1), after warnings that are not deprecations."""


def test_a_deprecated_call_in_a_notebook_is_found(tmp_path: Path):
    cells = [*OLD_CALL_CELLS, "warnings.warn('old', PendingDeprecationWarning)"]
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    found = deprecations(nb, tmp_path)
    assert [f.split(":")[0] for f in found] == ["cell 3, line 1", "cell 4, line 1"]
    assert "DeprecationWarning: Crane.simulate(dt=...) is deprecated" in found[0]
    assert found[1].endswith("PendingDeprecationWarning: old")


def test_the_wheels_tour_run_fails_a_notebook_that_uses_a_deprecated_call(tmp_path: Path):
    # tools/check_tour.py's run of one notebook (here in this environment, not a fresh one with the wheel)
    cells = [*OLD_CALL_CELLS[:2], "x = 1\n" + OLD_CALL_CELLS[2]]  # the call on line 2
    path = tmp_path / "old.ipynb"
    nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells]), path)
    r = CHECK_TOUR.run_notebook(sys.executable, path, {**os.environ, "MPLBACKEND": "Agg"})
    assert r["error"] is not None and r["error"].startswith("uses what is deprecated"), r["error"]
    said = r["error"].splitlines()[1:]
    assert len(said) == 1 and said[0].startswith("cell 3, line 2: DeprecationWarning: Crane.simulate(dt=")
    path.write_text(path.read_text().replace("dt=0.1", "output_spacing=0.1"))
    assert CHECK_TOUR.run_notebook(sys.executable, path, {**os.environ, "MPLBACKEND": "Agg"})["error"] is None
