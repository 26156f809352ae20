"""The integrator of sweeps (``pl.sweep(..., method=...)``, docs/sweeps.md): RATTLE (the default) or its
symmetric compositions "rattle4", "rattle6", "rattle8", carried to the ensemble kernel (each point the
numbers of ``pl.simulate_ensemble`` with that method, bit for bit), recorded (metadata, manifest), its
sub-steps counted by the work bound, honoured on resume (another method refused, before any work; a
record without a method ran RATTLE), and the same from a sweep file's ``[simulation] method`` and
``pendulab sweep --method``; anything else refused naming the value and the allowed ones. Times in
seconds, angles in radians, lengths in metres."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from sweep_records import counting, drop_chunk, manifest, same, sweep_file
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.integrators import unknown_method
from pendulab.sweeps.design import as_design
from pendulab.sweeps.file import SweepFileError, load_sweep_file
from pendulab.sweeps.resume import ResumeConflict
from pendulab.validate.table import MAX_STEPS

GRID = {"theta0": np.linspace(0.3, 2.5, 5), "phi_dot0": np.array([0.0, 1.5, -2.0])}
QS = ["final_state", "max_sway", "energy_drift"]
KW: dict[str, Any] = {"t_end": 0.2, "dt": 1e-2, "progress": False}
ALLOWED = "'rattle', 'rattle4', 'rattle6', 'rattle8'"


@pytest.mark.parametrize("method", ["rattle6", "rattle"])
def test_a_sweep_is_simulate_ensemble_of_its_method_bit_for_bit(method: str) -> None:
    """Every column of a sweep with a method (in chunks of 4) equals one simulate_ensemble call with
    that method and the sweep's arithmetic over all points, bit for bit; the method is recorded; the
    methods give other numbers (so the keyword reaches the kernel)."""
    sw = pl.sweep(GRID, QS, method=method, chunk_size=4, **KW)
    assert sw.metadata["spec"]["method"] == method
    th, pd = np.meshgrid(GRID["theta0"], GRID["phi_dot0"], indexing="ij")
    p = pl.Pendulum()
    starts = np.array(
        [p.state_from_angles(a, 0.0, 0.0, b).as_array() for a, b in zip(th.ravel(), pd.ravel(), strict=True)]
    )
    arithmetic = sw.metadata["spec"]["arithmetic"]
    ens = pl.simulate_ensemble(p, starts, 0.2, dt=1e-2, method=method, arithmetic=arithmetic, progress=False)
    assert ens.summary is not None
    for k, name in enumerate("xyz"):
        assert np.array_equal(sw[name], ens.final_x[:, k]), name
        assert np.array_equal(sw["v" + name], ens.final_v[:, k]), name
    for name in ("max_sway", "energy_drift"):
        assert np.array_equal(sw[name], ens.summary[name]), name
    other = pl.sweep(GRID, QS, method="rattle4" if method == "rattle6" else "rattle6", **KW)
    assert not np.array_equal(sw["x"], other["x"])
    assert same(sw, pl.sweep(GRID, QS, method=method, **KW))  # whatever the chunking
    if method == "rattle":
        assert same(sw, pl.sweep(GRID, QS, **KW))  # the default


@pytest.mark.parametrize("bad", ["rk4", "RATTLE6", "dop853", "", 6, None])
def test_a_bad_method_is_refused_naming_it_and_the_allowed_ones(bad: Any) -> None:
    """Refused before any work, also where nothing integrates (as arithmetic is); a name no integrator
    has as everywhere (``unknown method 'RATTLE6' (did you mean 'rattle6'?); available: …``)."""
    shown = repr(bad)
    for quantity, kw in ((QS, KW), ("period", {"progress": False})):
        with pytest.raises(pl.InvalidInputError) as e:
            pl.sweep(GRID, quantity, method=bad, **kw)
        if bad in ("RATTLE6", ""):
            assert str(e.value) == unknown_method(bad)
            assert ("(did you mean 'rattle6'?)" in str(e.value)) is (bad == "RATTLE6"), str(e.value)
        else:
            assert f"method = {shown}: sweeps integrate with {ALLOWED}" in str(e.value), str(e.value)


def test_exact_quantities_record_no_method() -> None:
    exact = pl.sweep({"theta0": [0.5, 1.0], "phi_dot0": [1.0]}, "period", method="rattle8", progress=False)
    assert "method" not in exact.metadata["spec"]


def test_the_work_bound_counts_sub_steps() -> None:
    """t_end·points/dt within the bound for RATTLE, not with 3 or 15 sub-steps per step: refused before
    any work, the count the sub-steps' (the RATTLE sweep gets past the bound to the bad backend). The
    message names the product it refuses, each factor with the values given, the limit and the fixes."""
    n = 15
    t_end = MAX_STEPS / n * 1e-2 / 2
    with pytest.raises(pl.InvalidInputError, match="backend"):
        pl.sweep(GRID, "final_state", t_end=t_end, dt=1e-2, backend="nope", progress=False)
    for method, substeps, work in (("rattle4", 3, "1.5e10"), ("rattle8", 15, "7.5e10")):
        with pytest.raises(pl.InvalidInputError) as e:
            pl.sweep(GRID, "final_state", t_end=t_end, dt=1e-2, method=method, backend="nope")
        assert str(e.value) == (
            f"the run would take {work} RATTLE steps (15 points × t_end/dt = {t_end!r} s / 0.01 s = 3.33e8 "
            f"steps × {substeps} RATTLE sub-steps per step of {method}), more than the limit of 1e10: lower "
            "t_end, raise dt, use fewer points or use a method of fewer sub-steps"
        ), str(e.value)


def test_one_point_beyond_the_work_bound(tmp_path: Path) -> None:
    """A single point's steps beyond the bound: refused as that (no count of points; fewer points would
    not help), by pl.sweep and when a sweep file is read ([simulation], whose t_end and dt it names)."""
    one = (
        "one point would take 1.5e10 RATTLE steps (t_end/dt = 1000000.0 s / 0.001 s = 1e9 steps × 15 "
        "RATTLE sub-steps per step of rattle8), more than the limit of 1e10: lower t_end, raise dt or use "
        "a method of fewer sub-steps"
    )
    with pytest.raises(pl.InvalidInputError) as e:
        pl.sweep({"theta0": [0.5]}, "final_state", t_end=1e6, dt=1e-3, method="rattle8")
    assert str(e.value) == one, str(e.value)
    path = tmp_path / "long.toml"
    path.write_text(
        'quantity = "final_state"\n[grid]\ntheta0 = [0.5]\n'
        '[simulation]\nt_end = 1e6\ndt = 1e-3\nmethod = "rattle8"\n'
    )
    with pytest.raises(SweepFileError) as f:
        load_sweep_file(path)
    assert f"{path}: [simulation] {one}" in str(f.value), str(f.value)


@pytest.mark.parametrize(
    ("design", "method", "work", "fixes"),
    [
        (
            "[grid]\ntheta0 = { start = 0.1, stop = 1.0, num = 1000 }\n"
            "phi_dot0 = { start = -1, stop = 1, num = 1000 }",
            "rattle",
            "2e10 RATTLE steps (1000000 points × t_end/dt = 20.0 s / 0.001 s = 2e4 steps)",
            "lower t_end, raise dt or use fewer points ([grid])",
        ),
        (
            "[random]\nn = 200_000\nranges = { theta0 = [0.1, 1.0] }",
            "rattle4",
            "1.2e10 RATTLE steps (200000 points × t_end/dt = 20.0 s / 0.001 s = 2e4 steps × 3 RATTLE "
            "sub-steps per step of rattle4)",
            "lower t_end, raise dt, use fewer points ([random] n) or use a method of fewer sub-steps",
        ),
    ],
)
def test_a_sweep_file_beyond_the_work_bound_is_refused_when_read(
    tmp_path: Path, design: str, method: str, work: str, fixes: str
) -> None:
    """Each point within the bound, the whole sweep (points × steps × sub-steps) beyond it: refused as
    the file is read, before any work, with pl.sweep's message (the product, each factor, the limit)
    and the fix naming the file's table; so is ``pendulab sweep``, which creates nothing. Before, only
    one point's steps were checked there."""
    path = tmp_path / "big.toml"
    path.write_text(
        f'quantity = "final_state"\n{design}\n[simulation]\nt_end = 20.0\ndt = 1e-3\nmethod = "{method}"\n'
    )
    with pytest.raises(SweepFileError) as e:
        load_sweep_file(path)
    assert str(e.value) == f"{path}: the run would take {work}, more than the limit of 1e10: {fixes}"
    if method == "rattle":  # the message pl.sweep gives for the same sweep
        grid = {"theta0": np.linspace(0.1, 1.0, 1000), "phi_dot0": np.linspace(-1, 1, 1000)}
        with pytest.raises(pl.InvalidInputError) as same_sweep:
            pl.sweep(grid, "final_state", t_end=20.0, dt=1e-3)
        assert str(same_sweep.value) == str(e.value)[len(f"{path}: ") :].replace(" ([grid])", "")
    code, out, err = invoke("sweep", str(path), "--out", str(tmp_path / "o"))
    assert_user_error(code, out, err, "more than the limit of 1e10")
    assert not (tmp_path / "o").exists()


