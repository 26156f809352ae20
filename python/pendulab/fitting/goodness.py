"""Goodness of fit: does the fitted motion explain the data to their noise, and are the residuals the
white noise the error bars assume? (docs/fit.md, "Noise and goodness of fit"; docs/theory.md T-10.5.)

Per data kind, from the residual r (measured − fitted, the kind's unit, N × columns):

- its rms against the data's white-noise floor (noise.py), read off the data before the fit: a model
  that explains the data leaves about the floor; a multiple of it is a misfit;
- the lag-1 autocorrelation ρ₁, the Ljung–Box test of the first LJUNG_BOX_LAGS autocorrelations, the
  runs test of the residual's signs and the band scan of its periodogram (whiteness.py: a misfit
  smaller than the noise still puts its power in a few frequencies near the swing's);
- with σ given, the χ² of the whole fit against the χ² distribution of its degrees of freedom (a fixed
  threshold on χ²/dof is too lax for large N: its spread is √(2/dof));
- outliers: values more than 5 robust standard deviations (1.4826 · median |r|) both from the fit and
  from the running median of their OUTLIER_WINDOW neighbours (isolated, not a smooth misfit's run);
- correlated noise or a misfit? The residual prewhitened by its own AR(1) fit, e_t = r_t − ρ₁ r_{t−1},
  is tested again (Ljung–Box, runs, band scan): AR(1) measurement noise (video tracking, a filter)
  leaves white e_t, while a misfit — a coherent oscillation at the swing's frequency ω, ρ₁ ≈ cos ωΔt —
  leaves a coherent oscillation of amplitude |1 − ρ₁e^{−iωΔt}| times the old one, still correlated.
  The difference-based noise floor underestimates such noise (by √(1 − ρ₁) for first differences), so a
  residual above the floor is then no misfit.

Error bars that account for correlated residuals: the Newey–West (1987, Econometrica 55:703) sandwich
C = A⁻¹ Ω A⁻¹ with A = JᵀJ and Ω = Σ_L w_L (Γ_L + Γ_Lᵀ), Γ_L = Σ_i g_i g_{i+L}ᵀ over the per-sample
scores g_i = Σ_rows of sample i J_rowᵀ r_row, Bartlett weights w_L = 1 − L/(S+1), and the bandwidth
S = 1.1447 (α n)^{1/3}, α = 4ρ²/((1−ρ)²(1+ρ)²) of Andrews (1991, Econometrica 59:817) for AR(1)
residuals. For strongly correlated residuals (ρ₁ ≥ PREWHITEN) the Bartlett sum is biased low (by
≈ 2Σ k ρ^k/((S+1) Σ ρ^|k|), 10 % of the variance at ρ = 0.8): Ω is then also formed after
prewhitening the scores by an AR(1) fit, Ω = Ω*/(1 − a)² with Ω* the Newey–West Ω of
e_i = g_i − a g_{i−1}, a the median over the unknowns k of a_k = Σ g_ik g_{i−1,k}/Σ g_{i−1,k}²,
clipped to [0, 0.95] (Andrews & Monahan 1992, Econometrica 60:953, a scalar AR(1): no inverse to
blow up; each score's own 1 − a_k broke the cancellations of nearly degenerate parameters, whose a_k
differ by hundredths, and left their bars 5x too wide); the larger variance is used. Each error bar
is the larger of the classical and the sandwich one (the classical covariance scaled by
D = diag(max(1, √(C_sandwich,ii / C_ii))): positive definite); for white residuals the two agree.
Units: SI, those of each data kind.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from ..model import FloatArray
from .swing_features import running_median
from .whiteness import autocorrelations, band_scan, chi2_tails, ljung_box, runs_z

LJUNG_BOX_LAGS = 20
#: p-values below this (Ljung–Box, χ²) are reported: about one false alarm in 10⁴ fits of a right model.
P_ALARM = 1e-4
#: |z| of the runs test above this is reported (two-sided p ≈ 7e-6).
RUNS_ALARM = 4.5
#: The residual's rms above this multiple of the noise floor is a misfit.
FLOOR_ALARM = 1.5
#: The band scan of the prewhitened residual must stay above this p-value for a correlated residual to
#: be called AR(1) noise: a misfit near the swing's frequency that itself raises ρ₁ loses some of its
#: band's power to the prewhitening (from p = 6e-7 to 1.2e-4 in a fit of dry friction); for AR(1)
#: noise the prewhitened scan's p is uniform, so 1 % of such fits are said to be a small misfit.
WHITENED_BAND = 1e-2
#: Columns of a kind whose residual rms is below this share of the largest column's are not tested.
COLUMN_SHARE = 0.3
#: Values farther than this many robust standard deviations from the fit are outliers.
OUTLIER_SIGMAS = 5.0
#: ... and as far from the running median of this many samples around them: a smooth run of large
#: residuals is a misfit, not outliers (loss="soft_l1" does not cure it); bursts of ≤ 3 still count.
OUTLIER_WINDOW = 7
#: A relative residual below this (rms / the data's spread) is noise-free data fitted to the model's
#: own precision (a sideways rate resolved to √ε, round-off): no statistics. Real measurements are
#: noisier by orders of magnitude (a 2400-step encoder: 1e-3 of a swing).
EXACT = 1e-6
#: Andrews' AR(1) bandwidth is multiplied by this: the Bartlett sum's downward bias falls as 1/S, and
#: with the plug-in S itself the error bars of fits to AR(1) noise covered too rarely (bench/fit_validate.py).
BANDWIDTH = 2.0
#: ρ₁ from which the Newey–West Ω is also formed after prewhitening (module doc).
PREWHITEN = 0.5
#: The largest scalar AR(1) coefficient of the scores used for recolouring (1/(1 − a)² ≤ 400).
MAX_SCORE_AR = 0.95
MAX_LAG_WORK = 2e8
"""At most this many multiply-adds (lags × samples × unknowns²) for the Newey–West sum."""


#: The verdicts (KindCheck.verdict) that are structure white noise does not have: a misfit.
MISFIT_VERDICTS = frozenset({"systematic", "correlated", "above_floor"})


@dataclass
class KindCheck:
    """One data kind's residual statistics (unit: the kind's)."""

    rms: float
    robust_rms: float
    floor: float
    spread: float
    lag1: float
    ljung_box_p: float
    runs_z: float
    outliers: int
    trend: float
    #: Ljung–Box p and runs z of the residual prewhitened by its AR(1) fit (module doc).
    whitened_p: float = 1.0
    whitened_runs_z: float = 0.0
    #: The median sampling interval [s].
    dt: float = 0.0
    #: The band scan (whiteness.py): its p-value, the frequency [Hz] of its strongest band and that
    #: band's power in units of the rest's; and its p-value after the AR(1) prewhitening.
    band_p: float = 1.0
    band_hz: float = 0.0
    band_ratio: float = 1.0
    whitened_band_p: float = 1.0

    @property
    def correlated(self) -> bool:
        return self.ljung_box_p < P_ALARM or abs(self.runs_z) > RUNS_ALARM or self.band_p < P_ALARM

    @property
    def ar1_noise(self) -> bool:
        """Correlated, but white once its own AR(1) part is removed: correlated noise, no misfit."""
        return (
            self.correlated
            and self.lag1 > 0.0
            and self.whitened_p >= P_ALARM
            and abs(self.whitened_runs_z) <= RUNS_ALARM
            and self.whitened_band_p >= WHITENED_BAND
        )

    @property
    def explained(self) -> float:
        """The share of the data's variance the fitted motion explains, 1 − rms²/spread²."""
        return 1.0 - (self.rms / self.spread) ** 2 if self.spread > 0.0 else 0.0

    def verdict(self, robust: bool = False) -> str:
        """What the residual says, one word that both :func:`findings` (its wording) and :func:`misfit`
        (the block check's trigger) read, so the two cannot disagree: ``"exact"`` (noise-free data fitted
        to round-off: nothing to test), ``"unexplained"`` (the fit explains under half the variance),
        ``"ar1_noise"`` (correlated noise, white once its AR(1) part is removed), ``"systematic"``
        (correlated and above the floor), ``"correlated"`` (correlated, at the floor), ``"above_floor"``
        (white but over 2 × FLOOR_ALARM times the floor) or ``"ok"``. With ``robust`` the residual's
        size is its robust spread."""
        if self.spread > 0.0 and self.rms <= EXACT * self.spread:
            return "exact"
        if self.explained < 0.5:
            return "unexplained"
        if self.ar1_noise:
            return "ar1_noise"
        ratio = self.size_ratio(robust)
        if self.correlated:
            return "systematic" if ratio > FLOOR_ALARM else "correlated"
        return "above_floor" if ratio > 2.0 * FLOOR_ALARM else "ok"

    def size_ratio(self, robust: bool = False) -> float:
        """The residual's rms (robust spread with ``robust``) in units of the noise floor."""
        size = self.robust_rms if robust else self.rms
        return size / self.floor if self.floor > 0.0 else math.inf


