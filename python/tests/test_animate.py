"""Movie files (pendulab.animate): the files decode to the frames asked for, the bob's pixels follow
the motion, frames between saved samples are accurate, and bad requests (also extreme spans and
speeds, a GIF beyond the pixel cap) fail up front with clear errors and leave no half-written file.

The pixel check: in every decoded frame the bob (the only red disc) is located by the centroid of its
red pixels and compared with the camera projection (canvas.Camera.project) of the exact position at
that frame's time t_k = t₀ + speed·k/fps (clock.py). Within 1.5 px for MP4 (lossy H.264 shifts edges)
and GIF. Times in seconds, lengths in metres, positions on screen in pixels."""

from __future__ import annotations

import re
import subprocess

import numpy as np
import pytest
from movie_pixels import red_centroid
from PIL import Image

import pendulab as pl
from pendulab import animate
from pendulab.animate.canvas import Camera
from pendulab.animate.layout import boxes

imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg")

SIZE = (480, 360)


def expected_pixels(sol: pl.ExactSolution, times: np.ndarray) -> np.ndarray:
    """Where the 3-D panel (default camera, the whole frame) draws the bob at ``times``."""
    x, _ = sol.state(times)
    return Camera(boxes(["3d"], *SIZE)[0], sol.pendulum.length).project(x)


def decode(path, size) -> tuple[dict, list[np.ndarray]]:
    """The frames of a video file decoded by ffmpeg to RGB, with its codec, frame count and duration [s]
    as ffmpeg reports them."""
    exe = imageio_ffmpeg.get_ffmpeg_exe()
    raw = subprocess.run(
        [exe, "-v", "error", "-i", str(path), "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
        capture_output=True,
        check=True,
    ).stdout
    w, h = size
    frames = list(np.frombuffer(raw, dtype=np.uint8).reshape(-1, h, w, 3))
    probe = subprocess.run([exe, "-hide_banner", "-i", str(path)], capture_output=True, text=True).stderr
    codec = re.search(r"Video: (\w+)", probe)
    fps = re.search(r"([\d.]+) fps", probe)
    n, secs = imageio_ffmpeg.count_frames_and_secs(str(path))
    meta = {
        "codec": codec and codec.group(1),
        "fps": fps and float(fps.group(1)),
        "frames": n,
        "duration": secs,
    }
    return meta, frames


def test_exact_mp4_frames_duration_and_bob_position(tmp_path, sol):
    out = tmp_path / "rosette.mp4"
    movie = sol.animate(out, t=(0.0, 5.0), fps=20, speed=1.5, duration=2.0, size=SIZE, trail=0.5)
    assert movie.frames == 40 and movie.fps == 20 and movie.size == SIZE
    assert movie.t_end == pytest.approx(1.5 * 39 / 20)
    assert out.stat().st_size == movie.bytes > 0
    assert not [p for p in tmp_path.iterdir() if p.name != "rosette.mp4"]  # no temporary left
    meta, frames = decode(out, SIZE)
    assert len(frames) == meta["frames"] == 40
    assert meta["codec"] == "h264" and meta["fps"] == pytest.approx(20.0)
    assert meta["duration"] == pytest.approx(2.0, abs=0.06)
    times = 1.5 * np.arange(40) / 20
    want = expected_pixels(sol, times)
    got = np.array([red_centroid(f) for f in frames])
    assert np.max(np.linalg.norm(got - want, axis=1)) < 1.5
    # the bob really moves across the frame (the check above is not satisfied by a still picture)
    assert np.ptp(got[:, 0]) > 50


def test_trajectory_gif_between_samples_follows_the_exact_motion(tmp_path, pendulum, rosette, sol):
    # saved every 0.1 s, shown at 25 frames/s of 0.04 s: most frames lie between samples (Hermite)
    tr = pl.simulate(pendulum, rosette, t_end=3.0, method="rattle4", dt=1e-3, save_every=100)
    out = tmp_path / "rosette.gif"
    movie = tr.animate(out, fps=25, duration=2.0, size=SIZE, panels=["3d"], trail=0.0)
    assert movie.fps == 25.0 and movie.frames == 50
    with Image.open(out) as im:
        assert im.n_frames == 50
        total_ms, got = 0, []
        for k in range(im.n_frames):
            im.seek(k)
            total_ms += im.info["duration"]
            got.append(red_centroid(np.asarray(im.convert("RGB"))))
    assert total_ms == 2000
    want = expected_pixels(sol, np.arange(50) / 25)
    assert np.max(np.linalg.norm(np.array(got) - want, axis=1)) < 1.5


def test_gif_rounds_the_frame_rate_to_whole_centiseconds(tmp_path, sol):
    movie = sol.animate(tmp_path / "a.gif", t=(0, 1), fps=30, size=(96, 64), progress=False)
    assert movie.fps == pytest.approx(100 / 3)  # 3 cs per frame
    assert movie.frames == 34  # 0 … 1 s at 1/33.3 s: the last frame is at t = 0.99 s


def test_hermite_frames_converge_at_fourth_order(sol):
    """Between samples of spacing h the interpolated position errs by O(h⁴) (motion.py)."""
    errors = []
    for h in (0.1, 0.05, 0.025):
        t = np.arange(0.0, 4.0 + h / 2, h)
        x, v = sol.state(t)
        motion = animate.from_samples(t, x, v, length=1.0, g=9.81, mass=1.0, label="samples")
        mid = t[:-1] + 0.37 * h
        xi, vi = motion.states(mid)
        xe, ve = sol.state(mid)
        errors.append(np.max(np.abs(xi[:, 0] - xe)))
        assert np.max(np.abs(vi[:, 0] - ve)) < 60 * h**3
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 3.7), orders


