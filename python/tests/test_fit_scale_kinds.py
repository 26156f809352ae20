"""What a camera's ``scale`` acts on (problem.LENGTH_KINDS): the lengths read off a scale bar —
positions and the horizontal sway — and no other data kind. A phone's |ω| = |x × v|/|x|² and its
|a − g⃗| are not measured against a ruler; ``scale`` multiplied the bob's x before every kind, so a
held scale changed the predicted |ω| by 1/scale. Data from an independent integrator
(testdata/generate/independent_pendulum.py: SciPy DOP853, no Pendulab code). SI units.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np

import pendulab as pl
from pendulab.fitting.data import observations
from pendulab.fitting.problem import LENGTH_KINDS, Problem

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "testdata" / "generate"))
import independent_pendulum as ip

TRUTH = ip.Truth(length=0.8, g=9.81)
START = {"theta0": 0.5, "phi0": 0.1, "theta_dot0": 0.0, "phi_dot0": 0.7}
VALUES = {"length": 0.8, "g": 9.81, "mass": 1.0, **START, "pivot_x": 0.0, "pivot_y": 0.0, "pivot_z": 0.0}


def _motion(span: float = 6.0, n: int = 301) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    t = np.linspace(0.0, span, n)
    x, v, _, _ = ip.simulate(TRUTH, ip.start_state(TRUTH, *START.values()), t)
    return t, x, v


def test_a_held_scale_leaves_a_phones_data_alone() -> None:
    """A phone's |ω| alone, and |a − g⃗| with |ω|: the predictions at scale 1.3 are those at 1.0."""
    t, x, v = _motion()
    omega = np.linalg.norm(np.cross(x, v), axis=1) / TRUTH.length**2
    force = np.full_like(omega, 9.81)  # the values do not enter the predictions
    for data in ({"angular_speed": omega}, {"specific_force": force, "angular_speed": omega}):
        problem = Problem("ideal", dict(VALUES), [], observations(t, data))
        plain = problem.predictions(VALUES)
        scaled = problem.predictions({**VALUES, "scale": 1.3})
        for kind in data:
            assert np.array_equal(scaled[kind], plain[kind]), kind
        assert np.allclose(plain["angular_speed"][:, 0], omega, rtol=1e-8), "the model is the generator's"


def test_a_scale_multiplies_the_lengths_only() -> None:
    """Positions and the horizontal sway are pivot + scale·x; angles (scale-free anyway) are not."""
    assert set(LENGTH_KINDS) == {"positions", "horizontal"}
    t, x, _ = _motion()
    pivot = {"pivot_x": 0.2, "pivot_y": -0.1, "pivot_z": 1.1}
    at = {**VALUES, **pivot}
    kinds = {
        "positions": x,
        "horizontal": x[:, :2],
        "planar_angle": np.arctan2(x[:, 0], -x[:, 2]),
    }
    for kind, data in kinds.items():
        problem = Problem("ideal", dict(at), [], observations(t, {kind: data}))
        plain = problem.predictions(at)[kind]
        scaled = problem.predictions({**at, "scale": 1.3})[kind]
        if kind in LENGTH_KINDS:
            origin = np.array(list(pivot.values()))[: plain.shape[1]]
            assert np.allclose(scaled - origin, 1.3 * (plain - origin), rtol=1e-12, atol=1e-13), kind
        else:
            assert np.array_equal(scaled, plain), kind


def test_a_free_scale_is_recovered_from_positions() -> None:
    """Filmed positions with a ruler 4 % long (measured = 1.04·x, σ 1 mm), g known: the fit finds the
    scale and the length within 3 standard errors."""
    t, x, _ = _motion(span=10.0, n=501)
    pos = ip.measure_positions(x, np.random.default_rng(7), 1e-3, scale=1.04)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = pl.fit(
            t, positions=pos, pendulum=pl.Pendulum(g=9.81), fit=["length", "scale", "state"], sigma=1e-3
        )
    assert res.converged
    for name, truth in (("scale", 1.04), ("length", 0.8)):
        assert abs(res.params[name] - truth) < 3.0 * res.stderr[name], (name, res.params[name], res.stderr)
        assert res.stderr[name] < 0.01 * truth, name
