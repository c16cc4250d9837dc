//! Dense LU factorisation with partial pivoting, row-major, blocked so that almost all of
//! its work is one matrix product per panel (LAPACK's right-looking `dgetrf`: Golub & Van
//! Loan, *Matrix Computations*, 4th ed., 2013, Algorithm 3.4.2 with the row exchanges of
//! §3.4.3). The trailing update A₂₂ ← A₂₂ − L₂₁U₁₂ goes through nalgebra's `gemm`, which
//! hands views of this size to `matrixmultiply`'s cache-blocked, SIMD kernel (selected at
//! run time): measured 402 × 402 (the line-EHL Newton matrix at 401 nodes) in about a
//! tenth of the unblocked elimination's time (see `benches/line_ehl.rs`).
//!
//! The factors are stored as LAPACK stores them: the unit lower factor's multipliers
//! below the diagonal, U on and above it, every row exchange applied to whole rows (so
//! the solve applies all exchanges to the right-hand side first). The pivots are the
//! unblocked elimination's (the same largest-magnitude rule column by column); only the
//! order of the floating-point operations differs.

use nalgebra::{DMatrixView, DMatrixViewMut};

/// Panel width: the trailing product has inner dimension `BLOCK`; 32–64 keeps the panel
/// (m × BLOCK, ≤ 0.2 MB at m = 1602) in L2 while giving the product enough depth.
const BLOCK: usize = 48;

/// Below this order the unblocked elimination is as fast (the product's setup dominates).
const UNBLOCKED_BELOW: usize = 96;

/// Factorise the row-major m × m matrix `a` in place; the row exchanges go to `piv`
/// (`piv[k]` is the row swapped with row k at step k). `None` when a pivot is zero or not
/// finite (the matrix is singular to working precision, or carries NaN/∞).
pub fn lu_factor(a: &mut [f64], piv: &mut [usize], m: usize) -> Option<()> {
    if a.len() != m * m || piv.len() < m || a.iter().any(|v| !v.is_finite()) {
        return None;
    }
    if m < UNBLOCKED_BELOW {
        return lu_factor_unblocked(a, piv, m);
    }
    let mut l21 = Vec::with_capacity(m * BLOCK);
    let mut k0 = 0;
    while k0 < m {
        let kb = BLOCK.min(m - k0);
        let k1 = k0 + kb;
        // The panel: columns k0..k1 of rows k0..m, eliminated column by column; each
        // exchange moves whole rows (the trailing columns follow their row).
        for k in k0..k1 {
            let p = pivot_row(a, m, k)?;
            piv[k] = p;
            if p != k {
                swap_rows(a, m, k, p);
            }
            let (top, rest) = a.split_at_mut((k + 1) * m);
            let pivot = &top[k * m..(k + 1) * m];
            let d = pivot[k];
            for row in rest.chunks_exact_mut(m) {
                let f = row[k] / d;
                row[k] = f;
                if f != 0.0 {
                    for (x, y) in row[k + 1..k1].iter_mut().zip(&pivot[k + 1..k1]) {
                        *x -= f * y;
                    }
                }
            }
        }
        if k1 == m {
            break;
        }
        // U₁₂ = L₁₁⁻¹ A₁₂ (unit lower triangular, forward substitution by rows).
        for k in k0..k1 {
            let (top, rest) = a.split_at_mut((k + 1) * m);
            let pivot = &top[k * m + k1..(k + 1) * m];
            for row in rest.chunks_exact_mut(m).take(k1 - k - 1) {
                let f = row[k];
                if f != 0.0 {
                    for (x, y) in row[k1..].iter_mut().zip(pivot) {
                        *x -= f * y;
                    }
                }
            }
        }
        // A₂₂ ← A₂₂ − L₂₁ U₁₂: L₂₁ copied out (it shares rows with A₂₂), U₁₂ read in place.
        let rows = m - k1;
        l21.clear();
        for r in k1..m {
            l21.extend_from_slice(&a[r * m + k0..r * m + k1]);
        }
        let (top, rest) = a.split_at_mut(k1 * m);
        let u12 = DMatrixView::from_slice_with_strides(&top[k0 * m + k1..], kb, rows, m, 1);
        let l = DMatrixView::from_slice_with_strides(&l21, rows, kb, kb, 1);
        let mut a22 =
            DMatrixViewMut::from_slice_with_strides_mut(&mut rest[k1..], rows, rows, m, 1);
        a22.gemm(-1.0, &l, &u12, 1.0);
        k0 = k1;
    }
    // A zero or non-finite last pivot (the loop checks each pivot before using it, the
    // final diagonal entry included).
    let last = a[m * m - 1];
    (last != 0.0 && last.is_finite()).then_some(())
}

/// The row (≥ k) of the largest |a[·][k]|; `None` when that is zero or not finite.
fn pivot_row(a: &[f64], m: usize, k: usize) -> Option<usize> {
    let mut p = k;
    let mut best = a[k * m + k].abs();
    for r in k + 1..m {
        let v = a[r * m + k].abs();
        if v > best {
            best = v;
            p = r;
        }
    }
    (best > 0.0 && best.is_finite()).then_some(p)
}

fn swap_rows(a: &mut [f64], m: usize, k: usize, p: usize) {
    let (lo, hi) = (k.min(p), k.max(p));
    let (top, rest) = a.split_at_mut(hi * m);
    top[lo * m..(lo + 1) * m].swap_with_slice(&mut rest[..m]);
}

