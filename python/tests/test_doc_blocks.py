"""Every code block of README.md and docs/*.md runs as written (issue 31: a new user can follow any page
to the letter). Blocks are taken from the text, nothing is added to them:

- ``python`` blocks: the blocks of one page run in order, in one fresh namespace (names defined earlier
  on the page stay defined, as for a reader going down the page; nothing else is set up), in this
  process (no second start-up of Python, NumPy and pendulab per page; warnings are printed, as for a
  reader, not raised) with a temporary folder as the working folder, ``examples`` linked to the
  checkout's (the pages are written for the top of the checkout). A block that is a script (``if
  __name__ == "__main__":``) runs as its own file, in a child process. Matplotlib draws off screen
  (``Agg``).
- shell blocks (```` ```sh ````, ```` ```console ````, or untagged with a first line that is a command):
  each command runs in bash there, with ``pendulab`` and ``python`` of this environment first on PATH.
  In a transcript (lines ``$ command`` followed by its output) a command whose shown output has
  lines starting with ``error:`` must fail with exit code 2 and print ``error:``; every other command
  must succeed. The output shown for a ``pendulab`` command must be what it prints: every shown line
  (an annotation ``(stderr)`` at its end dropped) equals a line of its stdout or stderr, where ``…``
  stands for any text, a round-off figure (``4.441e-16``: an exponent of -13 or below) for any number
  and ``'fused'`` (``, fused arithmetic``) for ``'unfused'`` (``, unfused arithmetic``) too (both depend
  on the CPU's arithmetic: docs/cli.md).
  Commands that cannot finish are checked, not run: a synopsis line (placeholders in capitals such as
  ``FILE.toml`` or ``tcp://HOST:8786``, ``[optional parts]``, ``…``) and ``pendulab serve`` (a server
  runs until stopped) must name a real command and only options its ``--help`` lists (an address to
  fill in is never contacted); a ``make TARGET`` line must name a target of the Makefile (``make -n``;
  building takes minutes and is what CI does anyway).
- ``toml`` blocks are whole files, loaded as ``pendulab validate`` and ``pendulab sweep`` load them: a
  sweep file (a top-level ``quantity``) by the sweep file's loader, any other as a scenario (crane files
  too). A block whose first line is ``# examples/….toml (abridged)…`` shows part of that shipped file:
  each value it shows must be the file's.
- other blocks (output, file trees) are text.

A block preceded by ``<!-- docs-test: skip (reason) -->`` is not run; :data:`ALLOWED_SKIPS` keeps that
list short and explicit. The README's wheel-install block (``<!-- wheel-install … -->``) is run by
tools/check_wheel.py (``make test-wheel``), its sweep script by test_readme.py.
"""

from __future__ import annotations

import os
import re
import shlex
import signal
import subprocess
import sys
import tomllib
import warnings
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import pytest
from conftest import REPO

# The README and every page of the site (docs/ with its sub-folders: the tour's index, the reference),
# but not the READMEs mkdocs.yml leaves out of it (exclude_docs).
PAGES = [REPO / "README.md", *sorted(p for p in (REPO / "docs").rglob("*.md") if p.name != "README.md")]
COMMANDS = ("pendulab", "make", "python", "python3", "pip", ".", "source", "echo", "cd")
# Blocks that are not run, by page: (first line of the block, reason). Keep this short.
ALLOWED_SKIPS = {
    "README.md": {"make wheel": "run by tools/check_wheel.py (make test-wheel) against the built wheel"},
}
TIMEOUT = 300.0  # s, one page's python blocks or one shell command


@dataclass(frozen=True)
class Block:
    page: str
    line: int  # 1-based line of the opening fence
    lang: str
    text: str
    marker: str  # the HTML comment just before the block, if any

    @property
    def where(self) -> str:
        return f"{self.page}:{self.line}"


