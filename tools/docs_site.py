"""MkDocs build hooks of the documentation site (mkdocs.yml ``hooks:``; run by ``make docs``).

- **CLI reference.** The marker ``<!-- cli-reference -->`` in ``docs/reference/cli.md`` is replaced by
  every command of the typer app of :mod:`pendulab.cli` with its help text, usage line and the help
  record (names, metavar, help, default) of each argument and option — what ``--help`` prints, taken
  from the command definitions themselves. (mkdocs-click cannot read typer ≥ 0.20 commands, whose
  parameters are typer's own click classes.)
- **Gallery.** Every ``docs/gallery/NN_name.py`` is run at build time in a fresh temporary directory
  (matplotlib's Agg backend, at most ``GALLERY_TIMEOUT`` seconds each); the pictures and movies it
  writes there become ``gallery/index.md``: the script's docstring, its output, its code (less the
  docstring, shown above it). A failing
  script, or one that writes nothing to show, fails the build. Results are cached by the script's
  content and the installed pendulab version in ``target/docs-gallery/`` (``make docs-serve``
  rebuilds quickly); ``make docs`` clears the cache, so CI always runs every script.
- **Guided tour.** ``docs/tour/index.md`` and the notebooks ``docs/tour/*.ipynb`` (rendered, and run,
  by mkdocs-jupyter) are added to the navigation in name order, each titled by its first heading; the
  files that running them writes into ``docs/tour/`` (movies) are removed after the build. MathJax is
  copied into the site from the ``jupyter-server-mathjax`` package, so that formulas render offline
  (with its STIX-Web fonts: ``config/pendulab.js``); each tour page links to its notebook's download
  and opens the lab in the notebook's set-up.
- **The lab.** The marker ``<!-- lab-scenarios -->`` in ``docs/lab.md`` becomes a table of the example
  scenarios, each with its "open in the lab" link (``lab/index.html?s=NAME``, the lab's share-link
  form); every gallery figure and tour notebook has one too (``tools/lab_links.py`` says where each
  is written; a script or notebook without one fails the build). ``dist/pendulab-lab.html``
  (``make lab-html``, which ``make docs`` runs first) is copied to ``site/lab/index.html``: the
  whole lab in the site, its physics in the page (docs/lab.md).
- **Checks after the build** (each failure fails the build): the API page has an anchor for every
  name of ``pendulab.__all__``, and no page loads a script, stylesheet or font from the network (the
  site must be readable offline from ``site/index.html``).
"""

from __future__ import annotations

import hashlib
import html
import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from inspect import cleandoc as inspect_cleandoc
from pathlib import Path
from typing import Any

import pendulab
import typer.main
from mkdocs.exceptions import PluginError
from mkdocs.structure.files import File, Files
from pendulab.cli import app

ROOT = Path(__file__).resolve().parents[1]
GALLERY_DIR = ROOT / "docs" / "gallery"
CACHE_DIR = ROOT / "target" / "docs-gallery"
GALLERY_TIMEOUT = 120.0  # s per script
MEDIA = {".png": "image", ".svg": "image", ".gif": "image", ".mp4": "video", ".webm": "video"}
TOUR_GLOB = "tour/*.ipynb"
CLI_MARKER = "<!-- cli-reference -->"
LAB_HTML = ROOT / "dist" / "pendulab-lab.html"
LAB_MARKER = "<!-- lab-scenarios -->"


def _load_lab_links() -> Any:
    """tools/lab_links.py (the site's "open in the lab" links; the tests read it too)."""
    spec = importlib.util.spec_from_file_location("lab_links", Path(__file__).with_name("lab_links.py"))
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


lab_links = _load_lab_links()

# Sphinx roles in docstrings (``:class:`pendulab.X```), which Markdown renders as ``:class:<code>…``.
_ROLE = re.compile(r":(?:class|func|meth|mod|attr|data|exc|obj|ref):(<code>)~?")
# A resource loaded from the network: <script src=http…>, <link rel=stylesheet|icon|preload|… href=http…>
# (not rel=canonical, which `mkdocs serve` sets and which loads nothing), @import and url(http…).
_REMOTE = re.compile(
    r"""<script\b[^>]*\bsrc=["']?(?:https?:)?//"""
    r"""|<link\b(?=[^>]*\brel=["']?(?:stylesheet|preload|modulepreload|icon|shortcut|preconnect|manifest"""
    r"""|dns-prefetch))[^>]*\bhref=["']?(?:https?:)?//"""
    r"""|@import\s+(?:url\()?["']?(?:https?:)?//|url\(["']?(?:https?:)?//""",
    re.IGNORECASE,
)


