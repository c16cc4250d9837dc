//! Stiffness matrices as text: what lies below the solve's precision is shown as 0
//! (issue 30 item 14). In the bearings layer so that every system's text report and the
//! workbench's Stiffness pane (both built here) share one rule.

/// Relative size below which a stiffness entry is round-off of the solve, not data: an
/// off-diagonal K_ij with |K_ij| < 1e-9·√(|K_ii·K_jj|) (the geometric mean of its two
/// diagonals has K_ij's unit in every block, so one threshold serves lineal, coupling and
/// angular terms). 1e-9 is the ring Newton's relative force tolerance: what lies below it
/// moves from solve to solve (the CLI and a warm-started workbench printed different
/// −4e-11 beside 1.5e7; issue 30 item 14).
pub const ROUND_OFF_REL: f64 = 1e-9;

/// `k[i][j]` for display: 0 where it is below [`ROUND_OFF_REL`] of its diagonals' scale.
/// Diagonals, and entries whose diagonals are not both positive and finite, are shown as
/// computed. JSON and CSV keep the computed values.
pub fn shown(k: impl Fn(usize, usize) -> f64, i: usize, j: usize) -> f64 {
    let v = k(i, j);
    if i == j {
        return v;
    }
    let scale = (k(i, i) * k(j, j)).abs().sqrt();
    if scale.is_finite() && scale > 0.0 && v.abs() < ROUND_OFF_REL * scale {
        0.0
    } else {
        v
    }
}

/// The note every stiffness text carries under its matrix.
pub fn round_off_note() -> String {
    format!(
        "  entries below {ROUND_OFF_REL:.0e} of sqrt(|K_ii K_jj|) are round-off and shown as 0 (JSON keeps them)"
    )
}

#[cfg(test)]
mod round_off_tests {
    use super::*;

    /// A coupling 1e-18 of its diagonals' scale is shown as 0 (issue 30 item 14's
    /// −4.25e-11 N/m beside 1.53e7 N/m is 2.8e-18 of it); one 1e-6 of it is data and kept;
    /// diagonals are never zeroed, nor entries whose diagonal is zero (a held DOF).
    #[test]
    fn round_off_is_shown_as_zero_and_data_is_kept() {
        let m = [
            [1.5254e7, -4.2544e-11, 3.0],
            [-4.2544e-11, 2.0e7, 0.0],
            [3.0, 0.0, 0.0],
        ];
        let k = |i: usize, j: usize| m[i][j];
        assert_eq!(shown(k, 0, 1), 0.0);
        assert_eq!(shown(k, 1, 0), 0.0);
        assert_eq!(shown(k, 0, 0), 1.5254e7);
        // Row 2's diagonal is 0: nothing to compare with, shown as computed.
        assert_eq!(shown(k, 0, 2), 3.0);
        let n = [[1.0e7, 10.0], [10.0, 1.0e7]];
        assert_eq!(shown(|i, j| n[i][j], 0, 1), 10.0);
    }
}