def _name(path: Path) -> str:
    """The page as the messages name it: README.md, cli.md, tour/index.md."""
    docs = REPO / "docs"
    return path.relative_to(docs).as_posix() if path.is_relative_to(docs) else path.name


def blocks(path: Path) -> list[Block]:
    lines = path.read_text(encoding="utf-8").split("\n")
    out, i = [], 0
    while i < len(lines):
        m = re.match(r"^```(\w*)\s*$", lines[i])
        if not m:
            i += 1
            continue
        j = i + 1
        while not lines[j].startswith("```"):
            j += 1
        k = i - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        marker = lines[k].strip() if k >= 0 and lines[k].strip().startswith("<!--") else ""
        out.append(Block(_name(path), i + 1, m.group(1), "\n".join(lines[i + 1 : j]), marker))
        i = j + 1
    return out


def kind(b: Block) -> str:
    """python, shell or text."""
    if b.lang == "python":
        return "python"
    if b.lang in ("sh", "bash", "console", "shell"):
        return "shell"
    if b.lang:
        return "text"
    first = next((ln for ln in b.text.splitlines() if ln.strip()), "")
    word = first.removeprefix("$ ").split(" ")[0]
    return "shell" if word in COMMANDS else "text"


def skipped(b: Block) -> str | None:
    """The reason a block is not run here, or None."""
    if "wheel-install" in b.marker:
        return "run by tools/check_wheel.py"
    m = re.match(r"<!--\s*docs-test:\s*skip\s*\((.+)\)\s*-->", b.marker)
    return m.group(1) if m else None


ALL = [b for page in PAGES for b in blocks(page)]


def test_skip_markers_are_few_and_listed() -> None:
    found = {(b.page, b.text.splitlines()[0].split("  #")[0].strip()) for b in ALL if skipped(b)}
    allowed = {(page, first) for page, entries in ALLOWED_SKIPS.items() for first in entries}
    assert found == allowed, f"skipped blocks {sorted(found)} != the list ALLOWED_SKIPS {sorted(allowed)}"


# ------------------------------------------------------------------------------------------ python


def _env() -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH",)}
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"
    env["MPLBACKEND"] = "Agg"
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    return env


@pytest.fixture
def work(tmp_path: Path) -> Path:
    (tmp_path / "examples").symlink_to(REPO / "examples")
    return tmp_path


PY_PAGES = sorted({b.page for b in ALL if kind(b) == "python" and not skipped(b)})


