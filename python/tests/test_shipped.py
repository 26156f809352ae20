"""What the package ships and how a user names it: the example data sets by name (``pendulab fit
example:filmed_swing``), the LICENSE beside pyproject.toml (maturin puts it in the wheel's
``.dist-info/licenses``), and the project's one address, the same in Cargo.toml, pyproject.toml and
CITATION.cff. (tools/check_wheel.py checks the built wheel itself.)"""

from __future__ import annotations

import re
import tomllib

import pytest
from conftest import REPO
from typer.testing import CliRunner

from pendulab import cli
from pendulab.scenario import examples


def test_example_data_are_package_files_found_by_name() -> None:
    assert set(examples.data_files()) == {"crane_sway", "encoder_decay", "filmed_swing", "phone_pendulum"}
    for spelling in ("filmed_swing", "filmed_swing.csv", "example:filmed_swing"):
        assert examples.find(spelling, "data") == examples.DATA / "filmed_swing.csv"
    assert examples.DATA.is_relative_to(examples.EXAMPLES)
    assert (REPO / "examples" / "data" / "filmed_swing.csv").resolve() == examples.find(
        "filmed_swing", "data"
    )
    with pytest.raises(FileNotFoundError, match=r"nope: No such file, and no example data .* filmed_swing"):
        examples.find("nope", "data")


def test_pendulab_fit_takes_an_example_by_name(tmp_path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    args = ["fit", "example:crane_sway", "--model", "damped", "--fit", "length,damping", "--param", "g=9.81"]
    result = CliRunner().invoke(cli.app, args)
    assert result.exit_code == 0, result.output
    # the truth of make_data.py (docs/fit.md): l = 12.0 m, c = 0.012 1/s
    length = float(re.search(r"length\s*=?\s*([\d.]+)", result.stdout).group(1))
    assert abs(length - 12.0) < 0.1, result.stdout


def test_the_license_is_beside_pyproject_for_the_wheel() -> None:
    assert (REPO / "python" / "LICENSE").read_text() == (REPO / "LICENSE").read_text()


def test_the_project_address_is_stated_once_and_repeated_the_same() -> None:
    cargo = tomllib.loads((REPO / "Cargo.toml").read_text())["workspace"]["package"]
    url = cargo["repository"]
    assert url.startswith("https://") and "example" not in url
    pyproject = tomllib.loads((REPO / "python" / "pyproject.toml").read_text())["project"]
    assert pyproject["urls"]["Repository"] == url
    cff = (REPO / "CITATION.cff").read_text()
    assert f'repository-code: "{url}"' in cff
    crates = [*sorted((REPO / "crates").glob("*/Cargo.toml")), REPO / "python" / "Cargo.toml"]
    assert len(crates) >= 3
    for crate in crates:
        assert "repository.workspace = true" in crate.read_text(), crate


def test_load_scenario_takes_a_shipped_example_by_name(tmp_path, monkeypatch) -> None:
    """``pl.load_scenario("rosette")`` loads the shipped example, as ``pendulab run rosette`` does, from
    any directory; a path that exists wins; anything else is refused naming it and the examples."""
    import pendulab as pl

    monkeypatch.chdir(tmp_path)  # outside the checkout: examples/scenarios/… is not here
    sc = pl.load_scenario("rosette")
    assert sc.source == str(examples.scenario_files()["rosette"])
    assert sc.spec == pl.load_scenario(examples.scenario_files()["rosette"]).spec
    assert pl.load_scenario("example:rosette.toml").title == sc.title
    text = examples.scenario_files()["rosette"].read_text(encoding="utf-8")
    (tmp_path / "rosette").write_text(text.replace("length = 1.0", "length = 2.5"), encoding="utf-8")
    assert pl.load_scenario("rosette").pendulum().length == 2.5  # the local file, not the example
    with pytest.raises(FileNotFoundError, match=r"rosete: No such file, and no example scenario .*rosette"):
        pl.load_scenario("rosete")
    with pytest.raises(FileNotFoundError, match=r"give its name alone, 'rosette'"):
        pl.load_scenario("examples/scenarios/rosette.toml")
