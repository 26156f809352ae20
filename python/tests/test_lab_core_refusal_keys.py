"""The core's refusals in a lab session reach the page keyed (docs/web.md, "Languages"): a command the core
refuses for a common reason — a state off the sphere, a model parameter out of its range — is an ``error``
notice with ``key`` and ``values`` (``pendulab/server/messages.json``), which the page words in English,
German and French (``web/src/i18n/*/refusals.ts``), not the core's English words alone. And a run that
blows up says it diverged (time, method, dt, what to do), never that a speed it computed "is not allowed"
as if the user had given it. SI units: m, m/s, s, m/s²."""

from __future__ import annotations

from typing import Any

import pytest
from conftest import page_words as _page_words
from ws_session import LabClient, until

import pendulab as pl
from pendulab.server.app import create_app
from pendulab.server.notices import message
from pendulab.server.protocol import CommandError, parse_command
from pendulab.server.scenarios import resolve_scenario
from pendulab.server.session import Session

OFF_SPHERE = '{"type": "set_state", "x": [0.5, 0, -0.5], "v": [0, 0, 0], "project": false}'
DAMPING = '{"type": "set_model", "model": "damped", "params": {"damping": -1}}'


def _error(text: str) -> dict[str, Any]:
    """The error notice a lab (over its WebSocket) answers ``text`` with."""
    with LabClient(create_app("rosette")).websocket_connect("/ws") as ws:
        ws.send_text(text)
        notice: dict[str, Any] = until(ws, lambda k, v: k == "json" and v["type"] == "error")
    return notice


@pytest.mark.parametrize(
    ("text", "command", "key", "values"),
    [
        (
            OFF_SPHERE,
            "set_state",
            "off_sphere",
            {"what": "(|x| - l)/l", "value": "-0.2928932188134524", "tolerance": "1e-9"},
        ),
        (DAMPING, "set_model", "invalid_parameter", {"name": "damping", "value": "-1"}),
    ],
)
def test_a_command_the_core_refuses_reaches_the_page_keyed(
    text: str, command: str, key: str, values: dict[str, str]
) -> None:
    n = _error(text)
    assert (n["command"], n.get("key")) == (command, key), n
    assert values.items() <= n["values"].items(), n["values"]
    assert "{" not in message(key, **n["values"])  # every placeholder of the English words filled
    assert n["message"] != message(key, **n["values"])  # the core's own English words stay beside the key


def test_the_page_words_a_state_off_the_sphere_in_english_german_and_french() -> None:
    n = _error(OFF_SPHERE)
    words = {lang: _page_words(lang, n["key"], n["values"]) for lang in ("en", "de", "fr")}
    r = "(|x| - l)/l = -0.2928932188134524"  # as the English words of the core write it
    assert words == {
        "en": f"the start is not on the sphere: {r} exceeds the tolerance 1e-9",
        "de": f"der Start liegt nicht auf der Kugel: {r} überschreitet die Toleranz 1e-9",
        "fr": f"le départ n’est pas sur la sphère : {r} dépasse la tolérance 1e-9",
    }
    assert r in n["message"]


def test_the_page_words_a_parameter_out_of_range_in_english_german_and_french() -> None:
    n = _error(DAMPING)
    words = {lang: _page_words(lang, n["key"], n["values"]) for lang in ("en", "de", "fr")}
    assert words["en"].startswith("damping = -1 is not allowed: ")
    assert words["de"].startswith("damping = -1 ist nicht erlaubt: ")  # the page names it "Dämpfung"
    assert words["fr"].startswith("damping = -1 n’est pas permis : ")


def test_a_refusal_of_the_core_in_session_apply_is_keyed() -> None:
    s = Session(resolve_scenario("rosette"))
    with pytest.raises(CommandError) as e:
        s.apply(parse_command(OFF_SPHERE))
    assert (e.value.command, e.value.key) == ("set_state", "off_sphere")
    assert e.value.values["value"] == "-0.2928932188134524"  # as the English words write it
    with pytest.raises(CommandError) as e:
        s.apply(parse_command('{"type": "load_scenario", "name": "nowhere"}'))
    assert e.value.key is None  # not a refusal of the core: its English words alone


def test_a_lab_run_that_blows_up_says_it_diverged_with_method_dt_and_what_to_do() -> None:
    # rk4_angles at g = 1000 m/s², dt = 0.05 s: stopped with "speed = 49745656823029380 is not allowed" before
    s = Session(resolve_scenario("rosette"))
    set_up = [
        '{"type": "set_params", "g": 1000}',
        '{"type": "set_method", "method": "rk4_angles", "dt": 0.05}',
    ]
    out, _, _ = s.tick([parse_command(t) for t in set_up], 0.0)
    assert not [m for m in out if isinstance(m, dict) and m["type"] == "error"], out
    errors: list[dict[str, Any]] = []
    for _ in range(20):
        out, _, _ = s.tick([], 0.1)
        errors += [m for m in out if isinstance(m, dict) and m["type"] == "error"]
        if errors:
            break
    [n] = errors
    assert (n["key"], n["values"]["why"], n["values"]["method"], n["values"]["dt"]) == (
        "integration_stopped",
        "diverged",
        "rk4_angles",
        "0.05",
    ), n
    assert "the integration diverged after t = " in n["message"] and "speed" not in n["message"], n["message"]
    assert s.status()["paused"] is True
    why = {k: v for k, v in n["values"].items() if k not in ("detail", "why")}
    assert _page_words("en", "diverged", why).endswith(
        "(dt = 0.05 s): reduce dt, or choose an adaptive (dop853) or structure-preserving (rattle) method"
    )
    assert _page_words("de", "diverged", why).startswith("die Integration ist nach t = ")
    assert "avec la méthode rk4_angles (dt = 0.05 s)" in _page_words("fr", "diverged", why)


def test_simulate_of_the_same_run_says_it_diverged() -> None:
    p = pl.Pendulum(g=1000.0)
    with pytest.raises(
        pl.IntegrationError, match=r"^the integration diverged after t = [\d.]+ s with method 'rk4_angles'"
    ):
        pl.simulate(p, p.state_from_angles(0.5, 0, 0, 2.0), t_end=5.0, dt=0.05, method="rk4_angles")
