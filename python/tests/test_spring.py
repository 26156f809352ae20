"""The swinging spring from Python (T-7.4): E and J₃ conserved by the symplectic integrator, the
1:1:2 resonance exchanges energy between bouncing and swinging, bad input. SI units."""

from __future__ import annotations

import numpy as np
import pytest

import pendulab as pl


def test_resonant_exchange_and_conservation() -> None:
    sp = pl.SwingingSpring.resonant(1.0)
    assert np.isclose(np.sqrt(sp.k_over_m), 2 * np.sqrt(sp.g / sp.equilibrium_length))
    tr = pl.simulate_spring(
        sp, [0.01, 0.002, -1.05], [0.0, 0.003, 0.0], t_end=60.0, dt=1e-3, save_every=10, order=4
    )
    assert np.max(np.abs(tr.energy - tr.energy[0])) < 1e-8 * abs(tr.energy[0])
    assert np.max(np.abs(tr.j3 - tr.j3[0])) < 1e-15
    b = tr.bouncing_energy
    assert b.min() < 0.1 * b[0], "energy must leave the bouncing mode at resonance"


def test_bad_input() -> None:
    with pytest.raises(pl.InvalidInputError, match="k_over_m"):
        pl.simulate_spring(pl.SwingingSpring(-1.0, 1.0), [0, 0, -1], [0, 0, 0], t_end=1.0)
    with pytest.raises(pl.InvalidInputError, match="rest_length"):
        pl.simulate_spring(pl.SwingingSpring(10.0, 0.0), [0, 0, -1], [0, 0, 0], t_end=1.0)
    with pytest.raises(pl.InvalidInputError, match="order"):
        pl.simulate_spring(pl.SwingingSpring(10.0, 1.0), [0, 0, -1], [0, 0, 0], t_end=1.0, order=3)