def test_resume_with_another_method_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A sweep recorded with rattle6, interrupted: resuming it with rattle or rattle4 is refused
    before any work (ResumeConflict naming both and the fix); with rattle6 it finishes bit for bit.
    With other settings different too, the generic refusal names every difference."""
    out = tmp_path / "sw"
    first = pl.sweep(GRID, QS, method="rattle6", out=out, chunk_size=4, **KW)
    assert manifest(out)["spec"]["method"] == "rattle6"
    drop_chunk(out, 1)
    calls = counting(monkeypatch)
    for method in ("rattle", "rattle4"):
        with pytest.raises(ResumeConflict) as e:
            pl.sweep(GRID, QS, method=method, out=out, resume=True, **KW)
        for needle in (f"method = {method!r} differs from 'rattle6'", str(out), "method='rattle6'"):
            assert needle in str(e.value), (needle, str(e.value))
    with pytest.raises(
        pl.InvalidInputError, match=r"different sweep: dt .*method \('rattle6' there, 'rattle'"
    ):
        pl.sweep(GRID, QS, out=out, resume=True, t_end=0.2, dt=2e-2, progress=False)
    assert calls == [0] and not (out / "chunk-000001.parquet").exists()
    again = pl.sweep(GRID, QS, method="rattle6", out=out, resume=True, **KW)
    assert calls == [1] and again.stats["computed"] == 1 and same(first, pl.read_sweep(out))


def test_a_sweep_that_records_no_method_ran_rattle(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A directory written before the method was recorded (its spec and fingerprint without it) resumes
    with the default (RATTLE), its record staying without one, and refuses another method."""
    out = tmp_path / "old"
    first = pl.sweep(GRID, QS, out=out, chunk_size=4, **KW)
    m = manifest(out)
    assert m["spec"].pop("method") == "rattle"
    text = json.dumps({"design": as_design(GRID).fingerprint(), "spec": m["spec"]}, sort_keys=True)
    m["fingerprint"] = hashlib.sha256(text.encode()).hexdigest()  # the fingerprint of the old format
    (out / "_manifest.json").write_text(json.dumps(m))
    drop_chunk(out, 2)
    calls = counting(monkeypatch)
    with pytest.raises(ResumeConflict, match=r"'rattle6' differs from 'rattle'.*records none"):
        pl.sweep(GRID, QS, method="rattle6", out=out, resume=True, **KW)
    assert calls == [0]
    again = pl.sweep(GRID, QS, out=out, resume=True, **KW)
    assert calls == [1] and same(first, pl.read_sweep(out))
    assert "method" not in again.metadata["spec"] and "method" not in manifest(out)["spec"]


