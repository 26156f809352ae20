"""A lab run that stops, and the lab's rarer refusals, reach the page keyed and worded once (docs/web.md,
"Languages"): a stopped run is one statement naming one time — the integrator's words and the last state
computed, where the session pauses — keyed ``integration_stopped`` with its cause's key (the advice for the
method that diverged: ``diverged``, ``diverged_rattle``, …); ``Session.advance()`` and
``take_pending_steps()`` called from Python raise that keyed error and leave nothing of the stop behind;
an unknown model, parameter or method, a model that runs only offline, too many waiting steps, a method the
model does not run and a crane command outside the crane mode are keyed in English, German and French; a
key's time is the English words' time (12 significant digits), its dt the English words' dt. SI units: m,
m/s, s, m/s²."""

from __future__ import annotations

import re
from typing import Any

import pytest
from conftest import page_words as _page_words
from ws_session import LabClient, until

from pendulab.server.app import create_app
from pendulab.server.notices import message
from pendulab.server.protocol import CommandError, parse_command
from pendulab.server.scenarios import resolve_scenario
from pendulab.server.session import Session

OFF_SPHERE = '{"type": "set_state", "x": [0.5, 0, -0.5], "v": [0, 0, 0], "project": false}'
BLOW_UP = ['{"type": "set_params", "g": 1000}', '{"type": "set_method", "method": "rk4_angles", "dt": 0.05}']


def _blowing_up() -> Session:
    s = Session(resolve_scenario("rosette"))
    for text in BLOW_UP:
        s.apply(parse_command(text))
    return s


def _errors(out: list[Any]) -> list[dict[str, Any]]:
    return [m for m in out if isinstance(m, dict) and m["type"] == "error"]


def test_a_stopped_run_names_one_time_where_it_pauses() -> None:
    # rk4_angles at g = 1000 m/s², dt = 0.05 s: "integration stopped at t = 0.05 s: the integration diverged
    # at t = 0.1 s …" named the last state and the step's end (0.15000000000000002 s, at other starts)
    s = _blowing_up()
    errors: list[dict[str, Any]] = []
    for _ in range(20):
        out, _, _ = s.tick([], 0.1)
        errors += _errors(out)
        if errors:
            break
    [n] = errors
    assert (n["key"], n["values"]["why"], n["values"]["dt"]) == ("integration_stopped", "diverged", "0.05")
    assert s.paused
    times = re.findall(r"\bt = ([^ ]+) s", n["message"])
    assert times == [n["values"]["t"]], n["message"]  # one time, the state the session pauses at
    assert float(times[0]) == pytest.approx(s.t, abs=1e-12) and round(s.t / 0.05) == pytest.approx(s.t / 0.05)
    assert n["message"].startswith("the integration diverged after t = ")
    assert n["message"].endswith("; paused")
    assert n["values"]["detail"] + "; paused" == n["message"]


def test_session_advance_raises_the_keyed_stop_and_leaves_nothing_behind() -> None:
    s = _blowing_up()
    with pytest.raises(CommandError) as e:  # it was an unkeyed "integration stopped at t = …"
        for _ in range(40):
            s.advance(0.1)
    assert (e.value.key, e.value.command, e.value.values["why"]) == ("integration_stopped", None, "diverged")
    assert e.value.values["method"] == "rk4_angles" and str(e.value).endswith("; paused")
    assert s.paused
    # a later refusal of a command is keyed by its own kind, not as the stop left in the core
    out, _, _ = s.tick([parse_command(OFF_SPHERE)], 0.0)
    assert [(n["command"], n["key"]) for n in _errors(out)] == [("set_state", "off_sphere")]


def test_take_pending_steps_raises_the_keyed_stop_and_leaves_nothing_behind() -> None:
    s = _blowing_up()
    s.apply(parse_command('{"type": "step", "n": 100}'))
    with pytest.raises(CommandError) as e:
        s.take_pending_steps()
    assert (e.value.key, e.value.command) == ("integration_stopped", "step")
    assert e.value.values["why"] == "diverged"
    assert (s.paused, s.pending_steps) == (True, 0)
    out, _, _ = s.tick([parse_command(OFF_SPHERE)], 0.0)
    assert [(n["command"], n["key"]) for n in _errors(out)] == [("set_state", "off_sphere")]