@dataclass
class Goodness:
    """The checks of the module doc per kind, the χ² probability (σ given; None otherwise), the
    factor each error bar was widened by for correlated residuals, and the plain-language findings."""

    kinds: dict[str, KindCheck]
    chi2_p: float | None
    inflation: dict[str, float] = field(default_factory=dict)
    findings: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.findings


def carrying_columns(a: FloatArray) -> list[int]:
    """The columns of a kind's residual (N, columns) that carry it: those with an rms of at least
    COLUMN_SHARE of the largest (a column 3x smaller adds < 10 % to χ²)."""
    col_rms = np.sqrt(np.mean(a**2, axis=0))
    return [j for j in range(a.shape[1]) if col_rms[j] >= COLUMN_SHARE * float(col_rms.max())]


def mean_lag1(a: FloatArray) -> float:
    """The mean lag-1 autocorrelation ρ₁ of the carrying columns of a kind's residual (N, columns)."""
    return float(np.mean([autocorrelations(a[:, j], 1)[0] for j in carrying_columns(a)]))


def check_kind(t: FloatArray, r: FloatArray, floor: float, spread: float) -> KindCheck:
    """The statistics of one kind's residual (N, columns), as :class:`KindCheck`."""
    a = r if r.ndim == 2 else r[:, None]
    cols = carrying_columns(a)
    rho1 = [float(autocorrelations(a[:, j], 1)[0]) for j in cols]
    lag1 = float(np.mean(rho1))
    p_lb = min(ljung_box(a[:, j], LJUNG_BOX_LAGS)[1] for j in cols)
    z = max((runs_z(a[:, j]) for j in cols), key=abs)
    dt = float(np.median(np.diff(t))) if len(t) > 1 else 0.0
    band = min((band_scan(a[:, j], dt) for j in cols), key=lambda b: b[0])
    white = [a[1:, j] - rho * a[:-1, j] for j, rho in zip(cols, rho1, strict=True)]
    white_p = min(ljung_box(w, LJUNG_BOX_LAGS)[1] for w in white) if len(a) > 2 else 1.0
    white_z = max((runs_z(w) for w in white), key=abs) if len(a) > 2 else 0.0
    white_band = min(band_scan(w, dt)[0] for w in white) if len(a) > 2 else 1.0
    outliers = 0
    for j in cols:
        dev = np.abs(a[:, j] - np.median(a[:, j]))
        far = OUTLIER_SIGMAS * 1.4826 * float(np.median(dev))
        short = len(a) < 2 * OUTLIER_WINDOW  # running_median keeps a short record as it is
        local = dev if short else np.abs(a[:, j] - running_median(a[:, j], OUTLIER_WINDOW))
        outliers += int(np.count_nonzero((dev > far) & (local > far))) if far > 0.0 else 0
    # a slow drift: the share of the residual's variance a straight line in time explains
    tt = (t - t.mean()) / max(float(np.ptp(t)), 1e-300)
    trend = 0.0
    total = float(np.sum((a - a.mean(axis=0)) ** 2))
    if total > 0.0 and float(tt @ tt) > 0.0:
        slopes = (tt @ (a - a.mean(axis=0))) / float(tt @ tt)
        trend = float(np.sum(slopes**2) * float(tt @ tt)) / total
    rms = float(math.sqrt(float(np.mean(a**2))))
    robust_rms = float(math.sqrt(np.mean((1.4826 * np.median(np.abs(a), axis=0)) ** 2)))
    return KindCheck(
        rms,
        robust_rms,
        floor,
        spread,
        lag1,
        p_lb,
        float(z),
        outliers,
        trend,
        white_p,
        float(white_z),
        dt,
        *band,
        white_band,
    )


