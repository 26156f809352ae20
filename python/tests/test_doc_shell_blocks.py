"""The shell blocks of README.md and docs/*.md run as written: each command succeeds (or fails as its
transcript shows) and prints the lines the page shows; synopses and ``make`` lines name what exists (the
rules: doc_blocks.py). A command that several blocks show (:data:`REPEATED`: the same text, such as
``pendulab fit examples/data/filmed_swing.csv … --out fitted.toml`` of the README, docs/cli.md and
docs/fit.md) runs once per session in a folder holding the same files (:func:`run_once`); every block
checks its exit code and output against what the block shows, and finds the files it wrote."""

from __future__ import annotations

import builtins
import hashlib
import os
import re
import shlex
import shutil
import subprocess
import time
import warnings
from collections import Counter
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import doc_blocks
import pytest
from conftest import REPO
from doc_blocks import (
    ALL,
    Block,
    TooLong,
    env,
    isolated,
    kind,
    no_deprecations,
    skipped,
    time_limit,
    workdir,
)


@dataclass(frozen=True)
class Command:
    text: str
    expect_error: bool
    shown: tuple[str, ...] = ()  # the output lines a transcript shows for it


def commands(b: Block) -> list[Command]:
    lines = b.text.splitlines()
    out: list[Command] = []
    if any(ln.startswith("$ ") for ln in lines):  # a transcript: commands and their output
        for i, ln in enumerate(lines):
            if ln.startswith("$ "):
                shown = []
                for x in lines[i + 1 :]:
                    if x.startswith("$ "):
                        break
                    shown.append(x)
                shown = [x for x in shown if x.strip()]
                error = any(x.startswith("error:") for x in shown)
                out.append(Command(ln[2:].strip(), error, tuple(shown)))
        return out
    for ln in lines:
        if not ln.strip():
            continue
        if ln[0].isspace() and out:  # the continuation of a long synopsis
            out[-1] = Command(out[-1].text + " " + ln.strip(), False)
        else:
            out.append(Command(re.sub(r"\s+#\s.*$", "", ln).strip(), False))
    return out


def is_synopsis(cmd: str) -> bool:
    words = shlex.split(cmd, comments=True)
    if words[:2] == ["pendulab", "serve"]:
        return True
    return any(
        w.startswith("[")
        or w in ("...", "…")
        or re.fullmatch(r"[A-Z][A-Z_]*(\.\w+)?(:[A-Z_:]+)?", w)
        or re.search(r"://[A-Z][A-Z_]*(:|/|$)", w)  # an address to fill in, tcp://HOST:8786: never run
        for w in words
    )


@cache
def _help(sub: str) -> str:
    from typer.testing import CliRunner

    from pendulab import cli

    result = CliRunner().invoke(cli.app, [sub, "--help"])
    assert result.exit_code == 0, f"pendulab {sub} --help failed: {result.output}"
    return result.stdout


def check_synopsis(cmd: str, where: str) -> None:
    words = shlex.split(cmd, comments=True)
    assert words[0] == "pendulab", f"{where}: a synopsis of something other than pendulab: {cmd!r}"
    sub = words[1]
    if sub.startswith("-"):
        return
    text = _help(sub)
    for w in words[2:]:
        for opt in re.findall(r"(?<![\w-])(--?[a-zA-Z][\w-]*)", w):
            assert re.search(rf"(?<![\w-]){re.escape(opt)}(?![\w-])", text), (
                f"{where}: `{cmd}`: pendulab {sub} has no option {opt}"
            )


_SHELL_SYNTAX = re.compile(r"[|&;<>*?$`~(){}]")
_ROUND_OFF = re.compile(r"\d\.\d+e-(?:1[3-9]|[2-9]\d|\d{3})")


def shown_pattern(line: str) -> re.Pattern[str]:
    """The regular expression a shown output line stands for (the rules: doc_blocks.py)."""
    line = re.sub(r"\s+\(stderr\)$", "", line.rstrip())
    parts = re.split(r"(…|'fused'|, fused arithmetic|" + _ROUND_OFF.pattern + ")", line)
    wild = {"…": ".*", "'fused'": "'(?:un)?fused'", ", fused arithmetic": ", (?:un)?fused arithmetic"}
    return re.compile(
        "".join(wild.get(x, r"[-+0-9.e]+" if _ROUND_OFF.fullmatch(x) else re.escape(x)) for x in parts)
    )


