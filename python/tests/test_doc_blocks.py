"""The python and toml blocks of README.md and docs/*.md run as written, and the list of blocks that are
not run is short (how blocks are found and run: doc_blocks.py; the shell blocks:
test_doc_shell_blocks.py)."""

from __future__ import annotations

import os
import random
import re
import signal
import sys
import threading
import time
import tomllib
import warnings
from pathlib import Path

import doc_blocks
import matplotlib
import numpy as np
import pytest
from conftest import REPO
from doc_blocks import ALL, ALLOWED_SKIPS, Block, TooLong, check, exec_in_order, kind, skipped, workdir


def test_skip_markers_are_few_and_listed() -> None:
    found = {(b.page, b.text.splitlines()[0].split("  #")[0].strip()) for b in ALL if skipped(b)}
    allowed = {(page, first) for page, entries in ALLOWED_SKIPS.items() for first in entries}
    assert found == allowed, f"skipped blocks {sorted(found)} != the list ALLOWED_SKIPS {sorted(allowed)}"


# ------------------------------------------------------------------------------------------ python

PY_PAGES = sorted({b.page for b in ALL if kind(b) == "python" and not skipped(b)})


@pytest.mark.parametrize("page", PY_PAGES)
def test_python_blocks_run_as_written(page: str, tmp_path: Path) -> None:
    work = workdir(tmp_path)
    todo = [b for b in ALL if b.page == page and kind(b) == "python" and not skipped(b)]
    scripts = [b for b in todo if re.search(r"""if __name__ == ["']__main__["']:""", b.text)]
    inline = [b for b in todo if b not in scripts]
    if scripts and page != "README.md":  # README.md's script: test_readme.py runs it, with its output checked
        for b in scripts:
            (work / "script.py").write_text(b.text, encoding="utf-8")
            check([sys.executable, "script.py"], work, b.where)
    exec_in_order(inline, work)


# A block that changes every piece of global state the guard puts back (doc_blocks.isolated).
LEAKY = """
import os, random, signal, sys, warnings
import matplotlib
import numpy as np
os.environ["PENDULAB_DOCS_LEAK"] = "1"
os.environ["PATH"] = "/nowhere"
os.chdir("/")
sys.path.insert(0, "/nowhere")
sys.stdout = sys.stderr
os.umask(0o077)
signal.signal(signal.SIGINT, signal.SIG_IGN)
np.set_printoptions(precision=2)
np.seterr(all="ignore")
np.random.seed(1)
random.seed(1)
warnings.simplefilter("ignore")
matplotlib.rcParams["lines.linewidth"] = 7.0
"""


def _state() -> dict[str, object]:
    umask = os.umask(0o022)
    os.umask(umask)
    return {
        "environ": dict(os.environ),
        "cwd": os.getcwd(),
        "path": list(sys.path),
        "stdout": sys.stdout,
        "umask": umask,
        "sigint": signal.getsignal(signal.SIGINT),
        "printoptions": np.get_printoptions(),
        "errstate": np.geterr(),
        "np_random": [x.tolist() if isinstance(x, np.ndarray) else x for x in np.random.get_state()],
        "random": random.getstate(),
        "warnings": list(warnings.filters),
        "rcParams": dict(matplotlib.rcParams),
    }


@pytest.mark.parametrize("fails", [False, True], ids=["passes", "fails"])
def test_a_block_leaves_no_global_state_behind(fails: bool, tmp_path: Path) -> None:
    matplotlib.use("Agg")  # what exec_in_order sets for every page, on purpose (draws off screen)
    before = _state()
    leaky = Block(
        "leak.md", 1, "python", LEAKY + ("raise ValueError('the block fails')" if fails else ""), ""
    )
    if fails:
        with pytest.raises(ValueError, match="the block fails"):
            exec_in_order([leaky], workdir(tmp_path))
    else:
        exec_in_order([leaky], workdir(tmp_path))
    after = _state()
    assert [k for k in before if before[k] != after[k]] == []