def andrews_bandwidth(rho: float, n: int) -> int:
    """Newey–West lags S for AR(1) residuals with lag-1 autocorrelation ``rho`` (module doc)."""
    rho = min(max(rho, 0.0), 0.999)
    if rho <= 0.0:
        return 1
    alpha = 4.0 * rho**2 / ((1.0 - rho) ** 2 * (1.0 + rho) ** 2)
    return int(min(max(1, math.ceil(BANDWIDTH * 1.1447 * (alpha * n) ** (1.0 / 3.0))), n - 1))


def scores(jac: FloatArray, r: FloatArray, sample: FloatArray, n: int) -> FloatArray:
    """g_i = Σ over the residual rows of sample i of J_rowᵀ r_row: (n, unknowns)."""
    weighted = jac * r[:, None]
    return np.stack(
        [np.bincount(sample, weights=weighted[:, j], minlength=n) for j in range(jac.shape[1])], 1
    )


def newey_west(g: FloatArray, lags: int) -> FloatArray:
    """Ω = Σ_{L=−S}^{S} (1 − |L|/(S+1)) Γ_L of the scores ``g`` (n, k) (module doc)."""
    n, k = g.shape
    lags = int(min(lags, max(1, MAX_LAG_WORK // max(n * k * k, 1)), n - 1))
    omega = g.T @ g
    for lag in range(1, lags + 1):
        gamma = g[:-lag].T @ g[lag:]
        omega += (1.0 - lag / (lags + 1.0)) * (gamma + gamma.T)
    return omega


def prewhitened_newey_west(g: FloatArray, n: int) -> FloatArray:
    """Ω of the scores ``g`` (n, k) after prewhitening them by one AR(1) coefficient (module doc)."""
    lagged, now = g[:-1], g[1:]
    denom = np.sum(lagged * lagged, axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        a = np.where(denom > 0.0, np.sum(now * lagged, axis=0) / denom, 0.0)
    common = float(np.clip(np.median(a), 0.0, MAX_SCORE_AR))
    e = now - common * lagged
    rho_e = float(np.mean([autocorrelations(e[:, k], 1)[0] for k in range(e.shape[1])]))
    return newey_west(e, andrews_bandwidth(rho_e, n)) * (n / (n - 1.0)) / (1.0 - common) ** 2


def inflation(
    jac: FloatArray, r: FloatArray, sample: FloatArray, n: int, rho: float, cov: FloatArray, keep: FloatArray
) -> FloatArray:
    """Per unknown, max(1, √(C_sandwich,ii / C_ii)) for the determined ones (``keep``; 1 elsewhere):
    how much correlated residuals widen the classical error bars ``cov``."""
    out = np.ones(jac.shape[1])
    idx = np.flatnonzero(keep)
    if idx.size == 0:
        return out
    j = jac[:, idx]
    a = j.T @ j
    if not np.all(np.isfinite(a)):
        return out
    try:
        a_inv = np.linalg.pinv(a, rcond=1e-14)
    except np.linalg.LinAlgError:
        return out
    g = scores(j, r, sample, n)
    omega = newey_west(g, andrews_bandwidth(rho, n))
    variance = np.diag(a_inv @ omega @ a_inv)
    if rho >= PREWHITEN:
        variance = np.maximum(variance, np.diag(a_inv @ prewhitened_newey_west(g, n) @ a_inv))
    classical = np.diag(cov)[idx]
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = variance / classical
    ratio = np.where(np.isfinite(ratio), ratio, 1.0)
    out[idx] = np.sqrt(np.maximum(ratio, 1.0))
    return out


def _band(c: KindCheck) -> str:
    """The band scan's clause of a finding, where it alarms (empty otherwise)."""
    if c.band_p >= P_ALARM:
        return ""
    return (
        f"; its power near {c.band_hz:.3g} Hz is {c.band_ratio:.3g}x that of the rest of its spectrum, "
        f"p = {c.band_p:.2g}"
    )


def misfit(checks: Mapping[str, KindCheck], chi2_p: float | None) -> bool:
    """Whether the residual has structure that noise does not explain: correlated but not correlated
    noise (whatever its size: a small systematic effect counts), far above the noise floor, or an
    improbable χ² with σ given — the verdicts (:meth:`KindCheck.verdict`) whose findings name a misfit
    or a small systematic effect. Noise-free data fitted to round-off never do."""
    if any(c.verdict() in MISFIT_VERDICTS for c in checks.values()):
        return True
    return chi2_p is not None and chi2_p < P_ALARM


def ar1_rho(checks: Mapping[str, KindCheck]) -> float:
    """The largest lag-1 autocorrelation of the kinds whose residual is AR(1) noise (else 0): for χ²."""
    return max((c.lag1 for c in checks.values() if c.verdict() == "ar1_noise"), default=0.0)


def findings(
    checks: Mapping[str, KindCheck], chi2_p: float | None, chi2: float, dof: int, robust: bool = False
) -> list[str]:
    """Plain-language findings: what looks wrong and what to try (empty when nothing does). With a
    ``robust`` loss the residual's size is its robust spread (1.4826 · median |r|) and outliers are
    not reported: the loss already discounts them."""
    out: list[str] = []
    for kind, c in checks.items():
        verdict = c.verdict(robust)
        if verdict == "exact":
            continue  # noise-free data fitted to round-off: nothing to test
        size = c.robust_rms if robust else c.rms
        ratio = c.size_ratio(robust)
        if verdict == "unexplained":
            out.append(
                f"{kind}: the fitted motion explains only {100 * max(c.explained, 0.0):.0f} % of the data's "
                f"variance (residual rms {c.rms:.3g} against a spread of {c.spread:.3g}): the data may not "
                "show a pendulum's swing above their noise, or the model or the starting values are far off"
            )
            continue
        if verdict == "ar1_noise":
            tau = -c.dt / math.log(c.lag1) if 0.0 < c.lag1 < 1.0 and c.dt > 0.0 else math.inf
            out.append(
                f"{kind}: the residual is correlated noise (lag-1 autocorrelation {c.lag1:.3f}, correlation "
                f"time {tau:.3g} s; with its AR(1) part removed it is white by the Ljung-Box, runs and "
                "band tests), "
                "as video tracking or a filter makes, not a misfit: the error bars are widened for it "
                "(res.inflation), and the noise floor read off the data underestimates it"
            )
        elif verdict == "systematic":
            drift = " with a slow drift over the record" if c.trend > 0.2 else ""
            out.append(
                f"{kind}: the fit misses the data systematically{drift}: the residual (rms {size:.3g}, "
                f"{ratio:.3g}x the data's noise floor {c.floor:.3g}) is correlated (lag-1 autocorrelation "
                f"{c.lag1:.3f}, runs test z = {c.runs_z:.1f}{_band(c)}). Either the model lacks something "
                "(another damping law: fit 'friction' or 'drag'; a sensor offset or bias; a moving pivot; "
                "wind; a wrong scale or time base), or the noise itself is correlated (video tracking, "
                "filtering). The error bars are widened for the correlation, but values may be biased by "
                "what is missing; see res.plot()"
            )
        elif verdict == "correlated":
            out.append(
                f"{kind}: the residual is correlated (lag-1 autocorrelation {c.lag1:.3f}, runs test "
                f"z = {c.runs_z:.1f}{_band(c)}) though no larger than the data's noise floor "
                f"({c.floor:.3g}): correlated noise (video tracking, filtering), or a small systematic "
                "effect the model lacks (a sensor bias: fit force_bias, rate_bias or angle_offset; a damping "
                "law: fit 'friction' or 'drag' and compare, pl.compare_fits); the error bars are widened for "
                "the correlation (and by the record's blocks where they disagree)"
            )
        elif verdict == "above_floor":
            out.append(
                f"{kind}: the residual rms {size:.3g} is {ratio:.3g}x the noise floor {c.floor:.3g} "
                "read off the data: a misfit, or noise that is not white"
            )
        n = c.outliers
        if n >= 3 and not robust:
            out.append(
                f"{kind}: {n} values lie more than {OUTLIER_SIGMAS:g} robust standard deviations from "
                "the fit (outliers?): try loss='soft_l1'"
            )
    if chi2_p is not None and chi2_p < P_ALARM and not robust:
        out.append(
            f"the fitted motion misses the data by {math.sqrt(chi2 / dof):.3g}x their given noise: chi2 = "
            f"{chi2:.6g} for {dof} degrees of freedom (chi2/dof = {chi2 / dof:.3g}) is improbable for a "
            f"right model (p = {chi2_p:.2g}): a model that lacks something (damping, drag, a moving "
            "pivot), a sigma too small, or a local minimum (try other starting values); see res.plot()"
        )
    elif chi2_p is not None and chi2_tails(chi2, dof, ar1_rho(checks))[1] < P_ALARM:
        out.append(
            f"chi2/dof = {chi2 / dof:.3g} is improbably small for {dof} degrees of freedom: the given "
            "sigma is too large, so the error bars are too"
        )
    return out
