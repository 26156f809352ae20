"""The example scenarios, sweeps and measured data sets shipped inside the package (files in
``pendulab/examples/scenarios/*.toml``, ``pendulab/examples/sweeps/*.toml`` and
``pendulab/examples/data/*.csv``; the source tree's ``examples/scenarios``, ``examples/sweeps`` and
``examples/data`` link there), found by name: ``pendulab run rosette``, ``pendulab scenarios``,
``pendulab sweep rotation_number``, ``pendulab fit example:filmed_swing``, the lab's scenario menu.

A name is a file's stem (``rosette`` for ``scenarios/rosette.toml``), optionally written
``example:rosette``. :func:`find` takes either a path to a file or such a name; a path that exists
always wins, so a local ``rosette.toml`` is never shadowed by the example of the same name.
"""

from __future__ import annotations

import os
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SCENARIOS = EXAMPLES / "scenarios"
SWEEPS = EXAMPLES / "sweeps"
DATA = EXAMPLES / "data"
PREFIX = "example:"
_SUFFIX = {"scenario": ".toml", "sweep": ".toml", "data": ".csv"}


def _by_name(folder: Path, suffix: str = ".toml") -> dict[str, Path]:
    return {p.stem: p for p in sorted(folder.glob(f"*{suffix}"))} if folder.is_dir() else {}


def scenario_files() -> dict[str, Path]:
    """The shipped example scenarios by name, sorted by name."""
    return _by_name(SCENARIOS)


def sweep_files() -> dict[str, Path]:
    """The shipped example sweeps by name, sorted by name."""
    return _by_name(SWEEPS)


def data_files() -> dict[str, Path]:
    """The shipped measured data sets (CSV, SI units; ``docs/fit.md``) by name, sorted by name."""
    return _by_name(DATA, ".csv")


def find(text: str | Path, kind: str = "scenario") -> Path:
    """The file ``text`` names: an existing path as given, else the shipped example ``kind``
    (``"scenario"``, ``"sweep"`` or ``"data"``) of that name, with or without its suffix
    (``.toml``; ``.csv`` for data) and with or without the prefix ``example:``.

    Raises :class:`FileNotFoundError` (:class:`IsADirectoryError` for a folder) naming the argument and
    listing the examples of that kind.

    Examples
    --------
    >>> find("rosette").name
    'rosette.toml'
    >>> find("example:filmed_swing", "data").name
    'filmed_swing.csv'
    """
    if kind not in _SUFFIX:
        raise ValueError(f"kind = {kind!r}: must be 'scenario', 'sweep' or 'data'")
    path = Path(text)
    if path.is_file() or (path.exists() and not path.is_dir()):  # a device or pipe (/dev/stdin) too:
        return path  # the reader bounds what it reads and says what is wrong (docs/limits.md, file_bytes)
    examples = {"scenario": scenario_files, "sweep": sweep_files, "data": data_files}[kind]()
    text = os.fspath(text)  # the messages name it as given (``./x.toml``, not ``x.toml``)
    name = str(path).removeprefix(PREFIX)
    suffix = _SUFFIX[kind]
    if name.endswith(suffix) and Path(name).parent == Path():
        name = name[: -len(suffix)]
    if name in examples:
        return examples[name]
    known = ", ".join(examples) or "none shipped"
    listing = "`pendulab scenarios` lists them" if kind != "data" else "docs/fit.md describes them"
    if path.is_dir():  # not "No such file": it exists, as a folder
        raise IsADirectoryError(
            f"{text}: a directory, not a {kind} file, and no example {kind} of that name (examples: {known}; "
            f"{listing})"
        )
    stem = Path(name).stem
    if Path(name).suffix == suffix and stem in examples:
        # A path into the checkout's examples/ (README, docs) typed where there is none, e.g. after
        # installing the wheel: the shipped example of that name is given by its name alone.
        given = stem if kind != "data" else PREFIX + stem
        raise FileNotFoundError(
            f"{text}: No such file here; the example {kind} {stem!r} ships with the package: give its "
            f"name alone, {given!r}, instead of the path (examples: {known}; {listing})"
        )
    raise FileNotFoundError(
        f"{text}: No such file, and no example {kind} of that name (examples: {known}; {listing})"
    )
