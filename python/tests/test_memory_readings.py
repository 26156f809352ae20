"""The memory check asks the operating system once per burst of small calls, and a fit builds each
pendulum once: the two costs that made a fit's many short model runs slow (pendulab/memory.py,
module doc; fitting/problem.py, ``Problem.pendulum``). Sizes in bytes, times in s."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

import pendulab as pl
from pendulab import memory
from pendulab.fitting.data import Observations
from pendulab.fitting.problem import BUILT_KEPT, Problem, model_params

GIB = 2**30


@pytest.fixture
def readings(monkeypatch: pytest.MonkeyPatch) -> dict[str, float]:
    """The operating system as a dict: ``avail`` [B] it reports, ``now`` [s] on its clock, ``reads``
    how often it was asked (RLIMIT and cgroup left out)."""
    os_side = {"avail": 8.0 * GIB, "now": 100.0, "reads": 0}

    def meminfo(key: str) -> int:
        assert key == "MemAvailable"
        os_side["reads"] += 1
        return int(os_side["avail"])

    monkeypatch.setattr(memory, "_meminfo", meminfo)
    monkeypatch.setattr(memory, "_cgroup_room", lambda: None)
    monkeypatch.setattr(memory.resource, "getrlimit", lambda _: (memory.resource.RLIM_INFINITY,) * 2)
    monkeypatch.setattr(memory.time, "monotonic", lambda: os_side["now"])
    monkeypatch.setattr(memory, "_recent", None)
    return os_side


def test_small_needs_in_a_burst_ask_the_system_once(readings: dict[str, float]) -> None:
    for _ in range(100):
        memory.check_memory("a short run", 1e6, "ask for less")
        assert memory.saved_bytes_cap(None) == int(0.8 * 8 * GIB / memory.SAMPLE_COPIES)
    assert readings["reads"] == 1
    readings["now"] += memory.FRESH_FOR  # the reading has aged: asked again
    memory.check_memory("a short run", 1e6, "ask for less")
    assert readings["reads"] == 2


def test_a_need_that_matters_is_checked_against_a_fresh_reading(readings: dict[str, float]) -> None:
    """A need above 1/SMALL_SHARE of the recent reading reads afresh, so memory taken since the last
    reading (8 GiB then, 1 GiB now) refuses it; one that fits the fresh reading passes."""
    memory.check_memory("a short run", 1e6, "ask for less")
    readings["avail"] = 1.0 * GIB
    memory.check_memory("half a GiB", 0.5 * GIB, "ask for less")
    assert readings["reads"] == 2
    refused = r"^one GiB needs about 1 GiB of memory.*\(1 GiB available"
    with pytest.raises(pl.InvalidInputError, match=refused):
        memory.check_memory("one GiB", 1.0 * GIB, "ask for less")
    assert readings["reads"] == 3
    # a need below 1/64 of the last (fresh) reading is passed on it
    memory.check_memory("a short run", 1.0 * GIB / memory.SMALL_SHARE, "ask for less")
    assert readings["reads"] == 3


def test_nothing_known_refuses_nothing(readings: dict[str, float], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(memory, "_meminfo", lambda _: None)
    monkeypatch.setattr(memory.os, "sysconf", lambda _: (_ for _ in ()).throw(ValueError("none")))
    memory.check_memory("a huge run", 1e18, "ask for less")
    assert memory.saved_bytes_cap(None) is None and memory.saved_bytes_cap(123) == 123


def _problem() -> Problem:
    t = np.linspace(0.0, 1.0, 5)
    obs = Observations(t, {"planar_angle": np.zeros((5, 1))}, {"planar_angle": 0.01}, 0, {"planar_angle": 1})
    values = {name: float(spec["default"]) for name, spec in model_params("damped").items()}
    values.update(length=1.0, g=9.81, mass=1.0, damping=0.1)  # every parameter, as pl.fit gives them
    return Problem("damped", values, ["length"], obs)


def test_a_fit_builds_each_pendulum_once_and_keeps_a_bounded_number() -> None:
    problem = _problem()
    full = {**problem.values, "theta0": 0.3, "scale": 1.5}  # a start and a systematic term: same model
    p = problem.pendulum(full)
    assert problem.pendulum(dict(problem.values)) is p
    assert p.params()["damping"] == 0.1 and p.length == 1.0
    longer = problem.pendulum({**full, "length": 1.25})
    assert longer is not p and longer.length == 1.25 and problem.pendulum({**full, "length": 1.25}) is longer
    for i in range(3 * BUILT_KEPT):
        problem.pendulum({**full, "damping": 0.2 + 1e-3 * i})
        assert len(problem.built) <= BUILT_KEPT
    assert problem.restricted(3).built == {}  # a view of other samples starts empty
    assert replace(problem, model="rotating").built == {}  # and so does a copy
