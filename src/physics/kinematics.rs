//! Internal speeds and sliding (seed 000 §7, §8, App. C, App. D), SI.
//!
//! # Frame and sign conventions (shared with the load-distribution code)
//!
//! Per roller, a right-handed frame (x, r, t): x along the bearing axis, r radially
//! outward through the roller centre, t = x × r (tangential). Vectors are `[x, r, t]`.
//! The roller centre sits nominally at (0, P_t/2, 0). The contact angle β is measured
//! from the radial plane; the nominal contact normal n = (sin β, cos β, 0) points from
//! the roller centre toward the outer raceway and the roller axis is
//! a = (cos β, −sin β, 0), so that a × n = e_t. Ring and cage angular velocities are
//! Ω₁ e_x (inner), Ω₂ e_x (outer), Ω_cg e_x; the roller spins relative to the cage at
//! ω_s about a (signed). Angular speeds in rad/s, lengths in m.
//!
//! # Relation to the seed's own signs
//!
//! Figures 9 and 10 (missing) draw the bearing axis to the right and the radius upward,
//! with the seed's y-axis "into the paper": that is −t here. With that mapping the
//! seed's eqs. 8.1–8.5 are the t-components below with the opposite sign, and the
//! seed's Ω_o is our ω_s. Two misprints follow from that reading and are corrected here:
//!
//! * Eq. 7.9 as printed, Ω_o,1·r_o,1 = (Ω₁ − Ω_cg)·r₁, has the opposite sign to eq. 7.11
//!   and to eqs. 8.1–8.2 (no slip at the inner contact of eq. 8.1–8.2 needs
//!   Ω_o·r_o,1 = −Ω₁·r₁). Taken literally, the mean of 7.12 would nearly cancel for an
//!   inner-rotating bearing. We use ω_s,1 = −(Ω₁ − Ω_cg)·r₁/r_o,1 and
//!   ω_s,2 = +(Ω₂ − Ω_cg)·r₂/r_o,2, which reproduce App. C exactly (tested).
//! * Eqs. 8.1 and 8.4 use the absolute ring speed Ω_i while 8.2 and 8.5 use the roller's
//!   rotation relative to the cage, which omits the roller's orbital velocity Ω_cg·r.
//!   Sliding is frame-independent; we evaluate it consistently in the cage frame, i.e.
//!   eq. 8.1/8.4 with Ω_i read as Ω_i − Ω_cg (identical to the printed form when
//!   Ω_cg = 0; both are tested).

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// Unit vector along the bearing axis, e_x.
const E_X: [f64; 3] = [1.0, 0.0, 0.0];

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn scale(s: f64, a: [f64; 3]) -> [f64; 3] {
    [s * a[0], s * a[1], s * a[2]]
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a/|a|`, or `None` for a zero or non-finite vector.
fn unit(a: [f64; 3]) -> Option<[f64; 3]> {
    let n = dot(a, a).sqrt();
    if n.is_finite() && n > 0.0 {
        Some(scale(1.0 / n, a))
    } else {
        None
    }
}

/// Nominal contact normal n = (sin β, cos β, 0), from the roller centre toward the outer
/// raceway; β in rad from the radial plane. Dimensionless unit vector `[x, r, t]`.
pub fn contact_normal(beta_rad: f64) -> [f64; 3] {
    [beta_rad.sin(), beta_rad.cos(), 0.0]
}

/// Roller axis a = (cos β, −sin β, 0); β in rad from the radial plane. Dimensionless unit
/// vector `[x, r, t]`, with a × n = e_t.
pub fn roller_axis(beta_rad: f64) -> [f64; 3] {
    [beta_rad.cos(), -beta_rad.sin(), 0.0]
}

/// Cage angular speed Ω_cg, rad/s, seed 000 eq. C.1:
/// Ω_cg = ½[Ω₁(1 − θ) + Ω₂(1 + θ)], θ = D·cos β/P_t (dimensionless).
///
/// `inner_speed_rad_s` Ω₁ and `outer_speed_rad_s` Ω₂ are signed ring speeds, rad/s. The
/// contact centres are assumed at the roller mid-plane, at radii (P_t/2)(1 ∓ θ), with no
/// gross slip.
pub fn cage_speed_estimate(inner_speed_rad_s: f64, outer_speed_rad_s: f64, theta: f64) -> f64 {
    0.5 * (inner_speed_rad_s * (1.0 - theta) + outer_speed_rad_s * (1.0 + theta))
}

/// Roller spin relative to the cage ω_s about a, rad/s, seed 000 eq. C.2 (the second one
/// so numbered): ω_s = (P_t/2D)(1 − θ)(1 + θ)(Ω₂ − Ω₁).
///
/// Ω₁, Ω₂ in rad/s, θ = D·cos β/P_t, `roller_diameter_m` D and `pitch_diameter_m` P_t in m.
/// Returns 0 for a non-positive or non-finite D (no roller).
pub fn roller_spin_estimate(
    inner_speed_rad_s: f64,
    outer_speed_rad_s: f64,
    theta: f64,
    roller_diameter_m: f64,
    pitch_diameter_m: f64,
) -> f64 {
    if !(roller_diameter_m.is_finite() && roller_diameter_m > 0.0) {
        return 0.0;
    }
    pitch_diameter_m / (2.0 * roller_diameter_m)
        * (1.0 - theta)
        * (1.0 + theta)
        * (outer_speed_rad_s - inner_speed_rad_s)
}

/// The most heavily loaded contact points of one roller (seed 000 §7, Figs. 9–10).
///
/// Each side is `Some((r_ring_axis_m, r_roller_axis_m))` when the roller is loaded on that
/// raceway: the point's radius from the bearing axis (r₁ of eq. 7.1 or r₂ of eq. 7.3, m)
/// and from the roller axis (r_o,1 of eq. 7.8 or r_o,2 of eq. 7.10, m). `None` means the
/// roller does not touch that raceway.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ContactPointPair {
    /// Inner contact (r₁, r_o,1), m.
    pub inner: Option<(f64, f64)>,
    /// Outer contact (r₂, r_o,2), m.
    pub outer: Option<(f64, f64)>,
}

impl ContactPointPair {
    /// Builds the pair from the contact points themselves (`[x, r, t]`, m, in the
    /// roller frame; `None` for an unloaded raceway): the radius from the bearing axis is
    /// √(r² + t²) (eqs. 7.1, 7.3: r = AP·cos β_i) and the radius from the roller axis is
    /// [`distance_from_axis`] of the line through `roller_centre` along `roller_axis`
    /// (eqs. 7.8, 7.10: r_o = OA·cos(β_i − β)).
    pub fn from_points(
        inner: Option<[f64; 3]>,
        outer: Option<[f64; 3]>,
        roller_centre: [f64; 3],
        roller_axis: [f64; 3],
    ) -> ContactPointPair {
        let radii = |p: [f64; 3]| {
            (
                (p[1] * p[1] + p[2] * p[2]).sqrt(),
                distance_from_axis(p, roller_centre, roller_axis),
            )
        };
        ContactPointPair {
            inner: inner.map(radii),
            outer: outer.map(radii),
        }
    }
}

/// §7's "most heavily loaded point" of a contact between lamina centres: the axial
/// position (m) of the vertex of the parabola through the line loads `q` (N/m) of the most
/// loaded lamina and its two neighbours at their centres `x` (m), and the weights that
/// carry any quantity sampled at those three centres to that position (the quadratic
/// Lagrange interpolant, exact for a quantity quadratic along the roller).
///
/// The seed takes the contact centre A at the most heavily loaded lamina (§7, Figs. 9–10),
/// whose centre jumps by a lamina width as Γ or the load changes, and the cage speed with
/// it (0.02–0.04 % on the aerospace deck between neighbouring Γ, 4× that on L-10 through
/// the centrifugal force). The vertex is the continuum reading of the same point: it
/// converges to it as Γ → ∞ and moves smoothly with the load. Kept within `[lo, hi]`, the
/// most loaded lamina's own extent. `None` (take the lamina centre) when a neighbour is
/// unloaded or the three loads do not make a concave parabola (the peak is at a roller end
/// or the profile is flat).
pub fn load_peak(x: [f64; 3], q: [f64; 3], lo: f64, hi: f64) -> Option<(f64, [f64; 3])> {
    if !(q[0] > 0.0 && q[2] > 0.0 && x[0] < x[1] && x[1] < x[2]) {
        return None;
    }
    let d01 = (q[1] - q[0]) / (x[1] - x[0]);
    let d12 = (q[2] - q[1]) / (x[2] - x[1]);
    let a = (d12 - d01) / (x[2] - x[0]);
    // Concave only (a NaN from degenerate input fails too).
    if a.is_nan() || a >= 0.0 {
        return None;
    }
    // q(x) = q₁ + d01·(x − x₁) + a·(x − x₀)(x − x₁): vertex where q' = 0.
    let xs = (0.5 * (x[0] + x[1]) - d01 / (2.0 * a)).clamp(lo, hi);
    let w = [
        (xs - x[1]) * (xs - x[2]) / ((x[0] - x[1]) * (x[0] - x[2])),
        (xs - x[0]) * (xs - x[2]) / ((x[1] - x[0]) * (x[1] - x[2])),
        (xs - x[0]) * (xs - x[1]) / ((x[2] - x[0]) * (x[2] - x[1])),
    ];
    xs.is_finite().then_some((xs, w))
}

/// Cage and roller speeds from the contact points (seed 000 eqs. 7.5–7.12).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct InternalSpeeds {
    /// Ω_cg, cage angular speed, rad/s (eq. 7.7).
    pub cage_speed_rad_s: f64,
    /// Z_eff, number of controlling rollers (loaded on both raceways) averaged in eq. 7.7.
    pub controlling_rollers: usize,
    /// ω_s per roller, spin about a relative to the cage, rad/s (eqs. 7.9, 7.11, 7.12);
    /// `None` for a roller that touches neither raceway (its spin is not determined by
    /// §7).
    pub roller_spin_rad_s: Vec<Option<f64>>,
}

/// Why §7's speeds cannot be computed.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum KinematicsError {
    /// No roller is loaded on both raceways, so eq. 7.7 has Z_eff = 0. Callers typically
    /// fall back to [`cage_speed_estimate`].
    #[error("no roller is loaded on both raceways: the cage speed of eq. 7.7 is undefined")]
    NoControllingRoller,
    /// The pitch diameter is not positive and finite.
    #[error("pitch diameter must be positive and finite, got {0} m")]
    InvalidPitchDiameter(f64),
    /// A contact radius is not positive and finite.
    #[error("roller {roller}: contact radii must be positive and finite")]
    InvalidRadius {
        /// Index of the offending roller in the input slice.
        roller: usize,
    },
}

fn valid_point(p: Option<(f64, f64)>) -> bool {
    match p {
        None => true,
        Some((r, ro)) => r.is_finite() && r > 0.0 && ro.is_finite() && ro > 0.0,
    }
}

/// Cage speed and roller spins from the most heavily loaded contact points, seed 000
/// eqs. 7.5–7.12. Speeds Ω₁, Ω₂ in rad/s, `pitch_diameter_m` P (m), radii in m.
///
/// * Cage (eqs. 7.5–7.7): for each controlling roller (loaded on both raceways)
///   v₁ = Ω₁·r₁, v₂ = Ω₂·r₂ are absolute tangential speeds, the cage's pitch-circle speed is
///   their mean, ½(v₁ + v₂) = ½·P·Ω_cg,j, so Ω_cg,j = (v₁ + v₂)/P with P the pitch
///   *diameter*; Ω_cg is the mean over the Z_eff controlling rollers. With the contacts at
///   the roller mid-plane, r₁,₂ = (P/2)(1 ∓ θ) and this is exactly App. C's eq. C.1
///   (tested). Averaging tangential speeds is the seed's approximation: it is exactly
///   no-slip at both points only when r₁ + r₂ = P.
/// * Spin (eqs. 7.9, 7.11, 7.12, signs corrected, see the module notes):
///   ω_s,1 = −(Ω₁ − Ω_cg)·r₁/r_o,1, ω_s,2 = (Ω₂ − Ω_cg)·r₂/r_o,2, ω_s = ½(ω_s,1 + ω_s,2);
///   a roller loaded on one raceway gets the spin of that raceway alone (it is
///   "controlled" by the cage, §7.1); with the App. C contacts this is eq. C.2.
///
/// # Errors
/// [`KinematicsError::NoControllingRoller`] when no roller has both contacts;
/// [`KinematicsError::InvalidPitchDiameter`] / [`KinematicsError::InvalidRadius`] for
/// non-positive or non-finite lengths.
pub fn internal_speeds(
    inner_speed_rad_s: f64,
    outer_speed_rad_s: f64,
    pitch_diameter_m: f64,
    rollers: &[ContactPointPair],
) -> Result<InternalSpeeds, KinematicsError> {
    if !(pitch_diameter_m.is_finite() && pitch_diameter_m > 0.0) {
        return Err(KinematicsError::InvalidPitchDiameter(pitch_diameter_m));
    }
    if let Some(roller) = rollers
        .iter()
        .position(|c| !(valid_point(c.inner) && valid_point(c.outer)))
    {
        return Err(KinematicsError::InvalidRadius { roller });
    }
    // Eqs. 7.2, 7.4, 7.6, 7.7.
    let mut sum = 0.0;
    let mut z_eff = 0usize;
    for c in rollers {
        if let (Some((r1, _)), Some((r2, _))) = (c.inner, c.outer) {
            sum += (inner_speed_rad_s * r1 + outer_speed_rad_s * r2) / pitch_diameter_m;
            z_eff += 1;
        }
    }
    if z_eff == 0 {
        return Err(KinematicsError::NoControllingRoller);
    }
    let cage = sum / z_eff as f64;
    // Eqs. 7.9, 7.11 (sign-corrected), 7.12.
    let spin_inner = |(r1, ro1): (f64, f64)| -(inner_speed_rad_s - cage) * r1 / ro1;
    let spin_outer = |(r2, ro2): (f64, f64)| (outer_speed_rad_s - cage) * r2 / ro2;
    let spins = rollers
        .iter()
        .map(|c| match (c.inner, c.outer) {
            (Some(i), Some(o)) => Some(0.5 * (spin_inner(i) + spin_outer(o))),
            (Some(i), None) => Some(spin_inner(i)),
            (None, Some(o)) => Some(spin_outer(o)),
            (None, None) => None,
        })
        .collect();
    Ok(InternalSpeeds {
        cage_speed_rad_s: cage,
        controlling_rollers: z_eff,
        roller_spin_rad_s: spins,
    })
}

/// Distance of `point` from the line through `centre` along `axis` (all `[x, r, t]`, m;
/// `axis` need not be normalised), m: the r_o of eqs. 7.8 and 7.10 for a contact point.
/// Returns the distance from `centre` if `axis` is zero.
pub fn distance_from_axis(point: [f64; 3], centre: [f64; 3], axis: [f64; 3]) -> f64 {
    let d = sub(point, centre);
    match unit(axis) {
        Some(a) => {
            let c = cross(a, d);
            dot(c, c).sqrt()
        }
        None => dot(d, d).sqrt(),
    }
}

/// Gyroscopic moment on the roller about e_t, N·m: the t-component of the couple the
/// raceways must apply to sustain steady precession, M = Ω_cg e_x × H, with
/// H = I_p (ω·a) a + I_t (ω − (ω·a) a) and ω = Ω_cg e_x + ω_s a (seed 000 App. D).
///
/// `polar_inertia_kg_m2` I_p is about the roller's own axis, `transverse_inertia_kg_m2`
/// I_t about a diameter through the mass centre (kg·m²), `cage_speed_rad_s` Ω_cg and
/// `roller_spin_rad_s` ω_s in rad/s, `beta_rad` β from the radial plane.
///
/// Closed form: M_t = −Ω_cg sin β [I_p (ω_s + Ω_cg cos β) − I_t Ω_cg cos β], i.e. minus
/// eq. D.1 read with the polar moment on the spin term (D.1's I_z = I_p, I_x = I_t, as
/// the reading notes prescribe, whatever the letters say) and Ω_o = ω_s. The minus sign
/// is the frame mapping: D.1's moment points along the seed's +y, "into the paper",
/// which is −t here. (Tested.)
pub fn gyroscopic_moment(
    polar_inertia_kg_m2: f64,
    transverse_inertia_kg_m2: f64,
    cage_speed_rad_s: f64,
    roller_spin_rad_s: f64,
    beta_rad: f64,
) -> f64 {
    let a = roller_axis(beta_rad);
    let omega = add(scale(cage_speed_rad_s, E_X), scale(roller_spin_rad_s, a));
    let w_a = dot(omega, a);
    let h_axial = scale(polar_inertia_kg_m2 * w_a, a);
    let h_trans = scale(transverse_inertia_kg_m2, sub(omega, scale(w_a, a)));
    let h = add(h_axial, h_trans);
    cross(scale(cage_speed_rad_s, E_X), h)[2]
}

/// Sliding velocity at a contact location, m/s: the t-component (rolling direction) of
/// (velocity of the raceway material point) − (velocity of the roller material point) at
/// `point`, seed 000 eqs. 8.1–8.5 generalised to any point and any orientation.
///
/// Evaluated in the cage frame (sliding is frame-independent): the raceway point moves
/// at (Ω_ring − Ω_cg) e_x × p, the roller point at ω_s a × (p − c). `point` p and
/// `roller_centre` c are `[x, r, t]` in m in the roller frame; `roller_axis` a is
/// normalised here (a zero axis means no spin contribution); `ring_omega_rad_s`
/// Ω_ring, `cage_omega_rad_s` Ω_cg and `roller_spin_rad_s` ω_s (about a, relative to the
/// cage) in rad/s.
///
/// Sign: relative to the seed's y-axis ("into the paper", −t here), this is −v_rel of
/// eq. 8.3, with the ring speed of 8.1/8.4 taken relative to the cage.
pub fn sliding_velocity(
    point: [f64; 3],
    ring_omega_rad_s: f64,
    cage_omega_rad_s: f64,
    roller_centre: [f64; 3],
    roller_axis: [f64; 3],
    roller_spin_rad_s: f64,
) -> f64 {
    let ring = cross(scale(ring_omega_rad_s - cage_omega_rad_s, E_X), point);
    let roller = match unit(roller_axis) {
        Some(a) => cross(scale(roller_spin_rad_s, a), sub(point, roller_centre)),
        None => [0.0; 3],
    };
    ring[2] - roller[2]
}

#[cfg(test)]
mod load_peak_tests {
    use super::load_peak;

    #[test]
    fn vertex_of_a_parabolic_load_and_interpolated_radius() {
        // Unequal spacing (cosine slicing): q(x) = 5 − 2(x − 0.3)², r(x) = 1 + 0.5x − x²:
        // the vertex is 0.3 and the weights reproduce r(0.3) exactly (quadratic).
        let x = [0.0, 0.25, 0.6];
        let q = x.map(|x: f64| 5.0 - 2.0 * (x - 0.3).powi(2));
        let r = |x: f64| 1.0 + 0.5 * x - x * x;
        let (xs, w) = load_peak(x, q, 0.1, 0.45).expect("concave");
        assert!((xs - 0.3).abs() < 1e-14, "{xs}");
        let ri = w[0] * r(x[0]) + w[1] * r(x[1]) + w[2] * r(x[2]);
        assert!((ri - r(0.3)).abs() < 1e-14, "{ri}");
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn symmetric_loads_keep_the_centre_and_the_peak_stays_in_its_lamina() {
        let (xs, w) = load_peak([-1.0, 0.0, 1.0], [2.0, 3.0, 2.0], -0.5, 0.5).expect("concave");
        assert_eq!(xs, 0.0);
        assert_eq!(w, [0.0, 1.0, 0.0]);
        // Vertex at 1/6 (q = 3 − 0.75x² + 0.25x): inside [−0.5, 0.5], held at the edge of a
        // narrower lamina (unequal spacing can put it beyond the lamina).
        let q = [2.0, 3.0, 2.5];
        let (xs, _) = load_peak([-1.0, 0.0, 1.0], q, -0.5, 0.5).expect("concave");
        assert!((xs - 1.0 / 6.0).abs() < 1e-15, "{xs}");
        let (xs, _) = load_peak([-1.0, 0.0, 1.0], q, -0.5, 0.05).expect("concave");
        assert_eq!(xs, 0.05);
    }

    #[test]
    fn no_peak_without_two_loaded_neighbours_or_concavity() {
        assert!(load_peak([-1.0, 0.0, 1.0], [0.0, 3.0, 2.0], -0.5, 0.5).is_none());
        assert!(load_peak([-1.0, 0.0, 1.0], [2.0, 3.0, 0.0], -0.5, 0.5).is_none());
        // Linear and convex profiles: the lamina centre stands.
        assert!(load_peak([-1.0, 0.0, 1.0], [1.0, 2.0, 3.0], -0.5, 0.5).is_none());
        assert!(load_peak([-1.0, 0.0, 1.0], [3.0, 1.0, 3.0], -0.5, 0.5).is_none());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::spherical_roller::Bearing;

    use crate::units::{INCH_M, RPM_RAD_S};

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * a.abs().max(b.abs()).max(1e-300)
    }

    /// a × n = e_t: the frame convention the brief fixes. Exact up to round-off (1e-15).
    #[test]
    fn axis_cross_normal_is_tangential() {
        for beta in [0.0, 0.2, 12f64.to_radians(), 1.0] {
            let t = cross(roller_axis(beta), contact_normal(beta));
            assert!((t[0]).abs() < 1e-15 && (t[1]).abs() < 1e-15);
            assert!((t[2] - 1.0).abs() < 1e-15);
        }
    }

    /// App. C speeds give pure rolling at both nominal contact points (the brief's
    /// verification), for any β. Tolerance 1e-12 relative to the ring surface speed:
    /// round-off only.
    #[test]
    fn app_c_speeds_roll_without_slip_at_nominal_points() {
        let g = Bearing::example_aerospace().geometry;
        for (w1, w2, beta) in [
            (17_000.0 * RPM_RAD_S, 0.0, 0.0),
            (17_000.0 * RPM_RAD_S, 0.0, g.contact_angle_rad),
            (-3_000.0 * RPM_RAD_S, 5_000.0 * RPM_RAD_S, 0.3),
        ] {
            let (d, pt) = (g.roller_diameter_m, g.pitch_diameter_m);
            let theta = d * beta.cos() / pt;
            let cage = cage_speed_estimate(w1, w2, theta);
            let spin = roller_spin_estimate(w1, w2, theta, d, pt);
            let c = [0.0, pt / 2.0, 0.0];
            let n = contact_normal(beta);
            let a = roller_axis(beta);
            let pin = add(c, scale(-d / 2.0, n));
            let pout = add(c, scale(d / 2.0, n));
            let vref = (w1.abs() + w2.abs()) * pt / 2.0;
            assert!(sliding_velocity(pin, w1, cage, c, a, spin).abs() < 1e-12 * vref);
            assert!(sliding_velocity(pout, w2, cage, c, a, spin).abs() < 1e-12 * vref);
        }
    }

    /// Harris' closed form for the aerospace example (inner ring 17 000 rpm, outer fixed):
    /// cage ½Ω₁(1 − γ) and roller (d_m/2D)(1 − γ²)(−Ω₁), γ computed by hand from
    /// D = 0.5 in, P_t = 3.3 in, β = 12°. Tolerance 1e-12: same formula, independent
    /// arithmetic.
    #[test]
    fn app_c_hand_values() {
        let w1 = 17_000.0 * RPM_RAD_S;
        let gamma = 0.5 * 12f64.to_radians().cos() / 3.3;
        let theta = Bearing::example_aerospace().geometry.theta();
        assert!(close(theta, gamma, 1e-12));
        assert!(close(
            cage_speed_estimate(w1, 0.0, theta),
            0.5 * w1 * (1.0 - gamma),
            1e-12
        ));
        let spin = roller_spin_estimate(w1, 0.0, theta, 0.5 * INCH_M, 3.3 * INCH_M);
        assert!(close(spin, -3.3 / 1.0 * (1.0 - gamma * gamma) * w1, 1e-12));
        assert_eq!(roller_spin_estimate(w1, 0.0, theta, 0.0, 1.0), 0.0);
    }

    /// §7 in the no-crown, mid-plane-contact limit (r₁,₂ = (P/2)(1 ∓ θ), r_o = D/2) gives
    /// App. C exactly: cage eq. C.1, spin eq. C.2, for two- and one-raceway rollers.
    /// Tolerance 1e-12 relative: round-off only.
    #[test]
    fn section7_reduces_to_app_c() {
        let (d, pt) = (0.0127, 0.08382);
        for beta in [0.0, 12f64.to_radians()] {
            let theta = d * f64::cos(beta) / pt;
            let (w1, w2) = (17_000.0 * RPM_RAD_S, -1_000.0 * RPM_RAD_S);
            let inner = Some((pt / 2.0 * (1.0 - theta), d / 2.0));
            let outer = Some((pt / 2.0 * (1.0 + theta), d / 2.0));
            let rollers = [
                ContactPointPair { inner, outer },
                ContactPointPair { inner, outer },
                ContactPointPair { inner: None, outer },
                ContactPointPair { inner, outer: None },
                ContactPointPair::default(),
            ];
            let s = internal_speeds(w1, w2, pt, &rollers).expect("valid input");
            assert_eq!(s.controlling_rollers, 2);
            let cage = cage_speed_estimate(w1, w2, theta);
            let spin = roller_spin_estimate(w1, w2, theta, d, pt);
            assert!(close(s.cage_speed_rad_s, cage, 1e-12));
            for k in 0..4 {
                let got = s.roller_spin_rad_s[k].expect("loaded roller has a spin");
                assert!(close(got, spin, 1e-12), "roller {k}: {got} vs {spin}");
            }
            assert_eq!(s.roller_spin_rad_s[4], None);
        }
    }

    /// Eq. 7.7 is the arithmetic mean of per-roller cage speeds (7.6); hand numbers:
    /// roller A (r₁, r₂) = (0.035, 0.049), roller B (0.036, 0.048), P = 0.084, Ω₁ = 1000,
    /// Ω₂ = 0 → Ω_cg = (35/84 + 36/84)·1000/2 = 422.619… rad/s; a one-raceway roller
    /// does not count. Spin of a one-raceway (outer) roller with r₂ = 0.049,
    /// r_o = 0.006: −Ω_cg·0.049/0.006. Tolerance 1e-12: exact arithmetic.
    #[test]
    fn section7_mean_over_controlling_rollers() {
        let rollers = [
            ContactPointPair {
                inner: Some((0.035, 0.006)),
                outer: Some((0.049, 0.006)),
            },
            ContactPointPair {
                inner: Some((0.036, 0.006)),
                outer: Some((0.048, 0.006)),
            },
            ContactPointPair {
                inner: None,
                outer: Some((0.049, 0.006)),
            },
        ];
        let s = internal_speeds(1000.0, 0.0, 0.084, &rollers).expect("valid");
        let cage = (35.0 / 84.0 + 36.0 / 84.0) * 1000.0 / 2.0;
        assert!(close(s.cage_speed_rad_s, cage, 1e-12));
        let spin2 = s.roller_spin_rad_s[2].expect("loaded");
        assert!(close(spin2, -cage * 0.049 / 0.006, 1e-12));
        // Both-raceway roller: mean of the two raceway spins.
        let spin0 = s.roller_spin_rad_s[0].expect("loaded");
        let want = 0.5 * (-(1000.0 - cage) * 0.035 / 0.006 + (0.0 - cage) * 0.049 / 0.006);
        assert!(close(spin0, want, 1e-12));
    }

    /// `from_points` reproduces eqs. 7.1, 7.3, 7.8, 7.10 for the Fig. 9–10 geometry: O on
    /// the roller axis (offset s from the centre), A at distance OA along the contact
    /// normal at β_i, P where that normal meets the bearing axis:
    /// r₁ = (OP − OA)·cos β₁, r_o,1 = OA·cos(β₁ − β); r₂ = (OP + OA)·cos β₂,
    /// r_o,2 = OA·cos(β − β₂). Tolerance 1e-12 relative: round-off.
    #[test]
    fn from_points_matches_eqs_7_1_to_7_10() {
        let (pt, beta, s, oa) = (0.08382, 12f64.to_radians(), 0.0011, 0.00631);
        let (b1, b2) = (13.1f64.to_radians(), 11.2f64.to_radians());
        let c = [0.0, pt / 2.0, 0.0];
        let a = roller_axis(beta);
        let o = add(c, scale(s, a));
        let pa1 = add(o, scale(-oa, contact_normal(b1)));
        let pa2 = add(o, scale(oa, contact_normal(b2)));
        let pair = ContactPointPair::from_points(Some(pa1), Some(pa2), c, a);
        let (r1, ro1) = pair.inner.expect("inner given");
        let (r2, ro2) = pair.outer.expect("outer given");
        let op1 = o[1] / b1.cos();
        let op2 = o[1] / b2.cos();
        assert!(close(r1, (op1 - oa) * b1.cos(), 1e-12));
        assert!(close(ro1, oa * (b1 - beta).cos(), 1e-12));
        assert!(close(r2, (op2 + oa) * b2.cos(), 1e-12));
        assert!(close(ro2, oa * (beta - b2).cos(), 1e-12));
        let none = ContactPointPair::from_points(None, Some(pa2), c, a);
        assert_eq!(none.inner, None);
    }

    /// Errors instead of NaN: no controlling roller, bad pitch, zero radius.
    #[test]
    fn section7_errors() {
        let one_sided = [ContactPointPair {
            inner: Some((0.035, 0.006)),
            outer: None,
        }];
        assert_eq!(
            internal_speeds(1.0, 0.0, 0.084, &one_sided),
            Err(KinematicsError::NoControllingRoller)
        );
        assert!(matches!(
            internal_speeds(1.0, 0.0, 0.0, &one_sided),
            Err(KinematicsError::InvalidPitchDiameter(_))
        ));
        let bad = [ContactPointPair {
            inner: Some((0.035, 0.0)),
            outer: Some((0.049, 0.006)),
        }];
        assert_eq!(
            internal_speeds(1.0, 0.0, 0.084, &bad),
            Err(KinematicsError::InvalidRadius { roller: 0 })
        );
    }

    /// The vector moment equals −(eq. D.1) with I_z = I_p (spin term) and I_x = I_t, for
    /// both signs of every input. Tolerance 1e-12 relative to the largest term: the two
    /// are algebraically identical.
    #[test]
    fn gyroscopic_moment_matches_eq_d1() {
        let (ip, it) = (2.3e-7, 1.9e-7);
        for &(wc, ws, beta) in &[
            (800.0, -9_000.0, 12f64.to_radians()),
            (-800.0, 9_000.0, 0.3),
            (800.0, 9_000.0, -0.2),
            (800.0, -9_000.0, 0.0),
        ] {
            let d1 = (ip * (ws + wc * f64::cos(beta)) - it * (wc * f64::cos(beta)))
                * wc
                * f64::sin(beta);
            let m = gyroscopic_moment(ip, it, wc, ws, beta);
            let scale = ip * ws.abs() * wc.abs();
            assert!((m + d1).abs() <= 1e-12 * scale, "{m} vs -{d1}");
        }
        // Sign, by hand for the aerospace case: inner ring forward, Ω_cg > 0, ω_s < 0,
        // β > 0: the I_p ω_s term dominates and M_t = −Ω_cg sin β I_p ω_s > 0.
        assert!(gyroscopic_moment(ip, it, 800.0, -9_000.0, 0.2) > 0.0);
        // No precession, no moment.
        assert_eq!(gyroscopic_moment(ip, it, 0.0, -9_000.0, 0.2), 0.0);
    }

    /// A hand example against eqs. 8.1–8.3 (inner) and 8.4–8.5 (outer). Geometry built as
    /// in Figs. 9–10: O on the roller axis at offset s from the centre, local z along OA
    /// (contact angle β_i), x perpendicular in the axial plane, P where the normal line
    /// meets the bearing axis. Seed y = −t. With Ω_cg = 0 the printed equations are
    /// compared literally; with Ω_cg ≠ 0 the ring speed of 8.1/8.4 is read as Ω_i − Ω_cg.
    /// Tolerance 1e-12 relative to the ring surface speed: round-off only.
    #[test]
    fn sliding_matches_eqs_8_1_to_8_5() {
        let pt = 0.08382;
        let beta: f64 = 12f64.to_radians();
        let c = [0.0, pt / 2.0, 0.0];
        let a = roller_axis(beta);
        for &(w_ring, w_cage, w_o) in &[(1700.0, 0.0, -9000.0), (1700.0, 780.0, -8000.0)] {
            let w_rel = w_ring - w_cage;
            for &(s, b1, x, z) in &[
                (0.0005, 13.5f64.to_radians(), 0.0008, 0.0062),
                (-0.001, 10.0f64.to_radians(), -0.0012, 0.0061),
            ] {
                // Inner: OA direction u = −(sin β₁, cos β₁); x direction v = (cos β₁, −sin β₁).
                let o = add(c, scale(s, a));
                let u = [-f64::sin(b1), -f64::cos(b1), 0.0];
                let v = [f64::cos(b1), -f64::sin(b1), 0.0];
                let op = o[1] / f64::cos(b1);
                let p = add(o, add(scale(z, u), scale(x, v)));
                let v1 = -(op - z) * w_rel * f64::cos(b1) + x * w_rel * f64::sin(b1);
                let vo = z * w_o * f64::cos(b1 - beta) + x * w_o * f64::sin(b1 - beta);
                let seed = v1 - vo;
                let ours = sliding_velocity(p, w_ring, w_cage, c, a, w_o);
                let vref = w_ring.abs() * pt / 2.0;
                assert!((ours + seed).abs() < 1e-12 * vref, "inner {ours} vs {seed}");
                // r_o of eq. 7.8 agrees with the geometric distance (z ≡ OA, x = 0 point).
                let pa = add(o, scale(z, u));
                assert!(close(
                    distance_from_axis(pa, c, a),
                    z * f64::cos(b1 - beta),
                    1e-12
                ));
                // Outer: u = (sin β₂, cos β₂), v = (cos β₂, −sin β₂), AP = OP + OA.
                let b2 = b1;
                let u = [f64::sin(b2), f64::cos(b2), 0.0];
                let v = [f64::cos(b2), -f64::sin(b2), 0.0];
                let op = o[1] / f64::cos(b2);
                let p = add(o, add(scale(z, u), scale(x, v)));
                let v2 = -(op + z) * w_rel * f64::cos(b2) + x * w_rel * f64::sin(b2);
                let vo = -z * w_o * f64::cos(beta - b2) - x * w_o * f64::sin(beta - b2);
                let seed = v2 - vo;
                let ours = sliding_velocity(p, w_ring, w_cage, c, a, w_o);
                assert!((ours + seed).abs() < 1e-12 * vref, "outer {ours} vs {seed}");
            }
        }
    }

    /// Hand numbers, β = β₁ = 0, O at the roller centre, x = 0: P/2 = OP = 0.04 m,
    /// OE = z = 0.006 m, Ω₁ = 100 rad/s, Ω_cg = 0, Ω_o = ω_s = −300 rad/s.
    /// Eq. 8.1: v₁ = −(0.04 − 0.006)·100 = −3.4 m/s; eq. 8.2: v_o = 0.006·(−300) = −1.8;
    /// eq. 8.3: v_rel = −1.6 m/s along the seed's y, i.e. +1.6 m/s along t.
    /// Tolerance 1e-15 m/s: round-off.
    #[test]
    fn sliding_hand_example() {
        let c = [0.0, 0.04, 0.0];
        let p = [0.0, 0.034, 0.0];
        let v = sliding_velocity(p, 100.0, 0.0, c, roller_axis(0.0), -300.0);
        assert!((v - 1.6).abs() < 1e-15, "{v}");
        // Same contact with the cage turning at 40 rad/s and the ring at 140: the ring's
        // speed relative to the cage is unchanged, so is the sliding.
        let v = sliding_velocity(p, 140.0, 40.0, c, roller_axis(0.0), -300.0);
        assert!((v - 1.6).abs() < 1e-14, "{v}");
    }

    /// Crowned roller on the inner raceway, points along the contact line at offset s
    /// along a, at the crowned radius ρ(s) = √(R_o² − s²) − (R_o − D/2) (App. A).
    fn crowned_inner_point(pt: f64, d: f64, ro: f64, beta: f64, s: f64) -> [f64; 3] {
        let rho = (ro * ro - s * s).sqrt() - (ro - d / 2.0);
        let c = [0.0, pt / 2.0, 0.0];
        add(
            c,
            add(
                scale(s, roller_axis(beta)),
                scale(-rho, contact_normal(beta)),
            ),
        )
    }

    /// Heathcote-type sliding across a crowned contact, β = 0: with the roller spin set
    /// by §7 from rolling points at ±s₀ (r_o = ρ(s₀) < D/2), sliding vanishes at ±s₀
    /// (tolerance 1e-9 of the surface speed: the rolling point is exact up to
    /// round-off), has one sign inside and the other outside, and |v| grows
    /// monotonically with distance from the rolling points.
    #[test]
    fn sliding_changes_sign_across_crowned_contact() {
        let b = Bearing::example_aerospace();
        let g = b.geometry;
        let (pt, d, ro) = (
            g.pitch_diameter_m,
            g.roller_diameter_m,
            g.roller_crown_radius_m,
        );
        let beta = 0.0;
        let w1 = b.operating.inner_speed_rad_s;
        let theta = d / pt;
        let cage = cage_speed_estimate(w1, 0.0, theta);
        let s0 = 0.15 * g.effective_length_m;
        let p0 = crowned_inner_point(pt, d, ro, beta, s0);
        let c = [0.0, pt / 2.0, 0.0];
        let a = roller_axis(beta);
        let ro0 = distance_from_axis(p0, c, a);
        let s = internal_speeds(
            w1,
            0.0,
            pt,
            &[ContactPointPair {
                inner: Some((p0[1], ro0)),
                outer: None,
            }],
        );
        // A one-raceway roller alone cannot set the cage: §7 reports it.
        assert_eq!(s, Err(KinematicsError::NoControllingRoller));
        let spin = -(w1 - cage) * p0[1] / ro0; // eq. 7.9, sign-corrected
        let vs = |s: f64| {
            sliding_velocity(
                crowned_inner_point(pt, d, ro, beta, s),
                w1,
                cage,
                c,
                a,
                spin,
            )
        };
        let vref = w1 * pt / 2.0;
        assert!(vs(s0).abs() < 1e-9 * vref && vs(-s0).abs() < 1e-9 * vref);
        let inside = vs(0.0);
        let edge = vs(0.5 * g.effective_length_m);
        assert!(inside * edge < 0.0, "sign change: {inside} vs {edge}");
        // Grows away from the rolling point, on both sides.
        let half = 0.5 * g.effective_length_m;
        let mut prev = 0.0;
        for k in 1..=10 {
            let sk = s0 + (half - s0) * k as f64 / 10.0;
            let v = vs(sk).abs();
            assert!(v > prev);
            prev = v;
        }
        let mut prev = 0.0;
        for k in 1..=10 {
            let sk = s0 - s0 * k as f64 / 10.0;
            let v = vs(sk).abs();
            assert!(v > prev);
            prev = v;
        }
    }

    /// With a contact angle, App. C speeds roll purely at the mid-plane: sliding is odd
    /// to first order in s (ring radius changes by −s sin β) so it changes sign across
    /// the centre and grows with |s| near it. Exact zero at s = 0 to 1e-12 (round-off).
    #[test]
    fn sliding_with_contact_angle_changes_sign_at_centre() {
        let b = Bearing::example_aerospace();
        let g = b.geometry;
        let (pt, d, ro, beta) = (
            g.pitch_diameter_m,
            g.roller_diameter_m,
            g.roller_crown_radius_m,
            g.contact_angle_rad,
        );
        let w1 = b.operating.inner_speed_rad_s;
        let cage = cage_speed_estimate(w1, 0.0, g.theta());
        let spin = roller_spin_estimate(w1, 0.0, g.theta(), d, pt);
        let c = [0.0, pt / 2.0, 0.0];
        let a = roller_axis(beta);
        let vs = |s: f64| {
            sliding_velocity(
                crowned_inner_point(pt, d, ro, beta, s),
                w1,
                cage,
                c,
                a,
                spin,
            )
        };
        // Near the centre the linear term −(Ω₁ − Ω_cg)·s·sin β dominates the crown's
        // quadratic one (which is even in s and wins near the edges of this roller).
        let e = 0.1 * 0.5 * g.effective_length_m;
        assert!(vs(0.0).abs() < 1e-12 * w1 * pt);
        assert!(vs(e) * vs(-e) < 0.0);
        assert!(vs(e).abs() > vs(0.5 * e).abs());
        assert!(vs(-e).abs() > vs(-0.5 * e).abs());
        // Zero axis: the roller contributes nothing, no NaN.
        let v = sliding_velocity([0.0, 0.04, 0.0], 10.0, 0.0, c, [0.0; 3], 5.0);
        assert!((v - 0.4).abs() < 1e-15);
    }
}
