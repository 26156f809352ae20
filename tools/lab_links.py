"""The documentation site's "open in the lab" links (issue 26 item 4): every example scenario, gallery
figure and tour notebook opens the site's one-file lab (``site/lab/index.html``) in its own set-up,
by the lab's share-link query (``web/src/url.ts``: ``s`` an example scenario, ``model``, ``mp`` the
model's parameters as name:value, ``l`` [m], ``m`` [kg], ``g`` [m/s²], ``method``, ``dt`` [s], ``x``,
``v`` the start [m, m/s], ``plot`` the plot's x,y variables, ``twin`` the second pendulum, …).

Where each link is written:

- an example scenario: ``s=NAME`` (the table of ``docs/lab.md``, from the scenarios the lab serves);
- a gallery script ``docs/gallery/NN_name.py``: a line ``Lab: QUERY`` at the end of its docstring
  (``docs_site.py`` shows it as the link instead of the text);
- a tour notebook: its metadata ``{"pendulab": {"lab": "QUERY"}}``.

``python/tests/test_lab_links.py`` reads every link through :func:`all_links` and checks that it
parses into a valid lab state (known keys, the lab's commands accepted by the server's session, the
session's status what the link asked for); the e2e suite opens a sample in the one-file lab. This
module needs only the standard library (mkdocs is not installed when the tests run).
"""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GALLERY_DIR = ROOT / "docs" / "gallery"
TOUR_DIR = ROOT / "docs" / "tour"
SCENARIO_DIR = ROOT / "examples" / "scenarios"

LAB_LINE = re.compile(r"^Lab:\s*(\S+)\s*$", re.M)
"""The docstring line of a gallery script that gives its lab link's query."""


def lab_scenarios() -> list[Path]:
    """The example scenario files the lab runs: all of them (a crane file, ``[crane]``, opens the lab's
    crane mode with its crane, docs/cranes.md "The lab's crane mode")."""
    return sorted(SCENARIO_DIR.glob("*.toml"))


def scenario_query(name: str) -> str:
    """The lab link's query of an example scenario."""
    return f"s={name}"


def gallery_query(script: Path) -> str | None:
    """The query of a gallery script's ``Lab:`` docstring line (None if it has none)."""
    doc = ast.get_docstring(ast.parse(script.read_text(encoding="utf-8"))) or ""
    m = LAB_LINE.search(doc)
    return m.group(1) if m else None


def without_lab_line(text: str) -> str:
    """A docstring's text less its ``Lab:`` line (the site shows the link instead)."""
    return LAB_LINE.sub("", text).strip()


def tour_query(notebook: Path) -> str | None:
    """The query in a tour notebook's metadata (``pendulab.lab``; None if it has none)."""
    meta = json.loads(notebook.read_text(encoding="utf-8")).get("metadata", {})
    value = meta.get("pendulab", {}).get("lab")
    return value if isinstance(value, str) else None


def all_links() -> list[tuple[str, str | None]]:
    """Every (where, query) of the site: the example scenarios, the gallery scripts, the notebooks."""
    out: list[tuple[str, str | None]] = [
        (f"examples/scenarios/{p.name}", scenario_query(p.stem)) for p in lab_scenarios()
    ]
    out += [(f"docs/gallery/{p.name}", gallery_query(p)) for p in sorted(GALLERY_DIR.glob("[0-9]*.py"))]
    out += [(f"docs/tour/{p.name}", tour_query(p)) for p in sorted(TOUR_DIR.glob("*.ipynb"))]
    return out


def link_html(query: str, prefix: str, text: str = "Open in the lab") -> str:
    """The link (``prefix`` is the way from the page to the site's root, e.g. ``../``)."""
    from html import escape

    href = f"{prefix}lab/index.html?{query}"
    return f'<a class="pendulab-lab-link" href="{escape(href)}">{escape(text)}</a>'


if __name__ == "__main__":  # the links as JSON, for the e2e suite (web/tests/e2e/doclinks.mjs)
    print(json.dumps([{"where": where, "query": query} for where, query in all_links()]))