def check_shown(c: Command, printed: str, where: str) -> None:
    lines = [ln.rstrip() for ln in printed.splitlines()]
    for shown in c.shown:
        pattern = shown_pattern(shown)
        assert any(pattern.fullmatch(ln) for ln in lines), (
            f"{where}: `{c.text}` does not print the line the page shows:\n{shown}\n"
            f"it printed:\n{printed[-3000:]}"
        )


def run(text: str, work: Path) -> tuple[int, str, str]:
    """Exit code, stderr and stdout of one command run in ``work``: a plain ``pendulab …`` line in this
    process (typer's CliRunner: the same app as the ``pendulab`` script, without a second of start-up per
    line; :func:`isolated`, :func:`time_limit`; a deprecation it makes fails: :func:`no_deprecations`),
    anything with shell syntax (pipes, globs, variables) in bash; each within :data:`TIMEOUT` s."""
    words = shlex.split(text, comments=True)
    if words[0] == "pendulab" and not _SHELL_SYNTAX.search(text):
        from typer.testing import CliRunner

        from pendulab import cli

        with time_limit(f"`{text}`"), isolated():
            os.chdir(work)
            warnings.simplefilter("default")  # as for a user: printed, not raised (pytest's "error")
            with no_deprecations(f"`{text}`"):
                result = CliRunner().invoke(cli.app, words[1:])
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            raise result.exception
        return result.exit_code, result.stderr, result.stdout
    p = subprocess.run(
        ["bash", "-c", text], cwd=work, env=env(), capture_output=True, text=True, timeout=doc_blocks.TIMEOUT
    )
    return p.returncode, p.stderr, p.stdout


Files = dict[str, bytes | None]  # a folder's contents (_files)
# (command, the folder's files by digest before it ran) -> (exit code, stderr, stdout), the files after it
_DONE: dict[tuple[str, tuple[tuple[str, str | None], ...]], tuple[tuple[int, str, str], Files]] = {}


def _files(work: Path) -> Files:
    """Every folder (None) and file (its bytes) under ``work``; links (``examples``) neither listed nor
    followed."""
    out: Files = {}
    for root, dirs, names in os.walk(work):
        for name in dirs + names:
            path = Path(root, name)
            if not path.is_symlink():
                out[path.relative_to(work).as_posix()] = None if path.is_dir() else path.read_bytes()
    return out


def run_once(text: str, work: Path) -> tuple[int, str, str]:
    """:func:`run`, once per session for a command in a folder holding the same files: a later call gets the
    first one's exit code, stderr and stdout, and its folder is left as the first run left its own (files
    written, changed, removed)."""
    before = _files(work)
    digests = ((k, v if v is None else hashlib.sha256(v).hexdigest()) for k, v in before.items())
    key = text, tuple(sorted(digests))
    if key not in _DONE:
        result = run(text, work)
        _DONE[key] = result, _files(work)
        return result
    result, after = _DONE[key]
    for rel in sorted(set(before) - set(after), reverse=True):  # what a folder holds before the folder
        if before[rel] is None:
            shutil.rmtree(work / rel)
        else:
            (work / rel).unlink()
    for rel, data in sorted(after.items()):  # a folder before what it holds
        if data is None:
            (work / rel).mkdir(exist_ok=True)
        elif before.get(rel) != data:
            (work / rel).write_bytes(data)
    return result


SHELL = [b for b in ALL if kind(b) == "shell" and not skipped(b)]
# commands shown by more than one block (or twice in one): run once per session (run_once)
REPEATED = {t for t, n in Counter(c.text for b in SHELL for c in commands(b)).items() if n > 1}


@pytest.mark.parametrize("block", SHELL, ids=[b.where for b in SHELL])
def test_shell_blocks_run_as_written(block: Block, tmp_path: Path) -> None:
    work = workdir(tmp_path)
    for c in commands(block):
        words = shlex.split(c.text, comments=True)
        if words[0] == "make":
            target = words[1] if len(words) > 1 else ""
            p = subprocess.run(
                ["make", "-n", *words[1:]], cwd=REPO, capture_output=True, text=True, timeout=60
            )
            assert p.returncode == 0, f"{block.where}: make has no target {target!r}: {p.stderr}"
            continue
        if words[0] in (".", "source"):
            assert (REPO / words[1]).exists() or words[1].startswith("~"), f"{block.where}: no {words[1]}"
            continue
        if is_synopsis(c.text):
            check_synopsis(c.text, block.where)
            continue
        try:
            code, stderr, stdout = (run_once if c.text in REPEATED else run)(c.text, work)
        except BaseException as e:
            e.add_note(f"FAILED: the block at {block.where}")
            raise
        if words[0] == "pendulab":
            check_shown(c, stdout + stderr, block.where)
        if c.expect_error:
            assert code == 2 and "error:" in stderr, (
                f"{block.where}: `{c.text}` should fail (exit 2), got {code}:\n{stderr}"
            )
        else:
            assert code == 0, f"{block.where}: `{c.text}` failed ({code}):\n{stderr[-3000:]}"


