"""The lab's REST endpoints for the models (docs/web.md): the scenario as TOML for ``pendulab run`` (a
slack string's too), loaded back bit for bit and run; V_eff."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient
from typer.testing import CliRunner
from ws_session import LabClient

import pendulab as pl
from pendulab import cli
from pendulab.server import create_app


@pytest.fixture(scope="module")
def client() -> TestClient:
    return LabClient(create_app("rosette"))


def test_the_scenario_as_toml_round_trips_and_runs(client: TestClient, tmp_path: Any) -> None:
    p = pl.Pendulum(length=1.3, g=9.5, mass=2.0, model="damped", damping=0.2, forcing_amplitude=0.5)
    st = p.state_from_angles(1.0, 0.5, 0.1, 1.5)
    body = {
        "title": "from the lab",
        "model": "damped",
        "length": 1.3,
        "mass": 2.0,
        "g": 9.5,
        "params": {"damping": 0.2, "forcing_amplitude": 0.5},
        "x": st.x.tolist(),
        "v": st.v.tolist(),
        "method": "rattle4",
        "dt": 0.002,
        "t0": 0.0,
        "t_end": 3.0,
    }
    r = client.post("/api/scenario.toml", json=body)
    assert r.status_code == 200 and r.headers["content-type"].startswith("application/toml")
    assert "attachment" in r.headers["content-disposition"]
    sc = pl.Scenario.from_toml_str(r.text)
    assert sc.pendulum().params() == p.params() | {"damping": 0.2, "forcing_amplitude": 0.5}
    np.testing.assert_array_equal(sc.initial_state().x, st.x)  # bit for bit
    np.testing.assert_array_equal(sc.initial_state().v, st.v)
    assert (sc.spec.simulation.method, sc.spec.simulation.dt, sc.title) == ("rattle4", 0.002, "from the lab")
    path = tmp_path / "lab.toml"
    path.write_text(r.text, encoding="utf-8")
    out = tmp_path / "lab.csv"
    res = CliRunner().invoke(cli.app, ["run", str(path), "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert out.is_file()
    bad = client.post("/api/scenario.toml", json=body | {"params": {"damping": -1}})
    assert bad.status_code == 422 and "damping = -1" in bad.json()["detail"]
    bad = client.post("/api/scenario.toml", json=body | {"t_end": -1.0})
    assert bad.status_code == 422 and "t_end" in bad.json()["detail"]


def test_effective_potential_is_t25_with_its_minimum_at_the_conical_orbit(client: TestClient) -> None:
    r = client.post(
        "/api/effective_potential", json={"length": 2.0, "mass": 0.5, "g": 9.81, "j3": 1.2, "n": 2000}
    )
    assert r.status_code == 200
    q = r.json()
    th, v = np.array(q["theta"]), np.array(q["v_eff"])
    assert th[0] > 0 and th[-1] < np.pi and len(th) == 2000
    np.testing.assert_allclose(v, -0.5 * 9.81 * 2 * np.cos(th) + 1.2**2 / (2 * 0.5 * 4 * np.sin(th) ** 2))
    # V_eff' = 0: m g l sin θ = J₃² cos θ / (m l² sin³ θ) at the conical orbit
    t0 = q["minimum"]["theta"]
    assert 0.5 * 9.81 * 2 * np.sin(t0) == pytest.approx(
        1.2**2 * np.cos(t0) / (0.5 * 4 * np.sin(t0) ** 3), rel=1e-2
    )
    bad = client.post("/api/effective_potential", json={"mass": -1})
    assert bad.status_code == 422 and "mass = -1" in bad.json()["detail"]


def test_a_slack_string_downloads_as_a_scenario_that_runs(client: TestClient) -> None:
    """The lab's TOML download at a slack moment of the string (x strictly inside the sphere, flying):
    the file loads back to the same start, bit for bit, and runs from it (slack first)."""
    x, v = [0.31, -0.2, -0.45], [1.1, 0.4, 2.0]  # m, m/s: |x| ≈ 0.58 m < l = 1 m
    body = {
        "model": "string",
        "length": 1.0,
        "mass": 1.0,
        "g": 9.81,
        "params": {"restitution": 0.5},
        "x": x,
        "v": v,
        "method": "rattle",
        "dt": 0.001,
        "t0": 0.0,
        "t_end": 2.0,
    }
    r = client.post("/api/scenario.toml", json=body)
    assert r.status_code == 200, r.text
    sc = pl.Scenario.from_toml_str(r.text)
    np.testing.assert_array_equal(sc.initial_state().x, x)
    np.testing.assert_array_equal(sc.initial_state().v, v)
    tr = sc.run(progress=False)
    assert tr.taut is not None and not tr.taut[0] and bool(tr.taut.any())
    outside = client.post("/api/scenario.toml", json=body | {"x": [0.0, 0.0, -1.2]})
    assert outside.status_code == 422 and "TS²" in outside.json()["detail"]
