"""Movies (pendulab.animate): the files decode to the frames asked for, the bob's pixels follow the
motion, frames between saved samples are accurate, and bad requests fail up front with clear errors.

The pixel check: in every decoded frame the bob (the only red disc) is located by the centroid of its
red pixels and compared with the camera projection (canvas.Camera.project) of the exact position at
that frame's time t_k = t₀ + speed·k/fps (clock.py). Within 1.5 px for MP4 (lossy H.264 shifts edges)
and GIF.
"""

from __future__ import annotations

import re
import subprocess

import numpy as np
import pytest
from PIL import Image

import pendulab as pl
from pendulab import animate
from pendulab.animate.canvas import Camera
from pendulab.animate.layout import boxes

imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg")

SIZE = (480, 360)


def red_centroid(rgb: np.ndarray) -> np.ndarray:
    """Pixel centroid (u, w) of the bob's red disc in an (h, w, 3) frame."""
    r, g, b = (rgb[..., i].astype(int) for i in range(3))
    mask = (r > 150) & (g < 120) & (b < 120)
    assert mask.sum() >= 8, "no bob found in the frame"
    w, u = np.nonzero(mask)
    return np.array([u.mean(), w.mean()])


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


@pytest.fixture
def sol(pendulum: pl.Pendulum, rosette: pl.State) -> pl.ExactSolution:
    return pl.exact(pendulum, rosette)


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


def test_every_panel_draws_a_damped_orbit(tmp_path):
    p = pl.Pendulum(length=2.0, g=9.81, mass=0.5, damping=0.2)
    s0 = p.state_from_angles(theta=1.0, phi=0.3, theta_dot=0.0, phi_dot=1.5)
    tr = pl.simulate(p, s0, t_end=4.0, dt=1e-3, save_every=20)
    frames = list(animate.frames(tr_motion(tr), fps=10, panels="3d,top,z,reduced,veff", size=(640, 360)))
    assert len(frames) == 41
    assert all(f.size == (640, 360) for f in frames)
    # frames differ (the bob moves) and every panel drew something besides the background
    a, b = (np.asarray(f) for f in (frames[0], frames[-1]))
    assert np.count_nonzero(np.any(a != b, axis=-1)) > 500
    for box in animate.layout.boxes(["3d", "top", "z", "reduced", "veff"], 640, 360):
        crop = b[box.top : box.top + box.height, box.left : box.left + box.width]
        assert np.count_nonzero(np.any(crop != 255, axis=-1)) > 200


def tr_motion(tr: pl.Trajectory) -> animate.Motion:
    p = tr.pendulum
    return animate.from_samples(tr.t, tr.x, tr.v, length=p.length, g=p.g, mass=p.mass, label=tr.method)


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


KINDS = {
    "planar": ({}, (2.0, 0.3, 0.0, 0.0)),
    "over the top (through both poles)": ({}, (0.0, 0.0, 7.0, 0.0)),
    "rest at the bottom": ({}, (0.0, 0.0, 0.0, 0.0)),
    "g < 0": ({"g": -9.81}, (2.0, 0.0, 0.0, 1.0)),
    "g = 0": ({"g": 0.0}, (1.0, 0.0, 1.0, 1.0)),
}
MODELS = {
    "string": {"model": "string", "restitution": 0.0},
    "slewing": {"model": "slewing", "radius": 2.0, "rate": 0.5},
    "rotating": {"model": "rotating", "frame_rate": 0.5, "latitude": 0.8},
    "vibrating": {"model": "vibrating", "amplitude": 0.1, "frequency": 30.0},
}


@pytest.mark.parametrize("case", list(KINDS), ids=list(KINDS))
def test_every_kind_of_exact_motion_draws_on_every_panel(tmp_path, case):
    """Poles (V_eff's 0/0 for J₃ = 0), rest, mirrored and zero gravity: no warning (pytest makes
    warnings errors), no NaN in the frames."""
    params, angles = KINDS[case]
    p = pl.Pendulum(**params)
    sol = pl.exact(p, p.state_from_angles(*angles))
    movie = sol.animate(
        tmp_path / "m.gif", t=(0.0, 2.0), fps=4, panels="3d,top,z,reduced,veff", size=(480, 270)
    )
    assert movie.frames == 9


