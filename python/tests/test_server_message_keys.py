"""The lab server's keyed error notices (``pendulab/server/messages.json``; docs/web.md, "Languages"): a
notice a page translates carries ``key`` and ``values`` beside its English ``message``; every key's words
fill from the values the server sends, and the page's tables translate every key (checked here against
the TypeScript tables' text, and in web/tests/unit/messages.test.ts against their placeholders)."""

from __future__ import annotations

import re

import pytest
from conftest import I18N, REPO, page_template

from pendulab.server.protocol import (
    MESSAGES,
    CommandError,
    error_notice_of,
    keyed_notice,
    message,
    parse_command,
)


def _refusal(text: str) -> CommandError:
    with pytest.raises(CommandError) as e:
        parse_command(text)
    return e.value


@pytest.mark.parametrize(
    ("command", "key", "values"),
    [
        (
            '{"type": "set_params", "length": -1}',
            "too_small",
            {"name": "length", "value": "-1", "limit": "0.001"},
        ),
        (
            '{"type": "set_params", "g": 1e9}',
            "too_large",
            {"name": "g", "value": "1e9", "limit": "1000"},
        ),
        ('{"type": "set_params", "colour": 3}', "unknown_key", {"name": "colour"}),
    ],
)
def test_a_refused_value_is_keyed_with_its_name_value_and_limit(command: str, key: str, values: dict) -> None:
    e = _refusal(command)
    assert (e.key, e.values) == (key, values)
    notice = error_notice_of(e)
    assert notice["key"] == key and notice["values"] == values and notice["command"] == "set_params"
    assert notice["message"] == str(e)  # the English message is unchanged
    assert message(key, **values)  # every placeholder filled


@pytest.mark.parametrize(
    ("command", "words"),
    [
        ('{"type": "set_method", "dt": 0}', "dt = 0: input should be greater than or equal to 1e-6"),
        ('{"type": "set_time_scale", "time_scale": 1e-9}', "time_scale = 1e-9: input should be greater"),
        ('{"type": "set_params", "g": -2e3}', "g = -2000: input should be greater than or equal to -1000"),
    ],
)
def test_refused_numbers_are_written_as_a_user_writes_them(command: str, words: str) -> None:
    # not pydantic's 0.000001 nor Python's 1e-09, -2000.0 (pendulab._numbers.shown)
    e = _refusal(command)
    assert str(e) == words or str(e).startswith(words), str(e)
    assert not re.search(r"e[-+]0\d|\.0\b|0\.00000", str(e) + str(e.values)), (str(e), e.values)


def test_two_problems_are_not_keyed() -> None:
    e = _refusal('{"type": "set_params", "length": -1, "mass": -1}')
    assert e.key is None and "key" not in error_notice_of(e)


def test_keyed_notices_fill_every_placeholder() -> None:
    n = keyed_notice("nonfinite_motion", t="1.5", fields="energy, tension")
    assert n["message"] == message("nonfinite_motion", t="1.5", fields="energy, tension")
    assert "energy, tension not finite" in n["message"] and "{" not in n["message"]
    with pytest.raises(KeyError):
        keyed_notice("throttled", lost=3)  # per_second missing: never a half-filled message


@pytest.mark.parametrize("lang", ["en", "de", "fr"])
def test_every_key_is_in_every_page_table(lang: str) -> None:
    table = (I18N / lang / "refusals.ts").read_text(encoding="utf-8")  # the table's server.<key> topic
    missing = [k for k in MESSAGES if f"'server.{k}'" not in table]
    assert not missing, f"{lang}/refusals.ts lacks server.{missing}"
    for k, words in MESSAGES.items():
        placeholders = set(re.findall(r"\{(\w+)\}", page_template(lang, k)))
        assert placeholders == set(re.findall(r"\{(\w+)\}", words)), (lang, k)


def test_a_fit_past_the_servers_time_limit_is_a_keyed_503() -> None:
    """The time-limit and busy answers of the REST API carry ``key`` and ``values`` (``work_timeout``,
    ``busy``), so that the page words them in its language (web/src/i18n/index.ts ``httpProblem``)."""
    import json

    from ws_session import LabClient

    from pendulab.server import create_app
    from pendulab.server.notices import keyed_body

    filmed = REPO / "examples" / "data" / "filmed_swing.csv"
    # a limit far below any fit's time (0.5 of the pool's 0.02 s): the worker is stopped
    client = LabClient(create_app("rosette", fit_seconds=0.02))
    body = json.dumps({"csv": filmed.read_text(), "name": "filmed_swing.csv"})
    r = client.post("/api/fit", content=body, headers={"content-type": "application/json"})
    answer = r.json()
    assert r.status_code == 503 and answer["key"] == "work_timeout", answer
    assert answer["detail"] == message("work_timeout", **answer["values"])
    assert keyed_body("busy", waiting=8) == {
        "detail": message("busy", waiting=8),
        "key": "busy",
        "values": {"waiting": 8},
    }


def test_every_key_the_data_readers_and_the_fit_raise_is_worded() -> None:
    """Every key a ``KeyedInputError`` of pendulab/fitting and the fit endpoint raises is a key of
    messages.json (so that the page's tables word it), found in the sources."""
    root = REPO / "python" / "pendulab"
    sources = [*(root / "fitting").glob("*.py"), root / "server" / "fit.py"]
    used = set()
    for path in sources:  # the keys are the only quoted strings of this form there
        used |= set(re.findall(r"\"((?:data|fit)_[a-z_]+)\"", path.read_text(encoding="utf-8")))
    assert len(used) >= 30, used
    assert used <= set(MESSAGES), used - set(MESSAGES)


@pytest.mark.parametrize("lang", ["de", "fr"])
def test_every_model_parameter_has_words_in_every_page_table(lang: str) -> None:
    """A parameter the lab's schema offers (``GET /api/schema``) is named and explained in the page's
    table of that language (``DE_PARAMS``, ``FR_PARAMS``), not left with the registry's English label."""
    from pendulab.server.schema import schema

    names: set[str] = set()

    def walk(o: object) -> None:
        if isinstance(o, dict):
            if isinstance(o.get("params"), list):
                names.update(p["name"] for p in o["params"] if isinstance(p, dict) and "name" in p)
            for v in o.values():
                walk(v)
        elif isinstance(o, list):
            for v in o:
                walk(v)

    walk(schema())
    text = (I18N / lang / "models.ts").read_text(encoding="utf-8")
    table = text[text.index(f"export const {lang.upper()}_PARAMS") :]
    table = table[: table.index("};")]
    assert len(names) > 20
    assert not [n for n in sorted(names) if not re.search(rf"^\s+{n}: \[", table, re.M)]
