"""One version: ``[workspace.package] version`` in Cargo.toml is the only source, and every place that
states a version agrees with it — the crates (``version.workspace = true``), the Python package
(maturin's ``dynamic = ["version"]``, the installed metadata), ``pendulab.__version__`` (compiled into
the core), ``pendulab --version``, the latest release in CHANGELOG.md, CITATION.cff and the web
front end's package.json."""

from __future__ import annotations

import json
import re
import subprocess
import sys
import tomllib
from importlib import metadata
from pathlib import Path

import pendulab as pl

ROOT = Path(__file__).resolve().parents[2]


def _cargo_version() -> str:
    workspace = tomllib.loads((ROOT / "Cargo.toml").read_text(encoding="utf-8"))
    version = workspace["workspace"]["package"]["version"]
    assert re.fullmatch(r"\d+\.\d+\.\d+([-+][0-9A-Za-z.-]+)?", version), version
    return version


def test_crates_and_pyproject_take_the_workspace_version() -> None:
    for manifest in (
        "crates/pendulab-core/Cargo.toml",
        "crates/pendulab-wasm/Cargo.toml",
        "python/Cargo.toml",
    ):
        package = tomllib.loads((ROOT / manifest).read_text(encoding="utf-8"))["package"]
        assert package["version"] == {"workspace": True}, manifest
    project = tomllib.loads((ROOT / "python/pyproject.toml").read_text(encoding="utf-8"))["project"]
    assert "version" not in project and "version" in project["dynamic"]


def test_python_package_reports_the_cargo_version() -> None:
    version = _cargo_version()
    assert pl.__version__ == version
    assert metadata.version("pendulab") == version


def test_cli_version_is_the_cargo_version() -> None:
    (script,) = metadata.entry_points(group="console_scripts", name="pendulab")
    code = (
        "import sys; sys.argv = ['pendulab', '--version']; "
        f"from {script.module} import {script.attr} as main; main()"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == f"pendulab {_cargo_version()}"


def test_changelog_citation_and_web_agree() -> None:
    version = _cargo_version()
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    released = re.findall(r"^## \[(\d[^\]]*)\] - (\d{4}-\d{2}-\d{2})$", changelog, flags=re.MULTILINE)
    assert released and released[0][0] == version, released[:1]
    citation = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    (cited,) = re.findall(r'^version: "?([^"\n]+)"?$', citation, flags=re.MULTILINE)
    assert cited == version
    (date,) = re.findall(r'^date-released: "?([^"\n]+)"?$', citation, flags=re.MULTILINE)
    assert date == released[0][1], "CITATION.cff date-released is the date of the latest release"
    web = json.loads((ROOT / "web/package.json").read_text(encoding="utf-8"))
    assert web["version"] == version
    assert "MIT" in (ROOT / "LICENSE").read_text(encoding="utf-8").splitlines()[0]