# A page that teaches a deprecated call (as its line on the page) fails; other warnings are printed.
CRANE = "from pendulab import crane\nc = crane.Crane(10.0)\n"
DEPRECATED = {
    "Crane.simulate(dt=…)": (CRANE + "run = c.simulate(1.0, sway=(0.1, 0.0), dt=0.1)", 13, "Crane.simulate"),
    "warn Deprecation": ("import warnings\nwarnings.warn('old', DeprecationWarning)", 12, "old"),
    "warn PendingDeprecation": (
        "import warnings\nwarnings.warn('old', PendingDeprecationWarning)",
        12,
        "old",
    ),
    "warn Future": ("import warnings\nwarnings.warn('old', FutureWarning)", 12, "old"),
}


@pytest.mark.parametrize("name", DEPRECATED)
def test_a_block_that_uses_a_deprecated_call_fails(name: str, tmp_path: Path) -> None:
    text, line, said = DEPRECATED[name]
    todo = [Block("old.md", 4, "python", "x = 1", ""), Block("old.md", 10, "python", text, "")]
    with pytest.raises(AssertionError, match=r"the block at old\.md:10 uses what is deprecated") as e:
        exec_in_order(todo, workdir(tmp_path))
    assert f"old.md:{line}: " in str(e.value) and said in str(e.value)
    assert "FAILED: the block at old.md:10" in e.value.__notes__


PRINTED = {
    "UserWarning": "import warnings\nwarnings.warn('shown on purpose', UserWarning)",
    "a library's own": "import warnings, numpy\n"
    "warnings.warn_explicit('old', DeprecationWarning, numpy.__file__, 1)",  # Matplotlib calling NumPy
    "Crane.simulate(output_spacing=…)": CRANE + "run = c.simulate(1.0, sway=(0.1, 0.0), output_spacing=0.1)",
}


@pytest.mark.parametrize("name", PRINTED)
def test_a_block_with_other_warnings_passes(
    name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    with warnings.catch_warnings(record=True) as shown:
        exec_in_order([Block("ok.md", 1, "python", PRINTED[name], "")], workdir(tmp_path))
    assert len(shown) == (name != "Crane.simulate(output_spacing=…)")


def test_the_python_blocks_of_a_page_have_a_time_limit(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(doc_blocks, "TIMEOUT", 0.2)
    start = time.perf_counter()
    with pytest.raises(TooLong, match=r"the python blocks of slow\.md did not finish within 0\.2 s"):
        exec_in_order([Block("slow.md", 1, "python", "import time\ntime.sleep(30)", "")], workdir(tmp_path))
    assert time.perf_counter() - start < 10


@pytest.mark.parametrize(
    "text",
    ["while True:\n    pass", "import time\nwhile True:\n    time.sleep(0.01)"],
    ids=["busy", "sleeps"],
)
def test_the_time_limit_holds_off_the_main_thread(
    text: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # a runner that runs tests in threads: SIGALRM reaches the main thread only (signal.signal refuses)
    monkeypatch.setattr(doc_blocks, "TIMEOUT", 0.2)
    said: list[BaseException] = []

    def run() -> None:
        try:
            exec_in_order([Block("slow.md", 3, "python", text, "")], workdir(tmp_path))
        except BaseException as e:
            said.append(e)

    start = time.perf_counter()
    thread = threading.Thread(target=run)
    thread.start()
    thread.join(30)
    assert not thread.is_alive() and time.perf_counter() - start < 10
    assert len(said) == 1 and isinstance(said[0], TooLong), said
    assert str(said[0]) == "the python blocks of slow.md did not finish within 0.2 s"
    assert "FAILED: the block at slow.md:3" in said[0].__notes__


def test_a_body_that_ends_in_time_off_the_main_thread_is_not_interrupted_later(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(doc_blocks, "TIMEOUT", 0.2)
    said: list[BaseException] = []

    def run() -> None:
        try:
            with doc_blocks.time_limit("quick"):
                pass
            time.sleep(0.5)  # past the limit: the timer was stopped with the body
        except BaseException as e:
            said.append(e)

    thread = threading.Thread(target=run)
    thread.start()
    thread.join(30)
    assert said == []


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
