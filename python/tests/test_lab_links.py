"""Every "open in the lab" link of the documentation site (issue 26 item 4: each example scenario,
gallery figure and tour notebook; ``tools/lab_links.py`` says where each is written) parses into a
valid lab state.

A link's query is read as the lab reads it (``web/src/url.ts``: its keys from the page's own list,
numbers finite, the plot's variables from ``web/src/variables.ts``, view options from the scene's
defaults, the second pendulum's forms), turned into the commands the page sends for it (``commandsFor``:
load_scenario, set_model, set_params, set_method, set_time_scale, set_state, reset, pause), and those
are parsed by the lab protocol and applied to a fresh session — the server's, whose checks the
WebAssembly engine shares (crates/pendulab-wasm). The session must accept every command and its status
must then be what the link asked for (scenario, model and its parameters, l, m, g, method, dt, start).
The e2e suite opens a sample of these links in the one-file lab (web/tests/e2e/lab_file.mjs).
"""

from __future__ import annotations

import json
import math
import re
from urllib.parse import parse_qsl

import pytest
from conftest import REPO, load_tool

from pendulab.server import Session, resolve_scenario
from pendulab.server.app import scenarios
from pendulab.server.protocol import parse_command

WEB = REPO / "web" / "src"


lab_links = load_tool("lab_links")
LINKS = lab_links.all_links()


def _url_keys() -> set[str]:
    """The keys the page's URL parser knows (``known`` in web/src/url.ts)."""
    m = re.search(r"const known = new Set\(\[([^\]]*)\]\)", (WEB / "url.ts").read_text(encoding="utf-8"))
    assert m, "web/src/url.ts: the list of known URL keys moved; update this test"
    return set(re.findall(r"'(\w+)'", m.group(1)))


def _plot_variables() -> set[str]:
    return set(re.findall(r"\{ name: '(\w+)'", (WEB / "variables.ts").read_text(encoding="utf-8")))


def _view_options() -> set[str]:
    text = (WEB / "scene" / "scene.ts").read_text(encoding="utf-8")
    m = re.search(r"export const DEFAULT_VIEW: ViewOptions = \{(.*?)\n\};", text, re.S)
    assert m, "web/src/scene/scene.ts: DEFAULT_VIEW moved; update this test"
    return set(re.findall(r"^\s+(\w+):", m.group(1), re.M))


NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def _number(key: str, text: str) -> float:
    assert NUMBER.match(text) and math.isfinite(float(text)), f"{key} = {text!r} is not a finite number"
    return float(text)


def _vec(key: str, text: str) -> list[float]:
    parts = text.split(",")
    assert len(parts) == 3, f"{key} = {text!r} is not three numbers"
    return [_number(key, p) for p in parts]


def _commands(query: str) -> tuple[list[dict], dict[str, str]]:
    """The page's commands for a link (url.ts decodeUrl + commandsFor), checking what they do not carry."""
    q = dict(parse_qsl(query, keep_blank_values=True, strict_parsing=True))
    assert len(q) == len(parse_qsl(query)), f"a key given twice in {query!r}"
    unknown = set(q) - _url_keys()
    assert not unknown, f"unknown URL keys {sorted(unknown)} (the lab knows {sorted(_url_keys())})"
    out: list[dict] = []
    if "s" in q:
        out.append({"type": "load_scenario", "name": q["s"]})
    if "model" in q:
        params = {}
        for pair in filter(None, q.get("mp", "").split(",")):
            k, _, v = pair.partition(":")
            params[k] = _number(f"mp {k}", v)
        out.append({"type": "set_model", "model": q["model"], "params": params})
    else:
        assert "mp" not in q, "mp (the model's parameters) goes with model"
    params = {
        name: _number(key, q[key]) for key, name in (("l", "length"), ("m", "mass"), ("g", "g")) if key in q
    }
    if params:
        out.append({"type": "set_params", **params})
    method = {k: (q[k] if k == "method" else _number(k, q[k])) for k in ("method", "dt") if k in q}
    if method:
        out.append({"type": "set_method", **method})
    if "ts" in q:
        out.append({"type": "set_time_scale", "time_scale": _number("ts", q["ts"])})
    assert ("x" in q) == ("v" in q), "the start needs both x and v"
    if "x" in q:
        out.append({"type": "set_state", "x": _vec("x", q["x"]), "v": _vec("v", q["v"])})
    if out:
        out.append({"type": "reset"})
    if q.get("paused") in ("1", "true"):
        out.append({"type": "pause"})
    if "plot" in q:
        pair = q["plot"].split(",")
        assert len(pair) == 2 and set(pair) <= _plot_variables(), (
            f"plot = {q['plot']!r}: two of {_plot_variables()}"
        )
    if "view" in q:
        for item in filter(None, q["view"].split(",")):
            key = re.match(r"^-?([A-Za-z]+)", item)
            assert key and key.group(1) in _view_options(), f"view option {item!r} (known: {_view_options()})"
    if "twin" in q:
        assert re.fullmatch(
            r"own:[\d.eE+-]+:[\d.eE+-]+:[\d.eE+-]+|eps:[\d.eE+-]+|method:[\w.-]+|damped:[\d.eE+-]+", q["twin"]
        ), f"twin = {q['twin']!r} is not own:l:m:θ₀, eps:ε, method:name or damped:c"
    if "lang" in q:
        assert re.fullmatch(r"[a-z]{2}", q["lang"]) and (WEB / "i18n" / q["lang"] / "index.ts").is_file()
    return out, q


