//! Traction curves µ(u_s): the EHD traction coefficient against the sliding speed,
//! tabulated before a bearing analysis (seed 001, Chen 1989, ch. 2 "EHD Traction
//! Coefficient", Fig. 2-10, and ch. 6, Fig. 6-20), SI.
//!
//! Chen describes a curve by four numbers: µ₀ at zero sliding, the maximum µ_m at the
//! sliding speed u_m, and µ_∞ at high sliding speeds. He gives three curves:
//!
//! | curve | u_m      | µ₀ | µ_m   | µ_∞                          |
//! |-------|----------|----|-------|------------------------------|
//! | 1     | 0.2 m/s  | 0  | 0.054 | 0.054                        |
//! | 2     | 0.2 m/s  | 0  | 0.075 | 0.035 (when sliding > 3 m/s) |
//! | 3     | 0.2 m/s  | 0  | 0.075 | 0.035 (when sliding > 2 m/s) |
//!
//! **The shape between the printed points is not given** (the figures are not in the
//! text): we read every curve as piecewise linear between them, constant beyond the last
//! one, e.g. curve 2 = (0, 0) → (0.2, 0.075) → (3, 0.035) → constant. A user table is
//! the same piecewise-linear law through the user's points; `Constant` is Coulomb
//! friction (µ independent of the sliding speed).
//!
//! µ depends only on the magnitude of the sliding speed; the traction force opposes the
//! sliding.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use thiserror::Error;

/// Why a traction curve is not usable.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TractionCurveError {
    /// A value is NaN or infinite.
    #[error("non-finite value in the traction curve")]
    NonFinite,
    /// A coefficient is negative.
    #[error("negative traction coefficient {0}")]
    NegativeCoefficient(f64),
    /// A table needs at least one point, the first at zero sliding speed, speeds
    /// strictly increasing.
    #[error("traction table: {0}")]
    BadTable(&'static str),
    /// Only curves 1, 2 and 3 are printed in the seed.
    #[error("unknown traction curve {0} (the seed gives curves 1, 2 and 3)")]
    UnknownCurve(u32),
}

/// µ against the magnitude of the sliding speed.
#[derive(Debug, Clone, PartialEq)]
pub enum TractionCurve {
    /// Coulomb friction: µ for every sliding speed (dimensionless).
    Constant {
        /// µ, dimensionless.
        mu: f64,
    },
    /// Piecewise linear through (sliding speed m/s, µ) points, the first at 0 m/s,
    /// speeds strictly increasing; constant beyond the last point.
    Table {
        /// (u_s m/s, µ) points.
        points: Vec<(f64, f64)>,
    },
}

impl TractionCurve {
    /// Chen's curve `n` (1, 2 or 3; ch. 6, Fig. 6-20), piecewise linear between the
    /// printed points.
    pub fn seed_curve(n: u32) -> Result<Self, TractionCurveError> {
        let points = match n {
            1 => vec![(0.0, 0.0), (0.2, 0.054)],
            2 => vec![(0.0, 0.0), (0.2, 0.075), (3.0, 0.035)],
            3 => vec![(0.0, 0.0), (0.2, 0.075), (2.0, 0.035)],
            _ => return Err(TractionCurveError::UnknownCurve(n)),
        };
        Ok(Self::Table { points })
    }

    /// A checked table (see [`TractionCurve::Table`]).
    pub fn table(points: Vec<(f64, f64)>) -> Result<Self, TractionCurveError> {
        let curve = Self::Table { points };
        curve.validate()?;
        Ok(curve)
    }

    /// Check the curve: finite, non-negative µ, a table starting at 0 m/s with strictly
    /// increasing speeds.
    pub fn validate(&self) -> Result<(), TractionCurveError> {
        match self {
            Self::Constant { mu } => check_mu(*mu),
            Self::Table { points } => {
                let Some(&(u0, _)) = points.first() else {
                    return Err(TractionCurveError::BadTable("no points"));
                };
                if u0 != 0.0 {
                    return Err(TractionCurveError::BadTable(
                        "the first point must be at zero sliding speed",
                    ));
                }
                for (i, &(u, mu)) in points.iter().enumerate() {
                    if !u.is_finite() {
                        return Err(TractionCurveError::NonFinite);
                    }
                    check_mu(mu)?;
                    if i > 0 && u <= points[i - 1].0 {
                        return Err(TractionCurveError::BadTable(
                            "sliding speeds must increase strictly",
                        ));
                    }
                }
                Ok(())
            }
        }
    }