@pytest.mark.parametrize("name", list(MODELS), ids=list(MODELS))
def test_every_model_draws_on_every_panel(tmp_path, name):
    p = pl.Pendulum(**MODELS[name])
    tr = pl.simulate(p, p.state_from_angles(theta=1.5, phi=0.0, theta_dot=0.0, phi_dot=0.5), t_end=2.0)
    movie = tr.animate(
        tmp_path / "m.mp4", fps=4, panels="3d,top,z,reduced,veff", size=(480, 270), vectors=True
    )
    assert movie.frames == 9


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


def theme_pixels(rgb: np.ndarray, colour: tuple[int, int, int]) -> np.ndarray:
    """Pixel coordinates (u, w) drawn in exactly ``colour``."""
    w, u = np.nonzero(np.all(rgb == np.array(colour, dtype=np.uint8), axis=-1))
    return np.stack([u, w], axis=-1)


def pivot_motion(tr: pl.Trajectory, with_pivot: bool = True) -> animate.Motion:
    p = tr.pendulum
    pivot = tr.pivot if with_pivot else None
    return animate.from_samples(tr.t, tr.x, tr.v, length=p.length, g=p.g, mass=p.mass, label="m", pivot=pivot)


@pytest.mark.parametrize("name", ["slewing", "vibrating", "sampled_pivot"])
def test_a_moving_pivot_is_drawn_where_it_is_with_its_path(name):
    """The pivot's disc (its own colour) is where the camera puts p(t_k); its trail and the rod hang
    from it. Without the pivot passed, no pixel has the pivot's colour."""
    if name == "sampled_pivot":  # a pivot swung 0.3 m sideways at 2 rad/s, given by 31 samples
        ts = np.linspace(0.0, 3.0, 31)
        p = pl.Pendulum(pivot_samples=(ts, np.stack([0.3 * np.sin(2 * ts), 0 * ts, 0 * ts], -1)))
    else:
        p = pl.Pendulum(**MODELS[name])
    tr = pl.simulate(p, p.state_from_angles(theta=0.5, phi=0.0, theta_dot=0.0, phi_dot=0.5), t_end=2.0)
    theme = animate.movie.Theme()
    size = (320, 240)
    for trail, fixed in ((None, False), (0.0, False), (None, True)):
        shots = [
            np.asarray(f) for f in animate.frames(pivot_motion(tr, not fixed), fps=2, size=size, trail=trail)
        ]
        assert len(shots) == 5
        counts = [len(theme_pixels(s, theme.pivot)) for s in shots]
        if fixed:
            assert counts == [0] * 5
            continue
        assert min(counts) >= 20
        if trail == 0.0:  # only the disc has the pivot's exact colour: it sits at p(t_k)
            t = np.arange(5) * 0.5
            path = np.asarray(animate.motion.from_samples(  # the same pivot on the movie's times
                tr.t, tr.x, tr.v, length=1, g=1, mass=1, label="", pivot=tr.pivot).pivot(t))  # fmt: skip
            scene = animate.scene.Scene(
                pivot_motion(tr), animate.clock.make_clock((0.0, 2.0), fps=2, speed=1.0, duration=None),
                animate.scene.Options(0.0), theme,
            )  # fmt: skip
            dense = scene.pivot
            centre = 0.5 * (dense.min(axis=0) + dense.max(axis=0))
            reach = p.length + float(np.linalg.norm(dense - centre, axis=-1).max())
            want = Camera(boxes(["3d"], *size)[0], reach).project(path - centre)
            got = np.array([theme_pixels(s, theme.pivot).mean(axis=0) for s in shots])
            assert np.abs(got - want).max() < 1.5  # px: the disc is rasterised on whole pixels
            if name == "slewing":  # the tip turns 1 rad on a 2 m circle: the disc moves across the frame
                assert np.linalg.norm(got[-1] - got[0]) > 20


