"""``GET /api/docs``: the lab's API as one self-contained HTML page, generated from the app's OpenAPI
document (``GET /openapi.json``).

FastAPI's own docs pages load Swagger UI or ReDoc from a CDN; the lab must work offline and its pages
make no third-party request (docs/web.md, "Security"), so this page lists each endpoint — method, path,
summary, and the request body's fields with their descriptions and limits — in plain HTML with no
script, served under the same Content-Security-Policy as the lab.
"""

from __future__ import annotations

import html
from typing import Any


def _fields(schema: dict[str, Any], components: dict[str, Any]) -> list[tuple[str, str]]:
    ref = schema.get("$ref", "")
    if ref:
        schema = components.get(ref.rsplit("/", 1)[-1], {})
    rows = []
    for name, prop in (schema.get("properties") or {}).items():
        bits = [str(prop.get("description", ""))]
        limits = [f"{k} {prop[k]}" for k in ("minimum", "maximum", "minLength", "maxLength") if k in prop]
        if limits:
            bits.append("(" + ", ".join(limits) + ")")
        if "default" in prop:
            bits.append(f"default {prop['default']!r}")
        rows.append((name, " ".join(b for b in bits if b)))
    return rows


def api_docs_page(openapi: dict[str, Any]) -> str:
    """The HTML page describing ``openapi`` (an OpenAPI 3 document as FastAPI generates it)."""
    components = openapi.get("components", {}).get("schemas", {})
    out = [
        "<!doctype html><html lang='en'><meta charset='utf-8'>",
        f"<title>{html.escape(openapi['info']['title'])} API</title>",
        "<style>body{font:15px/1.45 system-ui,sans-serif;max-width:60em;margin:2em auto;padding:0 1em}"
        "code{background:#eee;padding:0 .2em}td{vertical-align:top;padding:.1em .6em}</style>",
        f"<h1>{html.escape(openapi['info']['title'])} {html.escape(str(openapi['info']['version']))}</h1>",
        "<p>The lab's REST endpoints (the WebSocket <code>/ws</code> and the whole protocol: docs/web.md). "
        "Machine-readable: <a href='/openapi.json'>/openapi.json</a>. POST bodies are JSON "
        "(<code>Content-Type: application/json</code>), at most 64 KiB; SI units.</p>",
    ]
    for path, ops in sorted(openapi.get("paths", {}).items()):
        for method, op in ops.items():
            out.append(f"<h2><code>{method.upper()} {html.escape(path)}</code></h2>")
            text = op.get("description") or op.get("summary") or ""
            if text:
                out.append(f"<p>{html.escape(text)}</p>")
            body = op.get("requestBody", {}).get("content", {}).get("application/json", {}).get("schema")
            if body:
                rows = _fields(body, components)
                if rows:
                    out.append("<table>")
                    out.extend(
                        f"<tr><td><code>{html.escape(n)}</code></td><td>{html.escape(d)}</td></tr>"
                        for n, d in rows
                    )
                    out.append("</table>")
    return "\n".join(out) + "\n"
