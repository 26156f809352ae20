"""``dop853`` with ``project=False`` next to the top: off TS² the equations T-2.4 are unstable wherever the
rod pushes (the bob high and slow, docs/theory.md T-2.4), so the drift grows until no step meets the
tolerance and the step size underflows. The error names the drift there and says to project
(docs/limits.md, "Leaving TS²"); projected, the same run follows the exact solution. Units: SI."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import pendulab as pl


def _underflow(p: pl.Pendulum, s: pl.State, t_end: float) -> str:
    with pytest.raises(pl.IntegrationError) as e:
        pl.simulate(p, s, t_end, method="dop853", project=False)
    return str(e.value)


@pytest.mark.parametrize(("g", "theta", "phi_dot", "t_end"), [(1e4, math.pi - 1e-3, 0.0, 1.0)])
def test_the_underflow_of_an_unprojected_run_names_the_drift_and_project_true(
    g: float, theta: float, phi_dot: float, t_end: float
) -> None:
    p = pl.Pendulum(g=g)
    s = p.state_from_angles(theta=theta, phi_dot=phi_dot)
    msg = _underflow(p, s, t_end)
    assert msg.startswith("step size underflow at t = "), msg
    assert "the run is not projected (project=False) and had left TS² there" in msg, msg
    assert "use project=True (the default)" in msg and "'rattle'" in msg, msg
    radial = re.search(r"\(\|x\| - l\)/l = (\S+) and", msg)
    assert radial is not None and abs(float(radial.group(1))) > 100 * 1e-10, msg  # > 100·rtol
    # projected, the same start runs to the end and keeps the energy of the exact solution (its start's;
    # measured 2e-10 of m|g|l at rtol 1e-10: dop853's energy error scales with rtol, docs/integrators.md)
    tr = pl.simulate(p, s, t_end, method="dop853", save_every=50)
    e_exact = p.energy(pl.exact(p, s).state(0.0))
    assert np.max(np.abs(tr.energy - e_exact)) / (p.mass * abs(p.g) * p.length) < 1e-9
