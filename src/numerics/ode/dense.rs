//! Dense output over one accepted step, and the bracketing root finder that
//! locates events on it.
//!
//! Both methods express their continuous extension in the nested form used by
//! Hairer's DOPRI5 code,
//!
//! ```text
//! y(t + θh) = r1 + θ (r2 + (1−θ) (r3 + θ (r4 + (1−θ) r5))),
//! ```
//!
//! where `r1..r4` alone are the cubic Hermite interpolant through
//! `(y0, h·f0)` and `(y1, h·f1)`, and `r5` is DOPRI5's fourth-order correction
//! (zero for the Hermite cubic). One evaluation routine therefore serves both.
//! DOP853's seventh-order extension continues the same nesting with `r6..r8`:
//! `… r4 + (1−θ) (r5 + θ (r6 + (1−θ) (r7 + θ r8)))` (Hairer's `contd8`).

/// Continuous extension of the numerical solution over `[t, t + h]`.
#[derive(Debug, Clone)]
pub(crate) struct Interpolant {
    t: f64,
    h: f64,
    r1: Vec<f64>,
    r2: Vec<f64>,
    r3: Vec<f64>,
    r4: Vec<f64>,
    r5: Vec<f64>,
    r6: Vec<f64>,
    r7: Vec<f64>,
    r8: Vec<f64>,
    /// Whether `r6..r8` are in use (DOP853).
    high: bool,
}

impl Interpolant {
    /// Storage for a system of dimension `n`.
    pub(crate) fn new(n: usize) -> Self {
        Interpolant {
            t: 0.0,
            h: 0.0,
            r1: vec![0.0; n],
            r2: vec![0.0; n],
            r3: vec![0.0; n],
            r4: vec![0.0; n],
            r5: vec![0.0; n],
            r6: vec![0.0; n],
            r7: vec![0.0; n],
            r8: vec![0.0; n],
            high: false,
        }
    }

    /// Fill the Hermite part `r1..r4` from the step end points and their slopes,
    /// and set `r5 = 0`. DOPRI5 then overwrites `r5` with its correction.
    pub(crate) fn set_hermite(
        &mut self,
        t: f64,
        h: f64,
        y0: &[f64],
        y1: &[f64],
        f0: &[f64],
        f1: &[f64],
    ) {
        self.t = t;
        self.h = h;
        self.high = false;
        let it = self
            .r1
            .iter_mut()
            .zip(self.r2.iter_mut())
            .zip(self.r3.iter_mut())
            .zip(self.r4.iter_mut())
            .zip(self.r5.iter_mut());
        for (((((r1, r2), r3), r4), r5), (((&a, &b), &fa), &fb)) in
            it.zip(y0.iter().zip(y1).zip(f0).zip(f1))
        {
            let dy = b - a;
            let bspl = h * fa - dy;
            *r1 = a;
            *r2 = dy;
            *r3 = bspl;
            *r4 = dy - h * fb - bspl;
            *r5 = 0.0;
        }
    }

    /// Mutable access to the quartic correction term (used by DOPRI5).
    pub(crate) fn r5_mut(&mut self) -> &mut [f64] {
        &mut self.r5
    }

    /// Mutable access to `r5..r8` of DOP853's extension (after `set_hermite`).
    pub(crate) fn high_mut(&mut self) -> (&mut [f64], &mut [f64], &mut [f64], &mut [f64]) {
        self.high = true;
        (&mut self.r5, &mut self.r6, &mut self.r7, &mut self.r8)
    }

    /// Evaluate the interpolant at time `t_out` into `out`.
    ///
    /// Callers only ask for times inside the step; outside it the polynomial is an
    /// extrapolation and loses its accuracy, but nothing breaks.
    pub(crate) fn eval(&self, t_out: f64, out: &mut [f64]) {
        let theta = if self.h == 0.0 {
            0.0
        } else {
            (t_out - self.t) / self.h
        };
        let theta1 = 1.0 - theta;
        if self.high {
            let it = self
                .r1
                .iter()
                .zip(&self.r2)
                .zip(&self.r3)
                .zip(&self.r4)
                .zip(self.r5.iter().zip(&self.r6).zip(&self.r7).zip(&self.r8));
            for (o, ((((r1, r2), r3), r4), (((r5, r6), r7), r8))) in out.iter_mut().zip(it) {
                let tail = r5 + theta * (r6 + theta1 * (r7 + theta * r8));
                *o = r1 + theta * (r2 + theta1 * (r3 + theta * (r4 + theta1 * tail)));
            }
            return;
        }
        let it = self
            .r1
            .iter()
            .zip(&self.r2)
            .zip(&self.r3)
            .zip(&self.r4)
            .zip(&self.r5);
        for (o, ((((r1, r2), r3), r4), r5)) in out.iter_mut().zip(it) {
            *o = r1 + theta * (r2 + theta1 * (r3 + theta * (r4 + theta1 * r5)));
        }
    }
}

