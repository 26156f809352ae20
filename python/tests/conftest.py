"""Shared fixtures: the repository paths and the rosette start (l = 1 m, g = 9.81 m/s², θ₀ = 60°,
φ̇₀ = 2 rad/s)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import pendulab as pl

REPO = Path(__file__).resolve().parents[2]
SCENARIOS = REPO / "examples" / "scenarios"
TESTDATA = REPO / "testdata"


@pytest.fixture
def pendulum() -> pl.Pendulum:
    return pl.Pendulum(length=1.0, g=9.81, mass=1.0)


@pytest.fixture
def rosette(pendulum: pl.Pendulum) -> pl.State:
    return pendulum.state_from_angles(theta=np.radians(60), phi=0.0, theta_dot=0.0, phi_dot=2.0)