def test_sweep_file_key_and_cli_option(tmp_path: Path) -> None:
    """``[simulation] method`` reaches pl.sweep (the same numbers as naming it there, recorded);
    without it the method is RATTLE; ``pendulab sweep --method`` overrides the file's key."""
    named = sweep_file(tmp_path, QS, 1e-2, method='"rattle6"')
    assert load_sweep_file(named).sweep_kwargs()["method"] == "rattle6"
    assert load_sweep_file(named).sweep_kwargs(method="rattle4")["method"] == "rattle4"
    assert load_sweep_file(sweep_file(tmp_path, QS, 1e-2)).sweep_kwargs()["method"] == "rattle"
    for toml, option, want in (
        (named, [], "rattle6"),
        (named, ["--method", "rattle8"], "rattle8"),
        (sweep_file(tmp_path, QS, 1e-2), [], "rattle"),
    ):
        out = tmp_path / f"out-{len(list(tmp_path.glob('out-*')))}"
        code, _, stderr = invoke("sweep", str(toml), "--out", str(out), "--no-progress", *option)
        assert code == 0, stderr
        assert f"{'RATTLE' if want == 'rattle' else want} to t = 0.2 s" in stderr, stderr
        res = pl.read_sweep(out)
        assert res.metadata["spec"]["method"] == want and manifest(out)["spec"]["method"] == want
        assert same(res, pl.sweep(GRID, QS, method=want, **KW)), (toml.read_text(), option)


def test_bad_method_in_a_sweep_file_or_on_the_command_line(tmp_path: Path) -> None:
    path = sweep_file(tmp_path, QS, 1e-2, method='"rk4"')
    with pytest.raises(SweepFileError) as e:
        load_sweep_file(path)
    assert f"{path}: [simulation] method = 'rk4': sweeps integrate with {ALLOWED}" in str(e.value)
    code, out, err = invoke("sweep", str(path), "--out", str(tmp_path / "o"), "--no-progress")
    assert_user_error(code, out, err, "[simulation] method = 'rk4'", ALLOWED)
    good = sweep_file(tmp_path, QS, 1e-2)
    code, out, err = invoke("sweep", str(good), "--out", str(tmp_path / "o"), "--method", "rk4")
    assert_user_error(code, out, err, "--method: method = 'rk4'", ALLOWED)
    assert not (tmp_path / "o").exists()


def test_cli_resume_refuses_another_method(tmp_path: Path) -> None:
    """The refusal names its fix as the command's options (``--method rattle6``)."""
    out = tmp_path / "sw"
    named = sweep_file(tmp_path, QS, 1e-2, method='"rattle6"')
    code, _, stderr = invoke("sweep", str(named), "--out", str(out), "--no-progress")
    assert code == 0, stderr
    drop_chunk(out, 0)
    code, stdout, stderr = invoke("sweep", str(named), "--out", str(out), "--resume", "--method", "rattle")
    assert_user_error(code, stdout, stderr, "differs from 'rattle6'", "resume with --method rattle6")
    code, stdout, stderr = invoke("sweep", str(named), "--out", str(out), "--resume", "--no-progress")
    assert code == 0 and "computed 1, skipped 3" in stdout, stderr
