"""``POST /api/fit`` (python/pendulab/server/fit.py, docs/fit.md "In the lab"): a shipped data file fitted
through the lab's server gives its documented answer, the fitted scenario loads, the measured path lies
on the fitted sphere; a bad file is a 422 naming the problem, a too large body 413 (the server's body
check, with this path's larger limit), another content type 415; the search stops at its time limit.
FastAPI's TestClient runs the app in-process."""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient
from ws_session import LabClient

import pendulab as pl
from pendulab.fitting.table import parse_table, read_table
from pendulab.server import create_app
from pendulab.server.fit import MAX_FIT_BODY, PATH_POINTS, FitRequest, default_fit, fit_data
from pendulab.server.notices import message

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "data"
JSON = {"content-type": "application/json"}


@pytest.fixture(scope="module")
def client() -> TestClient:
    return LabClient(create_app())


@pytest.fixture(scope="module")
def filmed(client: TestClient) -> dict[str, Any]:
    text = (EXAMPLES / "filmed_swing.csv").read_text()
    r = client.post("/api/fit", content=json.dumps({"csv": text, "name": "filmed_swing.csv"}), headers=JSON)
    assert r.status_code == 200, r.text
    return r.json()


def test_the_filmed_swing_gives_its_documented_length_through_the_lab(filmed: dict[str, Any]) -> None:
    # the truth of examples/data/make_data.py (docs/fit.md): l = 0.620 m, g = 9.81 m/s², c = 0.020 1/s
    assert filmed["fit"] == ["length", "g", "pivot", "damping"]  # the default for positions, damped
    assert filmed["converged"]
    for name, truth in {"length": 0.62, "g": 9.81, "damping": 0.02, "pivot_x": 0.312}.items():
        p = filmed["params"][name]
        assert p["determined"] and 0 < p["stderr"] < 0.1 * truth
        assert abs(p["value"] - truth) < 3 * p["stderr"], (name, p)
    assert filmed["params"]["length"]["unit"] == "m"
    assert "length" in filmed["report"] and "±" in filmed["report"]


def test_the_fitted_scenario_loads_and_is_the_lab_s(filmed: dict[str, Any]) -> None:
    sc = pl.Scenario.from_toml_str(filmed["scenario_toml"])
    length = filmed["params"]["length"]["value"]
    assert sc.spec.pendulum.model == "damped" and sc.spec.pendulum.length == pytest.approx(length, rel=1e-12)
    lab = filmed["lab"]
    assert lab["model"] == "damped" and lab["params"]["length"] == pytest.approx(length, rel=1e-12)
    assert lab["model_params"]["damping"] == pytest.approx(filmed["params"]["damping"]["value"], rel=1e-12)
    assert np.linalg.norm(lab["start"]["x"]) == pytest.approx(length, rel=1e-9)


def test_the_measured_path_lies_on_the_fitted_sphere(filmed: dict[str, Any]) -> None:
    m = filmed["measured"]
    data = read_table(EXAMPLES / "filmed_swing.csv")
    n = len(data["t"])
    assert m["points"] == n and len(m["x"]) == len(m["t"]) == min(n, PATH_POINTS)
    x = np.array(m["x"])
    assert x.shape[1] == 3 and np.all(np.diff(m["t"]) > 0) and m["t"][0] == 0.0
    # (x, z) minus the fitted pivot, y from the fitted motion: at the fitted length within the noise
    # (1.5 mm per coordinate: 10 mm is > 6 σ), and the swing is not drawn about the camera's origin
    r = np.linalg.norm(x, axis=1)
    assert np.max(np.abs(r - filmed["params"]["length"]["value"])) < 0.01
    assert np.all(x[:, 2] < 0)  # below the pivot
    first = data["positions"][0] - [
        filmed["params"]["pivot_x"]["value"],
        filmed["params"]["pivot_z"]["value"],
    ]
    assert x[0, [0, 2]] == pytest.approx(first, abs=1e-12)


def test_a_bad_file_is_a_422_naming_row_and_column(client: TestClient) -> None:
    bad = "t,x,z\n0,0.1,-0.5\n0.1,oops,-0.5\n"
    r = client.post("/api/fit", content=json.dumps({"csv": bad, "name": "bad.csv"}), headers=JSON)
    assert r.status_code == 422
    assert r.json()["detail"] == "bad.csv: row 2 (line 3), column 'x': 'oops' is not a number"
    # keyed for a page that words it in its language (messages.json; issue 28)
    row = {"file": "bad.csv", "row": 2, "line": 3, "column": "'x'", "cell": "'oops'"}
    assert (r.json()["key"], r.json()["values"]) == ("data_not_number", row)
    assert message("data_not_number", **row) == r.json()["detail"]
    r = client.post("/api/fit", content=json.dumps({"csv": "a,b\n1,2\n"}), headers=JSON)
    assert r.status_code == 422 and "no time column 't'" in r.json()["detail"]
    assert r.json()["key"] == "data_no_time" and r.json()["values"]["columns"] == "['a', 'b']"
    r = client.post("/api/fit", content=json.dumps({"csv": "t,x,z\n", "model": "spring"}), headers=JSON)
    assert r.status_code == 422 and "model 'spring'" in r.json()["detail"]
    assert r.json()["key"] == "fit_unknown_model" and r.json()["values"]["model"] == "spring"
    r = client.post("/api/fit", content=b"{not json", headers=JSON)
    assert r.status_code == 422 and "JSON" in r.json()["detail"] and r.json()["key"] == "not_json"
    r = client.post("/api/fit", content=json.dumps({"csv": "t\n", "extra": 1}), headers=JSON)
    assert r.status_code == 422 and "extra" in r.json()["detail"]
    assert (r.json()["key"], r.json()["values"]) == ("unknown_key", {"name": "extra"})


