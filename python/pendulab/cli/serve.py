"""``pendulab serve``: the interactive 3-D lab in the browser (docs/web.md).

Registered on :data:`pendulab.cli.app`. Starts the FastAPI server of :mod:`pendulab.server` with uvicorn,
prints its URL and opens it in a browser where one exists. The server and its dependencies (the
``lab`` extra) are imported only when the command runs, so other commands stay fast without them.
Exit codes: 0 after Ctrl-C (the normal way to stop a server), 2 on a user error (bad scenario, port
in use, missing extra).
"""

from __future__ import annotations

import contextlib
import ipaddress
import math
import os
import socket
import sys
import threading
import time
import webbrowser
from collections.abc import Callable
from typing import Annotated

import typer

from .common import UsageError, _fail, _say, _user_errors, app

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8000

_CONSOLE_BROWSERS = ("www-browser", "lynx", "links", "elinks", "w3m")


def browser_available() -> bool:
    """True where opening a browser makes sense: not in CI, and on Linux/BSD only with a display.

    ``webbrowser`` would otherwise start a text browser (lynx, w3m) in the terminal of a headless machine.
    """
    if os.environ.get("CI") or os.environ.get("PENDULAB_NO_BROWSER"):
        return False
    if sys.platform.startswith(("linux", "freebsd", "openbsd", "netbsd")) and not (
        os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
    ):
        return False
    try:
        browser = webbrowser.get()
    except webbrowser.Error:
        return False
    return getattr(browser, "name", "") not in _CONSOLE_BROWSERS


def url_for(host: str, port: int) -> str:
    """The address to print and open: a wildcard host is shown as the loopback address."""
    shown = host
    try:
        ip = ipaddress.ip_address(host)
        if ip.is_unspecified:
            shown = "127.0.0.1" if ip.version == 4 else "::1"
        if ip.version == 6:
            shown = f"[{ipaddress.ip_address(shown)}]"
    except ValueError:  # a host name
        pass
    return f"http://{shown}:{port}"


def _check_port(host: str, port: int) -> None:
    """Fails early with one line when the address cannot be bound (in use, not local, no permission)."""
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)
    except socket.gaierror as e:
        _fail(f"--host {host!r}: {e.strerror or e}")
    family, kind, proto, _, addr = infos[0]
    with socket.socket(family, kind, proto) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind(addr)
        except OSError as e:
            _fail(f"cannot listen on {host}:{port}: {e.strerror or e}; choose another --port or --host")


def _check_proxies(value: str) -> None:
    """Fails with one line unless ``value`` is ``*`` or comma-separated IP addresses or networks."""
    for item in value.split(","):
        item = item.strip()
        if item == "*":
            continue
        try:
            ipaddress.ip_network(item, strict=False)
        except ValueError:
            _fail(f"--trust-proxy: {item!r} is not an IP address or network (e.g. 127.0.0.1, 10.0.0.0/8, *)")


def _checked_by(option: str, load_rule: Callable[[], Callable[[float], float]]) -> Callable[[float], float]:
    """A typer callback checking ``option`` by the server's own rule, which ``load_rule()`` imports and
    returns (a function of the value that raises ValueError naming what is allowed), as the command line
    is read. nan and ±inf pass through to the one message every float option gives them
    (``cli.common._checked``); without the ``lab`` extra (``load_rule`` raises ImportError) the value
    passes too, and serve names the missing extra itself."""

    def check(value: float) -> float:
        if not math.isfinite(value):
            return value
        try:
            rule = load_rule()
        except ImportError:
            return value
        try:
            return rule(value)
        except ValueError as e:
            raise UsageError(f"{option}: {e}") from None

    return check


def _idle_timeout_rule() -> Callable[[float], float]:
    """:func:`pendulab.server.serving.check_idle_timeout`, imported when ``--idle-timeout`` is read."""
    from ..server.serving import check_idle_timeout

    return check_idle_timeout


def _fit_time_limit_rule() -> Callable[[float], float]:
    """:func:`pendulab.server.fit.check_fit_time_limit`, imported when ``--fit-time-limit`` is read."""
    from ..server.fit import check_fit_time_limit

    return check_fit_time_limit


_idle_timeout = _checked_by("--idle-timeout", _idle_timeout_rule)
_fit_time_limit = _checked_by("--fit-time-limit", _fit_time_limit_rule)


def _open_when_up(server: object, url: str) -> None:
    for _ in range(200):  # up to 10 s
        if getattr(server, "started", False):
            with contextlib.suppress(Exception):  # no browser after all: the URL is printed
                webbrowser.open(url)
            return
        time.sleep(0.05)


