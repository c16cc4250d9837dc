//! The cage angle's sine and cosine for the right-hand side (issue 25, Speed): one
//! `sin_cos` per evaluation was ≈ 10 % of the film-off run (two libm calls, each with
//! its full argument reduction). Here ω_c·t is reduced by Cody–Waite on a grid of
//! Δ = 2π/256, a = kΔ + r with |r| ≤ Δ/2 ≈ 0.0123, and
//! (sin a, cos a) = rotation of the tabulated (sin kΔ, cos kΔ) by Taylor series of
//! sin r, cos r (truncation below 1e-20): within a few ulps of `f64::sin_cos`
//! (tested), a pure function of the angle, no branch on the hot path below 16 384 rad.

use std::f64::consts::PI;

/// Grid points per turn.
const TABLE: usize = 256;
/// 1/Δ = 128/π.
const INV_DELTA: f64 = 128.0 / PI;
/// Δ = π/128 split as D_HI + D_LO: D_HI keeps Δ's top 33 bits, so k·D_HI is exact for
/// |k| < 2^20; D_LO = (π/128 − D_HI) + π_lo/128 (π_lo = π − fl(π)).
const D_HI: f64 = f64::from_bits((PI / 128.0).to_bits() & !((1u64 << 20) - 1));
const PI_LO: f64 = 1.224_646_799_147_353_2e-16;
const D_LO: f64 = (PI / 128.0 - D_HI) + PI_LO / 128.0;
/// |a| beyond which `f64::sin_cos` is used (k stays below 2^20 well inside it).
const FAST_LIMIT: f64 = 16_384.0;
/// 1.5·2^52 (rounds to an integer held in the low mantissa bits).
const ROUND: f64 = 6_755_399_441_055_744.0;

/// (sin kΔ, cos kΔ) for k = 0..256.
#[derive(Debug, Clone)]
pub(crate) struct AngleTable {
    sin_cos: Vec<(f64, f64)>,
}

impl AngleTable {
    pub(crate) fn new() -> Self {
        // The first quadrant at x_i = i·D_HI (exact) corrected by i·D_LO to first order
        // (second order < 1e-20), the others by exact sign changes and swaps.
        let quadrant: Vec<(f64, f64)> = (0..=TABLE / 4)
            .map(|i| {
                let (s, c) = (i as f64 * D_HI).sin_cos();
                let lo = i as f64 * D_LO;
                (s + c * lo, c - s * lo)
            })
            .collect();
        let sin_cos = (0..TABLE)
            .map(|k| {
                let (q, i) = (k / (TABLE / 4), k % (TABLE / 4));
                let (s, c) = quadrant[i];
                match q {
                    0 => (s, c),
                    1 => (c, -s),
                    2 => (-s, -c),
                    _ => (-c, s),
                }
            })
            .collect();
        AngleTable { sin_cos }
    }

    /// (sin a, cos a).
    #[inline(always)]
    pub(crate) fn sin_cos(&self, a: f64) -> (f64, f64) {
        if !(a.abs() < FAST_LIMIT) {
            return a.sin_cos();
        }
        let kr = a * INV_DELTA + ROUND;
        let k = kr - ROUND;
        let r = (a - k * D_HI) - k * D_LO;
        // k mod 256 from the low mantissa bits (two's complement for k < 0: 2^51 + k,
        // and 2^51 is a multiple of 256).
        let idx = (kr.to_bits() as usize) & (TABLE - 1);
        let (sk, ck) = self.sin_cos.get(idx).copied().unwrap_or((0.0, 1.0));
        let r2 = r * r;
        // sin r = r − r³/3! + … − r¹¹/11!... to r⁹/9!; cos r to r⁸/8!; |r| ≤ 0.0123.
        let sr = r
            * (1.0
                + r2 * (-1.0 / 6.0
                    + r2 * (1.0 / 120.0 + r2 * (-1.0 / 5040.0 + r2 * (1.0 / 362_880.0)))));
        let cr =
            1.0 + r2 * (-0.5 + r2 * (1.0 / 24.0 + r2 * (-1.0 / 720.0 + r2 * (1.0 / 40_320.0))));
        (sk * cr + ck * sr, ck * cr - sk * sr)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tabulated_sin_cos_is_libms() {
        // Over the angles the dynamics meets (ω_c·t up to 1000 s at 83 rad/s and
        // beyond the fast range), densely and at the grid points and half-way: within
        // 4e-16 absolute of `f64::sin_cos` (≤ 2 ulps of 1 for the table, the rotation's
        // two products and sum, and libm's own half ulp).
        let table = AngleTable::new();
        let mut worst: f64 = 0.0;
        let mut check = |a: f64| {
            let (s, c) = table.sin_cos(a);
            let (s0, c0) = a.sin_cos();
            let e = (s - s0).abs().max((c - c0).abs());
            worst = worst.max(e);
            assert!(e <= 4e-16, "{a}: ({s}, {c}) vs ({s0}, {c0})");
        };
        for j in 0..2_000_000 {
            check(-50.0 + 1e-4 * f64::from(j) * 1.000_000_7);
        }
        for k in -4096..4096 {
            let a = f64::from(k) * (PI / 128.0);
            check(a);
            check(a + PI / 256.0);
            check(a - PI / 256.0);
        }
        for a in [0.0, 1e-300, -1e-20, 8.3e4, 16_383.9, 16_384.0, 1e7, -3e5] {
            check(a);
        }
        eprintln!("worst absolute difference {worst:e}");
    }
}