    /// µ at the sliding speed u_s (m/s; its sign does not matter), dimensionless.
    pub fn mu(&self, sliding_m_s: f64) -> f64 {
        let u = sliding_m_s.abs();
        match self {
            Self::Constant { mu } => *mu,
            Self::Table { points } => {
                let mut prev = match points.first() {
                    Some(&p) => p,
                    None => return 0.0,
                };
                for &(ui, mi) in &points[1..] {
                    if u <= ui {
                        let (u0, m0) = prev;
                        return m0 + (mi - m0) * (u - u0) / (ui - u0);
                    }
                    prev = (ui, mi);
                }
                prev.1
            }
        }
    }

    /// The largest µ of the curve (µ_m; the Coulomb coefficient the race-control theory
    /// and the skidding condition 2-4 use), dimensionless.
    pub fn max_mu(&self) -> f64 {
        match self {
            Self::Constant { mu } => *mu,
            Self::Table { points } => points.iter().map(|p| p.1).fold(0.0, f64::max),
        }
    }
}

fn check_mu(mu: f64) -> Result<(), TractionCurveError> {
    if !mu.is_finite() {
        Err(TractionCurveError::NonFinite)
    } else if mu < 0.0 {
        Err(TractionCurveError::NegativeCoefficient(mu))
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The printed points of curves 1–3 are reproduced exactly (they are the table's
    /// nodes), the curves are linear between them (midpoints exact to 1e-15) and
    /// constant beyond the last point; µ_m = 0.054, 0.075, 0.075.
    #[test]
    fn seed_curves_pass_through_printed_points() {
        let c1 = TractionCurve::seed_curve(1).unwrap();
        let c2 = TractionCurve::seed_curve(2).unwrap();
        let c3 = TractionCurve::seed_curve(3).unwrap();
        for c in [&c1, &c2, &c3] {
            c.validate().unwrap();
            assert_eq!(c.mu(0.0), 0.0);
        }
        assert_eq!(c1.mu(0.2), 0.054);
        assert_eq!(c1.mu(50.0), 0.054);
        assert!((c1.mu(0.1) - 0.027).abs() < 1e-15);
        assert!((c1.mu(-0.1) - 0.027).abs() < 1e-15);
        assert_eq!(c2.mu(0.2), 0.075);
        assert_eq!(c2.mu(3.0), 0.035);
        assert_eq!(c2.mu(10.0), 0.035);
        assert!((c2.mu(1.6) - 0.055).abs() < 1e-15);
        assert_eq!(c3.mu(2.0), 0.035);
        assert!((c3.mu(1.1) - 0.055).abs() < 1e-15);
        // Curves 2 and 3 differ only between 0.2 and 3 m/s (Chen: "only the traction
        // coefficients in the range between 0.5 m/sec to 2 m/sec are really important").
        assert_eq!(c2.mu(0.15), c3.mu(0.15));
        assert!(c2.mu(1.0) > c3.mu(1.0));
        assert_eq!(c1.max_mu(), 0.054);
        assert_eq!(c2.max_mu(), 0.075);
        assert_eq!(c3.max_mu(), 0.075);
        assert!(TractionCurve::seed_curve(4).is_err());
    }

    #[test]
    fn bad_tables_and_coefficients_are_refused() {
        assert!(TractionCurve::table(vec![]).is_err());
        assert!(TractionCurve::table(vec![(0.1, 0.0)]).is_err());
        assert!(TractionCurve::table(vec![(0.0, 0.0), (0.0, 0.1)]).is_err());
        assert!(TractionCurve::table(vec![(0.0, -0.1)]).is_err());
        assert!(TractionCurve::table(vec![(0.0, f64::NAN)]).is_err());
        assert!(TractionCurve::Constant { mu: -1.0 }.validate().is_err());
        let t = TractionCurve::table(vec![(0.0, 0.01), (1.0, 0.05)]).unwrap();
        assert!((t.mu(0.5) - 0.03).abs() < 1e-15);
        assert_eq!(TractionCurve::Constant { mu: 0.054 }.mu(3.0), 0.054);
    }
}
