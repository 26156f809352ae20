"""The RATTLE arithmetic of sweeps (``pl.sweep(..., arithmetic=...)``, docs/sweeps.md "Arithmetic"):
resolved once and recorded (metadata, manifest, chunk files, merged file), the same numbers bit for bit
as ``pl.simulate_ensemble`` with that arithmetic, and honoured on resume — "auto" adopts the recorded
arithmetic even where this CPU's "auto" resolves otherwise (``fused_is_fast`` monkeypatched, as in
test_arithmetic.py), a named one that differs is refused, a file that records none warns; the sweep
file's ``[simulation] arithmetic`` and ``pendulab sweep --arithmetic`` (which overrides it) the same,
bad values refused naming them. Times in seconds, angles in radians, lengths in metres."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest
from sweep_records import GRID, KW, QS, counting, drop_chunk, manifest, same, sweep_file
from test_cli import assert_user_error, invoke

import pendulab as pl
import pendulab.integrators as integrators
from pendulab.sweeps.design import as_design
from pendulab.sweeps.file import SweepFileError, load_sweep_file


def _cpu(monkeypatch: pytest.MonkeyPatch, fma: bool) -> None:
    """This process's "auto" as on a CPU with (True) or without (False) a fast fused multiply-add."""
    monkeypatch.setattr(integrators, "fused_is_fast", lambda: fma)


@pytest.mark.parametrize("arithmetic", ["unfused", "fused"])
def test_a_sweep_is_simulate_ensemble_of_its_arithmetic_bit_for_bit(arithmetic: str) -> None:
    """final_state of a sweep with a named arithmetic (in chunks of 4) equals one simulate_ensemble
    call with that arithmetic over all points, bit for bit, and records it; the two arithmetics give
    other bits (so the keyword does something)."""
    sw = pl.sweep(GRID, QS, arithmetic=arithmetic, chunk_size=4, **KW)
    other = pl.sweep(GRID, QS, arithmetic="fused" if arithmetic == "unfused" else "unfused", **KW)
    th, pd = np.meshgrid(GRID["theta0"], GRID["phi_dot0"], indexing="ij")
    p = pl.Pendulum()
    starts = np.array(
        [p.state_from_angles(a, 0.0, 0.0, b).as_array() for a, b in zip(th.ravel(), pd.ravel(), strict=True)]
    )
    ens = pl.simulate_ensemble(p, starts, 0.2, dt=1e-3, arithmetic=arithmetic, progress=False)
    for k, name in enumerate("xyz"):
        assert np.array_equal(sw[name], ens.final_x[:, k]), name
        assert np.array_equal(sw["v" + name], ens.final_v[:, k]), name
    assert not same(sw, other)
    assert sw.metadata["spec"]["arithmetic"] == arithmetic


@pytest.mark.parametrize("fma", [True, False])
def test_auto_is_resolved_once_and_recorded(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, fma: bool
) -> None:
    """ "auto" is the CPU's arithmetic (fused with FMA): the same numbers as naming it, recorded in the
    metadata, the manifest, every chunk file and the merged .parquet file; exact quantities (nothing
    integrates) record none; a bad name is refused with simulate_ensemble's message."""
    _cpu(monkeypatch, fma)
    want = "fused" if fma else "unfused"
    sw = pl.sweep(GRID, QS, out=tmp_path / "d", chunk_size=4, **KW)
    assert same(sw, pl.sweep(GRID, QS, arithmetic=want, **KW))
    assert sw.metadata["spec"]["arithmetic"] == want
    assert manifest(tmp_path / "d")["spec"]["arithmetic"] == want
    for path in sorted((tmp_path / "d").glob("chunk-*.parquet")):
        info = json.loads(pq.read_schema(path).metadata[b"pendulab_sweep"])
        assert info["spec"]["arithmetic"] == want, path
    assert pl.read_sweep(tmp_path / "d").metadata["spec"]["arithmetic"] == want
    assert f">arithmetic</th><td style='text-align:right'>{want}</td>" in sw._repr_html_()
    merged = pl.sweep(GRID, QS, out=tmp_path / "m.parquet", **KW)
    assert pl.read_sweep(merged.path).metadata["spec"]["arithmetic"] == want  # type: ignore[arg-type]
    exact = pl.sweep({"theta0": [0.5, 1.0], "phi_dot0": [1.0]}, "period", arithmetic="fused", progress=False)
    assert "arithmetic" not in exact.metadata["spec"]
    with pytest.raises(pl.InvalidInputError, match=r"arithmetic.*'fma'.*'unfused', 'fused'"):
        pl.sweep(GRID, QS, arithmetic="fma", **KW)


