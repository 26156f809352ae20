"""Finite bounds for every model parameter and start state (docs/models.md, "Limits"): the registry
declares them, docs/models.md lists them with their physical reasons (checked here against each
other), and every way in — pl.Pendulum, scenario files, the lab — refuses a value outside them with an
error naming it, where before 1e308 was accepted."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl

DOCS = Path(__file__).resolve().parents[2] / "docs" / "models.md"
COMMON = ("length", "mass", "g")


def _limits_table() -> dict[str, tuple[float, float]]:
    """{parameter name: (min, max)} from docs/models.md's Limits table (`forcing_x/y/z` names three)."""
    text = DOCS.read_text(encoding="utf-8").split("### Limits", 1)[1]
    rows: dict[str, tuple[float, float]] = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 5 or not cells[2].startswith(("[", "(")):
            continue
        lo, hi = (float(v.strip().replace("π/2", repr(math.pi / 2))) for v in cells[2][1:-1].split(","))
        for name in re.findall(r"`([a-z_/]+)`", cells[0]):
            base, *more = name.split("/")
            rows[base] = (lo, hi)
            for suffix in more:
                rows[base[:-1] + suffix] = (lo, hi)
    return rows


def test_every_parameter_has_finite_bounds_listed_in_the_docs_with_the_registrys_numbers() -> None:
    table = _limits_table()
    names = set()
    for m in pl.models():
        for p in m["params"]:
            lo, hi = p["min"], p["max"]
            assert math.isfinite(lo) and math.isfinite(hi) and lo < hi, (m["name"], p["name"])
            assert table[p["name"]] == pytest.approx((lo, hi), rel=1e-15), (m["name"], p["name"])
            names.add(p["name"])
    assert names >= {"length", "mass", "g", "damping", "forcing_omega", "stiffness", "restitution"}


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"length": 1e308}, "length"),
        ({"mass": 1e308}, "mass"),
        ({"g": -1e308}, "g"),
        ({"model": "damped", "damping": 1e308}, "damping"),
        ({"model": "damped", "drag": 1e5}, "drag"),
        ({"model": "damped", "forcing_omega": 1e9}, "forcing_omega"),
        ({"model": "rotating", "frame_rate": 1e308}, "frame_rate"),
        ({"model": "vibrating", "frequency": 1e6}, "frequency"),
        ({"model": "slewing", "radius": 1e5}, "radius"),
    ],
)
def test_a_value_beyond_its_bound_is_refused_naming_it_and_the_limits(kwargs: dict, name: str) -> None:
    with pytest.raises(pl.InvalidInputError, match=rf"{name}.*\[.*\]"):
        pl.Pendulum(**kwargs)


def test_a_start_faster_than_the_speed_bound_is_refused() -> None:
    p = pl.Pendulum()
    with pytest.raises(pl.InvalidInputError, match=r"speed.*1e7"):
        p.state_from_angles(1.0, 0.0, 0.0, 2e7)
    with pytest.raises(pl.InvalidInputError, match=r"speed"):
        p.state([1.0, 0.0, 0.0], [0.0, 2e7, 0.0])
    assert np.isfinite(p.state_from_angles(1.0, 0.0, 0.0, 9e6).v).all()  # 9e6 m/s: allowed


def test_the_lab_and_scenario_files_refuse_the_same_values(tmp_path: Path) -> None:
    from pendulab.server import Session, resolve_scenario
    from pendulab.server.protocol import CommandError, parse_command

    s = Session(resolve_scenario("rosette"))
    bad = '{"type": "set_model", "model": "damped", "params": {"forcing_omega": 1e9}}'
    with pytest.raises(CommandError, match=r"forcing_omega.*\[-1e4, 1e4\]"):
        s.apply(parse_command(bad))
    text = (DOCS.parents[1] / "examples" / "scenarios" / "damped.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^forcing_omega\s*=.*\n", "", text).replace(
        "[pendulum]", "[pendulum]\nforcing_omega = 1e9", 1
    )
    path = tmp_path / "fast.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises((pl.ScenarioError, pl.InvalidInputError), match=r"forcing_omega"):
        pl.load_scenario(path)
