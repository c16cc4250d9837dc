//! The film-off right-hand side's roller loop as structure-of-arrays passes (issue 25,
//! Speed): θ_i's sine and cosine by rotation, δ_i = ½(x cos θ_i + y sin θ_i) − C, and
//! W_i = k δ₊^(10/9) with δ^(1/9) by [`ninth_root_branch_free`], branch-free and without
//! a table, so that the compiler vectorises each pass across the rollers (the generic
//! x86-64 target has SSE2: two lanes per instruction, no FMA) and the rollers'
//! independent chains overlap instead of each waiting on a table lookup.

/// 1.5·2^52: adding it rounds a float of magnitude < 2^51 to an integer held in the low
/// mantissa bits.
const ROUND: f64 = 6_755_399_441_055_744.0;
/// m^(1/9) on m ∈ [1, 2] in powers of u = m − 1.5: the Chebyshev fit of degree 6
/// (relative error 1.3e-7, computed with NumPy's `chebfit` at 200 Chebyshev nodes).
const Q: [f64; 7] = [
    1.046_081_934_380_345_8,
    0.077_489_032_648_491,
    -0.022_961_263_068_229_196,
    0.009_590_638_524_167_814,
    -0.004_601_184_808_725_2,
    0.002_765_179_664_982_042_5,
    -0.001_546_153_001_072_525_5,
];
/// 2^f = e^(f ln 2) on f ∈ [−½, ½] by its Taylor series to degree 6 (remainder below
/// (½ ln 2)^7/7! = 1.2e-7).
const P: [f64; 7] = [
    1.0,
    std::f64::consts::LN_2,
    0.240_226_506_959_100_7,
    0.055_504_108_664_821_58,
    0.009_618_129_107_628_477,
    0.001_333_355_814_642_844_3,
    0.000_154_035_303_933_816_1,
];

/// x^(1/9) for x ≥ f64::MIN_POSITIVE (normal, finite) without branches or tables:
/// x = 2^e·m (m ∈ [1, 2)), e/9 = k + f with k the nearest integer, a first guess
/// y₀ = 2^k·P(f)·Q(m) within 2.5e-7, then one Halley step for y⁹ = x,
/// y₁ = y₀(8y₀⁹ + 10x)/(10y₀⁹ + 8x), whose error 6.7·ε³ ≈ 1e-19 leaves the rounding of
/// its five operations: within 1e-15 of the lamina law's `ninth_root` (tested).
#[inline(always)]
pub(crate) fn ninth_root_branch_free(x: f64) -> f64 {
    let bits = x.to_bits();
    // The biased exponent as a float: its 11 bits placed in 2^52's mantissa.
    let e =
        f64::from_bits(0x4330_0000_0000_0000 | (bits >> 52)) - (4_503_599_627_370_496.0 + 1023.0);
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    let v = e * (1.0 / 9.0);
    let kr = v + ROUND;
    let k = kr - ROUND;
    let f = v - k;
    // 2^k from k's integer bits (|k| ≤ 114: a normal power of two).
    let scale = f64::from_bits((kr.to_bits().wrapping_add(1023)) << 52);
    let p = P[0] + f * (P[1] + f * (P[2] + f * (P[3] + f * (P[4] + f * (P[5] + f * P[6])))));
    let u = m - 1.5;
    let q = Q[0] + u * (Q[1] + u * (Q[2] + u * (Q[3] + u * (Q[4] + u * (Q[5] + u * Q[6])))));
    let y0 = scale * (p * q);
    let y2 = y0 * y0;
    let y4 = y2 * y2;
    let y9 = y4 * y4 * y0;
    // Halley's factor as a ratio of terms ≤ 0.9·max(x, y⁹): no overflow near f64::MAX,
    // no underflow of y₀·(…) near the smallest normals.
    y0 * ((0.4 * y9 + 0.5 * x) / (0.5 * y9 + 0.4 * x))
}

/// Rollers per block of the lane loop: one elementwise loop over a block with a run-time
/// trip count, which the compiler's loop vectoriser turns into two-lane SSE2 (a fixed
/// trip count of 4 was unrolled first and vectorised worse: 98 against ~85
/// instructions per roller, callgrind), then the block's sums in roller order.
const BLOCK: usize = 16;