def on_config(config: Any) -> Any:
    """Adds the guided tour (its ``index.md`` first, then the notebooks) to the navigation."""
    docs = Path(config["docs_dir"])
    notebooks = sorted(docs.glob(TOUR_GLOB))
    if notebooks and config["nav"] is not None:
        tour = [{_title_of_notebook(nb): nb.relative_to(docs).as_posix()} for nb in notebooks]
        if (docs / "tour" / "index.md").is_file():
            tour.insert(0, {"Overview": "tour/index.md"})
        position = next((i for i, item in enumerate(config["nav"]) if "Gallery" in item), 2)
        config["nav"].insert(position, {"Guided tour": tour})
    return config


def _title_of_notebook(path: Path) -> str:
    """The first Markdown heading of the notebook, else its file name."""
    try:
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    except (OSError, ValueError, KeyError) as e:
        raise PluginError(f"{path.name} is not a readable notebook: {e}") from e
    for cell in cells:
        if cell.get("cell_type") == "markdown":
            for line in "".join(cell.get("source", "")).splitlines():
                if line.startswith("#"):
                    return line.lstrip("#").strip()
    return re.sub(r"^\d+[_-]", "", path.stem).replace("_", " ").capitalize()


_tour_files_before: set[Path] = set()


def on_pre_build(config: Any) -> None:
    """Notes the tour folder's files: running the notebooks writes movies next to them (the kernel's
    working directory is the notebook's folder), which on_post_build removes again."""
    _tour_files_before.clear()
    _tour_files_before.update(_tour_files(Path(config["docs_dir"])))


def _tour_files(docs: Path) -> set[Path]:
    tour = docs / "tour"
    return {p for p in tour.iterdir() if p.is_file()} if tour.is_dir() else set()


def on_files(files: Files, config: Any) -> Files:
    """Runs the gallery scripts and adds their page and media to the site."""
    scripts = sorted(GALLERY_DIR.glob("[0-9]*.py"))
    sections = [
        "# Gallery",
        "",
        "Every figure here is made while the site is built, by the script shown under it; each script "
        "runs as it is (`python docs/gallery/NAME.py`) and writes its pictures into the current "
        "directory. Equation numbers refer to the [theory](../theory.md).",
        "",
    ]
    for script in scripts:
        outputs = _run_gallery_script(script)
        title, body = _docstring_parts(script)
        query = lab_links.gallery_query(script)
        if query is None:
            raise PluginError(
                f"gallery script {script.name} has no 'Lab: QUERY' line in its docstring (its "
                "'open in the lab' link: tools/lab_links.py)"
            )
        body = lab_links.without_lab_line(body)
        sections += [f"## {title}", "", body, "", lab_links.link_html(query, "../"), ""]
        for out in outputs:
            uri = f"gallery/{script.stem}/{out.name}"
            files.append(File.generated(config, uri, abs_src_path=str(out)))
            if MEDIA[out.suffix] == "video":
                sections += [f'<video controls loop muted src="{script.stem}/{out.name}"></video>', ""]
            else:
                sections += [f"![{html.escape(title)}]({script.stem}/{out.name})", ""]
        code = re.sub(r'^\s*""".*?"""\s*', "", script.read_text(encoding="utf-8"), count=1, flags=re.DOTALL)
        sections += [f'```python title="{script.name}"', code.rstrip(), "```", ""]
    files.append(File.generated(config, "gallery/index.md", content="\n".join(sections)))
    return files


def _docstring_parts(script: Path) -> tuple[str, str]:
    match = re.match(r'\s*"""(.*?)"""', script.read_text(encoding="utf-8"), flags=re.DOTALL)
    if not match:
        raise PluginError(f"gallery script {script.name} has no module docstring (its title and text)")
    lines = match.group(1).strip().splitlines()
    return lines[0].rstrip("."), "\n".join(lines[1:]).strip()


