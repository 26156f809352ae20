"""A seeded corpus of mutated scenario files through ``pendulab validate`` and ``pendulab run``
(issue 13; the generator and the rules: ``tools/fuzz_scenarios.py``). CI runs ``FUZZ_FILES`` files
(default 80; valid files are run up to 2e4 steps); ``make fuzz`` runs 2 500 and prints the counts.
A smaller ``FUZZ_FILES`` (5) checks those files and then the corpus's next ones, up to its 80th, only
until every outcome has been reached (file k is the same whatever the number: it depends on the seed
and k only), so that the count check holds for any number: before, 5 files were all refused and the
check failed."""

from __future__ import annotations

import os
from pathlib import Path

from conftest import load_tool

FILES = int(os.environ.get("FUZZ_FILES", "80"))
REACH = 80
"""The corpus (seed 13) reaches every outcome of both commands within its first ``REACH`` files."""
OUTCOMES = ("validate: exit 0", "validate: exit 2", "run: exit 0", "run: exit 2")


def test_mutated_scenarios_exit_0_or_2_with_error_lines_only(tmp_path: Path) -> None:
    fz = load_tool("fuzz_scenarios")
    tally = fz.Tally()
    for k, path in enumerate(fz.generate(max(FILES, REACH), seed=13, directory=tmp_path)):
        if k >= FILES and all(tally.counts[o] for o in OUTCOMES):
            break
        fz.check_file(path, tally, run_work=2e4)
    assert not tally.failures, tally.failures[:10]
    # the corpus reaches both outcomes of both commands
    assert all(tally.counts[o] > 0 for o in OUTCOMES), tally.counts
