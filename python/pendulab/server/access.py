"""Who may use the lab: the allowed ``Host`` names, same-origin pages only, and the classroom token
(docs/web.md, "Security").

A browser lets any web page open a WebSocket to any address (no CORS for WebSockets) and send
CORS-"simple" requests to it, and a DNS name controlled by an attacker can be made to point at
127.0.0.1 (DNS rebinding). So every request passes three checks, in this order:

1. **Host** (starlette's :class:`~starlette.middleware.trustedhost.TrustedHostMiddleware`): the
   ``Host`` header must name this machine as the user reaches it — the loopback names by default,
   plus the bound address and the machine's names and addresses when bound elsewhere
   (:func:`allowed_hosts`), plus ``--allow-host`` names. Otherwise HTTP 400.
2. **Origin**: a WebSocket upgrade or a non-GET request that carries an ``Origin`` header must come
   from the page's own origin (:func:`same_origin`: the scheme the server is reached by, the host and
   port of the ``Host`` header, nothing else); a WebSocket from another
   origin is accepted only to be told why and closed with code 1008 (policy violation), an HTTP request
   gets 403. Requests without ``Origin`` (scripts, curl, the tests) are not from a page in a browser.
3. **Token** (classroom mode, when the app has one): the request carries it as ``?token=…``, as the
   cookie set on the first visit (:func:`cookie_name`; ``HttpOnly``, ``SameSite=Strict``), or as
   ``Authorization: token …``. A page visit with ``?token=`` gets the cookie and is redirected to the
   same URL without the token (so it is not shared with the page's links). Otherwise HTTP 403 / close
   1008 with a message saying where the token is.
"""

from __future__ import annotations

import hashlib
import hmac
import ipaddress
import json
import re
import socket
from collections.abc import Iterable, Sequence
from urllib.parse import urlsplit

from starlette.datastructures import URL, Headers, QueryParams
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.requests import cookie_parser
from starlette.responses import PlainTextResponse, RedirectResponse
from starlette.types import ASGIApp, Message, Receive, Scope, Send

LOOPBACK_HOSTS: tuple[str, ...] = ("localhost", "127.0.0.1", "::1", "[::1]")
"""The names of this machine that only this machine reaches: always allowed."""

TOKEN_PARAM = "token"
"""The query parameter that carries the classroom token."""


def is_loopback(host: str) -> bool:
    """True for an address or name that only this machine reaches (127.0.0.0/8, ::1, localhost)."""
    name = host.strip("[]").lower()
    if name == "localhost":
        return True
    try:
        return ipaddress.ip_address(name).is_loopback
    except ValueError:
        return False


def is_wildcard(host: str) -> bool:
    """True for 0.0.0.0 and :: (listen on every interface)."""
    try:
        return ipaddress.ip_address(host.strip("[]")).is_unspecified
    except ValueError:
        return False


def machine_addresses() -> list[str]:
    """This machine's host name, its fully qualified name, ``<name>.local`` (mDNS) and every address
    they resolve to, plus the address of the interface that routes to the outside (found without
    sending anything): the names other machines of a LAN may use to reach it."""
    names: list[str] = []
    hostname = socket.gethostname()
    for name in (hostname, socket.getfqdn(), f"{hostname}.local"):
        if name and name not in names:
            names.append(name)
    for name in list(names):
        try:
            infos = socket.getaddrinfo(name, None, type=socket.SOCK_STREAM)
        except OSError:
            continue
        for info in infos:
            addr = str(info[4][0]).split("%")[0]
            if addr not in names:
                names.append(addr)
    primary = primary_address()
    if primary is not None and primary not in names:
        names.append(primary)
    return names