def test_the_pivot_is_interpolated_between_samples_to_third_order():
    """p(t) between saved samples (Hermite with finite-difference slopes) against the exact circle of
    the slewing crane's boom tip: the error falls ≈ 8x or more when the sample spacing halves."""
    t_fine = np.linspace(0.0, 2.0, 401)
    exact = np.stack([2 * np.cos(0.5 * t_fine), 2 * np.sin(0.5 * t_fine), 0 * t_fine], -1)
    errors = []
    for n in (11, 21, 41):
        ts = np.linspace(0.0, 2.0, n)
        ps = np.stack([2 * np.cos(0.5 * ts), 2 * np.sin(0.5 * ts), 0 * ts], -1)
        x, v = np.tile([0.0, 0.0, -1.0], (n, 1)), np.zeros((n, 3))
        m = animate.from_samples(ts, x, v, length=1, g=9.81, mass=1, label="", pivot=ps)
        errors.append(np.abs(m.pivot(t_fine) - exact).max())
    assert errors[0] / errors[1] > 7 and errors[1] / errors[2] > 7, errors


def test_the_swinging_spring_is_animated_with_a_varying_length(tmp_path):
    """A vertical bounce of 30 cm: the drawn distance from the pivot to the bob follows |x| (11 frames
    over one bounce period of 1 s), the coil is drawn and the title is in words."""
    sp = pl.SwingingSpring.resonant(1.0)
    tr = pl.simulate_spring(sp, [0.0, 0.0, -1.3], [0.0, 0.0, 0.0], 1.0, dt=1e-3, save_every=10)
    size = (320, 240)
    movie = tr.animate(tmp_path / "spring.gif", fps=10, size=size, trail=0)
    assert movie.frames == 11
    with Image.open(tmp_path / "spring.gif") as im:
        shots = []
        for k in range(im.n_frames):
            im.seek(k)
            shots.append(np.asarray(im.convert("RGB")))
    pivot = np.array(boxes(["3d"], *size)[0].centre)
    drawn = np.array([np.linalg.norm(red_centroid(s) - pivot) for s in shots])
    r = np.linalg.norm(tr.x[::10], axis=1)  # samples every 0.01 s: frame k at sample 10 k
    assert drawn.max() - drawn.min() > 10  # pixels: the spring stretches and shortens
    assert np.corrcoef(drawn, r[: len(drawn)])[0, 1] > 0.99
    with pytest.raises(pl.InvalidInputError, match="swinging spring leaves it and takes 3d, top, z"):
        tr.animate(tmp_path / "x.gif", fps=10, size=size, panels="3d,veff")
    assert not (tmp_path / "x.gif").exists()


def test_the_3d_panel_has_a_floor_grid(sol):
    """A faint grid in the floor's own colour, below the pivot (the middle of the frame)."""

    def states(t):
        x, v = sol.state(t)
        return x[:, None], v[:, None]

    motion = animate.from_function(states, length=1.0, g=9.81, mass=1.0, span=(0.0, 1.0), label="exact")
    shot = np.asarray(next(animate.frames(motion, fps=1, size=(320, 240))))
    floor = theme_pixels(shot, animate.movie.Theme().floor)
    assert len(floor) > 200
    assert floor[:, 1].mean() > 130  # pixels below the pivot at w = 120


def test_movie_settings_are_one_object_reused_and_overridden() -> None:
    """A MovieSettings gives the same frames as its fields as keywords; keywords go over it; an unknown
    keyword is named."""
    from pendulab.animate import MovieSettings, frames
    from pendulab.animate.movie import movie_settings

    p = pl.Pendulum()
    tr = pl.simulate(p, p.state_from_angles(theta=0.6, phi_dot=1.0), t_end=0.5, dt=1e-2)
    m = pl.animate.from_samples(tr.t, tr.x, tr.v, length=1.0, g=9.81, mass=1.0, label="x")
    look = MovieSettings(fps=10, size=(320, 180), panels="3d,top")
    a = [np.asarray(f) for f in frames(m, look)]
    b = [np.asarray(f) for f in frames(m, fps=10, size=(320, 180), panels="3d,top")]
    assert len(a) == len(b) > 1 and all(np.array_equal(x, y) for x, y in zip(a, b, strict=True))
    assert movie_settings(look, {"fps": 5}).fps == 5 and look.fps == 10
    with pytest.raises(TypeError, match="unknown movie setting"):
        movie_settings(look, {"frames_per_second": 5})
