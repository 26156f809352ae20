"""The golden states as JSON: each case and quantity as a float64 and as a 30-digit string, the
document (``testdata/golden_states.json``, its schema in testdata/README.md), its compact indented
text, the atomic write, and the comparison of a recomputed document with the committed one
(``--check``: strings to 1e-28 relative, floors to 5 %). Units SI, as listed in ``UNITS``.
"""

from __future__ import annotations

import json
import math
import os
import re
import tempfile
from pathlib import Path
from typing import Any

import mpmath
from golden_base import DPS, GENERATOR, STR_DIGITS, TIMES, UNITS, GoldenError, norm, sub
from golden_case import CaseResult
from golden_special import MirroredSolution
from mpmath import mpf

# --------------------------------------------------------------------------------------
# JSON


def sci(x: Any, digits: int = STR_DIGITS) -> str:
    """x to `digits` significant digits in exponent notation."""
    if x == 0:
        return "0.0"
    return mpmath.nstr(x, digits, strip_zeros=False, min_fixed=0, max_fixed=0)


def opt_float(x: Any) -> float | None:
    return None if x is None else float(x)


def opt_sci(x: Any) -> str | None:
    return None if x is None else sci(x)


def quantity_fields(quantities: dict[str, Any]) -> dict[str, Any]:
    """Each quantity as a float (nearest float64) and as a 30-digit string, key + "_str"."""
    out: dict[str, Any] = {}
    for key, val in quantities.items():
        out[key] = opt_float(val)
        out[key + "_str"] = opt_sci(val)
    return out


def case_json(r: CaseResult) -> dict[str, Any]:
    sc, sol = r.scenario, r.solution
    out: dict[str, Any] = {
        "name": sc.name,
        "scenario": sc.path,
        "length": sc.length,
        "mass": sc.mass,
        "g": sc.g,
        "x0": list(sc.x0),
        "v0": list(sc.v0),
        "kind": sol.kind,
        "mirrored": isinstance(sol, MirroredSolution),
        "energy": sci(r.energy),
        "j3": sci(r.j3),
    }
    out.update(quantity_fields(r.derived))
    out["samples"] = [
        {
            "t": t,
            "x": [float(c) for c in x],
            "v": [float(c) for c in v],
            "x_str": [sci(c) for c in x],
            "v_str": [sci(c) for c in v],
            "floor": f,
            "floor_normwise": fn,
        }
        for t, (x, v), f, fn in zip(TIMES, r.samples, r.floors, r.floors_normwise, strict=True)
    ]
    return out


def document(results: list[CaseResult], example: dict[str, Any]) -> dict[str, Any]:
    return {
        "generator": GENERATOR,
        "mp_dps": DPS,
        "string_digits": STR_DIGITS,
        "units": UNITS,
        "times": list(TIMES),
        "floor_method": (
            "floor: x0, v0 perturbed componentwise by relative 2^-53 (all 64 sign "
            "patterns), "
            "projected onto TS^2, solved exactly; max over the patterns of "
            "max(|dx|/l, |dv|/max(|v|, l w0)). floor_normwise: the same with absolute "
            "perturbations 2^-53 l (x) and 2^-53 max(|v0|, l w0) (v)"
        ),
        "cases": [case_json(r) for r in results],
        "phase_example": example,
    }


def to_json(doc: dict[str, Any]) -> str:
    """Indented JSON with every list of numbers or strings on one line."""
    text = json.dumps(doc, indent=1)
    text = re.sub(
        r"\[\s*([^\[\]{}\n]*(?:\n[^\[\]{}\n]*)*?)\s*\]",
        lambda mo: "[" + " ".join(mo.group(1).split()) + "]",
        text,
    )
    if json.loads(text) != doc:  # pragma: no cover - guards the regex
        raise GoldenError("internal error: compacted JSON does not round-trip")
    return text + "\n"


def write_atomic(path: Path, text: str) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.name + ".", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes it 0600
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def compare(new: dict[str, Any], old: dict[str, Any]) -> list[str]:
    """Differences that matter between a recomputed and a committed document."""
    problems: list[str] = []
    for key in ("generator", "mp_dps", "times"):
        if new[key] != old.get(key):
            problems.append(f"{key}: {old.get(key)!r} != {new[key]!r}")
    new_cases = {c["name"]: c for c in new["cases"]}
    old_cases = {c["name"]: c for c in old.get("cases", [])}
    if set(new_cases) != set(old_cases):
        problems.append(f"case names differ: {sorted(old_cases)} vs {sorted(new_cases)}")
    for name in sorted(set(new_cases) & set(old_cases)):
        a, b = new_cases[name], old_cases[name]
        for key in ("scenario", "length", "mass", "g", "x0", "v0", "kind", "mirrored"):
            if a[key] != b.get(key):
                problems.append(f"{name}.{key}: committed {b.get(key)!r}, now {a[key]!r}")
        problems += compare_quantities(name, a, b)
        for sa, sb in zip(a["samples"], b.get("samples", []), strict=False):
            for key in ("x_str", "v_str"):
                va = [mpf(s) for s in sa[key]]
                vb = [mpf(s) for s in sb[key]]
                sc = max(norm(va), mpf(1e-300))
                if norm(sub(va, vb)) / sc > mpf("1e-28"):
                    problems.append(f"{name} t={sa['t']} {key}: committed {sb[key]}, now {sa[key]}")
            for key in ("floor", "floor_normwise"):
                if not math.isclose(sa[key], sb.get(key, math.nan), rel_tol=0.05):
                    problems.append(f"{name} t={sa['t']} {key}: committed {sb.get(key)}, now {sa[key]}")
        if len(a["samples"]) != len(b.get("samples", [])):
            problems.append(f"{name}: number of samples differs")
    problems += compare_quantities("phase_example", new["phase_example"], old.get("phase_example", {}))
    return problems


def compare_quantities(name: str, a: dict[str, Any], b: dict[str, Any]) -> list[str]:
    """Same keys (except samples) and every scalar *_str (energy, j3 too) to 1e-28 relative."""
    problems: list[str] = []
    if set(a) != set(b):
        problems.append(f"{name}: keys differ: {sorted(set(a) ^ set(b))}")
    for key in sorted(set(a) & set(b)):
        va, vb = a[key], b[key]
        if not (key.endswith("_str") or key in ("energy", "j3")) or not isinstance(va, str):
            continue
        if not isinstance(vb, str):
            problems.append(f"{name}.{key}: committed {vb!r}, now {va!r}")
            continue
        ma, mb = mpf(va), mpf(vb)
        if abs(ma - mb) > mpf("1e-28") * max(abs(ma), mpf(1e-300)):
            problems.append(f"{name}.{key}: committed {vb}, now {va}")
    return problems
