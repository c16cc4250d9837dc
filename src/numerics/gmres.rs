//! GMRES with a right preconditioner, no restart (Saad & Schultz 1986; Saad, *Iterative
//! Methods for Sparse Linear Systems*, 2nd ed., 2003, Algorithm 9.5): the Krylov step of
//! an inexact Newton method whose preconditioner is an earlier Jacobian's LU factors.
//! Right preconditioning (A M⁻¹ u = b, x = M⁻¹u) makes the quantity GMRES minimises the
//! true residual ‖b − A x‖₂, so the stopping test is on the system actually solved.
//! Arnoldi by modified Gram–Schmidt, the least-squares problem by Givens rotations.

/// What one GMRES solve did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GmresOutcome {
    /// Krylov iterations (products with A) taken.
    pub iterations: usize,
    /// ‖b − A x‖₂ / ‖b‖₂ at the end (the Givens estimate, exact in exact arithmetic).
    pub relative_residual: f64,
    /// Whether `relative_residual` reached the tolerance.
    pub converged: bool,
}

/// Scratch for [`gmres`], reused across calls (the basis is the large part:
/// (max_iterations + 1) × n).
#[derive(Debug, Default, Clone)]
pub struct GmresWork {
    basis: Vec<f64>,
    hessenberg: Vec<f64>,
    cosines: Vec<f64>,
    sines: Vec<f64>,
    g: Vec<f64>,
    w: Vec<f64>,
}

