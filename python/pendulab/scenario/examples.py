"""The example scenarios and sweeps shipped inside the package (data files in
``pendulab/examples/scenarios/*.toml`` and ``pendulab/examples/sweeps/*.toml``; the source tree's
``examples/scenarios`` and ``examples/sweeps`` link there), found by name: ``pendulab run
rosette``, ``pendulab scenarios``, ``pendulab sweep rotation_number``, the lab's scenario menu.

A name is a file's stem (``rosette`` for ``scenarios/rosette.toml``). :func:`find` takes either a
path to a TOML file or such a name; a path that exists always wins, so a local ``rosette.toml`` is
never shadowed by the example of the same name.
"""

from __future__ import annotations

from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SCENARIOS = EXAMPLES / "scenarios"
SWEEPS = EXAMPLES / "sweeps"


def _by_name(folder: Path) -> dict[str, Path]:
    return {p.stem: p for p in sorted(folder.glob("*.toml"))} if folder.is_dir() else {}


def scenario_files() -> dict[str, Path]:
    """The shipped example scenarios by name, sorted by name."""
    return _by_name(SCENARIOS)


def sweep_files() -> dict[str, Path]:
    """The shipped example sweeps by name, sorted by name."""
    return _by_name(SWEEPS)


def find(text: str | Path, kind: str = "scenario") -> Path:
    """The file ``text`` names: an existing path as given, else the shipped example ``kind``
    (``"scenario"`` or ``"sweep"``) of that name (with or without ``.toml``).

    Raises :class:`FileNotFoundError` naming the argument and listing the examples of that kind.
    """
    if kind not in ("scenario", "sweep"):
        raise ValueError(f"kind = {kind!r}: must be 'scenario' or 'sweep'")
    path = Path(text)
    if path.is_file():
        return path
    examples = scenario_files() if kind == "scenario" else sweep_files()
    name = path.name[: -len(".toml")] if path.name.endswith(".toml") and path.parent == Path() else str(text)
    if name in examples:
        return examples[name]
    known = ", ".join(examples) or "none shipped"
    raise FileNotFoundError(
        f"{text}: No such file, and no example {kind} of that name (examples: {known}; "
        f"`pendulab scenarios` lists them)"
    )
