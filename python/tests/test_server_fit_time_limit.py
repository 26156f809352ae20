"""The lab's fit time limit is a setting of the server (``pendulab serve --fit-time-limit SECONDS``,
``create_app(fit_time_limit=…)``; docs/web.md): it was fixed at 20 s. Bounded (> 0, at most
MAX_FIT_SECONDS) with a message naming the bad value and what is allowed; the fit endpoint gives its
fits that limit and its worker twice it plus 10 s. Units: s."""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path
from typing import Any

import pytest
from test_server_client_caps import _free_port, _serve_configs
from typer.testing import CliRunner
from ws_session import LabClient

from pendulab.cli import app as cli
from pendulab.server import create_app
from pendulab.server.fit import (
    FIT_SECONDS,
    MAX_FIT_SECONDS,
    check_fit_time_limit,
    fit_wall_seconds,
)

FILMED = Path(__file__).resolve().parents[2] / "examples" / "data" / "filmed_swing.csv"


def test_the_fit_endpoint_gives_its_fits_the_servers_time_limit() -> None:
    """A limit far below the filmed swing's fit (hundreds of model runs): the answer is the fit stopped
    at that limit, the best values reached, not converged, said with the limit's seconds."""
    app = create_app("rosette", fit_time_limit=0.001)
    assert app.state.fit_time_limit == 0.001 and app.state.pools[1].seconds == fit_wall_seconds(0.001)
    body = json.dumps({"csv": FILMED.read_text(), "name": "filmed_swing.csv"})
    r = LabClient(app).post("/api/fit", content=body, headers={"content-type": "application/json"})
    assert r.status_code == 200, r.text
    out = r.json()
    assert not out["converged"]
    assert any("time limit of 0.001 s" in w for w in out["warnings"]), out["warnings"]


def test_the_default_is_twenty_seconds_and_the_limit_is_bounded() -> None:
    app = create_app("rosette")
    assert app.state.fit_time_limit == FIT_SECONDS == 20.0
    assert app.state.pools[1].seconds == fit_wall_seconds(20.0) == 50.0
    assert check_fit_time_limit(MAX_FIT_SECONDS) == 600.0 and check_fit_time_limit(1) == 1.0
    bads: list[Any] = [0.0, -1.0, float("nan"), float("inf"), 600.5, 1e9, True, "20", None]
    for bad in bads:
        allowed = (
            "the lab's fit time limit must be a number of seconds > 0 and at most 600 (longer fits: "
            f"pendulab fit FILE --time-limit none), got {bad!r}"
        )
        with pytest.raises(ValueError, match=re.escape(allowed)):
            create_app("rosette", fit_time_limit=bad)


def test_pendulab_serve_takes_the_fit_time_limit(monkeypatch: pytest.MonkeyPatch) -> None:
    ran = _serve_configs(monkeypatch)
    args = ["serve", "--no-browser", "--port", str(_free_port()), "--fit-time-limit", "45"]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.output
    (config,) = ran
    assert config.app.state.fit_time_limit == 45.0
    assert config.app.state.pools[1].seconds == fit_wall_seconds(45.0) == 100.0
    for arg, shown in (("0", "0.0"), ("-3", "-3.0"), ("600.5", "600.5"), ("1e9", "1000000000.0")):
        bad = CliRunner().invoke(cli, ["serve", "--no-browser", "--fit-time-limit", arg])
        assert bad.exit_code == 2, bad.output
        assert (
            "error: pendulab serve: --fit-time-limit: the lab's fit time limit must be a number of "
            "seconds > 0 and at most 600 (longer fits: pendulab fit FILE --time-limit none), got "
            f"{shown}; see 'pendulab serve --help'" in bad.output
        ), bad.output
    for arg in ("nan", "inf", "soon"):  # the message of every float option (test_cli_values.py)
        bad = CliRunner().invoke(cli, ["serve", "--no-browser", "--fit-time-limit", arg])
        assert bad.exit_code == 2 and "--fit-time-limit" in bad.output and repr(arg) in bad.output, bad.output
    assert len(ran) == 1  # none of them started a server


def test_the_lab_says_when_its_time_limit_stopped_the_block_check(monkeypatch: pytest.MonkeyPatch) -> None:
    """A misfit (a decay with dry friction fitted with viscous damping alone) whose fit's clock runs out
    at the block check: the lab's answer carries the finding that the check was not made, keyed with
    the limit's seconds, and the report shows it (before: nothing said, only narrow bars)."""
    import numpy as np
    from test_fit_blocks import encoder_decay

    from pendulab.fitting import inference
    from pendulab.server.fit import FitRequest, fit_data

    check = inference.check_blocks

    def late(search: Any, *args: Any) -> Any:
        search.clock.began -= 1000.0  # the clock runs out here
        return check(search, *args)

    monkeypatch.setattr(inference, "check_blocks", late)
    t = np.arange(0.0, 12.0, 0.01)
    rows = "\n".join(f"{a:.17g},{b:.17g}" for a, b in zip(t, encoder_decay(1.2, t, kappa=0.0), strict=True))
    out = fit_data(FitRequest(csv="t,angle\n" + rows, name="decay.csv"), time_limit=20.0)
    notes = [n for n in out["notes"] if n["key"] == "blocksTimeLimit"]
    assert [n["values"] for n in notes] == [{"seconds": "20"}], out["notes"]
    assert "the block check of the misfit was not made" in out["report"]
    # the answer's blocks: not made, what stopped it, the scale factors null (not measured, not widened)
    blocks = out["blocks"]
    assert blocks["made"] is False and blocks["stop"] == "timeLimit" and blocks["starts"] == []
    assert blocks["scale"] == {"length": None, "damping": None}, blocks
    json.dumps(out, allow_nan=False)  # JSON without NaN


@pytest.mark.parametrize("module", ["pendulab.server.fit", "pendulab.server.serving"])
def test_without_the_lab_extra_serves_limits_pass_to_serves_own_message(
    module: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """--fit-time-limit and --idle-timeout are checked by the server's rules as the command line is read;
    where the server cannot be imported (no ``lab`` extra) the value passes, and serve then names the
    missing extra (not an ImportError out of a typer callback)."""
    from pendulab.cli import serve
    from pendulab.cli.common import UsageError

    check = serve._fit_time_limit if module.endswith(".fit") else serve._idle_timeout
    with pytest.raises(UsageError, match="must be a number of seconds"):
        check(1e9)
    monkeypatch.setitem(sys.modules, module, None)  # `from … import` it: ImportError, as without FastAPI
    assert check(1e9) == 1e9