def test_a_bad_setting_or_value_is_keyed_with_what_it_names(client: TestClient) -> None:
    """A parameter the model cannot fit, a cell beyond the bounds, a short row: each 422 names itself by
    a key of messages.json with the values its words need."""
    rows = "t,x,z\n" + "".join(f"{0.05 * i:.2f},{0.1 * np.sin(i / 3):.4f},-0.5\n" for i in range(100))
    cases = [
        ({"csv": rows, "fit": ["colour"]}, "fit_cannot_fit", {"param": "colour", "model": "damped"}),
        ({"csv": "t,x,z\n0,1e300,-0.5\n0.1,0.2,-0.5\n"}, "data_cell_beyond", {"row": 1, "limit": "1e9"}),
        ({"csv": "t,x,z\n0,0.1,-0.5\n0.1,0.2\n"}, "data_row_short", {"row": 2, "have": 2, "need": 3}),
        ({"csv": "t,x,z\n0,0.1,-0.5\n0.1,0.2,-0.5\n"}, "data_too_few", {"have": 2}),
    ]
    for body, key, some in cases:
        r = client.post("/api/fit", content=json.dumps(body), headers=JSON)
        answer = r.json()
        assert r.status_code == 422 and answer["key"] == key, answer
        assert some.items() <= answer["values"].items(), answer
        assert "{" not in message(key, **answer["values"])  # every placeholder filled


def test_a_too_large_body_is_a_413_before_it_is_read(client: TestClient) -> None:
    big = json.dumps({"csv": "0,0,0\n" * (MAX_FIT_BODY // 6 + 1)})
    r = client.post("/api/fit", content=big, headers=JSON)
    assert r.status_code == 413 and f"at most {MAX_FIT_BODY} bytes" in r.text

    def chunks() -> Any:  # no Content-Length: refused once the stream passes the limit
        for _ in range(MAX_FIT_BODY // 2**16 + 2):
            yield b" " * 2**16

    r = client.post("/api/fit", content=chunks(), headers=JSON)
    assert r.status_code == 413
    # the other endpoints keep their 64 KiB
    r = client.post("/api/exact", content=json.dumps({"theta": 1.0, "pad": " " * 2**17}), headers=JSON)
    assert r.status_code == 413


def test_another_content_type_is_a_415(client: TestClient) -> None:
    text = (EXAMPLES / "crane_sway.csv").read_text()
    for media in ("text/csv", "multipart/form-data; boundary=x", "text/plain"):
        r = client.post("/api/fit", content=text, headers={"content-type": media})
        assert r.status_code == 415 and "application/json" in r.text, media
    r = client.post("/api/fit", content=text)
    assert r.status_code == 415


def test_angle_data_are_drawn_on_the_fitted_sphere_and_scalars_not_at_all() -> None:
    text = (EXAMPLES / "crane_sway.csv").read_text()
    out = fit_data(FitRequest(csv=text, name="crane_sway.csv"))
    assert out["fit"] == ["length", "damping"]  # angles: l with g fixed (only g/l is determined)
    x = np.array(out["measured"]["x"])
    angle = parse_table(text)["planar_angle"]
    assert np.linalg.norm(x, axis=1) == pytest.approx(out["params"]["length"]["value"], rel=1e-12)
    assert np.arctan2(x[:, 0], -x[:, 2]) == pytest.approx(angle[: len(x)], abs=1e-12)  # 10 Hz, < 2000 rows
    assert default_fit("ideal", {"specific_force", "angular_speed"}) == ["length", "g"]


def test_the_search_stops_at_its_time_limit() -> None:
    data = read_table(EXAMPLES / "filmed_swing.csv")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(
            pendulum=pl.Pendulum(model="damped"), fit="length,g,damping,pivot", time_limit=1e-6, **data
        )
    assert not res.converged and res.interrupted
    # stopped in the first of the growing windows (the full fit takes hundreds of model runs): what ran
    # is the error analysis at the values reached, about 2 runs per unknown
    assert res.evaluations <= 2 * len(res.names) + 10, res.evaluations
    assert res.message == "interrupted (the time limit of 1e-06 s)"
    assert any("time limit" in str(w.message) for w in caught)
    with pytest.raises(pl.InvalidInputError, match="time_limit"):
        pl.fit(time_limit=-1.0, **data)


def test_the_api_page_lists_the_body_of_the_fit(client: TestClient) -> None:
    body = client.get("/openapi.json").json()["paths"]["/api/fit"]["post"]["requestBody"]
    fields = body["content"]["application/json"]["schema"]["properties"]
    assert {"csv", "name", "model", "fit", "columns", "sigma"} == set(fields)
    assert "/api/fit" in client.get("/api/docs").text
