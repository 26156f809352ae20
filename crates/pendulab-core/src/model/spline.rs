//! A pivot path given as samples (times t_i \[s\], positions p_i \[m\]): the C² cubic spline through them
//! with not-a-knot end conditions (the third derivative is continuous at t₁ and t_{n−1}, as in
//! SciPy's `CubicSpline` default), one per coordinate. It gives the pivot's velocity ṗ [m/s] and the
//! acceleration p̈ [m/s²] that enters the moving-pivot equation ẍ = −g e₃ − p̈(t) + λx (T-7.2).
//!
//! With h_i = t_{i+1} − t_i, d_i = (p_{i+1} − p_i)/h_i and M_i = p̈(t_i), continuity of ṗ gives
//!   h_{i−1} M_{i−1} + 2(h_{i−1} + h_i) M_i + h_i M_{i+1} = 6(d_i − d_{i−1}),   i = 1 … n−1,
//! and not-a-knot M₀ = (1 + h₀/h₁) M₁ − (h₀/h₁) M₂ (likewise at the right end), eliminated into the
//! first and last rows of a tridiagonal system solved by the Thomas algorithm. On [t_i, t_{i+1}], with
//! A = (t_{i+1} − t)/h_i, B = 1 − A:
//!   p = A p_i + B p_{i+1} + ((A³ − A) M_i + (B³ − B) M_{i+1}) h_i²/6,
//!   ṗ = d_i + ((1 − 3A²) M_i + (3B² − 1) M_{i+1}) h_i/6,   p̈ = A M_i + B M_{i+1}.
//! The spline reproduces cubics exactly; for a smooth path sampled every h, p̈ is accurate to O(h²).
//! Outside [t₀, t_n] the end pieces are extended (cubic extrapolation): a run must stay inside (the
//! Python layer checks it), but higher-order compositions such as `rattle4` evaluate the force
//! slightly before t₀ in their first step (the triple jump's backward substep), and a path that
//! stopped dead there would cost them their order.
//!
//! Rejected: fewer than 4 samples, non-finite values, times not strictly increasing, and a
//! positions array whose length differs from the times'.

use crate::error::{Error, Result};
use glam::DVec3;

/// The not-a-knot cubic spline through (t_i, p_i) (see the module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct PivotSamples {
    t: Vec<f64>,
    p: Vec<DVec3>,
    m: Vec<DVec3>,
    /// The inner samples where p⃛ = (M_{i+1} − M_i)/h_i steps: every one in general; not where it is
    /// exactly continuous (a pivot at rest, a sampled straight line).
    kinks: Vec<f64>,
}

fn bad(reason: String) -> Error {
    Error::InvalidPivotSamples { reason }
}

