//! Monotone piecewise-cubic Hermite interpolation (Fritsch–Carlson, SIAM J. Numer. Anal.
//! 17 (1980) 238–246), used by the tabulated curves of `subsurface` and `life`.
//!
//! A monotone scheme is used because the tabulated quantities are monotone between
//! their turning points (the life factor against film parameter everywhere, the
//! subsurface stresses against ellipse ratio piecewise) and an ordinary cubic spline can
//! overshoot between knots, which would invent a life factor above the curve's plateau
//! or a spurious wiggle in a stress. Slopes are the Fritsch–Butland weighted harmonic
//! means (the "pchip" choice), which satisfy the Fritsch–Carlson monotonicity region;
//! at a local extremum of the data the slope is zero, so extrema are not overshot.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

/// Knots and slopes of a monotone cubic Hermite interpolant, `y(x)` dimensionless.
#[derive(Debug, Clone, PartialEq)]
pub struct MonotoneCubic {
    x: Vec<f64>,
    y: Vec<f64>,
    slope: Vec<f64>,
}

impl MonotoneCubic {
    /// Builds the interpolant through `(x[i], y[i])`. Returns `None` unless there are at
    /// least two knots, `x` is strictly increasing, and every value is finite.
    pub fn new(x: Vec<f64>, y: Vec<f64>) -> Option<Self> {
        let n = x.len();
        if n < 2 || y.len() != n || x.iter().chain(y.iter()).any(|v| !v.is_finite()) {
            return None;
        }
        if x.windows(2).any(|w| w[1] <= w[0]) {
            return None;
        }
        // Secant slopes of each interval.
        let delta: Vec<f64> = (0..n - 1)
            .map(|i| (y[i + 1] - y[i]) / (x[i + 1] - x[i]))
            .collect();
        let mut slope = vec![0.0; n];
        // Fritsch–Butland weighted harmonic mean at interior knots: zero where the
        // data turn, so the interpolant never overshoots (the Fritsch–Carlson condition
        // α² + β² ≤ 9 holds by construction).
        for i in 1..n - 1 {
            let (d0, d1) = (delta[i - 1], delta[i]);
            if d0 * d1 > 0.0 {
                let h0 = x[i] - x[i - 1];
                let h1 = x[i + 1] - x[i];
                let w0 = 2.0 * h1 + h0;
                let w1 = h1 + 2.0 * h0;
                slope[i] = (w0 + w1) / (w0 / d0 + w1 / d1);
            }
        }
        // One-sided three-point end slopes, limited to keep monotonicity.
        slope[0] = end_slope(
            x[1] - x[0],
            x.get(2).map_or(0.0, |x2| x2 - x[1]),
            delta[0],
            delta.get(1).copied(),
        );
        slope[n - 1] = end_slope(
            x[n - 1] - x[n - 2],
            if n > 2 { x[n - 2] - x[n - 3] } else { 0.0 },
            delta[n - 2],
            if n > 2 { Some(delta[n - 3]) } else { None },
        );
        Some(MonotoneCubic { x, y, slope })
    }

    /// Interpolated value at `x`; constant extrapolation beyond the end knots (the
    /// callers' curves are flat outside their range by definition).
    pub fn eval(&self, x: f64) -> f64 {
        let n = self.x.len();
        if x.is_nan() {
            return self.y[0];
        }
        if x <= self.x[0] {
            return self.y[0];
        }
        if x >= self.x[n - 1] {
            return self.y[n - 1];
        }
        // Binary search for the interval: tables are short, this is cheaper than a
        // hash and keeps the call allocation-free.
        let i = match self.x.partition_point(|&xi| xi <= x) {
            0 => 0,
            p => (p - 1).min(n - 2),
        };
        let h = self.x[i + 1] - self.x[i];
        let t = (x - self.x[i]) / h;
        let t2 = t * t;
        let t3 = t2 * t;
        let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
        let h10 = t3 - 2.0 * t2 + t;
        let h01 = -2.0 * t3 + 3.0 * t2;
        let h11 = t3 - t2;
        h00 * self.y[i]
            + h10 * h * self.slope[i]
            + h01 * self.y[i + 1]
            + h11 * h * self.slope[i + 1]
    }

    /// The knots' abscissae.
    pub fn knots(&self) -> &[f64] {
        &self.x
    }
}

/// Shape-preserving one-sided end slope (Moler, *Numerical Computing with MATLAB*, pchip).
fn end_slope(h0: f64, h1: f64, d0: f64, d1: Option<f64>) -> f64 {
    let Some(d1) = d1 else {
        return d0;
    };
    let s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if s * d0 <= 0.0 {
        0.0
    } else if d0 * d1 <= 0.0 && s.abs() > 3.0 * d0.abs() {
        3.0 * d0
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pchip_reproduces_knots_and_stays_monotone() {
        let x = vec![0.0, 1.0, 2.0, 3.0, 4.0];
        let y = vec![0.0, 0.1, 0.2, 5.0, 5.1];
        let p = MonotoneCubic::new(x.clone(), y.clone()).unwrap();
        // Knots exactly (to round-off, 1e-14): Hermite basis interpolates.
        for (xi, yi) in x.iter().zip(&y) {
            assert!((p.eval(*xi) - yi).abs() < 1e-14);
        }
        // Monotone: a natural cubic spline overshoots on this step-like data.
        let mut prev = p.eval(0.0);
        for i in 1..=400 {
            let v = p.eval(i as f64 * 0.01);
            assert!(v >= prev - 1e-15, "not monotone at {}", i);
            prev = v;
        }
        assert!(MonotoneCubic::new(vec![0.0, 0.0], vec![1.0, 2.0]).is_none());
    }
}
