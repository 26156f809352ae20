"""A seeded corpus of mutated scenario files through ``pendulab validate`` and ``pendulab run``
(issue 13; the generator and the rules: ``tools/fuzz_scenarios.py``). CI runs ``FUZZ_FILES`` files
(default 80; valid files are run up to 2e4 steps); ``make fuzz`` runs 2 500 and prints the counts."""

from __future__ import annotations

import os
from pathlib import Path

from conftest import load_tool

FILES = int(os.environ.get("FUZZ_FILES", "80"))


def test_mutated_scenarios_exit_0_or_2_with_error_lines_only(tmp_path: Path) -> None:
    fz = load_tool("fuzz_scenarios")
    tally = fz.Tally()
    for path in fz.generate(FILES, seed=13, directory=tmp_path):
        fz.check_file(path, tally, run_work=2e4)
    assert not tally.failures, tally.failures[:10]
    # the corpus reaches both outcomes of both commands
    assert tally.counts["validate: exit 0"] > 0 and tally.counts["validate: exit 2"] > 0, tally.counts
    assert tally.counts["run: exit 0"] > 0 and tally.counts["run: exit 2"] > 0, tally.counts
