"""Classroom mode (docs/web.md, "Security"): bound beyond this machine, the lab requires a random token
on every request and WebSocket — in the printed URL, then as a cookie —, refuses pages without it,
and serves a class of 30 pages from the LAN at once. The token's choice, the URL and its QR code."""

from __future__ import annotations

import json
from typing import Any

import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect
from typer.testing import CliRunner
from ws_session import LabClient

from pendulab import cli
from pendulab.server import create_app
from pendulab.server.access import allowed_hosts, cookie_name
from pendulab.server.classroom import access_token, lab_url, qr_text

TOKEN = "classroom-token-1234"


@pytest.fixture(scope="module")
def lab() -> Any:
    return create_app("rosette", token=TOKEN)


def first_notice(ws: Any) -> dict[str, Any]:
    return json.loads(ws.receive_text())


def test_without_the_token_every_request_and_websocket_is_refused_with_a_pointer(lab: Any) -> None:
    c = LabClient(lab)
    for path in ("/", "/api/schema", "/?token=wrong-token-0000", "/api/docs"):
        r = c.get(path)
        assert r.status_code == 403 and "token" in r.text and "pendulab serve" in r.text, path
    assert c.post("/api/exact", json={"theta": 1.0}).status_code == 403
    assert "wrong token" in c.get("/?token=nope-nope-nope").text
    with c.websocket_connect("/ws") as ws:
        notice = first_notice(ws)
        assert notice["type"] == "error" and "access token" in notice["message"]
        with pytest.raises(WebSocketDisconnect) as closed:
            ws.receive_text()
    assert closed.value.code == 1008


def test_the_first_visit_sets_a_cookie_and_drops_the_token_from_the_address(lab: Any) -> None:
    c = LabClient(lab, follow_redirects=False)
    r = c.get(f"/?scenario=conical&token={TOKEN}")
    assert r.status_code == 303 and r.headers["location"] == "/?scenario=conical"
    cookie = r.headers["set-cookie"]
    assert cookie.startswith(f"{cookie_name(TOKEN)}={TOKEN}")
    assert "HttpOnly" in cookie and "SameSite=strict" in cookie and "Path=/" in cookie
    # the browser now sends the cookie: the page, the API and the WebSocket are served
    assert c.get("/?scenario=conical").status_code == 200
    assert c.get("/api/schema").status_code == 200
    assert c.post("/api/exact", json={"theta": 1.0}).status_code == 200
    with c.websocket_connect("/ws") as ws:
        assert first_notice(ws)["type"] == "status"


def test_scripts_may_send_the_token_as_a_query_or_a_header(lab: Any) -> None:
    c = LabClient(lab)
    assert c.get(f"/api/schema?token={TOKEN}").status_code == 200
    assert c.get("/api/schema", headers={"authorization": f"token {TOKEN}"}).status_code == 200
    with c.websocket_connect(f"/ws?token={TOKEN}") as ws:
        assert first_notice(ws)["type"] == "status"


def test_thirty_pages_of_a_lan_are_served_at_once_with_the_printed_address() -> None:
    lan = "192.168.7.20"  # the address a class's machines reach the teacher's by
    # the test client has one address for all its pages; the cap per device (8) is for real devices
    app = create_app("rosette", token=TOKEN, allowed_hosts=allowed_hosts(lan), max_sessions_per_client=30)
    url = lab_url(lan, 8000, TOKEN)
    assert url == f"http://{lan}:8000/?token={TOKEN}"
    pages = []
    with TestClient(app, base_url=f"http://{lan}:8000", follow_redirects=False) as c:
        first = c.get(url)  # the first visit: the cookie (kept by the client) and a redirect
        assert first.status_code == 303
        for _ in range(30):
            ws = c.websocket_connect(f"ws://{lan}:8000/ws", headers={"origin": f"http://{lan}:8000"})
            pages.append(ws.__enter__())
        try:
            assert all(first_notice(ws)["type"] == "status" for ws in pages)
        finally:
            for ws in pages:
                ws.__exit__(None, None, None)


def test_the_token_is_random_beyond_loopback_and_as_asked_otherwise() -> None:
    assert access_token("127.0.0.1") is None and access_token("localhost") is None
    a, b = access_token("0.0.0.0"), access_token("192.168.1.5")
    assert a and b and a != b and len(a) >= 22
    assert access_token("0.0.0.0", no_token=True) is None
    assert access_token("127.0.0.1", token="my-secret-1") == "my-secret-1"
    for bad in ("short", "has space 123"):
        with pytest.raises(ValueError, match="at least 8"):
            access_token("0.0.0.0", token=bad)
    with pytest.raises(ValueError, match="not both"):
        access_token("0.0.0.0", token="my-secret-1", no_token=True)


def test_the_url_and_its_qr_code() -> None:
    assert lab_url("127.0.0.1", 8000) == "http://127.0.0.1:8000/"
    assert lab_url("::1", 8000, "a/b+c") == "http://[::1]:8000/?token=a%2Fb%2Bc"
    code = qr_text("http://192.168.1.5:8000/?token=abc")
    lines = code.splitlines()
    assert len(lines) > 10 and all(len(line) == len(lines[0]) for line in lines)
    assert set(code) <= {"█", "▀", "▄", "\xa0", " ", "\n"}  # half blocks; no-break spaces


def test_serve_refuses_token_and_no_token_together_and_a_short_token() -> None:
    r = CliRunner().invoke(cli.app, ["serve", "--no-browser", "--token", "abcdefgh12", "--no-token"])
    assert r.exit_code == 2 and "not both" in r.stderr
    r = CliRunner().invoke(cli.app, ["serve", "--no-browser", "--token", "abc"])
    assert r.exit_code == 2 and "at least 8" in r.stderr
    r = CliRunner().invoke(cli.app, ["serve", "--help"])
    assert "--token" in r.stdout and "--no-token" in r.stdout and "--allow-host" in r.stdout