def primary_address() -> str | None:
    """The IPv4 address of the interface with the default route (what a LAN's machines use to reach
    this one), or None without a network. A UDP ``connect`` sends no packet."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        try:
            s.connect(("192.0.2.1", 9))  # TEST-NET-1: never routed anywhere real, nothing is sent
            addr = str(s.getsockname()[0])
        except OSError:
            return None
    return None if is_loopback(addr) or is_wildcard(addr) else addr


def allowed_hosts(bind: str = "127.0.0.1", extra: Iterable[str] = ()) -> list[str]:
    """The ``Host`` names the lab answers to when listening on ``bind``: the loopback names; the bound
    address itself; when bound to a wildcard address (0.0.0.0, ::) or another non-loopback address,
    also this machine's names and addresses (:func:`machine_addresses`); and ``extra`` (``--allow-host``;
    ``*`` allows every name, ``*.example.org`` a domain's names)."""
    hosts = list(LOOPBACK_HOSTS)

    def add(name: str) -> None:
        name = name.strip().lower()
        if name and name not in hosts:
            hosts.append(name)
            if ":" in name and not name.startswith("["):  # an IPv6 literal, as it appears in Host
                hosts.append(f"[{name}]")

    if not is_wildcard(bind):
        add(bind)
    if not is_loopback(bind):
        for name in machine_addresses():
            add(name)
    for name in extra:
        add(name)
    return hosts


def cookie_name(token: str) -> str:
    """The cookie that carries ``token`` after the first visit; named after a hash of the token, so two
    labs on one machine (cookies ignore the port) do not overwrite each other's."""
    return "pendulab-token-" + hashlib.sha256(token.encode()).hexdigest()[:12]


_DEFAULT_PORTS = {"http": 80, "https": 443}
_SERVED = {"http": "http", "https": "https", "ws": "http", "wss": "https"}
_AUTHORITY = re.compile(
    r"(?P<host>[a-z0-9_](?:[a-z0-9_.-]*[a-z0-9_.])?|\[(?P<ipv6>[0-9a-f:.]+)\])"
    r"(?::(?P<port>0|[1-9][0-9]{0,4}))?",
    re.IGNORECASE,
)


def _authority(text: str, scheme: str) -> tuple[str, int] | None:
    """``host[:port]`` as ``(host, port)``: the host lower-cased (an IPv6 literal in brackets, in its
    compressed form), the port the scheme's default when none is given; None for anything else
    (userinfo, an empty or non-numeric port, a port with leading zeros or over 65535, spaces, …)."""
    m = _AUTHORITY.fullmatch(text)
    if m is None:
        return None
    host = m["host"].lower()
    if m["ipv6"] is not None:
        try:
            host = f"[{ipaddress.IPv6Address(m['ipv6']).compressed}]"
        except ValueError:
            return None
    port = int(m["port"]) if m["port"] is not None else _DEFAULT_PORTS[scheme]
    return (host, port) if port <= 65535 else None


def same_origin(origin: str, host: str | None, scheme: str = "http") -> bool:
    """True when the ``Origin`` header names the page's own origin: exactly ``scheme://host[:port]`` as a
    browser writes it (RFC 6454: no userinfo, path, query or fragment), its scheme the one the server is
    reached by (``scheme``: the request's, ``ws``/``wss`` counting as ``http``/``https``), its host and
    port those of the ``Host`` header (host names compared without case, IPv6 literals in any spelling,
    a missing port the scheme's default). ``null`` (sandboxed pages, files), other schemes and anything
    unparsable are refused."""
    served = _SERVED.get(scheme.lower())
    if not host or served is None or not origin.isascii():
        return False
    try:
        parts = urlsplit(origin)
    except ValueError:
        return False
    if parts.scheme != served or origin[: len(served) + 3].lower() != served + "://":
        return False
    if origin[len(served) + 3 :] != parts.netloc:  # a path, "?", "#", or whatever urlsplit dropped
        return False
    mine = _authority(parts.netloc, served)
    return mine is not None and mine == _authority(host, served)


