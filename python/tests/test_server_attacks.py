"""The lab server against a foreign web page and hostile HTTP clients (docs/web.md, "Security"): a
WebSocket or POST from another origin, a foreign Host (DNS rebinding), CORS-"simple" text/plain POSTs,
huge and deeply nested bodies, missing security headers, third-party requests from served pages.
Each test is one attack of issue 12 that the server of before answered with 101/200/500."""

from __future__ import annotations

import json
import re
import socket
import time
from typing import Any

import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect
from ws_session import LabClient, live_lab

from pendulab.server import create_app, hygiene
from pendulab.server.access import allowed_hosts, same_origin
from pendulab.server.hygiene import MAX_BODY_BYTES

LOCAL = "http://127.0.0.1"


@pytest.fixture(scope="module")
def client() -> TestClient:
    return LabClient(create_app("rosette"))


def first_notice(ws: Any) -> dict[str, Any]:
    msg = ws.receive()
    assert msg.get("text") is not None, msg
    return json.loads(msg["text"])


# --- 1. same origin only -------------------------------------------------------------------------------


def test_a_websocket_from_a_foreign_page_is_refused_with_1008_and_a_message(client: TestClient) -> None:
    with client.websocket_connect("/ws", headers={"origin": "http://evil.example"}) as ws:
        notice = first_notice(ws)
        assert notice["type"] == "error" and "evil.example" in notice["message"]
        assert "same origin" in notice["message"]
        with pytest.raises(WebSocketDisconnect) as closed:
            ws.receive_text()
    assert closed.value.code == 1008
    # the lab's own page, and a client that is no browser page (no Origin), are served
    for headers in ({"origin": LOCAL}, {}):
        with client.websocket_connect("/ws", headers=headers) as ws:
            assert first_notice(ws)["type"] == "status"


def test_a_foreign_page_on_the_same_host_but_another_port_is_refused(client: TestClient) -> None:
    with client.websocket_connect("/ws", headers={"origin": "http://127.0.0.1:9999"}) as ws:
        assert first_notice(ws)["type"] == "error"
        with pytest.raises(WebSocketDisconnect):
            ws.receive_text()
    r = client.post("/api/exact", json={"theta": 1.0}, headers={"origin": "http://evil.example"})
    assert r.status_code == 403 and "evil.example" in r.text
    assert client.post("/api/exact", json={"theta": 1.0}, headers={"origin": LOCAL}).status_code == 200


def test_same_origin_compares_host_and_port() -> None:
    assert same_origin("http://127.0.0.1:8000", "127.0.0.1:8000")
    assert same_origin("http://localhost", "localhost:80")
    assert same_origin("http://[::1]:8000", "[::1]:8000")
    assert not same_origin("http://127.0.0.1:8001", "127.0.0.1:8000")
    assert not same_origin("http://evil.example:8000", "127.0.0.1:8000")
    assert not same_origin("null", "127.0.0.1:8000")
    assert not same_origin("file://", "127.0.0.1:8000")
    assert not same_origin("http://127.0.0.1:8000", None)


def test_a_foreign_host_header_is_refused_dns_rebinding(client: TestClient) -> None:
    evil = TestClient(create_app("rosette"), base_url="http://evil.example:8000")
    for path in ("/", "/api/schema"):
        r = evil.get(path)
        assert r.status_code == 400 and "host" in r.text.lower()
    with pytest.raises(WebSocketDisconnect), evil.websocket_connect("/ws") as ws:
        ws.receive_text()
    assert client.get("/api/schema").status_code == 200
    assert TestClient(create_app("rosette"), base_url="http://localhost:8000").get("/").status_code == 200


def test_allowed_hosts_are_the_loopback_names_plus_the_bound_address_and_given_names() -> None:
    local = allowed_hosts("127.0.0.1")
    assert {"localhost", "127.0.0.1", "::1"} <= set(local) and "evil.example" not in local
    lan = allowed_hosts("192.168.1.20", extra=["lab.school.example"])
    assert "192.168.1.20" in lan and "lab.school.example" in lan
    ok = TestClient(create_app("rosette", allowed_hosts=lan), base_url="http://lab.school.example")
    assert ok.get("/api/schema").status_code == 200


# --- 3. POST hygiene --------------------------------------------------------------------------------


