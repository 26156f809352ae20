"""The guided tour (docs/tour/*.ipynb): every notebook is stored without outputs and runs from top to
bottom in a fresh kernel within its time limit. The notebooks check their own claims with ``assert``
(Newton's law along the motion, the slack height of a string, observed orders, Holm's relations and the
sign of the Nambu flow, T-4.2 against SciPy's elliptic functions, the phase split of T-5.1, monodromy,
Foucault's 31.8 h, an ensemble row against pl.simulate), so a failing claim fails this test.

A notebook added to docs/tour/ is picked up automatically. Each runs in its own temporary directory
(the movies they write go there).
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest
from conftest import REPO

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


def test_the_tour_has_its_seven_notebooks():
    names = [p.name for p in NOTEBOOKS]
    assert names[:7] == [
        "01_newton_lagrange.ipynb",
        "02_hamiltonian_integrators.ipynb",
        "03_reduction.ipynb",
        "04_exact_solution.ipynb",
        "05_phases.ipynb",
        "06_real_pendulums.ipynb",
        "07_many_trajectories.ipynb",
    ]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_is_stored_without_outputs(path: Path):
    nb = nbformat.read(path, as_version=4)
    for cell in nb.cells:
        if cell.cell_type == "code":
            assert cell.outputs == [] and cell.execution_count is None, f"{path.name}: clear the outputs"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path: Path, tmp_path: Path):
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=CELL_TIMEOUT, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    )
    start = time.perf_counter()
    client.execute()  # raises CellExecutionError (with the cell and traceback) if any cell fails
    seconds = time.perf_counter() - start
    assert seconds < NOTEBOOK_LIMIT, f"{path.name} took {seconds:.0f} s (limit {NOTEBOOK_LIMIT} s)"
