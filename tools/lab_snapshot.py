"""What the one-file lab carries besides the engine (docs/lab.md, ``make lab-html``): the answers of
``GET /api/schema`` and ``GET /api/scenarios`` exactly as ``pendulab serve`` gives them (the same
functions), each scenario with its dop853 tolerances ``rtol``, ``atol`` added (the page's engine builds
its sessions from these), and the scenario to start with (``rosette``, the server's default).

Usage: ``python tools/lab_snapshot.py OUT.json`` (written atomically). SI units as in the API.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from pendulab.scenario import load_scenario
from pendulab.server.app import scenarios
from pendulab.server.scenarios import Setup, scenario_files
from pendulab.server.schema import schema

DEFAULT_SCENARIO = "rosette"


def snapshot() -> dict[str, object]:
    """The schema, the example scenarios (with rtol, atol) and the one to start with."""
    files = scenario_files()
    listed = scenarios()
    for entry in listed:
        if "error" in entry:
            continue
        setup = Setup.from_scenario(load_scenario(files[entry["name"]]), entry["name"])
        entry["rtol"], entry["atol"] = setup.rtol, setup.atol
    names = [e["name"] for e in listed if "error" not in e]
    start = DEFAULT_SCENARIO if DEFAULT_SCENARIO in names else (names[0] if names else None)
    return {"schema": schema(), "scenarios": listed, "scenario": start}


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: python tools/lab_snapshot.py OUT.json", file=sys.stderr)
        return 2
    out = Path(argv[0])
    tmp = out.with_name(out.name + ".tmp")
    tmp.write_text(json.dumps(snapshot(), allow_nan=False), encoding="utf-8")
    tmp.replace(out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
