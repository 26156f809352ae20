"""The version of a sweep's arithmetic (docs/sweeps.md "Arithmetic"; ``sweeps/resume.py``): recorded
with the arithmetic (``_core.arithmetic_version``, the core's ``Arithmetic::version``), checked on
resume — a sweep recorded with another version, or with none while this pendulab's version of its
arithmetic is no longer 1, is refused before any work, naming both versions and a new out; a sweep
recorded without a version whose arithmetic is still at version 1 (unfused; fused too, its bits not
having changed) resumes bit for bit and keeps its record. Versions other than this build's are made
by rewriting a manifest as another build would have written it, or by patching the version this
build reports (as after a change to the fused arithmetic's bits). The refusals name their fix as
``pl.sweep``'s keywords there and as ``pendulab sweep``'s options on the command line. Times in
seconds, angles in radians."""

from __future__ import annotations

import hashlib
import json
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow.parquet as pq
import pytest
from sweep_records import GRID, KW, QS, counting, drop_chunk, manifest, same, sweep_file
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab import _core
from pendulab.sweeps import compute as sweep_compute
from pendulab.sweeps import resume as sweep_resume
from pendulab.sweeps.design import as_design
from pendulab.sweeps.resume import ResumeConflict


def _rewrite(out: Path, **spec: Any) -> None:
    """The manifest in ``out`` as a build that records ``spec``'s keys so would have written it (a value
    None: the key left out, as before it was recorded), with that build's fingerprint."""
    m = manifest(out)
    for key, value in spec.items():
        if value is None:
            m["spec"].pop(key, None)
        else:
            m["spec"][key] = value
    text = json.dumps({"design": as_design(GRID).fingerprint(), "spec": m["spec"]}, sort_keys=True)
    m["fingerprint"] = hashlib.sha256(text.encode()).hexdigest()
    (out / "_manifest.json").write_text(json.dumps(m))


def _versions(monkeypatch: pytest.MonkeyPatch, fused: int) -> None:
    """This build's versions as if the fused arithmetic's bits had changed to version ``fused``."""
    real = _core.arithmetic_version

    def patched(name: str) -> int:
        return fused if name == "fused" else real(name)

    monkeypatch.setattr(sweep_resume, "arithmetic_version", patched)
    monkeypatch.setattr(sweep_compute, "arithmetic_version", patched)


def _interrupted(tmp_path: Path, computed_with: str, **spec: Any) -> Path:
    """A sweep computed with arithmetic ``computed_with`` in chunks of 4, its record rewritten with
    ``spec``, chunk 1 missing."""
    out = tmp_path / f"sw-{computed_with}"
    pl.sweep(GRID, QS, out=out, chunk_size=4, arithmetic=computed_with, **KW)
    _rewrite(out, **spec)
    drop_chunk(out, 1)
    return out


def test_the_version_of_the_arithmetic_is_recorded(tmp_path: Path) -> None:
    """Simulated quantities record the version of their arithmetic's bits beside it (this build's:
    unfused 1, fused 1) in the metadata, the manifest and every chunk file; exact ones none."""
    assert (_core.arithmetic_version("unfused"), _core.arithmetic_version("fused")) == (1, 1)
    with pytest.raises(pl.InvalidInputError, match="fma"):
        _core.arithmetic_version("fma")
    for arithmetic in ("unfused", "fused"):
        out = tmp_path / arithmetic
        sw = pl.sweep(GRID, QS, out=out, chunk_size=4, arithmetic=arithmetic, **KW)
        want = _core.arithmetic_version(arithmetic)
        assert sw.metadata["spec"]["arithmetic_version"] == want
        assert manifest(out)["spec"]["arithmetic_version"] == want
        for path in sorted(out.glob("chunk-*.parquet")):
            info = json.loads(pq.read_schema(path).metadata[b"pendulab_sweep"])
            assert info["spec"]["arithmetic_version"] == want, path
        assert f">arithmetic version</th><td style='text-align:right'>{want}</td>" in sw._repr_html_()
    exact = pl.sweep({"theta0": [0.5, 1.0], "phi_dot0": [1.0]}, "period", progress=False)
    assert "arithmetic_version" not in exact.metadata["spec"]


@pytest.mark.parametrize("asked", ["auto", "fused"])
def test_resume_refuses_another_version(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, asked: str) -> None:
    """A sweep recorded with version 2 of the fused arithmetic (by a later build), resumed here (1):
    refused before any work, naming both versions and a new out, with "auto" and with "fused"."""
    out = _interrupted(tmp_path, "fused", arithmetic_version=2)
    calls = counting(monkeypatch)
    with pytest.raises(ResumeConflict) as e:
        pl.sweep(GRID, QS, out=out, resume=True, arithmetic=asked, **KW)
    text = str(e.value)
    for needle in (str(out), "fused arithmetic of version 2", "of version 1", "new out"):
        assert needle in text, (needle, text)
    assert calls == [0] and not (out / "chunk-000001.parquet").exists()
    assert manifest(out)["spec"]["arithmetic_version"] == 2


