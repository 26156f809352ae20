"""``pendulab fit DATA`` names the data file as typed (``./nope.csv``, not the ``nope.csv`` that typer's
``Path`` made of it), as every other command names its file (test_cli.py)."""

from __future__ import annotations

from pathlib import Path

import pytest
from test_cli import assert_user_error, invoke


@pytest.mark.parametrize("typed", ["./nope.csv", ".//nope.csv", "sub/../nope.csv"])
def test_a_missing_data_file_is_named_as_typed(
    typed: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    assert_user_error(*invoke("fit", typed), f"error: {typed}: No such file")


def test_a_bad_data_file_is_named_as_typed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    Path("bad.csv").write_text("t,x\n0,1\n")  # no column a pendulum is fitted to
    assert_user_error(*invoke("fit", "./bad.csv"), "error: ./bad.csv: ")
