"""The lab's geometric views (docs/web.md): the reduced view in σ-space (Holm's Figure 2: the orbit lies on
the J₃ surface and in the energy plane) and the energy–momentum map with the current (J₃, E)."""

from __future__ import annotations

import numpy as np
import pytest
from fastapi.testclient import TestClient
from ws_session import LabClient

import pendulab as pl
from pendulab.server import create_app
from pendulab.theory.reduce import invariants


@pytest.fixture(scope="module")
def client() -> TestClient:
    return LabClient(create_app("rosette"))


START = {"theta": 1.1, "phi": 0.2, "theta_dot": 0.4, "phi_dot": 1.7}


def test_reduced_orbit_lies_on_the_j3_surface_and_in_the_energy_plane(client: TestClient) -> None:
    body = {"length": 1.5, "mass": 2.0, "g": 9.81, **START, "n": 300, "grid": 21}
    r = client.post("/api/reduced", json=body)
    assert r.status_code == 200, r.text
    q = r.json()
    p = pl.Pendulum(length=1.5, g=9.81, mass=2.0)
    st = p.state_from_angles(*START.values())
    sol = pl.exact(p, st)
    assert q["orbit_time"] == pytest.approx(sol.period_z, rel=1e-12)
    s1, s2, s3 = (np.array(q["orbit"][k]) for k in ("sigma1", "sigma2", "sigma3"))
    assert len(s1) == 300
    j, h, gamma = q["j"], q["plane"]["h"], q["plane"]["gamma"]
    assert j == pytest.approx(p.j3(st) / (2.0 * 1.5**2), rel=1e-12)  # σ₆ = J₃/(m l²)
    assert h == pytest.approx(p.energy(st) / (2.0 * 1.5**2), rel=1e-12)  # H = E/(m l²)
    assert gamma == pytest.approx(9.81 / 1.5)
    np.testing.assert_allclose(s3 * (1 - s1**2) - s2**2 - j**2, 0, atol=1e-9)  # C = 0
    np.testing.assert_allclose(0.5 * s3 + gamma * s1, h, atol=1e-9)  # the energy plane
    # one z-period: σ₁ covers the turning heights [z₁, z₂]/l
    z1, z2 = sol.turning_heights[:2]
    assert s1.min() == pytest.approx(z1 / 1.5, abs=1e-4) and s1.max() == pytest.approx(z2 / 1.5, abs=1e-4)
    np.testing.assert_allclose(q["point"], invariants(p, st.x, st.v)[0, :3], rtol=1e-14)
    surf = q["surface"]
    a, b, c = np.array(surf["sigma1"]), np.array(surf["sigma2"]), np.array(surf["sigma3"])
    assert c.shape == (21, 21)
    np.testing.assert_allclose(c * (1 - a[:, None] ** 2) - b[None, :] ** 2 - j**2, 0, atol=1e-9)


def test_reduced_view_of_planar_motion_and_bad_input(client: TestClient) -> None:
    q = client.post("/api/reduced", json={"theta": 0.5}).json()
    assert q["j"] == 0 and len(q["orbit"]["sigma1"]) == 400
    bad = client.post("/api/reduced", json={"theta": 0.5, "n": 5})
    assert bad.status_code == 422 and "n = 5" in bad.json()["detail"]


def test_em_map_boundary_and_the_current_point(client: TestClient) -> None:
    r = client.post("/api/em_map", json={"length": 2.0, "mass": 0.5, "g": 9.81, **START})
    assert r.status_code == 200, r.text
    q = r.json()
    weight = 0.5 * 9.81 * 2.0
    assert q["bottom"] == {"j3": 0.0, "energy": -weight} and q["top"] == {"j3": 0.0, "energy": weight}
    j, e = np.array(q["boundary"]["j3"]), np.array(q["boundary"]["energy"])
    assert np.all(np.diff(j) > 0) and e.min() == pytest.approx(-weight)
    p = pl.Pendulum(length=2.0, g=9.81, mass=0.5)
    st = p.state_from_angles(*START.values())
    assert q["point"] == pytest.approx({"j3": p.j3(st), "energy": p.energy(st)}, rel=1e-14)
    assert q["point"]["energy"] >= np.interp(q["point"]["j3"], j, e)  # inside the image
    bad = client.post("/api/em_map", json={"g": 0.0, "theta": 0.5})
    assert bad.status_code == 422 and "needs gravity" in bad.json()["detail"]
