"""A seeded corpus of mutated scenario files through ``pendulab validate`` and ``pendulab run``
(issue 13; the generator and the rules: ``tools/fuzz_scenarios.py``). CI runs ``FUZZ_FILES`` files
(default 80; valid files are run up to 2e4 steps); ``make fuzz`` runs 2 500 and prints the counts."""

from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path

from conftest import REPO

FILES = int(os.environ.get("FUZZ_FILES", "80"))


def _corpus_module():  # tools/ is not a package: load the script by path
    spec = importlib.util.spec_from_file_location("fuzz_scenarios", REPO / "tools" / "fuzz_scenarios.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def test_mutated_scenarios_exit_0_or_2_with_error_lines_only(tmp_path: Path) -> None:
    fz = _corpus_module()
    tally = fz.Tally()
    for path in fz.generate(FILES, seed=13, directory=tmp_path):
        fz.check_file(path, tally, run_work=2e4)
    assert not tally.failures, tally.failures[:10]
    # the corpus reaches both outcomes of both commands
    assert tally.counts["validate: exit 0"] > 0 and tally.counts["validate: exit 2"] > 0, tally.counts
    assert tally.counts["run: exit 0"] > 0 and tally.counts["run: exit 2"] > 0, tally.counts
