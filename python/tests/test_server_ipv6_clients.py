"""IPv6 clients and the caps per client (docs/web.md, "A pupil in the room"): one device may take any
number of addresses in its /64 (SLAAC privacy addresses, or any it assigns itself), so the caps key an
IPv6 client by its /64 network (``pendulab.server.room.address_key``); keyed by the whole address, as
before, each new address was a new client with its own 8 sessions, 24 connections and 2 computations.
An IPv4 client is its address, whether it comes as itself or IPv4-mapped (``::ffff:a.b.c.d``, through a
socket bound to ``::``). The attack is made with addresses of the documentation prefix 2001:db8::/32
given to the application (the test machine routes none of them): many addresses of one /64 share one
client's caps; two /64s are two clients. A link-local address (``fe80::/10``) is a client by
itself (and its zone where the address names one): every link's addresses share ``fe80::/64``."""

from __future__ import annotations

import asyncio
import contextlib
import ipaddress
import socket
from pathlib import Path
from typing import Any

import pytest
from uvicorn.protocols.utils import get_remote_addr
from uvicorn.server import ServerState
from ws_session import LabClient, receive

from pendulab.server import create_app
from pendulab.server.room import address_key, client_key
from pendulab.server.serving import server_config

ONE_64 = ["2001:db8:1:2::a", "2001:db8:1:2::b", "2001:db8:1:2:ffff:ffff:ffff:ffff", "2001:db8:1:2:0:5efe:1:2"]
OTHER_64 = "2001:db8:1:3::a"


@pytest.mark.parametrize(
    ("host", "key"),
    [
        ("192.0.2.7", "192.0.2.7"),
        ("::ffff:192.0.2.7", "192.0.2.7"),  # IPv4-mapped: the IPv4 client
        ("2001:db8:1:2::a", "2001:db8:1:2::/64"),
        ("2001:DB8:1:2:abcd:ef01:2345:6789", "2001:db8:1:2::/64"),
        ("2001:db8:1:2::a%eth0", "2001:db8:1:2::/64"),  # a global address's zone index dropped
        ("fe80::1%eth0", "fe80::1%eth0"),  # link-local: the whole address, with its zone
        ("FE80::A:0:0:1%2", "fe80::a:0:0:1%2"),
        ("fe80::1", "fe80::1"),
        ("febf:ffff::1", "febf:ffff::1"),  # the last of fe80::/10
        ("fec0::1", "fec0::/64"),  # beyond it: a /64 again
        ("::1", "::/64"),
        ("testclient", "testclient"),  # no IP address: its own key
    ],
)
def test_the_key_of_an_address(host: str, key: str) -> None:
    assert address_key(host) == key
    assert client_key({"client": (host, 50000)}) == key


def test_ipv4_clients_are_their_addresses() -> None:
    assert address_key("192.0.2.7") != address_key("192.0.2.8")
    assert address_key("10.1.2.3") != address_key("10.1.2.4")


def test_link_local_clients_are_their_addresses_on_their_links() -> None:
    """Every link-local address, on every link, lies in ``fe80::/64``: keyed by its /64, as before, all
    link-local clients of all the server's interfaces shared one client's caps (one pupil's 8 sessions
    for the whole link). Keyed by the address, and its zone where it names one: two devices of one
    link, or one address on two links (two devices), are two clients; one address on one link is one
    client. (uvicorn names a client without its zone: the next test.)"""
    app = create_app("rosette", max_sessions_per_client=1)
    with _lab("fe80::1%eth0", app).websocket_connect("/ws") as first:
        assert receive(first)[1]["type"] == "status"
        with _lab("FE80::0:1%eth0", app).websocket_connect("/ws") as again:
            assert receive(again)[1]["key"] == "device_full"
        for other in ("fe80::2%eth0", "fe80::1%eth1", "fe80::1:0:0:1%eth0"):
            with _lab(other, app).websocket_connect("/ws") as ws:
                assert receive(ws)[1]["type"] == "status", other


def _link_local() -> tuple[str, int] | None:
    """A link-local address of this machine and its interface's index (Linux: /proc/net/if_inet6), or
    None."""
    with contextlib.suppress(OSError):
        for line in Path("/proc/net/if_inet6").read_text().splitlines():
            digits, _, _, scope, _, name = line.split()
            if scope == "20":  # link
                return str(ipaddress.IPv6Address(int(digits, 16))), socket.if_nametoindex(name)
    return None


