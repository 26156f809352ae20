"""The result of an ensemble run, ``EnsembleResult``, and its arrays on disk: ``to_xarray()`` and
``save(path)``.

The dataset has dims ``trajectory`` (N), ``time`` (n_save) and ``axis`` (0, 1, 2 = x, y, z) and holds
``x`` [m], ``v`` [m/s], ``t`` [s] as the time coordinate, the per-trajectory summary (``z_min``,
``z_max`` [m], ``e_min``, ``e_max`` [J/kg], ``j3_min``, ``j3_max`` [m²/s], ``energy_drift`` [1],
``j3_drift`` [m²/s], ``max_sway`` [rad], ``crossings`` [1]: passages through the pivot's horizontal
plane) and ``settle_time`` [s] when they were asked for, a
``valid`` flag per trajectory (False for non-finite start rows), and the run's settings as JSON in
``attrs["pendulab"]``. Formats by suffix: ``.nc`` (NetCDF 3 through SciPy) and ``.zarr`` (a Zarr
store, chunked by trajectory, for runs larger than memory readers want to load at once). Both are
written atomically: to a temporary name beside the target, renamed when complete. Read them back
with ``xarray.open_dataset(path)`` or ``xarray.open_zarr(path)``.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from .. import io
from ..display import Row, html_table, number
from ..model import FloatArray

if TYPE_CHECKING:
    from ..animate import Movie, MovieSettings

SUMMARY_UNITS = {
    "z_min": "m",
    "z_max": "m",
    "e_min": "J/kg",
    "e_max": "J/kg",
    "j3_min": "m^2/s",
    "j3_max": "m^2/s",
    "energy_drift": "1",
    "j3_drift": "m^2/s",
    "max_sway": "rad",
    "crossings": "1",
}

ARRAY_SUFFIXES = (".nc", ".zarr")


def to_xarray(res: EnsembleResult) -> Any:
    """The result as an ``xarray.Dataset`` (see the module doc for variables and units)."""
    xr = io._require("xarray")
    n = len(res)
    valid = np.ones(n, dtype=bool)
    valid[res.invalid_rows] = False
    data: dict[str, Any] = {
        "x": (("trajectory", "time", "axis"), res.x, {"units": "m", "long_name": "bob position (x, y, z)"}),
        "v": (("trajectory", "time", "axis"), res.v, {"units": "m/s", "long_name": "bob velocity (x, y, z)"}),
        "valid": ("trajectory", valid, {"long_name": "start row was finite and was integrated"}),
    }
    for name, values in (res.summary or {}).items():
        data[name] = ("trajectory", values, {"units": SUMMARY_UNITS.get(name, "1")})
    if res.settle_time is not None:
        long = "time after which the sway stays within the settle angle (inf: not settled)"
        data["settle_time"] = ("trajectory", res.settle_time, {"units": "s", "long_name": long})
    coords = {
        "trajectory": np.arange(n),
        "time": ("time", res.t, {"units": "s"}),
    }
    attrs = {
        "pendulab": json.dumps(res.metadata, sort_keys=True, default=float),
        "interrupted": int(res.interrupted),
        "steps": int(res.steps),
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)


def save(res: EnsembleResult, path: str | os.PathLike[str]) -> Path:
    """Writes ``res`` to ``path`` (``.nc`` or ``.zarr``) atomically; returns the path."""
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in ARRAY_SUFFIXES:
        raise ValueError(f"unknown ensemble output suffix {suffix!r} in {str(path)!r}; use .nc or .zarr")
    ds = to_xarray(res)
    if suffix == ".nc":
        io._require("scipy")
        ds = ds.assign(valid=ds["valid"].astype(np.int8))  # NetCDF 3 has no booleans
        with io.atomic_path(target) as tmp:
            ds.to_netcdf(tmp, engine="scipy")
        return target
    io._require("zarr")
    if target.exists() and not (target / "zarr.json").exists() and not (target / ".zgroup").exists():
        raise FileExistsError(f"{str(target)!r} exists and is not a Zarr store: not overwriting it")
    target.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent))
    try:
        # chunks of whole trajectories, about 8 MiB each for x and v
        ns = res.x.shape[1]
        chunk = max(1, min(len(res), 2**20 // (3 * max(1, ns))))
        encoding = {k: {"chunks": (chunk, ns, 3)} for k in ("x", "v")}
        # Zarr format 2 with consolidated metadata: readable by every Zarr library and xr.open_zarr
        ds.to_zarr(tmp, mode="w", encoding=encoding, zarr_format=2, consolidated=True)
        if target.exists():  # replace an older store: move it aside, then swap
            old = tmp.with_name(tmp.name + ".old")
            target.rename(old)
            tmp.rename(target)
            shutil.rmtree(old, ignore_errors=True)
        else:
            tmp.rename(target)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            shutil.rmtree(tmp)
        raise
    return target


@dataclass(frozen=True)
class EnsembleResult:
    """Saved states of N trajectories: ``t`` (n_save,) [s], ``x`` and ``v`` (N, n_save, 3) [m, m/s];
    ``summary`` (if asked): per trajectory z_min, z_max [m], e_min, e_max [J/kg] (E/m), j3_min, j3_max
    [m²/s] (J₃/m), ``crossings`` (how many steps crossed the horizontal plane through the pivot, z = 0,
    in either direction: 2 per turn of a swing over the top, 0 below the pivot; float64 counts, NaN
    for invalid rows), and derived ``energy_drift`` = (e_max − e_min)/(|g| l), ``j3_drift`` [m²/s] and
    ``max_sway`` [rad] (largest angle from the stable equilibrium −sign(g) e₃); ``settle_time`` (N,)
    [s] when a settle angle was given."""

    t: FloatArray
    x: FloatArray
    v: FloatArray
    summary: dict[str, FloatArray] | None
    interrupted: bool
    steps: int
    metadata: dict[str, Any] = field(default_factory=dict)
    settle_time: FloatArray | None = None
    invalid_rows: npt.NDArray[np.int64] = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    """Rows of the input whose start was not finite (NaN or inf): not integrated, all results NaN."""

    def __len__(self) -> int:
        return int(self.x.shape[0])

    @property
    def final_x(self) -> FloatArray:
        """Final positions (N, 3) [m]."""
        return self.x[:, -1, :]

    @property
    def final_v(self) -> FloatArray:
        """Final velocities (N, 3) [m/s]."""
        return self.v[:, -1, :]

    def _key_numbers(self) -> list[Row]:
        n_save = int(self.t.shape[0])
        rows: list[Row] = [
            ("trajectories", len(self), ""),
            ("saved times", n_save, ""),
            ("time span", f"{number(self.t[0])} … {number(self.t[-1])}" if n_save else "—", "s"),
            ("steps", self.steps, ""),
        ]
        if len(self.invalid_rows):
            rows.append(("invalid start rows (NaN results)", len(self.invalid_rows), ""))
        if self.summary is not None and "energy_drift" in self.summary:
            drift = number(np.nanmax(self.summary["energy_drift"]), 3)
            rows.append(("largest energy drift / (|g| l)", drift, ""))
        if self.settle_time is not None:
            rows.append(("median settle time", number(np.nanmedian(self.settle_time)), "s"))
        if self.interrupted:
            rows.append(("interrupted", "yes (Ctrl-C)", ""))
        return rows

    def __repr__(self) -> str:
        n_save = int(self.t.shape[0])
        span = f", t = {number(self.t[0])} … {number(self.t[-1])} s" if n_save else ""
        return (
            f"EnsembleResult({len(self)} trajectories, {n_save} saved times{span}, {self.steps} steps"
            + (", INTERRUPTED" if self.interrupted else "")
            + ")"
        )

    def _repr_html_(self) -> str:
        note = "res.x, res.v (N, n_save, 3); res.to_xarray()"
        return html_table("Ensemble", self._key_numbers(), note=note)

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset`` with dims (trajectory, time, axis), units as attributes
        (see :func:`to_xarray`)."""
        return to_xarray(self)

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Writes the arrays to ``path``: ``.nc`` (NetCDF) or ``.zarr`` (a Zarr store), atomically."""
        return save(self, path)

    def animate(
        self, path: str | os.PathLike[str], settings: MovieSettings | None = None, **options: Any
    ) -> Movie:
        """Writes a movie of all N bobs at once to ``path`` (.mp4, .webm or .gif), coloured by row, over
        the saved times (Hermite-interpolated between them, as :meth:`pendulab.Trajectory.animate`).
        Panels ``3d`` and ``top`` (the others show one orbit's invariants). Rows that were not
        integrated (``invalid_rows``) are not drawn. Returns a :class:`pendulab.animate.Movie`."""
        from ..animate import from_samples, render

        radius = np.linalg.norm(self.x[:, 0, :], axis=-1)
        length = float(np.nanmax(radius)) if np.isfinite(radius).any() else 1.0
        params = self.metadata.get("pendulum", {})
        motion = from_samples(
            self.t,
            self.x,
            self.v,
            length=length,
            g=float(params.get("g", 9.81)),
            mass=float(params.get("mass", 1.0)),
            label=f"{len(self)} trajectories, {self.metadata.get('method', 'rattle')}",
        )
        return render(motion, path, settings, **options)
