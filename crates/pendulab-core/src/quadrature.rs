//! Adaptive Gauss–Kronrod quadrature (7-point Gauss, 15-point Kronrod; Piessens et al., QUADPACK,
//! 1983, routine QK15), used where an integral must be computed independently of the elliptic
//! integrals that give it in closed form (e.g. the area of the reduced orbit for the geometric phase,
//! T-5.1). Dimensionless: the caller supplies units.
//!
//! On [a, b] with centre c and half-width h: K15 = h Σ wₖ f(c + h xₖ) (exact for polynomials of
//! degree ≤ 22), G7 on every second node (degree ≤ 13); |K15 − G7| estimates the error. Intervals
//! are bisected until the estimate is below max(abs_tol, rel_tol·|total|) for their share.

/// Kronrod nodes on [0, 1) (symmetric about 0; the last is the centre).
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights for XGK.
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// Gauss weights for the nodes XGK[1], XGK[3], XGK[5], XGK[7].
const WG: [f64; 4] =
    [0.129_484_966_168_869_7, 0.279_705_391_489_276_7, 0.381_830_050_505_118_9, 0.417_959_183_673_469_4];

/// One K15/G7 panel: (Kronrod estimate, |Kronrod − Gauss|).
fn panel(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    let fc = f(c);
    let (mut k, mut g) = (WGK[7] * fc, WG[3] * fc);
    for i in 0..7 {
        let s = f(c - h * XGK[i]) + f(c + h * XGK[i]);
        k += WGK[i] * s;
        if i % 2 == 1 {
            g += WG[i / 2] * s;
        }
    }
    (k * h, ((k - g) * h).abs())
}

/// ∫ₐᵇ f to max(abs_tol, rel_tol·|∫|), bisecting at most `max_depth` times in any place.
/// Returns (estimate, estimated error).
pub fn integrate(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, rel_tol: f64, abs_tol: f64) -> (f64, f64) {
    let (whole, err) = panel(&mut f, a, b);
    let mut stack = vec![(a, b, whole, err, 0u32)];
    let (mut total, mut total_err) = (0.0, 0.0);
    let scale = whole.abs();
    while let Some((lo, hi, value, err, depth)) = stack.pop() {
        let share = (hi - lo) / (b - a);
        let tol = abs_tol.max(rel_tol * scale) * share.abs().sqrt();
        if err <= tol || depth >= 60 || err <= 1e-3 * f64::EPSILON * value.abs() {
            total += value;
            total_err += err;
            continue;
        }
        let mid = 0.5 * (lo + hi);
        let (l, el) = panel(&mut f, lo, mid);
        let (r, er) = panel(&mut f, mid, hi);
        stack.push((lo, mid, l, el, depth + 1));
        stack.push((mid, hi, r, er, depth + 1));
    }
    (total, total_err)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_panel_is_exact_for_polynomials_of_degree_22() {
        // A typo in a node or weight breaks this.
        for n in 0..=22 {
            let (k, _) = panel(&mut |x: f64| x.powi(n), 0.0, 1.0);
            let exact = 1.0 / f64::from(n + 1);
            assert!((k - exact).abs() < 4e-16, "degree {n}: {k} vs {exact}");
        }
        let (k, _) = panel(&mut |x: f64| x.powi(24), -1.0, 1.0);
        assert!((k - 2.0 / 25.0).abs() > 1e-12, "K15 should not be exact at degree 24");
    }

    #[test]
    fn gauss_part_is_exact_for_degree_13() {
        for n in 0..=13 {
            let (k, e) = panel(&mut |x: f64| x.powi(n), 0.0, 1.0);
            assert!(e < 1e-15, "degree {n}: |K − G| = {e:e}, K = {k}");
        }
    }

    #[test]
    fn adaptive_handles_a_sharp_feature() {
        // ∫₀¹ x²/(w + x²) dx = 1 − √w atan(1/√w) with w = 1e-10: a step of width 1e-5 at 0.
        let w: f64 = 1e-10;
        let (v, _) = integrate(|x| x * x / (w + x * x), 0.0, 1.0, 1e-14, 0.0);
        let exact = 1.0 - w.sqrt() * (1.0 / w.sqrt()).atan();
        assert!((v - exact).abs() < 1e-13, "{v} vs {exact}");
    }
}