@pytest.mark.parametrize("fma_first", [True, False])
def test_resume_with_auto_adopts_the_recorded_arithmetic(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, fma_first: bool
) -> None:
    """Written where "auto" is one arithmetic, interrupted, resumed where it is the other: the missing
    chunk is computed with the recorded arithmetic, so the result is the first machine's bit for bit
    (and not the second's); resuming with the recorded arithmetic named works too."""
    out = tmp_path / "sw"
    _cpu(monkeypatch, fma_first)
    pl.sweep(GRID, QS, out=out, chunk_size=4, **KW)
    recorded = "fused" if fma_first else "unfused"
    first = pl.sweep(GRID, QS, arithmetic=recorded, **KW)  # in memory (out's columns are read lazily)
    drop_chunk(out, 2)
    _cpu(monkeypatch, not fma_first)
    calls = counting(monkeypatch)
    again = pl.sweep(GRID, QS, out=out, resume=True, **KW)
    assert calls == [1] and again.stats["computed"] == 1
    assert (
        again.metadata["spec"]["arithmetic"] == recorded and manifest(out)["spec"]["arithmetic"] == recorded
    )
    assert same(first, again) and same(first, pl.read_sweep(out))
    assert not same(first, pl.sweep(GRID, QS, **KW))  # this machine's own "auto" gives other bits
    drop_chunk(out, 0)
    assert same(first, pl.sweep(GRID, QS, out=out, resume=True, arithmetic=recorded, **KW))