def test_a_real_link_local_client_is_keyed_as_the_server_sees_it() -> None:
    """A TCP connection over a link-local address of this machine, named as uvicorn names the client
    (``get_remote_addr``): the address without its zone (the socket gives the interface as a separate
    index, which uvicorn drops), and that address is the key (was ``fe80::/64``)."""
    local = _link_local()
    if local is None:
        pytest.skip("no link-local IPv6 address on this machine")
    address, index = local
    with socket.socket(socket.AF_INET6) as server, socket.socket(socket.AF_INET6) as client:
        server.bind((address, 0, 0, index))
        server.listen(1)
        client.settimeout(10)
        client.connect((address, server.getsockname()[1], 0, index))
        accepted, _ = server.accept()
        with accepted:
            transport = type("Transport", (), {"get_extra_info": lambda _, name: accepted})()
            remote = get_remote_addr(transport)  # type: ignore[arg-type]
    assert remote is not None and remote[0] == address
    assert address_key(remote[0]) == address != "fe80::/64"


def _lab(host: str, app: Any) -> LabClient:
    return LabClient(app, client=(host, 50000))


def test_many_addresses_of_one_64_share_one_clients_sessions() -> None:
    """Two sessions per client: the third, from a third address of the same /64, is refused with
    ``device_full``; one from another /64 is served meanwhile."""
    app = create_app("rosette", max_sessions_per_client=2)
    a, b, c = (_lab(h, app) for h in ONE_64[:3])
    with a.websocket_connect("/ws") as wa, b.websocket_connect("/ws") as wb:
        assert receive(wa)[1]["type"] == "status" and receive(wb)[1]["type"] == "status"
        with c.websocket_connect("/ws") as wc:
            notice = receive(wc)[1]
            assert notice["type"] == "error" and notice["key"] == "device_full", notice
        with _lab(OTHER_64, app).websocket_connect("/ws") as other:
            assert receive(other)[1]["type"] == "status"


def test_an_ipv4_client_mapped_or_not_is_one_client() -> None:
    app = create_app("rosette", max_sessions_per_client=1)
    with _lab("192.0.2.7", app).websocket_connect("/ws") as plain:
        assert receive(plain)[1]["type"] == "status"
        with _lab("::ffff:192.0.2.7", app).websocket_connect("/ws") as mapped:
            assert receive(mapped)[1]["key"] == "device_full"
        with _lab("192.0.2.8", app).websocket_connect("/ws") as neighbour:
            assert receive(neighbour)[1]["type"] == "status"


def test_many_addresses_of_one_64_share_one_clients_computations() -> None:
    app = create_app("rosette", max_computations_per_client=1)
    app.state.room.requests[client_key({"client": (ONE_64[0], 1)})] = 1  # one under way
    for host in ONE_64[1:]:
        r = _lab(host, app).post("/api/exact", json={"theta": 1.0})
        assert r.status_code == 429 and r.json()["key"] == "device_busy", host
    assert _lab(OTHER_64, app).post("/api/exact", json={"theta": 1.0}).status_code == 200


class _Transport(asyncio.Transport):
    """An accepted connection from ``host``: only whether it was cut is kept."""

    def __init__(self, host: str) -> None:
        super().__init__()
        self.host = host
        self.cut = False

    def get_extra_info(self, name: str, default: Any = None) -> Any:
        peer, local = (self.host, 50000, 0, 0), ("::", 8000, 0, 0)  # an AF_INET6 socket's names
        sock = type("Socket", (), {"getpeername": lambda _: peer, "getsockname": lambda _: local})()
        return {"peername": peer, "sockname": local, "socket": sock}.get(name, default)

    def is_closing(self) -> bool:
        return self.cut

    def abort(self) -> None:
        self.cut = True

    def close(self) -> None:
        self.cut = True

    def set_protocol(self, protocol: Any) -> None:
        pass

    def get_protocol(self) -> Any:
        return None


def test_many_addresses_of_one_64_share_one_clients_connections() -> None:
    """The lab's HTTP protocol (``server_config``'s, at most 3 connections per client) accepting
    connections as uvicorn does: the fourth from the /64, from a new address, is cut as soon as it is
    accepted; another /64 (and an IPv4 client) still gets in."""

    async def run() -> list[bool]:
        config = server_config(create_app("rosette"), "::", 8000, max_connections_per_client=3)
        config.load()
        state = ServerState()
        cut = []
        for host in [*ONE_64, OTHER_64, "::ffff:192.0.2.7"]:
            protocol = config.http_protocol_class(config=config, server_state=state, app_state={})
            transport = _Transport(host)
            protocol.connection_made(transport)
            cut.append(transport.cut)
        for c in list(state.connections):
            c._disarm()  # no header timer left behind
        return cut

    assert asyncio.run(run()) == [False, False, False, True, False, False]
