"""The dicts the compiled core returns against the TypedDicts of the hand-written stub
python/pendulab/_core.pyi: the same keys and values of the declared types. mypy (``make lint``) checks
the package against the stub and stubtest (``make lint-stubs``) the stub's signatures against the core,
but neither looks inside a returned dict; this test does, for every TypedDict of the stub.
"""

from __future__ import annotations

import ast
from pathlib import Path
from typing import Any

import pytest

from pendulab import _core

STUB = Path(_core.__file__).with_name("_core.pyi")

# the Python type of each annotation the stub's TypedDicts use
_TYPES = {"str": str, "int": int, "bool": bool, "float": float}


def _typed_dicts() -> dict[str, dict[str, str]]:
    """Each TypedDict of the stub: field name -> its annotation as written."""
    out = {}
    for node in ast.parse(STUB.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.ClassDef) and any(
            isinstance(b, ast.Name) and b.id == "TypedDict" for b in node.bases
        ):
            out[node.name] = {
                f.target.id: ast.unparse(f.annotation)
                for f in node.body
                if isinstance(f, ast.AnnAssign) and isinstance(f.target, ast.Name)
            }
    return out


def _samples() -> dict[str, list[dict[str, Any]]]:
    """Every dict of each kind the core hands out."""
    models = _core.models()
    return {
        "MethodInfo": list(_core.methods()),
        "ModelInfo": list(models),
        "ParamSpec": [*_core.limits(), *(p for m in models for p in m["params"])],
        "LiveLimit": list(_core.LiveSession.limits().values()),
    }


def _conforms(value: Any, annotation: str) -> bool:
    if annotation.startswith("list["):
        return isinstance(value, list)
    kind = _TYPES[annotation]
    if kind is int:
        return isinstance(value, int) and not isinstance(value, bool)
    return isinstance(value, kind)


def test_every_typed_dict_is_checked():
    assert set(_typed_dicts()) == set(_samples())


@pytest.mark.parametrize("name", sorted(_samples()))
def test_core_dicts_match_the_stub(name):
    fields = _typed_dicts()[name]
    samples = _samples()[name]
    assert samples, f"the core returned no {name} to check"
    for d in samples:
        assert set(d) == set(fields), f"{name}: core keys {sorted(d)} != stub keys {sorted(fields)}"
        bad = {k: type(d[k]).__name__ for k, a in fields.items() if not _conforms(d[k], a)}
        assert not bad, f"{name} {d.get('name', '')}: values not of the stub's types: {bad} ({fields})"
