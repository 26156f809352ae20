"""Classroom mode of ``pendulab serve`` (docs/web.md, "Security"): a random access token when the lab
listens beyond this machine, the address that carries it, and that address as a QR code in the
terminal, as Jupyter does with its token URL.

:func:`access_token` decides the token: ``--token VALUE`` as given, ``--no-token`` none, otherwise a
new random one (:func:`new_token`, 128 bits from :mod:`secrets`) exactly when the bind address is not
loopback. :func:`lab_url` is the address to print and open (the machine's LAN address for a wildcard
bind, with ``?token=…``); :func:`qr_text` draws it with the ``qrcode`` package in half-block
characters, two modules per character cell, with the quiet zone the standard asks for.
"""

from __future__ import annotations

import io
import ipaddress
import secrets
from urllib.parse import quote

from .access import TOKEN_PARAM, is_loopback, is_wildcard, primary_address

TOKEN_BYTES = 16
"""Random bytes of a generated token (128 bits; 22 URL-safe characters)."""


def new_token() -> str:
    """A fresh random token (URL-safe text)."""
    return secrets.token_urlsafe(TOKEN_BYTES)


def access_token(host: str, token: str | None = None, no_token: bool = False) -> str | None:
    """The token the lab requires: ``token`` when given (``--token``), None with ``no_token``
    (``--no-token``), a new random one when ``host`` is not a loopback address, else None. Raises
    ValueError for both, or for a token that is empty, too short (< 8 characters) or not printable."""
    if token is not None and no_token:
        raise ValueError("give --token VALUE or --no-token, not both")
    if token is not None:
        if len(token) < 8 or not token.isprintable() or any(c.isspace() for c in token):
            raise ValueError("--token must be at least 8 printable characters without spaces")
        return token
    if no_token or is_loopback(host):
        return None
    return new_token()


def lab_url(host: str, port: int, token: str | None = None) -> str:
    """The address to print and open: a wildcard host is shown as this machine's LAN address (the
    loopback address without a network), an IPv6 address in brackets; with ``token``, ``?token=…``."""
    shown = host
    if is_wildcard(host):
        lan = primary_address()
        shown = lan if lan is not None and token is not None else ("127.0.0.1" if ":" not in host else "::1")
    try:
        if ipaddress.ip_address(shown.strip("[]")).version == 6:
            shown = f"[{shown.strip('[]')}]"
    except ValueError:  # a host name
        pass
    url = f"http://{shown}:{port}/"
    return url if token is None else f"{url}?{TOKEN_PARAM}={quote(token, safe='')}"


def qr_text(text: str) -> str:
    """``text`` as a QR code drawn with Unicode half blocks (dark modules as the terminal's
    background), for a phone or tablet to scan from the terminal; empty when the ``qrcode`` package
    is missing."""
    try:
        import qrcode
    except ImportError:
        return ""
    qr = qrcode.QRCode(border=2, error_correction=qrcode.constants.ERROR_CORRECT_L)
    qr.add_data(text)
    qr.make(fit=True)
    out = io.StringIO()
    qr.print_ascii(out=out, invert=True)
    return out.getvalue()
