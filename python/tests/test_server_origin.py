"""The lab's ``Origin`` check against odd and hostile origins (docs/web.md, "Security"): only the page's own
origin exactly as a browser writes it — the scheme the server is reached by, the ``Host`` header's host and
port, no userinfo, path, query or fragment — may open a WebSocket or send a non-GET request.

Before, the check compared only the parsed host and port: ``http://evil.com@127.0.0.1:8765`` (userinfo),
``https://127.0.0.1:8765`` on a plain-http server and ``http://127.0.0.1:8765/path?q#f`` were all taken
for the lab's own page."""

from __future__ import annotations

import json

import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect
from ws_session import LabClient

from pendulab.server import create_app
from pendulab.server.access import same_origin

HOST = "127.0.0.1:8765"

ACCEPTED = [
    ("http://127.0.0.1:8765", HOST, "http"),
    ("http://127.0.0.1:8765", HOST, "ws"),  # the page's WebSocket: ws counts as http
    ("HTTP://127.0.0.1:8765", HOST, "http"),  # schemes are case-insensitive
    ("http://LOCALHOST:8765", "localhost:8765", "http"),  # so are host names
    ("http://localhost:8765", "LocalHost:8765", "http"),
    ("http://localhost", "localhost", "http"),  # default port on both sides
    ("http://localhost", "localhost:80", "http"),
    ("http://localhost:80", "localhost", "http"),
    ("https://lab.example", "lab.example", "https"),  # behind a TLS proxy that is trusted
    ("https://lab.example:443", "lab.example", "wss"),
    ("http://[::1]:8765", "[::1]:8765", "http"),
    ("http://[0:0:0:0:0:0:0:1]:8765", "[::1]:8765", "ws"),  # one IPv6 address, two spellings
    ("http://[FE80::1]:8765", "[fe80::1]:8765", "http"),
]

REFUSED = [
    ("null", HOST, "http"),  # sandboxed frames, file:// pages, redirects across origins
    ("", HOST, "http"),
    ("http://127.0.0.1:8765", None, "http"),  # no Host header
    ("http://127.0.0.1:8765", "", "http"),
    ("http://127.0.0.1:8765.evil.com", HOST, "http"),
    ("http://127.0.0.1.evil.com:8765", HOST, "http"),
    ("http://evil.com@127.0.0.1:8765", HOST, "http"),  # userinfo
    ("http://127.0.0.1:8765@evil.com", HOST, "http"),
    ("http://:@127.0.0.1:8765", HOST, "http"),
    ("http://evil.com:8765", HOST, "http"),
    ("http://127.0.0.1:8766", HOST, "http"),  # wrong port
    ("http://127.0.0.1", HOST, "http"),  # port 80, the server's is 8765
    ("http://127.0.0.1:08765", HOST, "http"),  # no browser writes leading zeros
    ("http://127.0.0.1:", HOST, "http"),
    ("http://127.0.0.1:99999", "127.0.0.1:99999", "http"),
    ("https://127.0.0.1:8765", HOST, "http"),  # another scheme than the server's
    ("http://lab.example", "lab.example", "https"),
    ("ws://127.0.0.1:8765", HOST, "ws"),  # no page has a ws: origin
    ("wss://127.0.0.1:8765", HOST, "wss"),
    ("file://", HOST, "http"),
    ("ftp://127.0.0.1:8765", HOST, "http"),
    ("chrome-extension://abcdef", HOST, "http"),
    ("http://127.0.0.1:8765/", HOST, "http"),  # a path, a query, a fragment: not an origin
    ("http://127.0.0.1:8765/lab", HOST, "http"),
    ("http://127.0.0.1:8765?", HOST, "http"),
    ("http://127.0.0.1:8765#x", HOST, "http"),
    ("http:127.0.0.1:8765", HOST, "http"),
    ("http:/127.0.0.1:8765", HOST, "http"),
    ("//127.0.0.1:8765", HOST, "http"),
    (" http://127.0.0.1:8765", HOST, "http"),  # urlsplit strips these spaces and tabs; the check does not
    ("http://127.0.0.1:8765 ", HOST, "http"),
    ("http://127.0.\t0.1:8765", HOST, "http"),
    ("http://127.0.0.1:8765", "127.0.0.1:8765, evil.com", "http"),
    ("http://[::1]:8765", "[::1]", "http"),
    ("http://[::1]", "[::1]:8765", "http"),
    ("http://[::1%25eth0]:8765", "[::1%25eth0]:8765", "http"),
    ("http://[127.0.0.1]:8765", "[127.0.0.1]:8765", "http"),
    ("http://::1:8765", "::1:8765", "http"),
    ("http://\u0440aypal.com:8765", "\u0440aypal.com:8765", "http"),  # non-ASCII: browsers send punycode
    ("http://127.0.0.1:8765", HOST, "gopher"),
]


@pytest.mark.parametrize(("origin", "host", "scheme"), ACCEPTED)
def test_the_pages_own_origin_is_accepted(origin: str, host: str, scheme: str) -> None:
    assert same_origin(origin, host, scheme)


@pytest.mark.parametrize(("origin", "host", "scheme"), REFUSED)
def test_any_other_origin_is_refused(origin: str, host: str | None, scheme: str) -> None:
    assert not same_origin(origin, host, scheme)


@pytest.fixture(scope="module")
def client() -> TestClient:
    return LabClient(create_app("rosette"))


def _refused_socket(client: TestClient, origin: str) -> bool:
    with client.websocket_connect("/ws", headers={"origin": origin}) as ws:
        notice = json.loads(ws.receive_text())
        if notice["type"] != "error":
            return False
        with pytest.raises(WebSocketDisconnect) as closed:
            ws.receive_text()
    return closed.value.code == 1008


@pytest.mark.parametrize(
    "origin",
    [
        "http://evil.com@127.0.0.1",
        "https://127.0.0.1",
        "ws://127.0.0.1",
        "http://127.0.0.1/",
        "http://127.0.0.1.evil.com",
        "null",
    ],
)
def test_the_server_refuses_an_odd_origin_on_its_websocket_and_its_posts(
    client: TestClient, origin: str
) -> None:
    """The attack end to end: the lab (on http://127.0.0.1) closes the WebSocket with 1008 and answers
    a POST with 403; its own page is served."""
    assert _refused_socket(client, origin)
    r = client.post("/api/exact", json={"theta": 1.0}, headers={"origin": origin})
    assert r.status_code == 403 and "same origin" in r.text
    assert not _refused_socket(client, "http://127.0.0.1")
    assert (
        client.post("/api/exact", json={"theta": 1.0}, headers={"origin": "http://127.0.0.1"}).status_code
        == 200
    )


def test_the_scheme_is_the_one_the_server_is_reached_by() -> None:
    """Reached over https (here: the test client's https URL; in use a TLS proxy named with
    ``--trust-proxy``, whose X-Forwarded-Proto uvicorn believes), the page's origin is https."""
    tls = TestClient(create_app("rosette"), base_url="https://127.0.0.1")
    ok = tls.post("/api/exact", json={"theta": 1.0}, headers={"origin": "https://127.0.0.1"})
    assert ok.status_code == 200
    plain = tls.post("/api/exact", json={"theta": 1.0}, headers={"origin": "http://127.0.0.1"})
    assert plain.status_code == 403
