"""The pure-Python parts of the peer benchmark bench/peers/ (issue 5, parts 3–4; issue 29, item 2):
error against the reference, the cheapest setting that reaches a tolerance, when a scan stops, the
targets as PASS/MISS ratios (with ``pl.simulate_ensemble`` against the C RK4 ensemble at 10³ and 10⁴
steps, from fake results) and the Markdown written between markers. Needs none of the peers (SciPy's
solve_ivp, numba, MuJoCo, JAX, Diffrax): bench/peers/ imports them only inside functions."""

from __future__ import annotations

import importlib.util
import math
import sys
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest

PEERS = Path(__file__).resolve().parents[2] / "bench" / "peers"


def _load(name: str) -> ModuleType:
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, PEERS / f"{name}.py")
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod
    spec.loader.exec_module(mod)
    return mod


hz = _load("harness")
run = _load("run")  # the entry point; loading it imports its parts below
pcases = _load("peers_cases")
pengines = _load("peers_engines")
pens = _load("peers_ensembles")
ptargets = _load("peers_targets")
preport = _load("peers_report")


def R(method: str, wall: float, error: float, case: str = "rosette", failed: str | None = None) -> object:
    return hz.Run(method, case, 1.0, "steps", wall, 100, error, error, 0.0, 0.0, 3, failed)


def test_errors_against_the_reference() -> None:
    x_ref, v_ref = np.array([0.0, 0.6, -0.8]), np.array([1.0, 0.0, 0.0])
    assert hz.position_error(x_ref + np.array([0, 0, 2e-3]), x_ref, 2.0) == pytest.approx(1e-3)
    assert math.isnan(hz.position_error(np.array([np.nan, 0, 0]), x_ref, 1.0))
    # velocity scaled by l ω₀ + |v_ref| = 1·3 + 1
    e = hz.state_error(x_ref, v_ref + np.array([0.4, 0, 0]), x_ref, v_ref, 1.0, 3.0)
    assert e == pytest.approx(0.1)
    de, dc = hz.drifts(
        np.array([0, 0, -1.0]), np.array([0, 0, 0.0]), np.array([0, 0, -1.0]), np.zeros(3), 1.0, 9.81
    )
    assert de == 0.0 and dc == 0.0
    de, dc = hz.drifts(
        np.array([0, 0, -1.1]), np.array([1.0, 0, 0]), np.array([0, 0, -1.0]), np.zeros(3), 1.0, 10.0
    )
    assert de == pytest.approx(abs(0.5 - 1.0) / 10.0) and dc == pytest.approx(0.1)


def test_cheapest_setting_reaching_a_tolerance() -> None:
    runs = [
        R("a", 1.0, 1e-4),
        R("a", 2.0, 1e-9),
        R("a", 4.0, 1e-11),
        R("a", 3.0, 5e-11),
        R("a", 0.1, math.nan),
    ]
    assert hz.cheapest(runs, 1e-3).wall == 1.0
    assert hz.cheapest(runs, 1e-10).wall == 3.0  # the cheaper of the two that reach it, not the finer
    assert hz.cheapest(runs, 1e-12) is None
    assert hz.cheapest([R("a", 0.1, 1e-12, failed="diverged")], 1e-6) is None
    env = hz.envelope(runs, (1e-4, 1e-10, 1e-12))
    assert env == {1e-4: 1.0, 1e-10: 3.0, 1e-12: None}
    assert hz.LEVELS[0] == 1e-4 and hz.LEVELS[-1] == pytest.approx(1e-12) and len(hz.LEVELS) == 9


def test_when_a_scan_stops() -> None:
    nan = math.nan
    assert hz.should_refine([], [], 1e-13, 5.0)
    assert not hz.should_refine([1e-3], [6.0], 1e-13, 5.0)  # the last run took longer than the cap
    assert not hz.should_refine([1e-3, 1e-14], [0.1, 0.2], 1e-13, 5.0)  # below the floor
    # O(1) errors of coarse steps and a few failures do not stop the scan
    assert hz.should_refine([1.2, 0.6, 1.1, 0.9, nan], [0.1] * 5, 1e-13, 5.0)
    # a single noisy setting does not stop it, three without a factor 2 do
    assert hz.should_refine([1e-6, 1e-8, 2e-8, 1e-9], [0.1] * 4, 1e-13, 5.0)
    assert not hz.should_refine([1e-6, 1e-12, 2e-12, 1.5e-12, 1e-12], [0.1] * 5, 1e-13, 5.0)
    # a lucky coarse error (above 1e-9) does not stop it either
    assert hz.should_refine([1e-2, 1e-6, 5e-5, 7e-6, 6e-6], [0.1] * 5, 1e-13, 5.0)
    assert hz.should_refine([nan] * 12, [0.01] * 12, 1e-13, 5.0)
    assert not hz.should_refine([nan] * 20, [0.01] * 20, 1e-13, 5.0)


