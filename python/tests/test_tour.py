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

import re
import time
import tomllib
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