def test_ensemble_webm_shows_every_bob(tmp_path, pendulum):
    states = pl.states_from_angles(pendulum, theta=np.linspace(0.3, 2.5, 12), phi_dot=1.0)
    res = pl.simulate_ensemble(pendulum, states, t_end=1.0, dt=1e-3, save=pl.Save.every(50))
    out = tmp_path / "many.webm"
    movie = res.animate(out, fps=10, size=(320, 240), panels="3d,top")
    assert movie.frames == 11
    meta, frames = decode(out, (320, 240))
    assert meta["codec"] == "vp9" and len(frames) == meta["frames"] == 11
    with pytest.raises(pl.InvalidInputError, match="panel 'veff' shows the invariants of one orbit"):
        res.animate(tmp_path / "x.mp4", panels="3d,veff")


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"path": "m.avi"}, "unknown movie format '.avi'"),
        ({"path": "m"}, "unknown movie format '\\(no suffix\\)'"),
        ({"size": (641, 480)}, "size = 641x480 pixels: mp4 .* even"),
        ({"size": (32, 480)}, "size = 32x480 pixels: width must be 64..3840"),
        ({"size": "big"}, "size = 'big': write it as WIDTHxHEIGHT"),
        ({"fps": 0}, "fps = 0 frames/s: must be finite and > 0"),
        ({"fps": float("nan")}, "fps = nan"),
        ({"speed": -1.0}, "speed = -1.0"),
        ({"duration": 11.0}, "duration = 11 s .* past the end of the data at t = 10 s"),
        ({"fps": 120, "speed": 1e-3}, "frames .* exceed the limit of 100000"),
        ({"panels": "3d,side"}, "unknown panel 'side'"),
        ({"panels": ""}, "give at least one of 3d, top, z, reduced, veff"),
        (
            {"panels": "3d,top,z", "size": (200, 200)},
            "too small for the panels 3d, top, z: each would be 80x100",
        ),
        ({"path": "m.gif", "size": (1920, 1080), "speed": 0.05, "fps": 50}, "a GIF of .* more than"),
        ({"path": "m.gif", "fps": 60}, "fps = 60: a GIF plays at most 50"),
        ({"path": "m.gif", "fps": 0}, "fps = 0 frames/s: must be finite and > 0"),
        ({"path": "m.gif", "fps": float("nan")}, "fps = nan frames/s"),
        ({"fps": "fast"}, "fps = 'fast' must be a number"),
        ({"trail": -1.0}, r"trail = -1.0 s: must be finite and within \[0, inf\]"),
        ({"elevation": 120}, r"elevation = 120 deg: must be finite and within \[-90, 90\]"),
    ],
)
def test_bad_requests_are_refused_before_any_work(tmp_path, sol, kwargs, message):
    kwargs = dict(kwargs)
    path = tmp_path / kwargs.pop("path", "m.mp4")
    with pytest.raises(pl.InvalidInputError, match=message):
        sol.animate(path, t=(0.0, 10.0), **kwargs)
    assert list(tmp_path.iterdir()) == []