def test_shown_lines_match_what_is_meant() -> None:
    assert shown_pattern("error: x.toml: bad (…)").fullmatch("error: x.toml: bad (and why)")
    assert shown_pattern("  rattle, dt = 0.001 s      (stderr)").fullmatch("  rattle, dt = 0.001 s")
    assert shown_pattern("max |J3 - J3_0| = 4.441e-16").fullmatch("max |J3 - J3_0| = 2.220e-16")
    assert not shown_pattern("max |E - E0| = 1.319e-06").fullmatch("max |E - E0| = 1.320e-06")
    assert shown_pattern("{'arithmetic': 'fused'}").fullmatch("{'arithmetic': 'unfused'}")
    shown = shown_pattern("rattle, dt = 0.001 s, fused arithmetic, saved every 10th step")
    assert shown.fullmatch("rattle, dt = 0.001 s, unfused arithmetic, saved every 10th step")
    assert not shown_pattern("error: missing.toml: No such file").fullmatch("error: missing.toml: other")
    assert is_synopsis("pendulab sweep s.toml --out s/ --scheduler tcp://HOST:8786 --resume")
    assert not is_synopsis("pendulab sweep s.toml --out s/ --workers 2")


def test_a_repeated_command_runs_once_and_leaves_its_files(tmp_path: Path) -> None:
    runs = tmp_path / "runs"  # a line each time the command really runs
    text = f"echo ran >> {runs}; mkdir -p out; echo $$ > out/pid.txt; rm -f gone.txt; echo printed $$"
    done = {}
    for name, gone in [("a", True), ("b", True), ("c", False)]:
        (tmp_path / name).mkdir()
        work = workdir(tmp_path / name)
        if gone:
            (work / "gone.txt").write_text("x")
        done[name] = run_once(text, work)
    assert done["b"] == done["a"] and done["a"][0] == 0 and done["a"][2].startswith("printed ")
    pid = done["a"][2].split()[1]
    written = {"out": None, "out/pid.txt": f"{pid}\n".encode()}  # and gone.txt removed
    assert _files(tmp_path / "b") == _files(tmp_path / "a") == written
    assert (tmp_path / "b" / "examples").is_symlink()
    assert done["c"] != done["a"]  # other files in the folder (no gone.txt): run again
    assert runs.read_text() == "ran\nran\n"


def _methods_then(then: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """``pendulab methods`` does ``then`` first: warns as pendulab's code deprecating something would, or
    takes 30 s."""
    from pendulab.cli import run as cli_run

    table = cli_run.method_table

    def slow_or_old() -> object:
        if then == "sleep":
            time.sleep(30)
        else:
            warnings.warn_explicit(f"old {then}", getattr(builtins, then), cli_run.__file__, 1)
        return table()

    monkeypatch.setattr(cli_run, "method_table", slow_or_old)


@pytest.mark.parametrize("category", ["DeprecationWarning", "PendingDeprecationWarning", "FutureWarning"])
def test_a_command_that_makes_a_deprecation_warning_fails(
    category: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _methods_then(category, monkeypatch)
    with pytest.raises(
        AssertionError, match=rf"`pendulab methods` uses what is deprecated.*\n.*{category}: old"
    ):
        run("pendulab methods", workdir(tmp_path))


def test_a_command_that_makes_another_warning_passes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _methods_then("UserWarning", monkeypatch)
    with warnings.catch_warnings(record=True) as shown:
        code, _, stdout = run("pendulab methods", workdir(tmp_path))
    assert code == 0 and "rattle" in stdout and [str(w.message) for w in shown] == ["old UserWarning"]


def test_a_command_run_in_this_process_has_a_time_limit(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _methods_then("sleep", monkeypatch)
    monkeypatch.setattr(doc_blocks, "TIMEOUT", 0.2)
    start = time.perf_counter()
    with pytest.raises(TooLong, match=r"`pendulab methods` did not finish within 0\.2 s"):
        run("pendulab methods", workdir(tmp_path))
    assert time.perf_counter() - start < 10
