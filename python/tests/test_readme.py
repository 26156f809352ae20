"""The README's sweep example, pasted into a script as a user would, runs: with ``backend="dask"``
the worker processes import the script again, which only works behind ``if __name__ == "__main__":``
(the README shows it that way). Run in a fresh directory, in a child process, with a time limit."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import REPO


def _sweep_example() -> str:
    text = (REPO / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## Sweeps") :]
    match = re.search(r"```python\n(.*?)```", section, re.S)
    assert match is not None, "the README's Sweeps section has no python block"
    return match.group(1)


def test_the_readme_sweep_example_runs_as_a_script(tmp_path: Path) -> None:
    pytest.importorskip("distributed")
    code = _sweep_example()
    assert 'backend="dask"' in code and 'if __name__ == "__main__":' in code
    script = tmp_path / "sweep_example.py"
    script.write_text(code, encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in sys.path if p)}
    proc = subprocess.run(
        [sys.executable, str(script)], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=240
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "SweepResult(1000000 points" in proc.stdout
    settle = float(proc.stdout.strip().splitlines()[-1].split()[0])
    # force −m c v with c = 0.1/s: the sway decays as e^(−c t/2); from θ₀ ≤ 0.6 rad most starts are
    # within 0.02 rad before t_end = 60 s, and none before ln(θ₀/0.02)/(c/2) for the median θ₀ ≈ 0.3
    assert 30.0 < settle < 60.0
    assert sorted(p.suffix for p in (tmp_path / "sway").iterdir())