@pytest.mark.parametrize(
    ("method", "key", "advice"),
    [
        ("rk4_angles", "diverged", {"de": "adaptives (dop853)", "fr": "adaptative (dop853)"}),
        ("rattle", "diverged_rattle", {"de": "schnellste Bewegung", "fr": "le plus rapide"}),
    ],
)
def test_each_language_gives_the_advice_for_the_method_that_diverged(
    method: str, key: str, advice: dict[str, str]
) -> None:
    values = {"t": "1", "method": method, "dt": "0.1"}
    for lang in ("de", "fr"):
        words = _page_words(lang, key, values)
        assert advice[lang] in words, words
        if method.startswith("rattle"):  # a diverged rattle is not told to use rattle
            assert "(rattle)" not in words and "rattle wählen" not in words, words


# (commands sent in order, key, values it carries at least, the German words' start, the French words' start
# or None: only every placeholder filled)
REFUSALS = [
    (
        ['{"type": "set_model", "model": "sprung"}'],
        "unknown_model",
        {"model": "sprung"},
        "unbekanntes Modell sprung; verfügbar: ",
        None,
    ),
    (
        ['{"type": "set_model", "model": "sampled_pivot"}'],
        "not_lab_model",
        {"model": "sampled_pivot"},
        "das Modell sampled_pivot läuft nicht im Labor (pendulab run verwenden)",
        None,
    ),
    (
        ['{"type": "set_model", "model": "damped", "params": {"lattitude": 1}}'],
        "unknown_parameter",
        {"model": "damped", "name": "lattitude"},
        "das Modell damped hat keinen Parameter lattitude; seine Parameter: ",
        None,
    ),
    (
        ['{"type": "set_params", "params": {"dampling": 0.1}}'],
        "no_parameters",
        {"model": "ideal", "name": "dampling"},
        "das Modell ideal hat keinen Parameter dampling; es hat keine außer Länge, Masse, g",
        None,
    ),
    # another model's parameter: named with the models that have it, as pl.Pendulum words it (was the two
    # above: "the 'damped' model has no parameter 'latitude'", no word of the rotating frame)
    (
        ['{"type": "set_model", "model": "damped", "params": {"latitude": 1}}'],
        "parameter_of_other_model",
        {"model": "damped", "name": "latitude", "owner": "rotating"},
        "latitude ist ein Parameter des Modells rotating, nicht von damped; seine Parameter: length, ",
        "latitude est un paramètre du modèle rotating, pas de damped ; ses paramètres : length, ",
    ),
    (
        ['{"type": "set_params", "params": {"damping": 0.1}}'],
        "parameter_of_other_models",
        {"model": "ideal", "name": "damping", "owner": "damped", "available": "length, mass, g"},
        "damping ist ein Parameter des Modells damped (und rotating, ",
        "damping est un paramètre du modèle damped (et rotating, ",
    ),
    # an unknown method, with the nearest name when there is one: Python's words alone before (the in-page
    # engine keys it alike: crates/pendulab-wasm/tests/engine.rs)
    (
        ['{"type": "set_method", "method": "RATTLE"}'],
        "unknown_method_hint",
        {"method": "RATTLE", "nearest": "rattle"},
        "unbekanntes Verfahren RATTLE (vielleicht rattle?); verfügbar: rattle, rattle4, ",
        "méthode inconnue RATTLE (rattle peut-être ?) ; disponibles : rattle, rattle4, ",
    ),
    (
        ['{"type": "set_method", "method": "euler"}'],
        "unknown_method",
        {"method": "euler"},
        "unbekanntes Verfahren euler; verfügbar: rattle, ",
        "méthode inconnue euler ; disponibles : rattle, ",
    ),
    # a method the model does not run and a crane command outside the crane mode: both were the core's
    # English words alone (Error::Refused), left in English on a German or French page; the page shows the
    # model by its name in the page's language (serverWords), filled raw here
    (
        ['{"type": "set_model", "model": "spring"}', '{"type": "set_method", "method": "dop853"}'],
        "method_not_for_spring",
        {"method": "dop853", "model": "spring", "available": "rattle, rattle4"},
        "das Verfahren dop853 kann das Modell spring nicht rechnen (es verlässt die Kugel: ",
        "la méthode dop853 ne peut pas calculer le modèle spring (il quitte la sphère : ",
    ),
    (
        ['{"type": "set_model", "model": "string"}', '{"type": "set_method", "method": "rk4"}'],
        "method_not_for_string",
        {"method": "rk4", "model": "string"},
        "das Verfahren rk4 kann das Modell ",
        "la méthode rk4 ne peut pas calculer le modèle ",
    ),
    (
        ['{"type": "crane", "move": [1, 0]}'],
        "not_crane",
        {"model": "ideal"},
        "nicht im Kranmodus (das Labor rechnet das Modell ",
        "pas en mode grue (le labo calcule le modèle ",
    ),
]


