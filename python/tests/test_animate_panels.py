"""What the movie panels draw (pendulab.animate): every panel (3d, top, z, reduced, veff) for a damped
orbit, for every kind of exact motion (poles, rest, g < 0, g = 0: no warning, no NaN) and for every
model; a moving pivot drawn where it is (the pixels of its colour against the camera projection of
p(t), within 1.5 px) and interpolated between samples to third order; the swinging spring's varying
length; the floor grid; one MovieSettings object reused and overridden; the fading trails, drawn in
batches, the same picture as drawn one curve at a time. Times in seconds, lengths in metres, positions
on screen in pixels."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from movie_pixels import red_centroid
from PIL import Image

import pendulab as pl
from pendulab import animate
from pendulab.animate import panel_3d
from pendulab.animate.canvas import Camera, blend, polyline
from pendulab.animate.layout import boxes

imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg")


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


def per_curve_fading(self, draw, pixels, i, colours):
    """The fading trail as first written: one curve at a time, every piece's colour and pixels worked
    out on their own (the picture the batched ``Panel3D._fading`` must keep)."""
    start = max(0, i - self.trail_points)
    if i - start < 1:
        return
    for curve, colour in enumerate(colours):
        pts = pixels[start : i + 1, curve]
        edges = np.linspace(0, len(pts) - 1, panel_3d.FADE_STEPS + 1).round().astype(int)
        for a, c in itertools.pairwise(edges):
            if c > a:
                age = (i - (start + (a + c) / 2.0)) / self.trail_points
                shade = blend(colour, self.theme.background, min(0.92, age))
                polyline(draw, pts[a : c + 1], shade, width=2)


def test_the_fading_trails_are_the_picture_drawn_one_curve_at_a_time(monkeypatch):
    """40 bobs (one with a gap of NaN samples: its trail drawn with a break) and a moving pivot's trail:
    every frame, from the first (trails shorter than ``trail``) on, equals the per-curve drawing pixel
    for pixel, and the trails are there (the frames differ from those without trails)."""
    p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    res = pl.simulate_ensemble(p, pl.states_from_angles(p, theta=np.linspace(0.2, 2.8, 40), phi_dot=1.0),
                               t_end=1.5, save=pl.Save.every(20))  # fmt: skip
    x, v = res.x.copy(), res.v.copy()
    x[7, 5:9] = np.nan  # a gap in one bob's samples
    ensemble = animate.from_samples(res.t, x, v, length=1.0, g=9.81, mass=1.0, label="forty")
    slewing = pl.Pendulum(**MODELS["slewing"])
    s0 = slewing.state_from_angles(theta=0.5, phi=0.0, theta_dot=0.0, phi_dot=0.5)
    crane = pivot_motion(pl.simulate(slewing, s0, t_end=1.5))
    for motion in (ensemble, crane):
        look = animate.MovieSettings(fps=8, size=(320, 240), panels="3d", trail=1.0)
        batched = [np.asarray(f) for f in animate.frames(motion, look)]
        bare = [np.asarray(f) for f in animate.frames(motion, look, trail=0.0)]
        with monkeypatch.context() as m:
            m.setattr(panel_3d.Panel3D, "_fading", per_curve_fading)
            single = [np.asarray(f) for f in animate.frames(motion, look)]
        assert len(batched) == len(single) == 13
        for k, (a, b) in enumerate(zip(batched, single, strict=True)):
            assert np.array_equal(a, b), f"frame {k}: {np.count_nonzero(np.any(a != b, axis=-1))} px differ"
        assert np.count_nonzero(np.any(batched[-1] != bare[-1], axis=-1)) > 100