def test_verdicts_and_formatting() -> None:
    assert hz.ratio_verdict(1.3, 1.2) == "PASS"
    assert hz.ratio_verdict(0.83, 1.2) == "MISS"
    assert hz.ratio_verdict(0.15, 0.2, higher_is_better=False) == "PASS"
    assert hz.ratio_verdict(None, 1.0) == "n/a"
    assert hz.ratio_verdict(math.nan, 1.0) == "n/a"
    assert hz.fmt_sci(3.19e7) == "3.19 × 10⁷"
    assert hz.fmt_sci(9.999e-5) == "1.00 × 10⁻⁴"
    assert hz.fmt_time(2.5e-6) == "2.5 µs" and hz.fmt_time(0.0123) == "12.3 ms" and hz.fmt_time(None) == "—"
    assert pcases.fixed_settings(False) == sorted(pcases.fixed_settings(False))
    rt = pcases.adaptive_settings(False)
    assert rt[0] == pytest.approx(1e-3) and rt[-1] == pytest.approx(1e-14)


def test_markdown_between_markers() -> None:
    table = hz.markdown_table(["a", "b"], [[1, "x|y"]])
    assert table.splitlines() == ["| a | b |", "|---|---|", "| 1 | x\\|y |"]
    doc = f"# Perf\n\nintro\n\n## Against peers\n{hz.BEGIN}\nold\n{hz.END}\n\n## After\nkept\n"
    new = hz.replace_between_markers(doc, "| new |")
    assert "old" not in new and "| new |" in new and new.endswith("## After\nkept\n")
    assert hz.replace_between_markers(new, "| new |") == new  # idempotent
    appended = hz.replace_between_markers("# Perf\n", "body")
    assert appended.endswith(f"## Against peers\n{hz.BEGIN}\nbody\n{hz.END}\n")
    with pytest.raises(ValueError):
        hz.replace_between_markers(f"{hz.BEGIN}\nno end\n", "body")
    with pytest.raises(ValueError):
        hz.replace_between_markers(f"{hz.END}\n{hz.BEGIN}\n", "body")


def test_median_time_repeats() -> None:
    calls = []
    wall, out, n = hz.median_time(lambda: calls.append(1) or len(calls), repeats=4)
    assert n == 4 and out == 4 and wall >= 0
    assert hz.repeats_for(2.0) == 1 and hz.repeats_for(1e-4) == 5 and hz.repeats_for(0.4, budget=1.0) == 3


def test_quaternion_for_mujoco_start() -> None:
    down = np.array([0.0, 0.0, -1.0])
    for target in ([0.866, 0.0, -0.5], [0.0174524, 0.0, 0.9998477], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]):
        b = np.array(target) / np.linalg.norm(target)
        w, *xyz = pengines._quat_rotating(down, b)
        u = np.array(xyz)
        rotated = down + 2 * w * np.cross(u, down) + 2 * np.cross(u, np.cross(u, down))
        assert np.allclose(rotated, b, atol=1e-12)


def _case(name: str) -> object:
    z = np.zeros(3)
    return pcases.Case(name, 1.0, 1.0, 9.81, z, z, z, z, 0.0, 1e-14)