/// The unblocked elimination (the reference the blocked one is tested against, and the
/// small-matrix path).
pub fn lu_factor_unblocked(a: &mut [f64], piv: &mut [usize], m: usize) -> Option<()> {
    if a.len() != m * m || piv.len() < m || a.iter().any(|v| !v.is_finite()) {
        return None;
    }
    for k in 0..m {
        let p = pivot_row(a, m, k)?;
        piv[k] = p;
        if p != k {
            swap_rows(a, m, k, p);
        }
        let (top, rest) = a.split_at_mut((k + 1) * m);
        let pivot_row = &top[k * m..(k + 1) * m];
        let d = pivot_row[k];
        for row in rest.chunks_exact_mut(m) {
            let f = row[k] / d;
            row[k] = f;
            if f != 0.0 {
                for (x, y) in row[k + 1..].iter_mut().zip(&pivot_row[k + 1..]) {
                    *x -= f * y;
                }
            }
        }
    }
    Some(())
}

/// Solve with the factors of [`lu_factor`]: `b` is overwritten by x. `None` if x is not
/// finite.
pub fn lu_solve(a: &[f64], piv: &[usize], b: &mut [f64], m: usize) -> Option<()> {
    // The exchanges moved the stored multipliers along with the rows (LAPACK's layout),
    // so all of them apply to b first. Both substitutions then go by rows: a row-major
    // matrix read along its rows, with a four-way dot product, rather than down its
    // columns (a cache line per element: measured as half the line-EHL warm step).
    for (k, p) in piv.iter().enumerate().take(m) {
        b.swap(k, *p);
    }
    for k in 1..m {
        let (done, rest) = b.split_at_mut(k);
        rest[0] -= dot(&a[k * m..k * m + k], done);
    }
    for k in (0..m).rev() {
        let row = &a[k * m..(k + 1) * m];
        let s = dot(&row[k + 1..], &b[k + 1..]);
        b[k] = (b[k] - s) / row[k];
    }
    b.iter().all(|v| v.is_finite()).then_some(())
}

/// x·y with four partial sums (lets the compiler use SIMD; the order of the additions
/// changes the result at round-off only).
pub fn dot(x: &[f64], y: &[f64]) -> f64 {
    let mut acc = [0.0; 4];
    let (xc, xr) = x.split_at(x.len() - x.len() % 4);
    for (a, b) in xc.chunks_exact(4).zip(y.chunks_exact(4)) {
        for l in 0..4 {
            acc[l] += a[l] * b[l];
        }
    }
    let mut s = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    for (a, b) in xr.iter().zip(&y[xc.len()..]) {
        s += a * b;
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic, non-symmetric test matrix whose elimination needs row exchanges
    /// (small diagonal), of the line-EHL Newton matrix's kind: a dense logarithmic part
    /// plus a banded part.
    fn matrix(m: usize) -> Vec<f64> {
        let mut a = vec![0.0; m * m];
        let mut s: u64 = 12345;
        for i in 0..m {
            for j in 0..m {
                s = s
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let noise = (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
                let d = i.abs_diff(j) as f64 + 0.5;
                a[i * m + j] = -d.ln() / 3.0 + 0.3 * noise;
            }
            a[i * m + i] *= 1e-3;
            if i + 1 < m {
                a[i * m + i + 1] += 2.0;
            }
        }
        a
    }

    fn residual(a: &[f64], x: &[f64], b: &[f64], m: usize) -> f64 {
        (0..m)
            .map(|i| {
                let ax: f64 = (0..m).map(|j| a[i * m + j] * x[j]).sum();
                (ax - b[i]).abs()
            })
            .fold(0.0, f64::max)
    }

    /// The blocked factors solve A x = b to round-off (backward error ≤ 1e-10 of ‖b‖∞ at
    /// m = 402, the line-EHL size, whose condition number here is ≈ 10⁴), pick the same
    /// pivots as the unblocked elimination, and agree with its solution to 1e-9.
    #[test]
    fn blocked_factors_agree_with_the_unblocked_elimination() {
        for m in [7, 95, 96, 97, 150, 402] {
            let a = matrix(m);
            let b: Vec<f64> = (0..m).map(|i| (i as f64 * 0.37).sin() + 1.0).collect();
            let (mut f1, mut p1) = (a.clone(), vec![0; m]);
            let (mut f2, mut p2) = (a.clone(), vec![0; m]);
            lu_factor(&mut f1, &mut p1, m).unwrap();
            lu_factor_unblocked(&mut f2, &mut p2, m).unwrap();
            assert_eq!(p1, p2, "m = {m}: pivots");
            let mut x1 = b.clone();
            let mut x2 = b.clone();
            lu_solve(&f1, &p1, &mut x1, m).unwrap();
            lu_solve(&f2, &p2, &mut x2, m).unwrap();
            let scale = b.iter().fold(0.0f64, |s, v| s.max(v.abs()));
            assert!(residual(&a, &x1, &b, m) <= 1e-10 * scale, "m = {m}");
            let xs = x2.iter().fold(0.0f64, |s, v| s.max(v.abs()));
            for (u, v) in x1.iter().zip(&x2) {
                assert!((u - v).abs() <= 1e-9 * xs, "m = {m}: {u} vs {v}");
            }
        }
    }

    /// A singular matrix (two equal rows) and a NaN are refused, not factorised.
    #[test]
    fn singular_and_nan_matrices_are_refused() {
        for m in [5, 200] {
            let mut a = matrix(m);
            let row: Vec<f64> = a[..m].to_vec();
            a[m..2 * m].copy_from_slice(&row);
            let mut piv = vec![0; m];
            assert!(lu_factor(&mut a, &mut piv, m).is_none(), "m = {m}");
            let mut a = matrix(m);
            a[3 * m + 1] = f64::NAN;
            assert!(lu_factor(&mut a, &mut piv, m).is_none(), "m = {m}: NaN");
        }
    }
}