def _run_gallery_script(script: Path) -> list[Path]:
    key = hashlib.sha256(script.read_bytes() + pendulab.__version__.encode()).hexdigest()[:16]
    cached = CACHE_DIR / f"{script.stem}-{key}"
    if not cached.is_dir():
        with tempfile.TemporaryDirectory(prefix="pendulab-gallery-") as tmp:
            env = {**os.environ, "MPLBACKEND": "Agg", "PYTHONHASHSEED": "0"}
            try:
                run = subprocess.run(
                    [sys.executable, str(script)],
                    cwd=tmp,
                    env=env,
                    capture_output=True,
                    text=True,
                    timeout=GALLERY_TIMEOUT,
                    check=False,
                )
            except subprocess.TimeoutExpired as e:
                raise PluginError(
                    f"gallery script {script.name} ran longer than {GALLERY_TIMEOUT:g} s"
                ) from e
            if run.returncode != 0:
                raise PluginError(f"gallery script {script.name} failed:\n{run.stderr[-3000:]}")
            made = sorted(p for p in Path(tmp).iterdir() if p.suffix.lower() in MEDIA)
            if not made:
                raise PluginError(
                    f"gallery script {script.name} wrote no picture or movie ({', '.join(MEDIA)})"
                )
            partial = cached.with_name(cached.name + ".partial")
            shutil.rmtree(partial, ignore_errors=True)
            partial.mkdir(parents=True)
            for p in made:
                shutil.copy2(p, partial / p.name.lower())
            try:
                partial.rename(cached)
            except OSError:
                if not cached.is_dir():
                    raise
                # another docs build filled the cache meanwhile (the same script and version): keep it
                shutil.rmtree(partial, ignore_errors=True)
    return sorted(cached.iterdir())


def on_page_markdown(markdown: str, page: Any, **kwargs: Any) -> str:
    """Fills in the CLI reference and the lab's scenario links."""
    if LAB_MARKER in markdown:
        markdown = markdown.replace(LAB_MARKER, lab_scenarios_markdown())
    if CLI_MARKER not in markdown:
        return markdown
    return markdown.replace(CLI_MARKER, cli_reference_markdown())


def lab_scenarios_markdown() -> str:
    """A table of the example scenarios the lab runs, each opened in the site's lab by its share link."""
    from pendulab.server.app import scenarios

    rows = ["| scenario | what | |", "|---|---|---|"]
    for s in scenarios():
        if "error" in s:
            continue
        title = _escape(str(s.get("title") or ""))
        link = lab_links.link_html(lab_links.scenario_query(s["name"]), "", "open in the lab")
        rows.append(f"| `{s['name']}` | {title} | {link} |")
    return "\n".join(rows)


def cli_reference_markdown() -> str:
    """Markdown for every ``pendulab`` command, from the command definitions (typer → click)."""
    root = typer.main.get_command(app)
    root_ctx = root.context_class(root, info_name="pendulab")
    out = [_command_markdown(root, root_ctx, "pendulab", level=2)]
    commands = getattr(root, "commands", {})
    for name in sorted(commands):
        command = commands[name]
        if not command.hidden:
            ctx = command.context_class(command, info_name=name, parent=root_ctx)
            out.append(_command_markdown(command, ctx, f"pendulab {name}", level=2))
            # a command group (``pendulab crane …``): its subcommands below it
            for sub_name in sorted(getattr(command, "commands", {})):
                sub = command.commands[sub_name]
                if not sub.hidden:
                    sub_ctx = sub.context_class(sub, info_name=sub_name, parent=ctx)
                    out.append(_command_markdown(sub, sub_ctx, f"pendulab {name} {sub_name}", level=3))
    return "\n".join(out)


def _command_markdown(command: Any, ctx: Any, path: str, level: int) -> str:
    usage = command.get_usage(ctx).removeprefix("Usage:").strip()
    lines = [f"{'#' * level} `{path}`", "", _escape(inspect_cleandoc(command.help or "")), ""]
    lines += ["```text", usage, "```", ""]
    rows = []
    for param in command.get_params(ctx):
        record = param.get_help_record(ctx)
        if record is None or param.name == "help":
            continue
        names, text = record
        rows.append(f"| `{names}` | {_escape(' '.join(text.split()))} |")
    if rows:
        lines += ["| argument / option | meaning |", "|---|---|", *rows, ""]
    return "\n".join(lines)