def test_ctrl_c_leaves_no_file(tmp_path, sol, monkeypatch):
    from pendulab.animate.panel_3d import Panel3D

    original = Panel3D.overlay

    def interrupted(self, draw, k):
        if k == 5:
            raise KeyboardInterrupt
        original(self, draw, k)

    monkeypatch.setattr(Panel3D, "overlay", interrupted)
    for name in ("m.mp4", "m.gif"):
        with pytest.raises(KeyboardInterrupt):
            sol.animate(tmp_path / name, t=(0.0, 2.0), fps=10, size=(160, 120))
    assert list(tmp_path.iterdir()) == []


def test_an_existing_movie_is_replaced_only_when_the_new_one_is_complete(tmp_path, sol, monkeypatch):
    out = tmp_path / "m.mp4"
    out.write_bytes(b"old movie")
    real = animate.movie._Plan.frames

    def failing(self):
        frames = real(self)
        yield next(frames)
        yield next(frames)
        raise OSError("no space left on device")

    monkeypatch.setattr(animate.movie._Plan, "frames", failing)
    with pytest.raises(OSError, match="no space left"):
        sol.animate(out, t=(0.0, 1.0), fps=10, size=(160, 120))
    assert out.read_bytes() == b"old movie"
    assert [p.name for p in tmp_path.iterdir()] == ["m.mp4"]


@pytest.mark.parametrize(
    "kwargs",
    [
        {"speed": 5e-324},  # span / speed overflows to inf frames (issue 30: OverflowError)
        {"duration": 1e308},
        {"t": (0.0, 1e308)},
        {"fps": 30, "speed": 1e-300},
    ],
)
def test_extreme_spans_and_speeds_are_clear_errors_not_overflows(tmp_path, sol, kwargs):
    kwargs = {"t": (0.0, 10.0), **kwargs}
    with pytest.raises(pl.InvalidInputError, match=r"frames .* exceed the limit of 100000"):
        sol.animate(tmp_path / "m.gif", **kwargs)
    assert list(tmp_path.iterdir()) == []


def test_a_trail_longer_than_the_movie_is_the_whole_path(tmp_path, sol):
    """trail=1e308 s overflowed when turned into a number of points; it is the whole path drawn so far."""
    movie = sol.animate(tmp_path / "m.gif", t=(0.0, 1.0), fps=10, size=(320, 180), trail=1e308)
    assert movie.frames == 11 and (tmp_path / "m.gif").stat().st_size > 0


@pytest.mark.parametrize("span", [1.0, 100.0, 1000.0, 1e5])
def test_gif_defaults_fit_the_pixel_cap(span):
    from pendulab.animate.clock import make_clock
    from pendulab.animate.encode import MAX_GIF_PIXELS, check_work, fit_gif, gif_fps

    size, fps, speed = fit_gif(span, None, None, 1.0)
    clock = make_clock((0.0, span), fps=gif_fps(fps), speed=speed, duration=None)
    check_work("gif", size, clock.frames)  # raises if it does not fit
    assert clock.frames * size[0] * size[1] <= MAX_GIF_PIXELS
    assert clock.t_last >= span - clock.frame_dt  # the whole span is shown
    assert fps >= 10.0 and (speed == 1.0) == (span * 10.0 + 1 <= MAX_GIF_PIXELS // (640 * 360))


def test_cli_animate_takes_a_scenario_name_and_fits_a_gif(tmp_path, monkeypatch):
    """`pendulab animate rosette --out a.gif` (issue 31: "rosette: No such file or directory"; and the
    one-command GIF of a shipped scenario refused its own defaults)."""
    from typer.testing import CliRunner

    from pendulab import cli

    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(cli.app, ["animate", "rosette", "--out", "a.gif", "--t-end", "2"])
    assert result.exit_code == 0, result.output
    assert "GIF: 640x360 at 20 frames/s, speed 1" in result.stderr
    with Image.open(tmp_path / "a.gif") as im:
        assert im.size == (640, 360) and im.n_frames == 41