impl PivotSamples {
    /// The spline through `times` \[s\] (≥ 4, finite, strictly increasing) and `positions` \[m\].
    pub fn new(times: &[f64], positions: &[DVec3]) -> Result<Self> {
        if times.len() != positions.len() {
            return Err(bad(format!("{} times but {} positions", times.len(), positions.len())));
        }
        let n = times.len();
        if n < 4 {
            return Err(bad(format!("{n} samples; a cubic spline with not-a-knot ends needs at least 4")));
        }
        if let Some(i) = times.iter().position(|t| !t.is_finite()) {
            return Err(bad(format!("time {i} is {}, not a finite number of seconds", times[i])));
        }
        if let Some(i) = positions.iter().position(|p| !p.is_finite()) {
            return Err(bad(format!("position {i} is {}, not three finite numbers (m)", positions[i])));
        }
        if let Some(i) = times.windows(2).position(|w| w[1] <= w[0]) {
            return Err(bad(format!(
                "times must be strictly increasing, but t[{i}] = {} s is followed by t[{}] = {} s",
                times[i],
                i + 1,
                times[i + 1]
            )));
        }
        let h: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
        let d: Vec<DVec3> = (0..n - 1).map(|i| (positions[i + 1] - positions[i]) / h[i]).collect();
        // unknowns M_1 … M_{n−2} (k = i − 1); rows (sub, diag, sup, rhs)
        let k = n - 2;
        let mut sub = vec![0.0; k];
        let mut diag = vec![0.0; k];
        let mut sup = vec![0.0; k];
        let mut rhs = vec![DVec3::ZERO; k];
        for r in 0..k {
            let i = r + 1;
            sub[r] = h[i - 1];
            diag[r] = 2.0 * (h[i - 1] + h[i]);
            sup[r] = h[i];
            rhs[r] = (d[i] - d[i - 1]) * 6.0;
        }
        let (h0, h1) = (h[0], h[1]);
        diag[0] += h0 + h0 * h0 / h1;
        sup[0] -= h0 * h0 / h1;
        let (ha, hb) = (h[n - 3], h[n - 2]);
        diag[k - 1] += hb + hb * hb / ha;
        sub[k - 1] -= hb * hb / ha;
        // Thomas algorithm
        for r in 1..k {
            let w = sub[r] / diag[r - 1];
            diag[r] -= w * sup[r - 1];
            rhs[r] = rhs[r] - rhs[r - 1] * w;
        }
        let mut inner = vec![DVec3::ZERO; k];
        inner[k - 1] = rhs[k - 1] / diag[k - 1];
        for r in (0..k - 1).rev() {
            inner[r] = (rhs[r] - inner[r + 1] * sup[r]) / diag[r];
        }
        let mut m = Vec::with_capacity(n);
        m.push(inner[0] * (1.0 + h0 / h1) - inner[1.min(k - 1)] * (h0 / h1));
        m.extend_from_slice(&inner);
        m.push(inner[k - 1] * (1.0 + hb / ha) - inner[k.saturating_sub(2)] * (hb / ha));
        let jerk = |i: usize| (m[i + 1] - m[i]) / h[i];
        let kinks = (1..n - 1).filter(|&i| jerk(i - 1) != jerk(i)).map(|i| times[i]).collect();
        Ok(Self { t: times.to_vec(), p: positions.to_vec(), m, kinks })
    }

    /// The sampled interval [t₀, t_n] \[s\].
    pub fn span(&self) -> (f64, f64) {
        (self.t[0], self.t[self.t.len() - 1])
    }

    /// The first kink of p̈ later than `t` \[s\] by more than round-off of t (+∞ after the last): an
    /// inner sample where the slope of p̈, p⃛, steps, so an adaptive step should end there rather than
    /// cross it ([`crate::model::Model::next_break`]). A kink within 64 ulp of t counts as reached.
    pub fn next_kink_after(&self, t: f64) -> f64 {
        let reached = t + 64.0 * f64::EPSILON * t.abs() + 1e3 * f64::MIN_POSITIVE;
        let i = self.kinks.partition_point(|&ti| ti <= reached);
        self.kinks.get(i).copied().unwrap_or(f64::INFINITY)
    }

    /// The index i of the piece [t_i, t_{i+1}] that holds t \[s\]; outside the span the end piece.
    pub fn piece_at(&self, t: f64) -> usize {
        self.t.partition_point(|&ti| ti <= t).clamp(1, self.t.len() - 1) - 1
    }

    /// (index i, A, h_i) of the piece for t; outside the span the end piece (extrapolated).
    fn locate(&self, t: f64) -> (usize, f64, f64) {
        self.on_piece(t, self.piece_at(t))
    }

    /// (i, A, h_i) of piece i evaluated at t, also outside [t_i, t_{i+1}] (its cubic continued).
    fn on_piece(&self, t: f64, i: usize) -> (usize, f64, f64) {
        let h = self.t[i + 1] - self.t[i];
        (i, (self.t[i + 1] - t) / h, h)
    }

    /// p(t) \[m\].
    pub fn position(&self, t: f64) -> DVec3 {
        let (i, a, h) = self.locate(t);
        let b = 1.0 - a;
        self.p[i] * a
            + self.p[i + 1] * b
            + (self.m[i] * (a * a * a - a) + self.m[i + 1] * (b * b * b - b)) * (h * h / 6.0)
    }