class AccessGuard:
    """ASGI middleware: the Origin and token checks of the module doc (the Host check wraps it, see
    :func:`guard`)."""

    def __init__(self, app: ASGIApp, token: str | None = None) -> None:
        self.app = app
        self.token = token
        self.cookie = cookie_name(token) if token else ""

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        kind = scope["type"]
        if kind not in ("http", "websocket"):
            await self.app(scope, receive, send)
            return
        headers = Headers(scope=scope)
        origin = headers.get("origin")
        checks_origin = kind == "websocket" or scope["method"] not in ("GET", "HEAD", "OPTIONS")
        if (
            origin is not None
            and checks_origin
            and not same_origin(origin, headers.get("host"), scope.get("scheme", "http"))
        ):
            await refuse(
                scope,
                receive,
                send,
                f"refused: a page from {origin[:100]!r} may not use this lab; "
                "only the lab's own page (same origin) may",
            )
            return
        if self.token is None:
            await self.app(scope, receive, send)
            return
        given = QueryParams(scope.get("query_string", b"").decode("latin-1")).get(TOKEN_PARAM)
        if given is not None and _equal(given, self.token):
            if kind == "http" and scope["method"] == "GET" and not scope["path"].startswith("/api/"):
                # First visit: the cookie, and the same URL without the token.
                redirect = RedirectResponse(local_location(scope), status_code=303)
                redirect.set_cookie(self.cookie, self.token, httponly=True, samesite="strict", path="/")
                await redirect(scope, receive, send)
                return
            await self.app(scope, receive, send)
            return
        cookie = cookie_parser(headers.get("cookie", "")).get(self.cookie)
        auth = headers.get("authorization", "")
        bearer = auth[6:].strip() if auth.lower().startswith("token ") else None
        if (cookie is not None and _equal(cookie, self.token)) or (
            bearer is not None and _equal(bearer, self.token)
        ):
            await self.app(scope, receive, send)
            return
        wrong = "a wrong token" if given is not None or cookie is not None or bearer else "no token"
        await refuse(
            scope,
            receive,
            send,
            f"refused: this lab needs its access token ({wrong} given); open the address that "
            "`pendulab serve` printed (it ends in ?token=...) or scan its QR code",
        )


def local_location(scope: Scope) -> str:
    """The request's own path and query without the token, as a redirect target that stays on this
    server: a path of ``//evil.example/`` (or ``/\\evil.example``, which browsers read alike) would
    otherwise be a link to another site (an open redirect), so leading slashes and backslashes are
    folded into one ``/``."""
    url = URL(scope=scope).remove_query_params(TOKEN_PARAM)
    path = "/" + url.path.lstrip("/\\")
    return path + (f"?{url.query}" if url.query else "")


def _equal(a: str, b: str) -> bool:
    return hmac.compare_digest(a.encode("utf-8", "replace"), b.encode("utf-8", "replace"))


async def refuse(scope: Scope, receive: Receive, send: Send, message: str) -> None:
    """HTTP 403 with ``message``; a WebSocket is accepted only to receive an ``error`` notice with it
    and is closed with code 1008 (policy violation), so the page can show why."""
    if scope["type"] == "http":
        await PlainTextResponse(message + "\n", status_code=403)(scope, receive, send)
        return
    msg: Message = await receive()
    if msg["type"] != "websocket.connect":
        return
    await send({"type": "websocket.accept"})
    notice = {"type": "error", "message": message, "command": None}
    await send({"type": "websocket.send", "text": json.dumps(notice)})
    await send(
        {"type": "websocket.close", "code": 1008, "reason": message.encode()[:120].decode(errors="ignore")}
    )


def guard(app: ASGIApp, hosts: Sequence[str], token: str | None) -> ASGIApp:
    """``app`` behind the Host check (starlette's TrustedHostMiddleware), then the Origin and token
    checks (:class:`AccessGuard`)."""
    return TrustedHostMiddleware(AccessGuard(app, token), allowed_hosts=list(hosts), www_redirect=False)