/// Upper bound on root-finder iterations. Brent's method needs at most about
/// `log2(width/tol)^2` evaluations in the worst case and typically ~10; the bound
/// only guarantees termination if the event function misbehaves (NaN, noise).
const MAX_ROOT_ITERATIONS: usize = 200;

/// Find a root of `f` in the bracket `[a, b]` by Brent's method (inverse quadratic
/// interpolation and secant steps safeguarded by bisection; R. P. Brent,
/// *Algorithms for Minimization without Derivatives*, 1973, ch. 4).
///
/// Requires `fa = f(a)` and `fb = f(b)` of opposite sign. The returned point lies
/// in the closed bracket and is within about `1e-13·max(|a|, |b|, |b−a|)` plus a few
/// ulps of a sign change of `f`. Brent rather than plain Illinois because it keeps
/// a guaranteed bracket reduction even for badly scaled event functions.
pub(crate) fn brent<F: FnMut(f64) -> f64>(
    mut f: F,
    a_in: f64,
    b_in: f64,
    fa_in: f64,
    fb_in: f64,
) -> f64 {
    let lo = a_in.min(b_in);
    let hi = a_in.max(b_in);
    let xtol = 1e-13 * a_in.abs().max(b_in.abs()).max((b_in - a_in).abs());
    let (mut a, mut b, mut fa, mut fb) = (a_in, b_in, fa_in, fb_in);
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    // `c` is the point that brackets the root together with `b`; `b` is the best
    // estimate so far, `a` the previous `b`. `d` is the last step, `e` the one before.
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..MAX_ROOT_ITERATIONS {
        if (fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * xtol;
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 || fb == 0.0 {
            break;
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                // Only two distinct points: secant step.
                p = 2.0 * xm * s;
                q = 1.0 - s;
            } else {
                // Inverse quadratic interpolation through a, b, c.
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * xm * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            // Accept the interpolation only if it stays well inside the bracket and
            // shrinks faster than bisection would; otherwise bisect.
            if 2.0 * p < (3.0 * xm * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(xm) };
        fb = f(b);
    }
    // Guards against a NaN-producing event function walking out of the step.
    if b.is_nan() {
        return hi;
    }
    b.clamp(lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_reproduces_cubic_exactly() {
        // y = t^3 - 2t + 1 on [0.5, 1.5]: a cubic is reproduced exactly by the
        // Hermite interpolant, so any error above rounding is a formula bug.
        let y = |t: f64| t * t * t - 2.0 * t + 1.0;
        let dy = |t: f64| 3.0 * t * t - 2.0;
        let mut ip = Interpolant::new(1);
        ip.set_hermite(0.5, 1.0, &[y(0.5)], &[y(1.5)], &[dy(0.5)], &[dy(1.5)]);
        let mut out = [0.0];
        for k in 0..=10 {
            let t = 0.5 + 0.1 * f64::from(k);
            ip.eval(t, &mut out);
            assert!(
                (out[0] - y(t)).abs() < 1e-14,
                "t={t}: {} vs {}",
                out[0],
                y(t)
            );
        }
    }

    #[test]
    fn brent_finds_roots_to_tolerance() {
        // cos has a simple root at pi/2; the tolerance 1e-13 relative is what the
        // event locator promises.
        let r = brent(f64::cos, 1.0, 2.0, 1f64.cos(), 2f64.cos());
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-13 * 2.0);
        // Reversed bracket (backward integration) and a flat, badly scaled function.
        let g = |t: f64| (t - 0.3).powi(3) * 1e-20;
        let r = brent(g, 1.0, 0.0, g(1.0), g(0.0));
        // Only the sign of g matters to a bracketing method, and it flips exactly
        // at 0.3, so the triple root is found as precisely as a simple one.
        assert!((r - 0.3).abs() < 1e-12, "r={r}");
    }

    #[test]
    fn brent_survives_nan() {
        let r = brent(|_| f64::NAN, 0.0, 1.0, -1.0, 1.0);
        assert!((0.0..=1.0).contains(&r));
    }
}