def test_targets_and_report_from_synthetic_runs() -> None:
    cases = [_case("rosette"), _case("near_top")]
    runs = [
        R("pendulab dop853", 0.001, 1e-11),
        R("pendulab rattle", 0.0001, 1e-5),
        R("C rk4", 0.01, 1e-10),
        R("C rk4", 0.002, 1e-6),
        R("mujoco rk4", 0.5, 1e-9),  # never reaches 1e-10: the ratio to its longest run is a bound
        R("pendulab exact", 1e-6, 1e-14),  # not an integrator: left out of "Pendulab's best"
        R("pendulab dop853", 0.02, 1e-11, case="near_top"),
        R("C rk4", 0.01, 1e-11, case="near_top"),  # faster than Pendulab here: a MISS
    ]
    rates = {
        "pendulab rattle (Stepper.step)": {"steps_per_s": 3.0e7},
        "C rk4": {"steps_per_s": 2.0e7},
        "mujoco rk4 (mj_step, nstep)": {"steps_per_s": 1.0e6},
    }
    ens = {
        "n": 8,
        "steps": 10,
        "arithmetic": "fused",
        "pendulab": {1: {"rate": 1e8}, 2: {"rate": 1.9e8}},
        "C rk4": {2: {"rate": 2e8}},
        "api_vs_c": _api_vs_c(2.5, 1.5),
    }
    rmap = {"points": 10**6, "wall": 1.5, "repeats": 3}
    tg = {t["target"]: t for t in ptargets.targets(runs, rates, ens, rmap, cases)}
    assert tg["RATTLE steps/s ≥ 1.2 × C RK4 loop"]["value"] == pytest.approx(1.5)
    assert tg["RATTLE steps/s ≥ 1.2 × C RK4 loop"]["verdict"] == "PASS"
    assert tg["RATTLE steps/s ≥ 50 × MuJoCo (RK4)"]["verdict"] == "MISS"  # 30×
    assert tg["ensemble ≥ 0.8 × C RK4 ensemble (2 threads)"]["verdict"] == "PASS"
    assert tg["ensemble speed-up 1 → 2 threads ≥ 1.8"]["value"] == pytest.approx(1.9)
    avc = tg[ptargets.API_VS_C_TARGET]
    assert avc["value"] == pytest.approx(1.5) and avc["verdict"] == "MISS"  # the smaller ratio counts
    assert "10³ steps: C / API wall 2.5" in avc["detail"] and "arithmetic fused" in avc["detail"]
    c_time = tg["time to ≤1e-10 (rosette) ≤ 0.2 × C rk4"]
    assert c_time["value"] == pytest.approx(0.1) and c_time["verdict"] == "PASS"
    mj = tg["time to ≤1e-10 (rosette) ≤ 0.01 × mujoco rk4"]
    assert mj["value"] == pytest.approx(0.002) and "never reached" in mj["detail"]
    level = next(t for k, t in tg.items() if k.startswith("every level"))
    assert level["verdict"] == "MISS" and "near_top" in level["detail"]
    robust = next(t for k, t in tg.items() if k.startswith("robustness"))
    assert robust["verdict"] == "PASS"
    assert next(t for k, t in tg.items() if "map" in k)["verdict"] == "PASS"

    meta = {
        "date": "2026-11-23 14:00 UTC",
        "wall_total": 60.0,
        "load_start": 3.0,
        "load_end": 2.5,
        "versions": {"scipy": "1", "pendulab": "0.1.0"},
        "skipped": {"mujoco": "mujoco is not installed", "C": None},
        "cap": 5.0,
    }
    body = preport.markdown(runs, cases, rates, ens, rmap, list(tg.values()), meta)
    assert "**MISS**" in body and "**PASS**" in body
    assert "mujoco: skipped, mujoco is not installed" in body
    assert "while other work was running on it" in body  # load average 3: the report says so
    assert "#### `pl.simulate_ensemble` against the C RK4 ensemble (issue 29)" in body
    assert "| 10⁴ | 3 | 200 ms | 300 ms | 1.5 | 1.8 |" in body
    assert "Load average 3.2 at the start, 3.9 at the end" in body
    assert "arithmetic fused, from the result's metadata" in body
    assert '`arithmetic="auto"` → fused' in body  # the kernel column's arithmetic
    quiet = preport.markdown(
        runs, cases, rates, ens, rmap, list(tg.values()), {**meta, "load_start": 1.2, "load_end": 1.0}
    )
    assert "with nothing else running on it" in quiet and "pessimistic" not in quiet
    doc = hz.replace_between_markers(f"# P\n{hz.BEGIN}\n{hz.END}\n", body)
    assert doc.count("| target | measured (ratio) | goal | verdict | detail |") == 1


def _api_vs_c(ratio_1e3: float, ratio_1e4: float) -> dict:
    """Fake results of ``peers_ensembles.api_vs_c``: the API at 20 ms (10³ steps) and 200 ms (10⁴)."""
    steps = {}
    for k, wall, ratio, reps in (("1000", 0.02, ratio_1e3, 9), ("10000", 0.2, ratio_1e4, 3)):
        steps[k] = {
            "repeats": reps, "api_wall": wall, "c_wall": wall * ratio, "ratio": ratio,
            "ratio_cpu": ratio * 1.2, "api_cpu": wall, "c_cpu": wall * ratio * 1.2,
        }  # fmt: skip
    return {"n": 4096, "threads": 2, "dt": 1e-3, "arithmetic": "fused", "steps": steps,
            "load_start": 3.2, "load_end": 3.9}  # fmt: skip