@app.command(short_help="Start the interactive 3-D lab in the browser.")
def serve(
    scenario: Annotated[
        str | None,
        typer.Argument(
            metavar="SCENARIO",
            help="An example name (see `pendulab scenarios`) or a scenario file; default rosette.",
            show_default=False,
        ),
    ] = None,
    host: Annotated[
        str, typer.Option(help="Address to listen on; 0.0.0.0 makes the lab reachable from other machines.")
    ] = DEFAULT_HOST,
    port: Annotated[int, typer.Option(min=1, max=65535, help="TCP port.")] = DEFAULT_PORT,
    no_browser: Annotated[bool, typer.Option("--no-browser", help="Do not open a browser.")] = False,
    max_sessions: Annotated[
        int,
        typer.Option(min=1, max=10_000, help="Most pages (WebSockets) served at once; one more is refused."),
    ] = 64,
    max_sessions_per_client: Annotated[
        int,
        typer.Option(
            min=1,
            max=10_000,
            help="Most pages one device (address; a global IPv6 address's /64) may hold open; one more is "
            "refused.",
        ),
    ] = 8,
    max_connections_per_client: Annotated[
        int,
        typer.Option(
            min=1,
            max=100_000,
            help="Most TCP connections one device (address; a global IPv6 address's /64) may hold open (its "
            "pages' WebSockets and requests); more are reset. Raise it for a class behind one NAT address.",
        ),
    ] = 24,
    max_computations_per_client: Annotated[
        int,
        typer.Option(
            min=1,
            max=1_000,
            help="Most computing requests (fits, exact solutions, reduced views, EM maps) one device may "
            "have under way or waiting; one more is answered 429.",
        ),
    ] = 2,
    idle_timeout: Annotated[
        float,
        typer.Option(
            callback=_idle_timeout,
            help="Seconds a page's WebSocket may send nothing (no command, no answer to the server's "
            "pings) before it is closed, 1 to 86400 (one day); an open page's browser answers the pings "
            "by itself.",
        ),
    ] = 60.0,
    fit_time_limit: Annotated[
        float,
        typer.Option(
            callback=_fit_time_limit,
            metavar="SECONDS",
            help="Seconds a measured data file's fit may take (pl.fit's time_limit: from reading the data "
            "to the error bars), > 0 and at most 600; then the best values reached are shown. Longer "
            "fits: pendulab fit FILE --time-limit none.",
        ),
    ] = 20.0,
    allow_host: Annotated[
        list[str] | None,
        typer.Option(
            metavar="HOST",
            help="Another Host name the lab answers to (repeatable; '*.example.org' a domain, '*' any). "
            "Always: the loopback names, the --host address and, bound elsewhere, this machine's names.",
            show_default=False,
        ),
    ] = None,
    token: Annotated[
        str | None,
        typer.Option(
            help="Classroom mode with this access token (at least 8 characters); bound to a non-loopback "
            "address a random one is made unless --no-token.",
            show_default=False,
        ),
    ] = None,
    no_token: Annotated[
        bool,
        typer.Option("--no-token", help="No access token, even on the network (anyone there may use it)."),
    ] = False,
    trust_proxy: Annotated[
        str | None,
        typer.Option(
            help="Behind a reverse proxy: its addresses or networks (comma-separated, '*' any), whose "
            "X-Forwarded-For / X-Forwarded-Proto name the client. Off by default: the client is the "
            "connecting address, whatever such headers say.",
            show_default=False,
        ),
    ] = None,
) -> None:
    """Start the lab: a web server with the 3-D pendulum, controls, live plots and the exact solution.

    Prints the URL (http://127.0.0.1:8000 by default) and opens it where a browser exists. Every page
    gets its own simulation, computed here by the core and streamed to the page. Ctrl-C stops it.
    Bound beyond this machine (--host 0.0.0.0) it runs in classroom mode: the printed URL and QR code
    carry a random access token that every page needs (docs/web.md, "Security").
    """
    try:
        import uvicorn

        from ..server import create_app
        from ..server.access import allowed_hosts
        from ..server.classroom import access_token, lab_url, qr_text
        from ..server.serving import server_config
    except ImportError as e:
        _fail(
            f"pendulab serve needs FastAPI, uvicorn and websockets ({e}); "
            "install them with: pip install 'pendulab[lab]'"
        )
    if trust_proxy is not None:
        _check_proxies(trust_proxy)
    try:
        secret = access_token(host, token, no_token)
    except ValueError as e:
        _fail(str(e))
    with _user_errors():
        hosts = allowed_hosts(host, allow_host or ())
        lab = create_app(
            scenario,
            max_sessions=max_sessions,
            allowed_hosts=hosts,
            token=secret,
            max_sessions_per_client=max_sessions_per_client,
            max_computations_per_client=max_computations_per_client,
            fit_time_limit=fit_time_limit,
        )
    _check_port(host, port)
    url = url_for(host, port) if secret is None else lab_url(host, port, secret)
    config = server_config(
        lab,
        host,
        port,
        max_sessions=max_sessions,
        max_connections_per_client=max_connections_per_client,
        idle_timeout=idle_timeout,
        trusted_proxies=trust_proxy,
    )
    server = uvicorn.Server(config)
    _say(f"Pendulab lab: {url}   (Ctrl-C stops the server)")
    if secret is not None:
        _say(qr_text(url).rstrip("\n"))
        _say(
            f"classroom mode: every page needs the token; open the address above or scan the code "
            f"(a page keeps a cookie after its first visit). At most {max_sessions} pages at once."
        )
    elif host not in ("127.0.0.1", "localhost", "::1"):
        _say(f"listening on {host} without a token (--no-token): anyone on the network can use the lab")
    for pool in lab.state.pools:  # the workers' first start (the fork server imports the package)
        threading.Thread(target=pool.warm, daemon=True).start()  # would delay the first analysis
    if not no_browser and browser_available():
        threading.Thread(target=_open_when_up, args=(server, url), daemon=True).start()
    with contextlib.suppress(KeyboardInterrupt):  # uvicorn re-raises the Ctrl-C it handled: exit 0
        server.run()
    if not server.started:
        _fail(f"the server could not start on {host}:{port}")
    # Stopped (Ctrl-C): leave at once. Tearing the interpreter down (numpy, the core, the server's
    # modules) adds most of a second on a loaded machine, and there is nothing left to clean up.
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)