def test_resume_refuses_a_conflicting_named_arithmetic(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A named arithmetic other than the recorded one is refused before any work, naming both and what
    to do, for an unfinished directory and a finished .parquet file; another setting that differs as
    well is reported as a different sweep, with the arithmetic among the differences."""
    out = tmp_path / "sw"
    pl.sweep(GRID, QS, out=out, chunk_size=4, arithmetic="fused", **KW)
    drop_chunk(out, 1)
    calls = counting(monkeypatch)
    with pytest.raises(pl.InvalidInputError) as e:
        pl.sweep(GRID, QS, out=out, resume=True, arithmetic="unfused", **KW)
    for needle in ("arithmetic = 'unfused' differs from 'fused'", str(out), "arithmetic='fused'", "'auto'"):
        assert needle in str(e.value), (needle, str(e.value))
    assert calls == [0] and not (out / "chunk-000001.parquet").exists()
    with pytest.raises(
        pl.InvalidInputError, match=r"different sweep: arithmetic \('fused' there, 'unfused' here\), dt"
    ):
        pl.sweep(GRID, QS, out=out, resume=True, arithmetic="unfused", t_end=0.2, dt=2e-3, progress=False)
    pl.sweep(GRID, QS, out=tmp_path / "m.parquet", arithmetic="unfused", **KW)
    with pytest.raises(pl.InvalidInputError, match=r"'fused' differs from 'unfused'.*m\.parquet"):
        pl.sweep(GRID, QS, out=tmp_path / "m.parquet", resume=True, arithmetic="fused", **KW)


def test_a_sweep_that_records_no_arithmetic_resumes_with_a_warning(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A directory written before the arithmetic was recorded (its spec and fingerprint without it, as
    that pendulab wrote them) resumes with this run's arithmetic and a RuntimeWarning saying the file
    does not record its arithmetic; its record stays without one; finished, it resumes silently."""
    out = tmp_path / "old"
    pl.sweep(GRID, QS, out=out, chunk_size=4, **KW)
    first = pl.sweep(GRID, QS, **KW)  # in memory (out's columns are read lazily)
    m = manifest(out)
    del m["spec"]["arithmetic"], m["spec"]["arithmetic_version"]
    text = json.dumps({"design": as_design(GRID).fingerprint(), "spec": m["spec"]}, sort_keys=True)
    m["fingerprint"] = hashlib.sha256(text.encode()).hexdigest()  # the fingerprint of the old format
    (out / "_manifest.json").write_text(json.dumps(m))
    drop_chunk(out, 3)
    calls = counting(monkeypatch)
    with pytest.warns(
        RuntimeWarning, match=r"does not record the arithmetic .* the remaining chunks use"
    ) as w:
        again = pl.sweep(GRID, QS, out=out, resume=True, **KW)
    assert [x.filename for x in w if "does not record" in str(x.message)] == [__file__]  # the caller's line
    assert calls == [1] and same(first, again)  # written and resumed with this machine's "auto"
    assert "arithmetic" not in again.metadata["spec"] and "arithmetic" not in manifest(out)["spec"]
    assert pl.sweep(GRID, QS, out=out, resume=True, **KW).stats["computed"] == 0  # no warning: nothing to do


@pytest.mark.parametrize("fma", [True, False])
def test_sweep_file_key_and_cli_option(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, fma: bool) -> None:
    """``[simulation] arithmetic`` reaches pl.sweep (the same numbers as naming it there, recorded in
    the result and the manifest); without it the file's arithmetic is "auto" (this CPU's);
    ``pendulab sweep --arithmetic`` overrides the file's key, as the other options its [run] table."""
    _cpu(monkeypatch, fma)
    auto = "fused" if fma else "unfused"
    other = "unfused" if fma else "fused"
    named = sweep_file(tmp_path, QS, 1e-3, arithmetic=f'"{other}"')
    assert load_sweep_file(named).sweep_kwargs()["arithmetic"] == other
    assert load_sweep_file(named).sweep_kwargs(arithmetic="auto")["arithmetic"] == "auto"
    assert load_sweep_file(sweep_file(tmp_path, QS, 1e-3)).sweep_kwargs()["arithmetic"] == "auto"
    for toml, option, want in (
        (named, [], other),
        (named, ["--arithmetic", auto], auto),
        (named, ["--arithmetic", "auto"], auto),
        (sweep_file(tmp_path, QS, 1e-3), [], auto),
        (sweep_file(tmp_path, QS, 1e-3, arithmetic='"auto"'), ["--arithmetic", other], other),
    ):
        out = tmp_path / f"out-{len(list(tmp_path.glob('out-*')))}"
        code, stdout, stderr = invoke("sweep", str(toml), "--out", str(out), "--no-progress", *option)
        assert code == 0, stderr
        assert f"; arithmetic {want}\n" in stdout, (option, stdout)
        res = pl.read_sweep(out)
        assert res.metadata["spec"]["arithmetic"] == want and manifest(out)["spec"]["arithmetic"] == want
        assert same(res, pl.sweep(GRID, QS, arithmetic=want, **KW)), (toml.read_text(), option)


@pytest.mark.parametrize("value", ['"fma"', '"FUSED"', "3", "true"])
def test_bad_arithmetic_in_a_sweep_file_or_on_the_command_line(tmp_path: Path, value: str) -> None:
    """A bad ``[simulation] arithmetic`` is refused when the file is read, and a bad ``--arithmetic``
    before it is, by pl.sweep's check: the key or option, the value and the allowed ones; exit code 2."""
    allowed = "one of 'auto', 'unfused', 'fused'"
    shown = value.replace('"', "'") if value.startswith('"') else value.capitalize()  # TOML true: True
    path = sweep_file(tmp_path, QS, 1e-3, arithmetic=value)
    with pytest.raises(SweepFileError) as e:
        load_sweep_file(path)
    assert f"{path}: [simulation] invalid arithmetic = {shown}: {allowed}" in str(e.value), str(e.value)
    code, out, err = invoke("sweep", str(path), "--out", str(tmp_path / "o"), "--no-progress")
    assert_user_error(code, out, err, "[simulation] invalid arithmetic", shown, allowed)
    if value.startswith('"'):
        good = sweep_file(tmp_path, QS, 1e-3)
        code, out, err = invoke("sweep", str(good), "--out", str(tmp_path / "o"), "--arithmetic", value[1:-1])
        assert_user_error(code, out, err, "--arithmetic", f"invalid arithmetic = {shown}", allowed)
    assert not (tmp_path / "o").exists()


def test_cli_resume_refuses_a_conflicting_arithmetic(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``pendulab sweep --resume`` keeps pl.sweep's rule: an arithmetic named by --arithmetic or by the
    file's key that differs from the recorded one is refused before any work (exit code 2, naming
    both); --arithmetic auto (and a file without the key) takes the recorded one and finishes the
    sweep bit for bit as it was begun."""
    _cpu(monkeypatch, False)  # this CPU's "auto" is unfused: resuming with it must not mix in unfused chunks
    out = tmp_path / "sw"
    code, _, stderr = invoke(
        "sweep", str(sweep_file(tmp_path, QS, 1e-3, arithmetic='"fused"')), "--out", str(out), "--no-progress"
    )
    assert code == 0, stderr
    first = pl.sweep(GRID, QS, arithmetic="fused", **KW)
    drop_chunk(out, 2)
    calls = counting(monkeypatch)
    unnamed = sweep_file(tmp_path, QS, 1e-3)
    for toml, option in (
        (unnamed, ["--arithmetic", "unfused"]),
        (sweep_file(tmp_path, QS, 1e-3, arithmetic='"unfused"'), []),
        (sweep_file(tmp_path, QS, 1e-3, arithmetic='"fused"'), ["--arithmetic", "unfused"]),
    ):
        code, stdout, stderr = invoke("sweep", str(toml), "--out", str(out), "--resume", *option)
        assert_user_error(code, stdout, stderr, "arithmetic = 'unfused' differs from 'fused'", str(out))
    assert calls == [0] and not (out / "chunk-000002.parquet").exists()
    for option in (["--arithmetic", "auto"], []):
        code, stdout, stderr = invoke(
            "sweep", str(unnamed), "--out", str(out), "--resume", "--no-progress", *option
        )
        assert code == 0, stderr
        assert "computed 1, skipped 3" in stdout and "; arithmetic fused\n" in stdout, stdout
        assert same(first, pl.read_sweep(out)) and manifest(out)["spec"]["arithmetic"] == "fused"
        drop_chunk(out, 2)
    assert calls == [2]