def test_post_needs_a_json_content_type_so_foreign_simple_requests_fail(client: TestClient) -> None:
    body = json.dumps({"length": 1.0, "theta": 1.0, "n": 400})
    for ctype in ("text/plain", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x"):
        r = client.post("/api/reduced", content=body, headers={"content-type": ctype})
        assert r.status_code == 415 and "application/json" in r.text
    r = client.post("/api/reduced", content=body)  # no content type at all
    assert r.status_code == 415
    ok = client.post("/api/exact", content=body[:-10] + "}", headers={"content-type": "application/json"})
    assert ok.status_code in (200, 422)  # JSON is read (422: the cut body's keys)


def test_a_body_over_the_cap_is_refused_before_it_is_read(client: TestClient) -> None:
    big = b'{"theta": 1.0, "pad": "' + b"x" * MAX_BODY_BYTES + b'"}'
    r = client.post("/api/exact", content=big, headers={"content-type": "application/json"})
    assert r.status_code == 413 and str(MAX_BODY_BYTES) in r.text
    # a declared length of 200 MB is refused from the header alone (nothing is read)
    r = client.post(
        "/api/exact",
        content=b"{}",
        headers={"content-type": "application/json", "content-length": str(200 * 2**20)},
    )
    assert r.status_code == 413


def test_a_deeply_nested_body_is_422_not_500(client: TestClient) -> None:
    for body in (b"[" * 5000, b'{"a":' * 5000 + b"1" + b"}" * 5000, b"\xff\xfe", b"NaN"):
        r = client.post("/api/exact", content=body, headers={"content-type": "application/json"})
        assert r.status_code == 422, (body[:10], r.status_code, r.text[:200])


# --- 6. headers, no third-party requests ----------------------------------------------------------------


def test_every_response_carries_the_security_headers(client: TestClient) -> None:
    for r in (client.get("/"), client.get("/api/schema"), client.get("/api/docs")):
        assert r.headers["x-content-type-options"] == "nosniff"
        csp = r.headers["content-security-policy"]
        assert "default-src 'self'" in csp and "frame-ancestors 'self'" in csp
        assert "script-src 'self';" in csp and "connect-src 'self' ws://127.0.0.1" in csp
        assert r.headers["referrer-policy"] == "no-referrer"
    refused = TestClient(create_app("rosette"), base_url="http://evil.example").get("/")
    assert refused.headers["x-content-type-options"] == "nosniff"


def test_no_served_page_loads_anything_from_another_site(client: TestClient) -> None:
    docs = client.get("/api/docs")
    assert docs.status_code == 200 and "/api/exact" in docs.text and "/openapi.json" in docs.text
    index = client.get("/")
    assets = re.findall(r'(?:src|href)="([^"]+)"', index.text)
    assert assets
    for page in (docs.text, index.text, *(client.get("/" + a.lstrip("./")).text for a in assets)):
        for url in re.findall(r"""(?:src|href|url)\s*[=(]\s*["']?(https?://[^"' )>]+)""", page):
            assert url.startswith("http://www.w3.org/"), url  # XML namespaces only, never fetched
    for gone in ("/docs", "/redoc"):
        assert client.get(gone).status_code == 404


# --- 6. slow clients, over a real socket ------------------------------------------------------------------


@pytest.fixture
def live_server(monkeypatch: pytest.MonkeyPatch) -> Any:
    """The lab under uvicorn on a free loopback port, with a 0.5 s header and body deadline."""
    monkeypatch.setattr(hygiene, "BODY_TIMEOUT", 0.5)
    with live_lab(create_app("rosette"), header_timeout=0.5) as port:
        yield port


def _closed_within(conn: socket.socket, seconds: float) -> tuple[bool, bytes]:
    conn.settimeout(seconds)
    data = b""
    try:
        while chunk := conn.recv(4096):
            data += chunk
    except TimeoutError:
        return False, data
    return True, data


def test_a_client_sending_its_headers_slowly_is_cut_off(live_server: int) -> None:
    with socket.create_connection(("127.0.0.1", live_server)) as conn:
        conn.sendall(b"GET /api/schema HTTP/1.1\r\nHost: 127.0.0.1\r\n")  # and never the blank line
        t0 = time.monotonic()
        closed, data = _closed_within(conn, 5.0)
        assert closed and data == b"" and time.monotonic() - t0 < 3.0
    with socket.create_connection(("127.0.0.1", live_server)) as idle:  # connects, sends nothing
        assert _closed_within(idle, 5.0)[0]


def test_a_body_that_never_arrives_times_out_with_408(live_server: int) -> None:
    with socket.create_connection(("127.0.0.1", live_server)) as conn:
        conn.sendall(
            b"POST /api/exact HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
            b'Content-Length: 100\r\n\r\n{"theta":'
        )
        closed, data = _closed_within(conn, 5.0)
    assert closed and data.startswith(b"HTTP/1.1 408")
    # a normal request is still served
    with socket.create_connection(("127.0.0.1", live_server)) as conn:
        conn.sendall(b"GET /api/schema HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        assert _closed_within(conn, 5.0)[1].startswith(b"HTTP/1.1 200")