def _escape(text: str) -> str:
    """Markdown-safe text (no raw HTML, emphasis or table cells from help strings); `code` is kept."""
    parts = text.split("`")
    for i in range(0, len(parts), 2):
        parts[i] = html.escape(parts[i], quote=False).replace("*", "\\*")
    return "`".join(parts).replace("|", "\\|")


def on_page_content(content: str, **kwargs: Any) -> str:
    """Drops the Sphinx role prefixes of docstrings (``:class:`X``` shows as code X)."""
    return _ROLE.sub(r"\1", content)


def on_post_page(output: str, page: Any, **kwargs: Any) -> str:
    """A tour page gets, under its title, a link that downloads its notebook (the .ipynb that
    mkdocs-jupyter copies beside the page) and one that opens the lab in the notebook's set-up (the
    share-link query of its metadata ``pendulab.lab``: tools/lab_links.py)."""
    source = getattr(page.file, "src_uri", "")
    if not (source.startswith("tour/") and source.endswith(".ipynb")):
        return output
    name = html.escape(Path(source).name)
    query = lab_links.tour_query(Path(page.file.abs_src_path))
    if query is None:
        raise PluginError(f'{source} has no lab link: add {{"pendulab": {{"lab": "QUERY"}}}} to its metadata')
    links = (
        f'<p class="pendulab-tour-links"><a href="{name}" download>Download this notebook</a> '
        "(it runs with the <code>tour</code> extra: README, <em>Install</em>) · "
        f"{lab_links.link_html(query, '../')}</p>"
    )
    return re.sub(r"(<h1\b[^>]*>.*?</h1>)", lambda m: m.group(1) + links, output, count=1, flags=re.DOTALL)


def on_post_build(config: Any) -> None:
    site = Path(config["site_dir"])
    docs = Path(config["docs_dir"])
    for made in sorted(_tour_files(docs) - _tour_files_before):
        made.unlink()
    if any(docs.glob(TOUR_GLOB)):
        _copy_mathjax(site / "assets" / "mathjax")
    _copy_lab(site / "lab")
    _check_api_coverage(site / "reference" / "api.html")
    _check_offline(site)


def _copy_lab(target: Path) -> None:
    """The one-file lab at ``site/lab/index.html`` (``make lab-html`` builds it)."""
    if not LAB_HTML.is_file():
        raise PluginError(f"{LAB_HTML.relative_to(ROOT)} is missing: run 'make lab-html' (make docs does)")
    target.mkdir(parents=True, exist_ok=True)
    shutil.copy2(LAB_HTML, target / "index.html")


MATHJAX_CONFIG = """MathJax.Hub.Config({
  "HTML-CSS": {availableFonts: [], preferredFont: null, webFont: "STIX-Web", imageFont: null}
});
MathJax.Ajax.loadComplete("[MathJax]/config/pendulab.js");
"""


def _copy_mathjax(target: Path) -> None:
    try:
        import jupyter_server_mathjax
    except ImportError as e:
        raise PluginError("the guided tour needs MathJax: pip install jupyter-server-mathjax") from e
    source = Path(jupyter_server_mathjax.__file__).parent / "static"
    shutil.copytree(source, target, dirs_exist_ok=True)
    # jupyter-server-mathjax ships the STIX-Web fonts only: without this configuration (named in
    # mkdocs.yml's custom_mathjax_url) MathJax asks for its TeX fonts first and every tour page logs a
    # 404 for jax/output/HTML-CSS/fonts/TeX/fontdata.js.
    (target / "config" / "pendulab.js").write_text(MATHJAX_CONFIG, encoding="utf-8")


def _check_api_coverage(api_page: Path) -> None:
    text = api_page.read_text(encoding="utf-8")
    missing = [name for name in pendulab.__all__ if f'id="pendulab.{name}"' not in text]
    if missing:
        raise PluginError(
            f"{api_page.name} documents no anchor for these names of pendulab.__all__: {', '.join(missing)} "
            "(add `::: pendulab.NAME` to docs/reference/api.md)"
        )


def _check_offline(site: Path) -> None:
    remote = []
    for page in sorted(site.rglob("*.html")):
        for match in _REMOTE.finditer(page.read_text(encoding="utf-8")):
            remote.append(f"{page.relative_to(site)}: {match.group(0)[:80]}")
    if remote:
        raise PluginError(
            "the site must be readable offline, but these pages load from the network:\n" + "\n".join(remote)
        )