    /// ṗ(t) [m/s].
    pub fn velocity(&self, t: f64) -> DVec3 {
        let (i, a, h) = self.locate(t);
        let b = 1.0 - a;
        (self.p[i + 1] - self.p[i]) / h
            + (self.m[i] * (1.0 - 3.0 * a * a) + self.m[i + 1] * (3.0 * b * b - 1.0)) * (h / 6.0)
    }

    /// p̈(t) [m/s²].
    pub fn acceleration(&self, t: f64) -> DVec3 {
        self.acceleration_of(self.locate(t))
    }

    /// p̈ [m/s²] at t \[s\] of piece `piece` (from [`PivotSamples::piece_at`]), its cubic continued
    /// beyond [t_i, t_{i+1}]: the smooth force a fixed step between two kinks needs even where its
    /// stages reach past them (the RATTLE compositions' substeps, [`crate::model::Model::smooth_piece`]).
    /// Inside the piece it is [`PivotSamples::acceleration`] bit for bit.
    pub fn acceleration_on_piece(&self, t: f64, piece: usize) -> DVec3 {
        self.acceleration_of(self.on_piece(t, piece.min(self.t.len() - 2)))
    }

    #[inline(always)]
    fn acceleration_of(&self, (i, a, _): (usize, f64, f64)) -> DVec3 {
        self.m[i] * a + self.m[i + 1] * (1.0 - a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_a_cubic_exactly_on_an_uneven_grid() {
        let f = |t: f64| DVec3::new(t * t * t - 2.0 * t, 0.5 * t * t, 3.0 - t);
        let df = |t: f64| DVec3::new(3.0 * t * t - 2.0, t, -1.0);
        let ddf = |t: f64| DVec3::new(6.0 * t, 1.0, 0.0);
        let ts = [0.0, 0.3, 0.5, 1.1, 1.2, 2.0];
        let s = PivotSamples::new(&ts, &ts.map(f)).unwrap();
        for t in [0.0, 0.1, 0.45, 0.9, 1.15, 1.7, 2.0] {
            assert!((s.position(t) - f(t)).length() < 1e-13, "p at {t}");
            assert!((s.velocity(t) - df(t)).length() < 1e-12, "v at {t}");
            assert!((s.acceleration(t) - ddf(t)).length() < 1e-11, "a at {t}");
        }
    }

    #[test]
    fn acceleration_converges_like_h_squared() {
        let err = |n: usize| {
            let ts: Vec<f64> = (0..=n).map(|k| 3.0 * k as f64 / n as f64).collect();
            let ps: Vec<DVec3> = ts.iter().map(|t| DVec3::new(t.cos(), t.sin(), 0.0)).collect();
            let s = PivotSamples::new(&ts, &ps).unwrap();
            (0..300)
                .map(|k| k as f64 * 0.01)
                .map(|t| (s.acceleration(t) + DVec3::new(t.cos(), t.sin(), 0.0)).length())
                .fold(0.0, f64::max)
        };
        let (a, b) = (err(50), err(100));
        assert!(a / b > 3.6 && a / b < 4.4, "{a:e} -> {b:e}");
    }

    #[test]
    fn bad_samples_are_refused() {
        let p = [DVec3::ZERO; 4];
        let e = |t: &[f64], p: &[DVec3]| PivotSamples::new(t, p).unwrap_err().to_string();
        assert!(e(&[0.0, 1.0, 2.0], &p[..3]).contains("at least 4"));
        assert!(e(&[0.0, 1.0, 1.0, 2.0], &p).contains("strictly increasing"));
        assert!(e(&[0.0, 2.0, 1.0, 3.0], &p).contains("strictly increasing"));
        assert!(e(&[0.0, f64::NAN, 1.0, 3.0], &p).contains("finite"));
        let mut q = p;
        q[2].y = f64::INFINITY;
        assert!(e(&[0.0, 1.0, 2.0, 3.0], &q).contains("position 2"));
        assert!(e(&[0.0, 1.0, 2.0], &p).contains("3 times but 4 positions"));
    }
}