/// Σ W_i cos θ_i, Σ W_i sin θ_i and Σ W_i (y cos θ_i − x sin θ_i) over the rollers
/// whose phases' sines and cosines are `sp`, `cp` (equal lengths), for W = k δ₊^(10/9),
/// δ = ½(x cos θ + y sin θ) − C and θ = θ_i + ω_c t given by (s0, c0) = sin, cos ω_c t.
///
/// With θ_i = φ_i + ω_c t, cos θ_i = c0·cos φ_i − s0·sin φ_i and sin θ_i = s0·cos φ_i +
/// c0·sin φ_i, so x cos θ_i + y sin θ_i = A·cos φ_i + B·sin φ_i and y cos θ_i − x sin θ_i
/// = B·cos φ_i − A·sin φ_i with A = x c0 + y s0 and B = y c0 − x s0, the same for every
/// roller: each roller costs δ_i = A′·cos φ_i + B′·sin φ_i − C (A′ = A/2, B′ = B/2) and
/// the two sums S_c = Σ W_i cos φ_i, S_s = Σ W_i sin φ_i, from which
/// Σ W cos θ = c0·S_c − s0·S_s, Σ W sin θ = s0·S_c + c0·S_s and
/// Σ W (y cos θ − x sin θ) = B·S_c − A·S_s (the same sums regrouped: within rounding
/// of the roller-by-roller form, tested).
#[allow(clippy::too_many_arguments)] // the hot loop's scalars, each distinct
#[inline]
pub(crate) fn dry_sums_ten_ninths(
    sp: &[f64],
    cp: &[f64],
    k: f64,
    clearance: f64,
    x: f64,
    y: f64,
    s0: f64,
    c0: f64,
) -> [f64; 3] {
    let a = x * c0 + y * s0;
    let b = y * c0 - x * s0;
    let (ah, bh) = (0.5 * a, 0.5 * b);
    let (mut sum_c, mut sum_s) = (0.0, 0.0);
    for (sg, cg) in sp.chunks(BLOCK).zip(cp.chunks(BLOCK)) {
        let nb = sg.len().min(cg.len()).min(BLOCK);
        let (sg, cg) = (&sg[..nb], &cg[..nb]);
        let mut wc = [0.0; BLOCK];
        let mut ws = [0.0; BLOCK];
        for l in 0..nb {
            let dl = ah * cg[l] + bh * sg[l] - clearance;
            // δ₊, and the root's argument kept normal (a separated roller's load is
            // then k·0·(finite) = 0; a subnormal δ < 2.2e-308 m loads nothing either).
            let d = if dl > 0.0 { dl } else { 0.0 };
            let arg = if dl > f64::MIN_POSITIVE {
                dl
            } else {
                f64::MIN_POSITIVE
            };
            let w = k * (d * ninth_root_branch_free(arg));
            wc[l] = w * cg[l];
            ws[l] = w * sg[l];
        }
        sum_c += wc[..nb].iter().sum::<f64>();
        sum_s += ws[..nb].iter().sum::<f64>();
    }
    [
        c0 * sum_c - s0 * sum_s,
        s0 * sum_c + c0 * sum_s,
        b * sum_c - a * sum_s,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::contact::lamina_law::ninth_root;

    #[test]
    fn the_branch_free_ninth_root_is_the_lamina_laws() {
        // Against `ninth_root` (itself within 8e-16 of the correctly rounded value): over
        // the whole normal range in steps of 1/64 of an octave and through every exponent
        // residue, and densely over the dynamics' deflections 1e-12..1e-4 m: within
        // 1e-15 relative (the Halley step's five roundings plus `ninth_root`'s own).
        let mut worst: f64 = 0.0;
        let mut check = |x: f64| {
            let r = ninth_root_branch_free(x);
            let e = (r / ninth_root(x) - 1.0).abs();
            worst = worst.max(e);
            assert!(e <= 1e-15, "{x:e}: {r:e} vs {:e}", ninth_root(x));
        };
        for e in -1022..=1023 {
            for j in 0..64 {
                check(2f64.powi(e) * (1.0 + f64::from(j) / 64.0));
            }
        }
        for j in 0..=200_000 {
            check(1e-12 * 1e8f64.powf(f64::from(j) / 200_000.0));
        }
        check(f64::MIN_POSITIVE);
        check(f64::MAX);
        eprintln!("worst relative difference {worst:e}");
    }

    #[test]
    fn the_lane_loop_is_the_scalar_loop() {
        // W = k δ₊^(10/9) summed over 12 and 13 rollers (a tail of one) at states that
        // unload some rollers: the same sums as a plain loop with `ninth_root` to 1e-14
        // relative of the largest term (the lanes sum in another order).
        use std::f64::consts::TAU;
        for m in [12usize, 13] {
            let (sp, cp): (Vec<f64>, Vec<f64>) = (0..m)
                .map(|i| (TAU * i as f64 / m as f64).sin_cos())
                .unzip();
            for (x, y, t) in [(-8e-6, 1e-7, 0.0), (-1.5e-5, 3e-6, 0.3), (0.0, 0.0, 1.0)] {
                let (k, clearance) = (2.0e9, -2e-6);
                let (s0, c0) = (83.26f64 * t).sin_cos();
                let got = dry_sums_ten_ninths(&sp, &cp, k, clearance, x, y, s0, c0);
                let mut want = [0.0; 3];
                let mut big: f64 = 0.0;
                for i in 0..m {
                    let (s, c) = (s0 * cp[i] + c0 * sp[i], c0 * cp[i] - s0 * sp[i]);
                    let d = 0.5 * (x * c + y * s) - clearance;
                    if d > 0.0 {
                        let w = k * d * ninth_root(d);
                        want[0] += w * c;
                        want[1] += w * s;
                        want[2] += w * (y * c - x * s);
                        big = big.max(w);
                    }
                }
                // The regrouped sums round like the roller-by-roller ones: within 1e-14
                // of the largest roller term (|W|, and |W|·|r| for the third).
                let r = x.hypot(y);
                for j in 0..3 {
                    let scale = if j == 2 { big * r } else { big };
                    assert!(
                        (got[j] - want[j]).abs() <= 1e-14 * scale.max(1e-300) * m as f64,
                        "{m} {j}: {got:?} vs {want:?}"
                    );
                }
            }
        }
    }
}