@pytest.mark.parametrize(("texts", "key", "values", "de", "fr"), REFUSALS, ids=[r[1] for r in REFUSALS])
def test_the_rarer_refusals_reach_the_page_keyed(
    texts: list[str], key: str, values: dict[str, str], de: str, fr: str | None
) -> None:
    with LabClient(create_app("rosette")).websocket_connect("/ws") as ws:
        for text in texts:
            ws.send_text(text)
        n: dict[str, Any] = until(ws, lambda k, v: k == "json" and v["type"] == "error")
    assert n.get("key") == key, n
    assert values.items() <= n["values"].items(), n["values"]
    assert "{" not in message(key, **n["values"])  # every placeholder of the English words filled
    assert _page_words("de", key, n["values"]).startswith(de)
    french = _page_words("fr", key, n["values"])
    assert "{" not in french and french.startswith(fr or ""), french


def test_too_many_waiting_steps_are_keyed() -> None:
    s = Session(resolve_scenario("rosette"))
    step = parse_command('{"type": "step", "n": 100000}')
    for _ in range(10):
        s.apply(step)
    with pytest.raises(CommandError) as e:
        s.apply(step)
    assert (e.value.key, e.value.values) == ("still_stepping", {"waiting": "1000000", "most": "1000000"})
    assert str(e.value).startswith("still stepping: 1000000 steps are waiting")
    assert _page_words("fr", "still_stepping", e.value.values).startswith("calcul en cours : 1000000 pas")


def test_the_time_and_step_of_a_stop_are_the_same_in_every_language() -> None:
    # a time off a round grid and dt = 0.0123457 s: the key's t was rounded to 4 decimals (0.0617 s where
    # the English words said 0.0617285 s) and its dt to 4 significant digits (0.01235 s for 0.0123457 s),
    # so a German or French page named another time and step than the English one
    s = Session(resolve_scenario("rosette"))
    s.apply(parse_command('{"type": "set_params", "g": 1000}'))
    s.apply(parse_command('{"type": "set_method", "method": "rk4_angles", "dt": 0.0123457}'))
    with pytest.raises(CommandError) as e:
        for _ in range(40):
            s.advance(0.1)
    t = e.value.values["t"]
    assert (e.value.key, e.value.values["why"]) == ("integration_stopped", "diverged")
    assert f"after t = {t} s " in str(e.value) and float(t) == pytest.approx(s.t, rel=1e-11)
    assert len(t.split(".")[1]) > 4, t  # more digits than 4 decimals hold
    assert e.value.values["dt"] == "0.0123457" and "(dt = 0.0123457 s)" in str(e.value)
    for lang in ("en", "de", "fr"):
        words = _page_words(lang, "diverged", e.value.values)
        assert f"t = {t} s" in words and "(dt = 0.0123457 s)" in words, (lang, words)