def test_every_scenario_gallery_figure_and_notebook_has_a_link():
    where = {w for w, _ in LINKS}
    lab_files = lab_links.lab_scenarios()  # every example, the crane files too (the crane mode)
    every = {p.name for p in (REPO / "examples" / "scenarios").glob("*.toml")}
    assert every == {p.name for p in lab_files}
    assert {f"examples/scenarios/{p.name}" for p in lab_files} <= where
    assert {f"docs/gallery/{p.name}" for p in (REPO / "docs" / "gallery").glob("[0-9]*.py")} <= where
    assert {f"docs/tour/{p.name}" for p in (REPO / "docs" / "tour").glob("*.ipynb")} <= where
    missing = [w for w, q in LINKS if not q]
    assert not missing, f"no 'open in the lab' link: {missing} (tools/lab_links.py says where to write it)"
    # the lab's own list of scenarios (docs/lab.md's table) is the shipped examples
    served = {s["name"] for s in scenarios() if "error" not in s}
    assert {p.stem for p in lab_files} <= served


@pytest.mark.parametrize(("where", "query"), LINKS, ids=[w.split("/")[-1] for w, _ in LINKS])
def test_link_parses_into_a_valid_lab_state(where: str, query: str | None):
    assert query, where
    commands, q = _commands(query)
    session = Session(resolve_scenario("rosette"))
    for cmd in commands:
        session.apply(parse_command(json.dumps(cmd)))  # raises CommandError, naming the value, if refused
    status = session.status()
    if "s" in q:
        assert status["scenario"] == q["s"]
    if "model" in q:
        assert status["model"] == q["model"]
    for key, name in (("l", "length"), ("m", "mass"), ("g", "g")):
        if key in q:
            assert status["params"][name] == float(q[key])
    if "method" in q:
        assert status["method"] == q["method"]
    if "dt" in q:
        assert status["dt"] == float(q["dt"])
    if "x" in q:
        for key in ("x", "v"):
            want = _vec(key, q[key])
            assert max(abs(a - b) for a, b in zip(status["start"][key], want, strict=True)) < 1e-12, (
                key,
                status,
            )
    assert status["paused"] == (q.get("paused") in ("1", "true"))


def test_a_bad_link_is_caught():
    """The checks above can fail: an unknown key, a state off the sphere, an unknown plot variable."""
    with pytest.raises(AssertionError, match="unknown URL keys"):
        _commands("s=rosette&lenght=2")
    with pytest.raises(AssertionError, match="plot"):
        _commands("s=rosette&plot=t,nonsense")
    commands, _ = _commands("model=ideal&x=1,0,0&v=0,0,1&l=2")  # |x| = 1 m on a 2 m rod
    session = Session(resolve_scenario("rosette"))
    from pendulab.server.protocol import CommandError

    with pytest.raises(CommandError, match="x"):
        for cmd in commands:
            session.apply(parse_command(json.dumps(cmd)))
