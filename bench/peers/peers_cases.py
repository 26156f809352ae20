"""The peers benchmark's cases and what a scanned method is (bench/peers/run.py, issue 5 parts 3-4).

Cases (t_end = ``T_END`` = 100 s, l = 1 m, m = 1 kg, g = 9.81 m/s²): the scenarios ``rosette``,
``near_top`` (1° below the top) and ``over_the_top`` (planar revolutions, J₃ = 0) of
examples/scenarios/. Reference: Pendulab's exact solution at t = 100 s (``pl.exact``), checked
against the 40-digit mpmath golden data of testdata/golden_states.json (``exact_vs_golden``, the
state error max(|Δx|/l, |Δv|/(lω₀ + |v|))), whose conditioning floor at 100 s is kept as ``floor``.
A ``Method`` is scanned over step counts over [0, 100 s] (fixed-step; dt = 100 s/n) or over rtol
(adaptive; atol = rtol/100): ``fixed_settings``, ``adaptive_settings``. Units SI (m, kg, s, rad).
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import harness as hz
import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
RESULTS = HERE / "results"
BUILD = HERE / "build"
DOCS = REPO / "docs" / "performance.md"
PLOT = REPO / "docs" / "img" / "peers_work_precision.png"
T_END = 100.0
CASES = ("rosette", "near_top", "over_the_top")
TOL_LO, TOL_HI = 1e-6, 1e-10
FLOOR = 1e-13
MUJOCO_IC = 1e-6  # the bob's isotropic inertia about its centre, in units of m l²


@dataclass
class Case:
    name: str
    length: float
    mass: float
    g: float
    x0: np.ndarray
    v0: np.ndarray
    x_ref: np.ndarray
    v_ref: np.ndarray
    exact_vs_golden: float
    floor: float

    @property
    def omega0(self) -> float:
        return math.sqrt(abs(self.g) / self.length)

    @property
    def y0(self) -> np.ndarray:
        return np.concatenate([self.x0, self.v0])


Runner = Callable[[float], tuple[np.ndarray, np.ndarray, int]]


@dataclass
class Method:
    """A method to scan: ``prepare(case)`` returns ``run(setting) -> (x, v, steps)``; ``kind`` is
    "fixed" (setting = number of steps over [0, 100 s]) or "adaptive" (setting = rtol)."""

    name: str
    family: str  # "pendulab" or the peer's name
    kind: str
    prepare: Callable[[Case], Runner]


def fixed_settings(quick: bool) -> list[int]:
    """Numbers of steps over [0, 100 s]: 500 (dt = 0.2 s) up by factors √2 to 1.6·10⁹ (dt ≈ 6e-8 s);
    the scan stops long before the end (``should_refine``)."""
    return [round(500 * 2 ** (k / 2)) for k in range(0, 44 if not quick else 24)]


def adaptive_settings(quick: bool) -> list[float]:
    """rtol = 1e-3 … 1e-14 by factors √10 (quick: … 1e-10)."""
    return [10.0 ** (-k / 2) for k in range(6, 29 if not quick else 21)]


# --------------------------------------------------------------------------------------------------
# Cases and reference


def load_cases(names: tuple[str, ...]) -> list[Case]:
    import pendulab as pl

    golden = json.loads((REPO / "testdata" / "golden_states.json").read_text())
    out = []
    for name in names:
        sc = pl.load_scenario(REPO / "examples" / "scenarios" / f"{name}.toml")
        p, s0 = sc.pendulum(), sc.initial_state()
        ref = pl.exact(p, s0).state(T_END)
        gcase = next(c for c in golden["cases"] if c["name"] == name)
        gs = next(s for s in gcase["samples"] if s["t"] == T_END)
        x0, v0 = np.asarray(s0.x, dtype=float), np.asarray(s0.v, dtype=float)
        if not (
            np.allclose(x0, gcase["x0"], rtol=0, atol=1e-15) and np.allclose(v0, gcase["v0"], atol=1e-15)
        ):
            raise SystemExit(f"{name}: the scenario's start is not the golden data's start")
        c = Case(
            name,
            p.length,
            p.mass,
            p.g,
            x0,
            v0,
            np.asarray(ref.x, dtype=float),
            np.asarray(ref.v, dtype=float),
            0.0,
            float(gs["floor"]),
        )
        c.exact_vs_golden = hz.state_error(
            c.x_ref, c.v_ref, np.array(gs["x"]), np.array(gs["v"]), c.length, c.omega0
        )
        out.append(c)
    return out