@pytest.mark.parametrize("page", PY_PAGES)
def test_python_blocks_run_as_written(page: str, work: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    todo = [b for b in ALL if b.page == page and kind(b) == "python" and not skipped(b)]
    scripts = [b for b in todo if re.search(r"""if __name__ == ["']__main__["']:""", b.text)]
    inline = [b for b in todo if b not in scripts]
    if scripts and page != "README.md":  # README.md's script: test_readme.py runs it, with its output checked
        for b in scripts:
            (work / "script.py").write_text(b.text, encoding="utf-8")
            _check([sys.executable, "script.py"], work, b.where)
    _exec_in_order(inline, work, monkeypatch)


def _exec_in_order(todo: list[Block], work: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The blocks ``todo`` in order in one fresh namespace, in this process, in the folder ``work``; each
    page within :data:`TIMEOUT` s. A failing block's error names it (``the block at fit.md:8``)."""
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.chdir(work)
    ns: dict[str, object] = {"__name__": "__docs__"}

    def too_long(signum: int, frame: object) -> None:
        raise TimeoutError(f"the python blocks of {todo[0].page} did not finish within {TIMEOUT:g} s")

    before = signal.signal(signal.SIGALRM, too_long)
    signal.setitimer(signal.ITIMER_REAL, TIMEOUT)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("default")  # as for a reader: printed, not raised (pytest's "error")
            for b in todo:
                try:
                    exec(compile(b.text, b.where, "exec"), ns)
                except BaseException as e:
                    e.add_note(f"FAILED: the block at {b.where}")
                    raise
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, before)
        if "matplotlib.pyplot" in sys.modules:  # a figure drawn with pyplot (xarray's .plot())
            sys.modules["matplotlib.pyplot"].close("all")


def _check(cmd: list[str], cwd: Path, where: str) -> subprocess.CompletedProcess[str]:
    p = subprocess.run(cmd, cwd=cwd, env=_env(), capture_output=True, text=True, timeout=TIMEOUT)
    assert p.returncode == 0, f"{where}:\n{p.stdout[-2000:]}\n{p.stderr[-4000:]}"
    return p


# -------------------------------------------------------------------------------------------- toml

TOML = [b for b in ALL if b.lang == "toml" and not skipped(b)]


def _shown(block: dict, file: dict, where: str, prefix: str = "") -> None:
    for key, value in block.items():
        assert key in file, f"{where}: {prefix}{key} is not in the file the block abridges"
        if isinstance(value, dict):
            _shown(value, file[key], where, f"{prefix}{key}.")
        else:
            assert value == file[key], f"{where}: {prefix}{key} = {value!r}, the file has {file[key]!r}"


@pytest.mark.parametrize("block", TOML, ids=[b.where for b in TOML])
def test_toml_blocks_are_valid_files(block: Block, tmp_path: Path) -> None:
    from pendulab import load_scenario
    from pendulab.sweeps.file import load_sweep_file

    data = tomllib.loads(block.text)
    abridged = re.match(r"#\s*(examples/\S+\.toml) \(abridged\)", block.text)
    if abridged:
        _shown(data, tomllib.loads((REPO / abridged.group(1)).read_text(encoding="utf-8")), block.where)
        return
    path = tmp_path / "block.toml"
    path.write_text(block.text, encoding="utf-8")
    if "quantity" in data:
        load_sweep_file(path)
    else:
        load_scenario(path)


# ------------------------------------------------------------------------------------------- shell


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


SHELL = [b for b in ALL if kind(b) == "shell" and not skipped(b)]


@pytest.mark.parametrize("block", SHELL, ids=[b.where for b in SHELL])
def test_shell_blocks_run_as_written(block: Block, work: Path) -> None:
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
        code, stderr, stdout = _run(c.text, work)
        if words[0] == "pendulab":
            check_shown(c, stdout + stderr, block.where)
        if c.expect_error:
            assert code == 2 and "error:" in stderr, (
                f"{block.where}: `{c.text}` should fail (exit 2), got {code}:\n{stderr}"
            )
        else:
            assert code == 0, f"{block.where}: `{c.text}` failed ({code}):\n{stderr[-3000:]}"


_SHELL_SYNTAX = re.compile(r"[|&;<>*?$`~(){}]")


_ROUND_OFF = re.compile(r"\d\.\d+e-(?:1[3-9]|[2-9]\d|\d{3})")


def shown_pattern(line: str) -> re.Pattern[str]:
    """The regular expression a shown output line stands for (see the module doc)."""
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


def _run(text: str, work: Path) -> tuple[int, str, str]:
    """Exit code, stderr and stdout of one command run in ``work``: a plain ``pendulab …`` line in this
    process (typer's CliRunner: the same app as the ``pendulab`` script, without a second of start-up per
    line), anything with shell syntax (pipes, globs, variables) in bash."""
    words = shlex.split(text, comments=True)
    if words[0] == "pendulab" and not _SHELL_SYNTAX.search(text):
        from typer.testing import CliRunner

        from pendulab import cli

        cwd = Path.cwd()
        os.chdir(work)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("default")  # as for a user: printed, not raised (pytest's "error")
                result = CliRunner().invoke(cli.app, words[1:])
        finally:
            os.chdir(cwd)
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            raise result.exception
        return result.exit_code, result.stderr, result.stdout
    p = subprocess.run(
        ["bash", "-c", text], cwd=work, env=_env(), capture_output=True, text=True, timeout=TIMEOUT
    )
    return p.returncode, p.stderr, p.stdout