/// Solve A x = b to ‖b − A x‖ ≤ `tolerance`·‖b‖ in at most `max_iterations` Krylov
/// iterations, from x = 0. `apply(v, out)` sets out = A v; `precondition(v)` replaces v by
/// M⁻¹v and returns `None` if it cannot (then the solve stops, not converged). `x` gets
/// the best iterate found (also when not converged).
pub fn gmres(
    mut apply: impl FnMut(&[f64], &mut [f64]),
    mut precondition: impl FnMut(&mut [f64]) -> Option<()>,
    b: &[f64],
    x: &mut [f64],
    tolerance: f64,
    max_iterations: usize,
    work: &mut GmresWork,
) -> GmresOutcome {
    let n = b.len();
    x.iter_mut().for_each(|v| *v = 0.0);
    let beta = norm(b);
    let mut outcome = GmresOutcome {
        iterations: 0,
        relative_residual: 1.0,
        converged: false,
    };
    if beta == 0.0 {
        outcome.relative_residual = 0.0;
        outcome.converged = true;
        return outcome;
    }
    if !beta.is_finite() || max_iterations == 0 {
        return outcome;
    }
    let k_max = max_iterations;
    let GmresWork {
        basis,
        hessenberg: h,
        cosines,
        sines,
        g,
        w,
    } = work;
    basis.resize((k_max + 1) * n, 0.0);
    h.resize((k_max + 1) * k_max, 0.0);
    cosines.resize(k_max, 0.0);
    sines.resize(k_max, 0.0);
    g.clear();
    g.resize(k_max + 1, 0.0);
    w.resize(n, 0.0);
    // Column j of H is h[j*(k_max+1) ..]: H is (k_max+1) × k_max, stored by columns.
    let ld = k_max + 1;
    for (v, bi) in basis[..n].iter_mut().zip(b) {
        *v = bi / beta;
    }
    g[0] = beta;
    let mut k = 0;
    while k < k_max {
        let (done, next) = basis.split_at_mut((k + 1) * n);
        // z = M⁻¹ v_k, w = A z.
        let z = &mut next[..n];
        z.copy_from_slice(&done[k * n..]);
        if precondition(z).is_none() {
            break;
        }
        apply(z, w);
        let col = &mut h[k * ld..(k + 1) * ld];
        for (i, hi) in col.iter_mut().enumerate().take(k + 1) {
            let vi = &done[i * n..(i + 1) * n];
            let d: f64 = w.iter().zip(vi).map(|(a, b)| a * b).sum();
            *hi = d;
            w.iter_mut().zip(vi).for_each(|(a, b)| *a -= d * b);
        }
        let wn = norm(w);
        col[k + 1] = wn;
        if !wn.is_finite() {
            break;
        }
        if wn > 0.0 {
            z.iter_mut().zip(w.iter()).for_each(|(v, a)| *v = a / wn);
        }
        // Earlier rotations on the new column, then the one that zeroes H[k+1][k].
        for i in 0..k {
            let (c, s) = (cosines[i], sines[i]);
            let (a, b) = (col[i], col[i + 1]);
            col[i] = c * a + s * b;
            col[i + 1] = -s * a + c * b;
        }
        let (a, b) = (col[k], col[k + 1]);
        let r = a.hypot(b);
        let (c, s) = if r == 0.0 { (1.0, 0.0) } else { (a / r, b / r) };
        cosines[k] = c;
        sines[k] = s;
        col[k] = r;
        col[k + 1] = 0.0;
        g[k + 1] = -s * g[k];
        g[k] *= c;
        k += 1;
        outcome.relative_residual = g[k].abs() / beta;
        if outcome.relative_residual <= tolerance || wn == 0.0 {
            outcome.converged = outcome.relative_residual <= tolerance;
            break;
        }
    }
    outcome.iterations = k;
    if k == 0 {
        return outcome;
    }
    // y = R⁻¹ g (R the rotated H's upper triangle), u = V y, x = M⁻¹ u.
    for i in (0..k).rev() {
        let mut s = g[i];
        for j in i + 1..k {
            s -= h[j * ld + i] * g[j];
        }
        let d = h[i * ld + i];
        g[i] = if d == 0.0 { 0.0 } else { s / d };
    }
    for (j, yj) in g.iter().enumerate().take(k) {
        let vj = &basis[j * n..(j + 1) * n];
        x.iter_mut().zip(vj).for_each(|(a, b)| *a += yj * b);
    }
    if precondition(x).is_none() {
        x.iter_mut().for_each(|v| *v = 0.0);
        outcome.converged = false;
    }
    outcome
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|a| a * a).sum::<f64>().sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matvec(a: &[f64], v: &[f64], out: &mut [f64]) {
        let n = v.len();
        for (i, o) in out.iter_mut().enumerate() {
            *o = (0..n).map(|j| a[i * n + j] * v[j]).sum();
        }
    }

    /// A non-symmetric, diagonally dominant matrix: unpreconditioned GMRES reaches the
    /// tolerance, and its x satisfies A x = b to it (checked with an independent product);
    /// with the exact inverse of the diagonal as M the same solve takes fewer iterations.
    #[test]
    fn solves_a_nonsymmetric_system_to_the_tolerance() {
        let n = 60;
        let mut a = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                a[i * n + j] = 0.3 / (1.0 + (i as f64 - 2.0 * j as f64).abs());
            }
            a[i * n + i] += 2.0 + i as f64;
        }
        let b: Vec<f64> = (0..n).map(|i| (i as f64).cos()).collect();
        let mut x = vec![0.0; n];
        let mut work = GmresWork::default();
        let plain = gmres(
            |v, o| matvec(&a, v, o),
            |_| Some(()),
            &b,
            &mut x,
            1e-12,
            n,
            &mut work,
        );
        assert!(plain.converged, "{plain:?}");
        let mut ax = vec![0.0; n];
        matvec(&a, &x, &mut ax);
        let err = ax
            .iter()
            .zip(&b)
            .map(|(p, q)| (p - q).powi(2))
            .sum::<f64>()
            .sqrt();
        assert!(err <= 1e-11 * norm(&b), "{err}");
        let diag: Vec<f64> = (0..n).map(|i| a[i * n + i]).collect();
        let jacobi = gmres(
            |v, o| matvec(&a, v, o),
            |v| {
                v.iter_mut().zip(&diag).for_each(|(x, d)| *x /= d);
                Some(())
            },
            &b,
            &mut x,
            1e-12,
            n,
            &mut work,
        );
        assert!(
            jacobi.converged && jacobi.iterations < plain.iterations,
            "{jacobi:?} vs {plain:?}"
        );
        matvec(&a, &x, &mut ax);
        let err = ax
            .iter()
            .zip(&b)
            .map(|(p, q)| (p - q).powi(2))
            .sum::<f64>()
            .sqrt();
        assert!(err <= 1e-11 * norm(&b), "{err}");
    }

    /// Too few iterations: reported as not converged, with the residual reached.
    #[test]
    fn reports_a_solve_that_did_not_converge() {
        let n = 40;
        let a: Vec<f64> = (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                if i == j {
                    1.0 + i as f64
                } else {
                    0.05
                }
            })
            .collect();
        let b = vec![1.0; n];
        let mut x = vec![0.0; n];
        let out = gmres(
            |v, o| matvec(&a, v, o),
            |_| Some(()),
            &b,
            &mut x,
            1e-14,
            3,
            &mut GmresWork::default(),
        );
        assert!(
            !out.converged && out.iterations == 3 && out.relative_residual < 1.0,
            "{out:?}"
        );
    }
}
