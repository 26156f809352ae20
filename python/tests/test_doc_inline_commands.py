"""Every ``pendulab`` command written inline in the prose of README.md and docs/*.md (in backticks,
outside code blocks: "`pendulab crane grid --ropes 5:30:50 --plot grid.png`") names options that its
``--help`` lists. The code blocks are run by test_doc_blocks.py (python, toml) and
test_doc_shell_blocks.py (shell); these are only read, so that an option renamed or removed cannot stay
in a sentence. Backticked text that is not a command of the app
("`pendulab X.Y.Z`", a table's "`pendulab rattle (simulate)`") is not a command and is left alone."""

from __future__ import annotations

import re
import shlex
from functools import cache

from conftest import REPO
from typer.testing import CliRunner

from pendulab import cli

PAGES = [REPO / "README.md", *sorted(p for p in (REPO / "docs").rglob("*.md") if p.name != "README.md")]
_OPTION = re.compile(r"(?<![\w-])(--?[a-zA-Z][\w-]*)")


@cache
def _help(path: tuple[str, ...]) -> str | None:
    result = CliRunner().invoke(cli.app, [*path, "--help"])
    return result.stdout if result.exit_code == 0 else None


def inline_commands() -> list[tuple[str, tuple[str, ...], list[str], str]]:
    """(where, command path, its other words, the text) of every inline command of the app."""
    found = []
    for page in PAGES:
        in_fence = False
        for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
            if line.startswith("```"):
                in_fence = not in_fence
                continue
            if in_fence:
                continue
            for text in re.findall(r"`(pendulab [^`]+)`", line):
                try:
                    words = shlex.split(text.replace("…", " ").replace("\\|", "|"))
                except ValueError:  # an unbalanced quote in prose: not a command
                    continue
                path = tuple(words[1:3]) if words[1:2] == ["crane"] else tuple(words[1:2])
                if not path or path[0].startswith("-") or _help(path) is None:
                    continue
                where = f"{page.relative_to(REPO).as_posix()}:{number}"
                found.append((where, path, words[1 + len(path) :], text))
    return found


def test_inline_commands_name_only_options_that_exist() -> None:
    commands = inline_commands()
    assert len(commands) >= 40, commands  # the extraction works (a regex finding nothing passes vacuously)
    wrong = []
    for where, path, rest, text in commands:
        helptext = _help(path)
        assert helptext is not None
        for word in rest:
            for option in _OPTION.findall(word):
                if not re.search(rf"(?<![\w-]){re.escape(option)}(?![\w-])", helptext):
                    wrong.append(f"{where}: `{text}`: pendulab {' '.join(path)} has no option {option}")
    assert not wrong, "\n".join(wrong)
