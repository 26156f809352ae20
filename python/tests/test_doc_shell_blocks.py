"""The shell blocks of README.md and docs/*.md run as written: each command succeeds (or fails as its
transcript shows) and prints the lines the page shows; synopses and ``make`` lines name what exists (the
rules: doc_blocks.py)."""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import warnings
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import pytest
from conftest import REPO
from doc_blocks import ALL, TIMEOUT, Block, env, isolated, kind, skipped, workdir


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
    line; :func:`isolated`), anything with shell syntax (pipes, globs, variables) in bash."""
    words = shlex.split(text, comments=True)
    if words[0] == "pendulab" and not _SHELL_SYNTAX.search(text):
        from typer.testing import CliRunner

        from pendulab import cli

        with isolated():
            os.chdir(work)
            warnings.simplefilter("default")  # as for a user: printed, not raised (pytest's "error")
            result = CliRunner().invoke(cli.app, words[1:])
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            raise result.exception
        return result.exit_code, result.stderr, result.stdout
    p = subprocess.run(
        ["bash", "-c", text], cwd=work, env=env(), capture_output=True, text=True, timeout=TIMEOUT
    )
    return p.returncode, p.stderr, p.stdout


SHELL = [b for b in ALL if kind(b) == "shell" and not skipped(b)]


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
        code, stderr, stdout = run(c.text, work)
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
