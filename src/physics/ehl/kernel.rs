//! The line-contact elastic kernel (seed 003 eq. 9 with no Y dependence: a roller long
//! against the contact width, side leakage and end effects neglected as the seed does).
//!
//! The combined normal surface displacement of two elastic half-spaces under a pressure
//! strip p(s) is (Johnson, *Contact Mechanics*, 1985, eq. 2.25, summed over both bodies)
//!
//!   Δ(x) = −(4/(πE′)) ∫ p(s) ln|x − s| ds + const,   E′ = 2E*.
//!
//! In Hertz-scaled variables X = x/b, P = p/p_H, H = hR/b² (b, p_H the Hertz half-width
//! and peak pressure of the same load) the coefficient 4 p_H R/(E′ b) is exactly 1, so
//!
//!   Δ̄(X) = −(1/π) ∫ P(X′) ln|X − X′| dX′ + const.
//!
//! With P piecewise constant over elements of width ΔX centred on the nodes, the integral
//! is exact: ∫ ln|t| dt = t ln|t| − t =: F(t), so the influence of node j on node i is
//!   K_{ij} = −(1/π) [F(X_i − X_j + ΔX/2) − F(X_i − X_j − ΔX/2)],
//! which depends on |i − j| only (F is odd): a symmetric Toeplitz matrix stored as one
//! row. The constant (ln b, the far-field reference) is absorbed into the film constant
//! h₀ of the load balance.

use crate::numerics::dense_lu::dot;

/// F(t) = t ln|t| − t, with its limit F(0) = 0.
fn f(t: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * t.abs().ln() - t
    }
}

/// The Toeplitz row K_m = K_{i, i±m}, m = 0 … n − 1, of the Hertz-scaled line kernel on a
/// uniform grid of step `dx` (in half-widths): the deflection at a node per unit scaled
/// pressure on an element m nodes away.
pub fn line_kernel(n: usize, dx: f64) -> Vec<f64> {
    (0..n)
        .map(|m| {
            let t = m as f64 * dx;
            -(f(t + 0.5 * dx) - f(t - 0.5 * dx)) / std::f64::consts::PI
        })
        .collect()
}

/// Deflection Δ̄_i = Σ_j K_{|i−j|} P_j: the dense direct product, O(n²). At n ≤ 1601 this
/// is ≤ 2.6·10⁶ multiply-adds, negligible beside the Newton solve's dense factorisation
/// (O(n³)), so DC-FFT would not change the solve time (the factorisation dominates).
pub fn deflection(kernel: &[f64], pressure: &[f64], out: &mut [f64]) {
    deflection_symmetric(&symmetric_row(kernel), pressure, out);
}

/// The Toeplitz row written out both ways, S_{n−1+d} = K_{|d|} for d = −(n−1) … n−1, so
/// that row i of the kernel matrix is the contiguous run S[n−1−i .. 2n−1−i]: products
/// with it vectorise (an index |i − j| per term does not).
pub fn symmetric_row(kernel: &[f64]) -> Vec<f64> {
    kernel
        .iter()
        .skip(1)
        .rev()
        .chain(kernel.iter())
        .copied()
        .collect()
}

/// [`deflection`] with the row of [`symmetric_row`]: Δ̄_i = S[n−1−i ..]·P.
pub fn deflection_symmetric(symmetric: &[f64], pressure: &[f64], out: &mut [f64]) {
    let n = pressure.len();
    for (i, o) in out.iter_mut().enumerate().take(n) {
        *o = dot(&symmetric[n - 1 - i..2 * n - 1 - i], pressure);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Hertz pressure P = √(1 − X²) gives, inside |X| < 1, the deflection
    /// Δ̄ = const − X²/2 (the film H₀ + X²/2 + Δ̄ is flat in the Hertz zone: Johnson
    /// eq. 4.44). Its curvature from the discrete kernel must be −1 to within the
    /// discretisation error of piecewise-constant elements on 801 nodes (tolerance 1 %
    /// of the central drop over |X| ≤ 0.8).
    #[test]
    fn hertz_pressure_deflects_as_a_parabola_inside_the_contact() {
        let n = 801;
        let (x0, x1) = (-2.0, 2.0);
        let dx = (x1 - x0) / (n - 1) as f64;
        let x: Vec<f64> = (0..n).map(|i| x0 + i as f64 * dx).collect();
        let p: Vec<f64> = x.iter().map(|&x| (1.0 - x * x).max(0.0).sqrt()).collect();
        let k = line_kernel(n, dx);
        let mut d = vec![0.0; n];
        deflection(&k, &p, &mut d);
        let centre = n / 2;
        for (i, xi) in x.iter().enumerate() {
            if xi.abs() <= 0.8 {
                let drop = d[centre] - d[i];
                let expected = 0.5 * xi * xi;
                assert!(
                    (drop - expected).abs() <= 0.01 * 0.5 * 0.64,
                    "X = {xi}: drop {drop}, expected {expected}"
                );
            }
        }
    }

    /// The kernel row is the exact integral: compare one entry with a fine midpoint sum.
    #[test]
    fn kernel_entry_is_the_exact_integral_of_the_log() {
        let dx = 0.1;
        let k = line_kernel(4, dx);
        for (m, km) in k.iter().enumerate() {
            let t = m as f64 * dx;
            let steps = 200_000;
            let h = dx / steps as f64;
            // Midpoint rule avoids the log singularity at m = 0.
            let s: f64 = (0..steps)
                .map(|q| {
                    let s = t - 0.5 * dx + (q as f64 + 0.5) * h;
                    s.abs().ln() * h
                })
                .sum();
            let expected = -s / std::f64::consts::PI;
            assert!((km - expected).abs() < 1e-6, "m = {m}: {km} vs {expected}");
        }
    }

    /// The vectorised product is the Toeplitz sum Σ_j K_{|i−j|} P_j written out, to
    /// round-off (1e-14 of the largest term: only the order of the additions differs).
    #[test]
    fn symmetric_row_product_is_the_toeplitz_sum() {
        let n = 37;
        let k = line_kernel(n, 0.05);
        let p: Vec<f64> = (0..n).map(|j| (j as f64 * 0.3).sin().abs()).collect();
        let mut fast = vec![0.0; n];
        deflection(&k, &p, &mut fast);
        let scale = k.iter().fold(0.0f64, |a, v| a.max(v.abs())) * n as f64;
        for (i, v) in fast.iter().enumerate() {
            let direct: f64 = (0..n).map(|j| k[i.abs_diff(j)] * p[j]).sum();
            assert!((v - direct).abs() <= 1e-14 * scale, "{i}: {v} vs {direct}");
        }
    }
}
