"""``pendulab animate``: a scenario to a movie in one command; bad options fail before any work with
one ``error:`` line and exit code 2."""

from __future__ import annotations

import re
import sys

import pytest
from conftest import SCENARIOS, ctrl_c_after
from PIL import Image
from typer.testing import CliRunner

from pendulab import cli

pytest.importorskip("imageio_ffmpeg")


def invoke(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli.app, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_animate_exact_gif_with_panels(tmp_path):
    out = tmp_path / "rosette.gif"
    code, stdout, _ = invoke(
        "animate", str(SCENARIOS / "rosette.toml"), "--out", str(out), "--exact", "--panels", "3d,top,z",
        "--size", "320x180", "--fps", "20", "--duration", "1.5",
    )  # fmt: skip
    assert code == 0, stdout
    assert "wrote" in stdout and "30 frames" in stdout
    with Image.open(out) as im:
        assert im.size == (320, 180) and im.n_frames == 30


def test_animate_integrated_mp4(tmp_path):
    out = tmp_path / "damped.mp4"
    code, stdout, _ = invoke(
        "animate", str(SCENARIOS / "damped.toml"), "--out", str(out), "--t-end", "1.0", "--size", "320x180",
        "--fps", "10", "--panels", "3d,veff", "--quiet",
    )  # fmt: skip
    assert code == 0 and stdout == ""
    assert out.stat().st_size > 0


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--out", "m.avi"], "unknown movie format '.avi'"),
        (["--out", "m.mp4", "--size", "1281x720"], "size = 1281x720 pixels: mp4 .* even"),
        (["--out", "m.mp4", "--size", "wide"], "size = 'wide'"),
        (["--out", "m.mp4", "--panels", "3d,sky"], "unknown panel 'sky'"),
        (["--out", "m.mp4", "--panels", "3d,z,veff", "--size", "200x200"], "too small for the panels"),
        (["--out", "m.mp4", "--fps", "-1"], "fps = -1.0 frames/s"),
        (["--out", "m.mp4", "--duration", "500"], "past the end of the data at t = 100 s"),
    ],
)
def test_animate_refuses_bad_options(tmp_path, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    code, _, stderr = invoke("animate", str(SCENARIOS / "rosette.toml"), *args)
    assert code == 2
    assert stderr.startswith("error: ") and stderr.count("\n") == 1, stderr  # before any work
    assert re.search(message, stderr), stderr
    assert list(tmp_path.iterdir()) == []


def test_animate_refuses_the_exact_solution_of_a_damped_pendulum(tmp_path):
    code, _, stderr = invoke(
        "animate", str(SCENARIOS / "damped.toml"), "--out", str(tmp_path / "m.mp4"), "--exact"
    )
    assert code == 2 and "exact solution exists only for the ideal pendulum" in stderr


def test_ctrl_c_stops_the_movie_and_leaves_no_file(tmp_path):
    """A real SIGINT while frames are encoded: exit code 130, one line saying so, and neither the movie
    nor its temporary file nor anything else left in the directory (ffmpeg runs in its own session
    and is stopped by Python)."""
    out = tmp_path / "long.mp4"
    cmd = [sys.executable, "-m", "pendulab.cli", "animate", str(SCENARIOS / "rosette.toml"), "--exact"]
    cmd += ["--out", str(out), "--size", "320x180", "--t-end", "1000", "--no-progress"]  # 30001 frames
    # "exact solution of …" is printed just before the frames start
    proc = ctrl_c_after(cmd, "exact solution of", stream="stderr", wait=1.0, timeout=30)
    stderr = proc.stderr
    assert proc.returncode == 130, stderr
    assert stderr.strip().endswith("error: interrupted (Ctrl-C)") and "Traceback" not in stderr
    assert list(tmp_path.iterdir()) == []


def test_animate_the_swinging_spring(tmp_path):
    out = tmp_path / "spring.gif"
    code, stdout, _ = invoke(
        "animate", str(SCENARIOS / "swinging_spring.toml"), "--out", str(out), "--t-end", "1.0",
        "--size", "320x180", "--fps", "5", "--panels", "3d,z",
    )  # fmt: skip
    assert code == 0, stdout
    assert "6 frames" in stdout
    with Image.open(out) as im:
        assert im.size == (320, 180) and im.n_frames >= 2  # identical frames are merged in a GIF


@pytest.mark.parametrize(
    ("args", "message"),
    [(["--exact"], "'spring' model has none"), (["--panels", "3d,veff"], "takes the panels 3d, top, z")],
)
def test_animate_refuses_what_a_spring_cannot_show(tmp_path, args, message):
    code, _, stderr = invoke(
        "animate", str(SCENARIOS / "swinging_spring.toml"), "--out", str(tmp_path / "m.mp4"), *args
    )
    assert code == 2 and message in stderr, stderr
    assert list(tmp_path.iterdir()) == []