def test_a_fused_sweep_without_a_version_is_refused_once_the_version_changed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Recorded with "fused" and no version (written before versions were recorded: version 1) and
    resumed by a build whose fused arithmetic is of version 2: refused before any work, saying it
    records none, naming versions 1 and 2; an unfused one of the same age resumes there."""
    out = _interrupted(tmp_path, "fused", arithmetic_version=None)
    _versions(monkeypatch, fused=2)
    calls = counting(monkeypatch)
    with pytest.raises(ResumeConflict) as e:
        pl.sweep(GRID, QS, out=out, resume=True, **KW)
    text = str(e.value)
    for needle in ("fused arithmetic of version 1 (it records none", "is of version 2", "new out"):
        assert needle in text, (needle, text)
    assert calls == [0] and not (out / "chunk-000001.parquet").exists()
    unfused = _interrupted(tmp_path, "unfused", arithmetic_version=None)
    assert pl.sweep(GRID, QS, out=unfused, resume=True, **KW).stats["computed"] == 1


@pytest.mark.parametrize("arithmetic", ["unfused", "fused"])
def test_a_sweep_without_a_version_at_version_1_resumes_bit_for_bit(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, arithmetic: str
) -> None:
    """Recorded without a version, its arithmetic still of version 1 here (unfused; fused, whose bits
    have not changed): the missing chunk is computed, the result is the uninterrupted sweep's bit for
    bit, and the record (and fingerprint) stays as it was, so a second resume finds it whole."""
    out = _interrupted(tmp_path, arithmetic, arithmetic_version=None)
    before = manifest(out)
    whole = pl.sweep(GRID, QS, arithmetic=arithmetic, **KW)
    calls = counting(monkeypatch)
    again = pl.sweep(GRID, QS, out=out, resume=True, **KW)
    assert calls == [1] and same(whole, again) and same(whole, pl.read_sweep(out))
    after = manifest(out)
    assert "arithmetic_version" not in after["spec"] and after["fingerprint"] == before["fingerprint"]
    assert pl.sweep(GRID, QS, out=out, resume=True, **KW).stats["computed"] == 0


def test_a_sweep_without_an_arithmetic_is_refused_where_fused_changed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Written before the arithmetic was recorded ("auto": fused or unfused, both of version 1), resumed
    with fused of version 2: refused (no chunk there can be of it), suggesting unfused or a new out."""
    out = _interrupted(tmp_path, "fused", arithmetic=None, arithmetic_version=None)
    _versions(monkeypatch, fused=2)
    calls = counting(monkeypatch)
    with pytest.raises(
        ResumeConflict, match=r"'fused', whose bits are of version 2 now.*arithmetic='unfused'"
    ):
        pl.sweep(GRID, QS, out=out, resume=True, arithmetic="fused", **KW)
    assert calls == [0]
    with pytest.warns(RuntimeWarning, match="does not record the arithmetic"):
        pl.sweep(GRID, QS, out=out, resume=True, arithmetic="unfused", **KW)
    assert calls == [1]


def test_a_worker_of_another_version_refuses_its_chunk() -> None:
    """A chunk whose spec records another version than this build's (a Dask worker with another
    pendulab) is refused, not computed with other bits."""
    d = as_design(GRID)
    spec = sweep_compute.make_spec(d, QS, t_end=0.2, dt=1e-3, arithmetic="fused")
    other = replace(spec, arithmetic_version=7)
    with pytest.raises(
        pl.InvalidInputError, match=r"fused arithmetic is of version 1, the sweep's of version 7"
    ):
        sweep_compute.compute_chunk(sweep_compute.ChunkTask(0, 0, 2, d.columns(0, 2), other))
    done = sweep_compute.compute_chunk(sweep_compute.ChunkTask(0, 0, 2, d.columns(0, 2), spec))
    assert np.isfinite(done["x"]).all()


def test_the_fix_is_spelled_as_keywords_in_python_and_as_options_on_the_command_line(
    tmp_path: Path,
) -> None:
    """One message, two spellings: pl.sweep's refusal of a conflicting arithmetic says
    ``arithmetic='fused'``, ``'auto'`` and ``out``; pendulab sweep's says ``--arithmetic fused``,
    ``--arithmetic auto`` and ``--out``, and no Python keyword; the same for another version."""
    out = tmp_path / "sw"
    code, _, stderr = invoke(
        "sweep", str(sweep_file(tmp_path, QS, 1e-3, arithmetic='"fused"')), "--out", str(out), "--no-progress"
    )
    assert code == 0, stderr
    drop_chunk(out, 2)
    with pytest.raises(ResumeConflict) as e:
        pl.sweep(GRID, QS, out=out, resume=True, arithmetic="unfused", **KW)
    api = str(e.value)
    assert "resume with arithmetic='fused' (or arithmetic='auto'," in api and "give another out" in api, api
    assert "--" not in api, api
    code, stdout, stderr = invoke(
        "sweep",
        str(sweep_file(tmp_path, QS, 1e-3)),
        "--out",
        str(out),
        "--resume",
        "--arithmetic",
        "unfused",
    )
    assert_user_error(
        code, stdout, stderr, "resume with --arithmetic fused (or --arithmetic auto,", "give another --out"
    )
    assert "arithmetic='" not in stderr and " out" not in stderr.replace("--out", ""), stderr
    _rewrite(out, arithmetic_version=2)
    code, stdout, stderr = invoke("sweep", str(sweep_file(tmp_path, QS, 1e-3)), "--out", str(out), "--resume")
    assert_user_error(code, stdout, stderr, "of version 2", "of version 1", "into a new --out")