def test_simulate_ensemble_against_c_target() -> None:
    """Issue 29: PASS only when both step counts reach 2; n/a when a count or the C side is missing."""

    def verdict(avc: dict) -> dict:
        ens = {"pendulab": {}, "api_vs_c": avc}
        rmap = {"points": 10**6, "wall": 1.5, "repeats": 3}
        tg = ptargets.targets([], {}, ens, rmap, [_case("rosette")])
        return next(t for t in tg if t["target"] == ptargets.API_VS_C_TARGET)

    ok = verdict(_api_vs_c(2.4, 2.1))
    assert ok["verdict"] == "PASS" and ok["value"] == pytest.approx(2.1) and ok["goal"] == 2.0
    assert verdict(_api_vs_c(1.9, 3.0))["verdict"] == "MISS"
    partial = _api_vs_c(2.4, 2.1)
    del partial["steps"]["10000"]
    assert verdict(partial)["verdict"] == "n/a"
    skipped = verdict({"skipped": "the C family is not run"})
    assert skipped["verdict"] == "n/a" and skipped["detail"] == "the C family is not run"
    assert preport.api_vs_c_table({"skipped": "the C family is not run"})[2] == (
        "Not measured: the C family is not run."
    )
    # best of 9 and 3 interleaved rounds (quick: 3 and 1)
    assert [pens.api_vs_c_reps(s, False) for s in (1000, 10_000)] == [9, 3]
    assert [pens.api_vs_c_reps(s, True) for s in (1000, 10_000)] == [3, 1]
    assert pens.API_VS_C["n"] == 4096 and pens.API_VS_C["threads"] == 2 and pens.API_VS_C["dt"] == 1e-3


def test_the_recorded_cpu_names_the_core_behind_a_generic_model_name(tmp_path: Path) -> None:
    # a virtual machine's cpuinfo says only "Intel(R) Xeon(R) Processor": the family and model tell
    # the core, whose FMA units decide the C baseline's speed (docs/performance.md)
    info = tmp_path / "cpuinfo"
    info.write_text(
        "processor\t: 0\nvendor_id\t: GenuineIntel\ncpu family\t: 6\nmodel\t\t: 207\n"
        "model name\t: Intel(R) Xeon(R) Processor\n"
    )
    assert hz.cpu_description(str(info)) == "Intel(R) Xeon(R) Processor (family 6, model 207, Emerald Rapids)"
    info.write_text("cpu family\t: 25\nmodel\t\t: 17\nmodel name\t: AMD EPYC 9354 32-Core Processor\n")
    assert hz.cpu_description(str(info)) == "AMD EPYC 9354 32-Core Processor (family 25, model 17)"
    # no cpuinfo (macOS, Windows): what platform knows, never an exception
    assert hz.cpu_description(str(tmp_path / "missing")) != ""


def test_ensemble_work_precision_table_from_synthetic_runs() -> None:
    """bench/peers/ensemble_work_precision.py: per error level (largest over the starts, then the
    median) the least wall time of each method that reaches it, and the C RK4 ensemble's time over the
    best Pendulab method's."""
    wp = _load("ensemble_work_precision")

    def run(setting: float, wall: float, largest: float) -> dict[str, float]:
        return {"setting": setting, "wall": wall, "max_error": largest, "median_error": largest / 10}

    rows = [run(1e-3, 0.4, 2e-7), run(1e-2, 0.1, 2e-3)]
    assert (
        wp.cheapest(rows, 1e-6) == 0.4 and wp.cheapest(rows, 1e-2) == 0.1 and wp.cheapest(rows, 1e-9) is None
    )
    assert wp.cheapest(rows, 1e-3, "median_error") == 0.1
    res = {
        "n": 8, "t_end": 10.0, "threads": 2, "arithmetic": "fused",
        "meta": {"date": "today", "cpu": "a CPU", "load_start": 0.1, "load_end": 0.2},
        "runs": {"rattle6": [run(0.01, 0.05, 1e-8)], "C rk4": rows},
    }  # fmt: skip
    text = wp.markdown(res)
    largest, median = text.split("| median error ≤ |")
    assert "| largest error ≤ | `rattle6` | `C rk4` |" in largest and "a CPU" in largest
    assert "| 1e-05 | 50 ms | 400 ms | 8.0 (`rattle6`) |" in largest
    assert "| 1e-09 | — | — | — |" in largest
    # by the median (10× below each largest error) C RK4's coarse run reaches 1e-3
    assert "| 1e-03 | 50 ms | 100 ms | 2.0 (`rattle6`) |" in median
