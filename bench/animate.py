"""Movie rendering speed and file size (pendulab.animate), with matplotlib as the baseline.

Case: the rosette (l = 1 m, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s), exact solution, 1280×720.
Measures, in one run on this machine:

- frames drawn per second (no encoder) of the 3-D panel and of all five panels (Pillow renderer);
- the same 3-D picture (sphere wireframe, rod, bob, trail) drawn by matplotlib's Agg backend, redrawn
  per frame (the baseline; a 3-D axes cannot blit): the ratio says what drawing with Pillow buys;
- a 30 s 720p MP4 at 30 frames/s end to end (draw + H.264 encode): frames/s and file size [MB];
- a 10 s 640×360 GIF at 20 frames/s: frames/s and size [MB].

Targets of issue 16: >= 20 frames/s at 1280×720 for the 3-D panel, a 30 s 720p MP4 under 5 MB.
Run: ``.venv/bin/python bench/animate.py [--markdown FILE]`` (about a minute).
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np
import pendulab as pl
from pendulab import animate


def rosette() -> pl.ExactSolution:
    p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    return pl.exact(p, p.state_from_angles(theta=np.radians(60), phi=0.0, theta_dot=0.0, phi_dot=2.0))


def motion(sol: pl.ExactSolution, span: tuple[float, float]) -> animate.Motion:
    def states(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x, v = sol.state(t)
        return x[:, None, :], v[:, None, :]

    return animate.from_function(states, length=1.0, g=9.81, mass=1.0, span=span, label="exact")


def draw_rate(m: animate.Motion, panels: str, frames: int) -> float:
    """Frames drawn per second [1/s] (Pillow, no encoder)."""
    start = time.perf_counter()
    n = sum(1 for _ in animate.frames(m, panels=panels, duration=frames / 30.0))
    return n / (time.perf_counter() - start)


def matplotlib_rate(sol: pl.ExactSolution, frames: int) -> float:
    """The same 3-D picture drawn by matplotlib (Agg), frames per second [1/s]."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(12.8, 7.2), dpi=100)
    ax = fig.add_subplot(projection="3d")
    u, w = np.meshgrid(np.linspace(0, 2 * np.pi, 13), np.linspace(0, np.pi, 7))
    ax.plot_wireframe(np.cos(u) * np.sin(w), np.sin(u) * np.sin(w), np.cos(w), color="0.85", linewidth=0.5)
    ax.set_box_aspect((1, 1, 1))
    ax.set_axis_off()
    (rod,) = ax.plot([], [], [], color="0.25", lw=2)
    (trail,) = ax.plot([], [], [], color="tab:blue", lw=1.5)
    (bob,) = ax.plot([], [], [], "o", color="tab:red", ms=12)
    times = np.arange(frames) / 30.0
    x, _ = sol.state(np.arange(-60, frames) / 30.0)
    start = time.perf_counter()
    for k in range(len(times)):
        p, past = x[k + 60], x[k : k + 61]
        rod.set_data_3d([0, p[0]], [0, p[1]], [0, p[2]])
        trail.set_data_3d(past[:, 0], past[:, 1], past[:, 2])
        bob.set_data_3d([p[0]], [p[1]], [p[2]])
        fig.canvas.draw()
        np.asarray(fig.canvas.buffer_rgba())
    rate = frames / (time.perf_counter() - start)
    plt.close(fig)
    return rate


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--markdown", type=Path, help="also write the table as Markdown to this file")
    args = ap.parse_args()
    sol = rosette()
    m = motion(sol, (0.0, 60.0))
    rows: list[tuple[str, str, str]] = []
    d3 = draw_rate(m, "3d", 300)
    all5 = draw_rate(m, "3d,top,z,reduced,veff", 300)
    mpl = matplotlib_rate(sol, 30)
    rows += [
        ("draw 3-D panel, 1280×720 (Pillow)", f"{d3:.0f} frames/s", f"{d3 / mpl:.0f}× matplotlib"),
        ("draw all five panels, 1280×720", f"{all5:.0f} frames/s", f"{all5 / mpl:.0f}× matplotlib"),
        ("baseline: matplotlib 3-D (Agg), 1280×720", f"{mpl:.1f} frames/s", "1×"),
    ]
    with tempfile.TemporaryDirectory() as tmp:
        mp4 = sol.animate(Path(tmp) / "rosette.mp4", t=(0.0, 30.0), fps=30, size=(1280, 720), progress=False)
        rows.append(
            (
                f"MP4 (H.264), 3-D panel, 1280×720, {mp4.duration:.0f} s at 30 frames/s",
                f"{mp4.frames_per_second:.0f} frames/s",
                f"{mp4.bytes / 1e6:.2f} MB",
            )
        )
        full = sol.animate(
            Path(tmp) / "panels.mp4",
            t=(0.0, 30.0),
            fps=30,
            size=(1280, 720),
            panels="3d,top,z,reduced,veff",
            progress=False,
        )
        rows.append(
            (
                f"MP4 (H.264), all five panels, 1280×720, {full.duration:.0f} s",
                f"{full.frames_per_second:.0f} frames/s",
                f"{full.bytes / 1e6:.2f} MB",
            )
        )
        gif = sol.animate(Path(tmp) / "rosette.gif", t=(0.0, 10.0), fps=20, size=(640, 360), progress=False)
        rows.append(
            (
                f"GIF (Pillow), 3-D panel, 640×360, {gif.duration:.0f} s at 20 frames/s",
                f"{gif.frames_per_second:.0f} frames/s",
                f"{gif.bytes / 1e6:.2f} MB",
            )
        )
    table = ["| what | speed | size / ratio |", "|---|---|---|"] + [
        f"| {a} | {b} | {c} |" for a, b, c in rows
    ]
    print("\n".join(table))
    if args.markdown:
        args.markdown.write_text("\n".join(table) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
