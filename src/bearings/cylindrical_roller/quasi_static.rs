//! Quasi-static lamina load distribution of a radially loaded cylindrical roller bearing
//! and its 2×2 ring stiffness (issue 25, model item 1).
//!
//! Each roller is cut into `slices` equal laminae along its length, each carrying the
//! project's lamina law (Palmgren, [`LaminaLaw`]) at its approach less the profile drop
//! (dub-off of seed 003 eq. 7 or the ISO/TS 16281 logarithmic profile), inner and outer
//! in series; each roller's radial position balances its inner and outer loads with the
//! centrifugal force (W_o = W_i + F_c); the inner ring's (x, y) balances the load by
//! Newton with the analytic stiffness. Rings are rigid; the rollers do not tilt (the
//! profile and the load are symmetric about the roller's middle in this 2-DOF model).

use crate::numerics::cancel::Cancel;
use crate::physics::contact::lamina_law::{ninth_root, LaminaLaw};
use crate::physics::contact::line::{line_contact_reduced, reduced_modulus, Elastic};
use crate::physics::material::Material;

/// The axial profile of the rollers (both ends alike).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Profile {
    /// Straight in the middle, a circular dub-off of radius `radius_m` over the last
    /// `length_m` at each end (seed 003 eq. 7): drop s(Y) = (l_d − Y)²/(2 R_d) for Y < l_d.
    DubOff {
        /// Dub-off radius R_d, m.
        radius_m: f64,
        /// Dub-off length l_d at each end, m.
        length_m: f64,
    },
    /// The ISO/TS 16281 logarithmic profile for the roller's length.
    Logarithmic,
}

/// Everything the lamina solve needs, SI. Built by the system from its deck.
#[derive(Debug, Clone, PartialEq)]
pub struct QuasiStaticModel {
    /// Number of rollers m.
    pub roller_count: usize,
    /// Azimuth of roller 1, rad from +x (roller i at this + 2π(i−1)/m).
    pub first_azimuth_rad: f64,
    /// Roller radius, m.
    pub roller_radius_m: f64,
    /// Inner raceway radius, m.
    pub inner_raceway_radius_m: f64,
    /// Outer raceway radius, m.
    pub outer_raceway_radius_m: f64,
    /// Roller length (end to end), m.
    pub roller_length_m: f64,
    /// The rollers' axial profile.
    pub profile: Profile,
    /// Slices (laminae) per roller.
    pub slices: usize,
    /// Radial interference ρ, m (negative: radial clearance; C = −ρ in seed 003 eq. 3).
    pub radial_interference_m: f64,
    /// Centrifugal force on each roller, N (pushes it onto the outer race).
    pub centrifugal_n: f64,
    /// Roller material.
    pub roller: Material,
    /// Inner ring material.
    pub inner: Material,
    /// Outer ring material.
    pub outer: Material,
    /// Force the shaft applies to the inner ring (applied load plus weight), N: (F_x, F_y).
    pub load_n: [f64; 2],
    /// Force tolerance, relative to |load| (dimensionless).
    pub tolerance: f64,
}

/// One slice of one roller in equilibrium.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SliceState {
    /// Axial position of the slice centre from the roller's middle, m.
    pub axial_m: f64,
    /// Profile drop of the roller at this slice, m.
    pub profile_drop_m: f64,
    /// Inner contact load of the slice, N.
    pub inner_load_n: f64,
    /// Outer contact load of the slice, N.
    pub outer_load_n: f64,
    /// Inner contact Hertz half-width, m.
    pub inner_half_width_m: f64,
    /// Outer contact Hertz half-width, m.
    pub outer_half_width_m: f64,
    /// Inner contact maximum Hertz pressure, Pa.
    pub inner_max_pressure_pa: f64,
    /// Outer contact maximum Hertz pressure, Pa.
    pub outer_max_pressure_pa: f64,
}

/// One roller in equilibrium.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RollerState {
    /// Azimuth, rad from +x.
    pub azimuth_rad: f64,
    /// Inner contact load, N.
    pub inner_load_n: f64,
    /// Outer contact load, N (inner + centrifugal when loaded).
    pub outer_load_n: f64,
    /// Inner contact approach, m.
    pub inner_approach_m: f64,
    /// Outer contact approach, m.
    pub outer_approach_m: f64,
    /// Slices, from one end to the other.
    pub slices: Vec<SliceState>,
    /// Tilt θ in the radial–axial plane, rad: a point at axial y moves radially by −θ·y
    /// (0 without axial load; `super::quasi_static_ribs`).
    pub tilt_rad: f64,
    /// Axial position of the roller, m (0 without axial load).
    pub axial_position_m: f64,
    /// Normal load of the inner ring's rib on the roller end, N (0 without axial load).
    pub inner_rib_load_n: f64,
    /// Normal load of the outer ring's rib on the roller end, N (equal to the inner's:
    /// the roller's axial balance).
    pub outer_rib_load_n: f64,
    /// The rib load of the roller, N: the mean of the two (which are equal in
    /// equilibrium).
    pub rib_load_n: f64,
}

/// The solved bearing.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct QuasiStatic {
    /// Inner-ring displacement (x, y) relative to the outer ring, m.
    pub displacement_m: [f64; 2],
    /// Rollers, in roller order.
    pub rollers: Vec<RollerState>,
    /// Ring stiffness ∂F/∂(x, y), N/m (analytic, symmetric).
    pub stiffness_n_m: [[f64; 2]; 2],
    /// Newton iterations of the ring equilibrium.
    pub iterations: usize,
    /// Final force residual, N.
    pub residual_n: f64,
    /// Axial displacement z of the inner ring, m (0 without axial load).
    pub axial_displacement_m: f64,
    /// The 3×3 ring stiffness ∂(F_x, F_y, F_z)/∂(x, y, z), N/m, when ribs carry axial
    /// load (`None`: the 2×2 radial one is the whole story).
    pub stiffness_xyz_n_m: Option<[[f64; 3]; 3]>,
}

/// Why the lamina solve failed, with the numbers, phrased for a person.
#[derive(Debug, Clone, PartialEq)]
pub enum QuasiStaticError {
    /// The inputs cannot describe a bearing.
    Invalid(String),
    /// No equilibrium within the iteration bound.
    NotConverged {
        /// Iterations used.
        iterations: usize,
        /// Force residual, N.
        residual_n: f64,
        /// The tolerance asked, N.
        tolerance_n: f64,
    },
    /// Cancelled by the caller.
    Cancelled,
}

impl std::fmt::Display for QuasiStaticError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            QuasiStaticError::Invalid(m) => write!(f, "{m}"),
            QuasiStaticError::NotConverged {
                iterations,
                residual_n,
                tolerance_n,
            } => write!(
                f,
                "the ring equilibrium did not converge in {iterations} iterations: force residual {residual_n:.3e} N against a tolerance of {tolerance_n:.3e} N"
            ),
            QuasiStaticError::Cancelled => write!(f, "cancelled"),
        }
    }
}

impl std::error::Error for QuasiStaticError {}

/// Newton iterations of the ring equilibrium before [`QuasiStaticError::NotConverged`].
pub const MAX_RING_ITERATIONS: usize = 100;

/// Iterations of one roller's radial equilibrium (bracketed Newton; bisection halves the
/// bracket each time it falls back, so 200 covers any f64 bracket).
const MAX_ROLLER_ITERATIONS: usize = 200;

/// Segments per slice. A slice's load is the lamina law integrated exactly over its width
/// with the profile drop interpolated linearly between SUB_LAMINAE + 1 nodes (closed form,
/// see [`segment`]), so a slice straddling the end of the loaded length (where the
/// dub-off's drop reaches the approach) carries its exact share. Sampling the drop at the
/// slice centre instead made the truck bearing's W_max differ by 1.2 % between 21 and 161
/// slices (and the stiffness by 2e-3 with 8 midpoint sub-laminae); now 21 slices are
/// within 1e-3 of 161 (issue 25 validation 7, tested). Segments of equal end drops (the
/// straight part, mirror pairs) share one evaluation.
pub const SUB_LAMINAE: usize = 16;

/// ISO/TS 16281's default logarithmic relief coefficient: drop(y) = 0.00035·D_we·
/// ln[1/(1 − (2y/L_we)²)] (the standard's profile when none is given; about 3 000 MPa).
pub const ISO_16281_LOG_COEFFICIENT: f64 = 0.00035;

impl Profile {
    /// Profile drop (m) at axial position `y_m` from the roller's middle, on a roller of
    /// length `length_m` and radius `radius_m`.
    ///
    /// Dub-off (seed 003 eq. 7): with Y the distance from the nearer end,
    /// s = (l_d − Y)²/(2R_d) for Y < l_d and 0 on the straight part (the X²/2R_x term of
    /// eq. 7 is the rolling-direction curvature, which the line contact carries).
    /// Logarithmic (ISO/TS 16281): 0.00035·D·ln[1/(1 − (2y/l)²)], infinite at the ends
    /// (slice centres never reach them).
    pub fn drop_m(&self, y_m: f64, length_m: f64, radius_m: f64) -> f64 {
        let half = 0.5 * length_m;
        match *self {
            Profile::DubOff {
                radius_m: rd,
                length_m: ld,
            } => {
                let from_end = half - y_m.abs();
                if from_end < ld {
                    let r = ld - from_end;
                    r * r / (2.0 * rd)
                } else {
                    0.0
                }
            }
            Profile::Logarithmic => {
                let u = y_m / half;
                let inside = 1.0 - u * u;
                if inside > 0.0 {
                    -ISO_16281_LOG_COEFFICIENT * 2.0 * radius_m * inside.ln()
                } else {
                    f64::INFINITY
                }
            }
        }
    }
}

impl QuasiStaticModel {
    /// The effective length L of Palmgren's law (the L^(1/9) of every slice's law), m:
    /// the straight part l − 2l_d of a dub-off roller (the 16 mm of the truck bearing,
    /// issue 25 trap 3), the whole length of a logarithmic one (ISO/TS 16281's L_we).
    pub fn effective_length_m(&self) -> f64 {
        match self.profile {
            Profile::DubOff { length_m, .. } => self.roller_length_m - 2.0 * length_m,
            Profile::Logarithmic => self.roller_length_m,
        }
    }

    /// The k_n of the 2-DOF model for this bearing (see [`effective_contact_stiffness`]).
    pub fn contact_stiffness(&self) -> Result<f64, QuasiStaticError> {
        validate(self)?;
        effective_contact_stiffness(
            self.effective_length_m(),
            &self.roller,
            &self.inner,
            &self.outer,
        )
    }
}

/// The contact stiffness k_n (N/m^(10/9)) of seed 003 eq. 2, W = k_n·δ^(10/9), where δ is
/// the per-contact approach (half the roller's total radial approach, eq. 3:
/// 2δ = 2(h − C) + x cos θ + y sin θ), from the slice law of a straight roller of
/// effective length L with its two contacts in series.
///
/// Each contact of the whole roller follows Palmgren's law W = K_c·δ_c^(10/9) with
/// K_c = L^(8/9)/(C·K̄^2.7)^(10/9) (the lamina law summed over the length). In series
/// the total approach is δ_i + δ_o = W^(9/10)·(K_i^(−9/10) + K_o^(−9/10)) = 2δ, so
/// k_n = [2/(K_i^(−9/10) + K_o^(−9/10))]^(10/9); for equal materials k_n = K_c. For the
/// truck bearing (L = 16 mm, steel) this is 2.0e9 N/m^(10/9) (issue 25 trap 3).
pub fn effective_contact_stiffness(
    effective_length_m: f64,
    roller: &Material,
    inner: &Material,
    outer: &Material,
) -> Result<f64, QuasiStaticError> {
    if !(effective_length_m > 0.0 && effective_length_m.is_finite()) {
        return Err(QuasiStaticError::Invalid(format!(
            "the rollers' effective length must be positive and finite, got {effective_length_m} m"
        )));
    }
    for (name, m) in [
        ("roller", roller),
        ("inner ring", inner),
        ("outer ring", outer),
    ] {
        check_material(name, m)?;
    }
    let l = effective_length_m;
    let k_i = LaminaLaw::new(l, l, roller, inner).stiffness;
    let k_o = LaminaLaw::new(l, l, roller, outer).stiffness;
    let compliance = k_i.powf(-0.9) + k_o.powf(-0.9);
    Ok((2.0 / compliance).powf(10.0 / 9.0))
}

fn check_material(name: &str, m: &Material) -> Result<(), QuasiStaticError> {
    if !(m.youngs_modulus_pa > 0.0 && m.youngs_modulus_pa.is_finite()) {
        return Err(QuasiStaticError::Invalid(format!(
            "the {name}'s Young's modulus must be positive and finite, got {} Pa",
            m.youngs_modulus_pa
        )));
    }
    if !(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5) {
        return Err(QuasiStaticError::Invalid(format!(
            "the {name}'s Poisson ratio must lie in (-1, 0.5), got {}",
            m.poisson_ratio
        )));
    }
    Ok(())
}

fn positive(name: &str, v: f64, unit: &str) -> Result<(), QuasiStaticError> {
    if v > 0.0 && v.is_finite() {
        Ok(())
    } else {
        Err(QuasiStaticError::Invalid(format!(
            "{name} must be positive and finite, got {v} {unit}"
        )))
    }
}

/// Checks that the model describes a bearing; every message names the field and range.
pub(super) fn validate(m: &QuasiStaticModel) -> Result<(), QuasiStaticError> {
    if !(3..=1000).contains(&m.roller_count) {
        return Err(QuasiStaticError::Invalid(format!(
            "roller_count must lie in 3..=1000, got {}",
            m.roller_count
        )));
    }
    if !(1..=10_000).contains(&m.slices) {
        return Err(QuasiStaticError::Invalid(format!(
            "slices must lie in 1..=10000, got {}",
            m.slices
        )));
    }
    positive("roller_radius_m", m.roller_radius_m, "m")?;
    positive("inner_raceway_radius_m", m.inner_raceway_radius_m, "m")?;
    positive("outer_raceway_radius_m", m.outer_raceway_radius_m, "m")?;
    positive("roller_length_m", m.roller_length_m, "m")?;
    if !(m.outer_raceway_radius_m > m.roller_radius_m) {
        return Err(QuasiStaticError::Invalid(format!(
            "outer_raceway_radius_m ({} m) must exceed roller_radius_m ({} m)",
            m.outer_raceway_radius_m, m.roller_radius_m
        )));
    }
    if let Profile::DubOff { radius_m, length_m } = m.profile {
        positive("the dub-off radius", radius_m, "m")?;
        if !(length_m >= 0.0 && 2.0 * length_m < m.roller_length_m) {
            return Err(QuasiStaticError::Invalid(format!(
                "the dub-off length must lie in [0, roller_length/2) = [0, {} m), got {length_m} m",
                0.5 * m.roller_length_m
            )));
        }
    }
    if !(m.radial_interference_m.is_finite() && m.radial_interference_m.abs() < m.roller_radius_m) {
        return Err(QuasiStaticError::Invalid(format!(
            "radial_interference_m must be finite and smaller in size than the roller radius {} m, got {} m",
            m.roller_radius_m, m.radial_interference_m
        )));
    }
    if !(m.centrifugal_n >= 0.0 && m.centrifugal_n.is_finite()) {
        return Err(QuasiStaticError::Invalid(format!(
            "centrifugal_n must be non-negative and finite, got {} N",
            m.centrifugal_n
        )));
    }
    if !(m.first_azimuth_rad.is_finite()) {
        return Err(QuasiStaticError::Invalid(format!(
            "first_azimuth_rad must be finite, got {}",
            m.first_azimuth_rad
        )));
    }
    if !(m.load_n[0].is_finite() && m.load_n[1].is_finite()) {
        return Err(QuasiStaticError::Invalid(format!(
            "load_n must be finite, got ({}, {}) N",
            m.load_n[0], m.load_n[1]
        )));
    }
    if !(m.tolerance >= 1e-15 && m.tolerance <= 0.1) {
        return Err(QuasiStaticError::Invalid(format!(
            "tolerance must lie in [1e-15, 0.1], got {}",
            m.tolerance
        )));
    }
    check_material("roller", &m.roller)?;
    check_material("inner ring", &m.inner)?;
    check_material("outer ring", &m.outer)?;
    Ok(())
}

/// (a₊^p − b₊^p)/(a − b) for a > b and p = m + 1/9 (m = 1, 2, 3), returned for the three
/// m at once, free of cancellation however close a and b are: with r = x^(1/9),
/// a^p − b^p = a^m·(r_a − r_b) + r_b·(a^m − b^m), r_a − r_b = (a − b)/Σ_{k=0}^{8} r_a^k r_b^(8−k)
/// and a^m − b^m = (a − b)·Σ_{k<m} a^k b^(m−1−k): every term positive. Two ninth roots,
/// no other transcendental (the hot loop of the dub-off's segments).
#[inline]
fn divided_powers(a: f64, b: f64) -> [f64; 3] {
    let ra = ninth_root(a);
    if b <= 0.0 {
        let inv = 1.0 / (a - b);
        let a10 = a * ra;
        return [a10 * inv, a10 * a * inv, a10 * a * a * inv];
    }
    let rb = ninth_root(b);
    // S = Σ_{k=0}^{8} r_a^k·r_b^(8−k) by Horner in r_a.
    let mut sum = 1.0;
    let mut pb = 1.0;
    for _ in 0..8 {
        pb *= rb;
        sum = pb + ra * sum;
    }
    let inv = 1.0 / sum;
    [
        a * inv + rb,
        a * a * inv + rb * (a + b),
        a * a * a * inv + rb * (a * a + a * b + b * b),
    ]
}

/// A segment of the lamina law whose approach varies linearly from `ua` to `ub` across
/// it: the law integrated exactly, (Q, dQ/dδ, U) for a common shift δ of both ends.
/// With q(u) = k·u₊^(10/9) per segment width, the mean over the segment is
/// k·[G(ua) − G(ub)]/(ua − ub) with G = (9/19)·u₊^(19/9); dQ/dδ is the divided difference
/// of u₊^(10/9) and U that of (9/19)(9/28)·u₊^(28/9). Equal ends: the law itself.
#[inline]
fn segment(law: &LaminaLaw, ua: f64, ub: f64) -> (f64, f64, f64) {
    if ua == ub {
        return law.eval(ua);
    }
    let (a, b) = if ua > ub { (ua, ub) } else { (ub, ua) };
    if a <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let k = law.stiffness;
    let [d10, d19, d28] = divided_powers(a, b);
    (k * (9.0 / 19.0) * d19, k * d10, k * (81.0 / 532.0) * d28)
}

/// One roller's radial equilibrium at a ring approach.
#[derive(Debug, Clone, Copy, Default)]
struct RollerEq {
    /// The roller's outward radial position s, m (see [`Prepared`]).
    s: f64,
    /// Inner and outer contact loads, N.
    w_in: f64,
    w_out: f64,
    /// dW_in/dp at fixed roller position and dW_out/ds, N/m (the a, b of the series law).
    k_in: f64,
    k_out: f64,
    /// The roller's potential E(p) = min_s [U_in + U_out − F_c·s], J (dE/dp = W_in).
    energy: f64,
}

impl RollerEq {
    /// dW_in/dp with the roller in equilibrium: the two contacts in series, ab/(a + b).
    fn stiffness(&self) -> f64 {
        let sum = self.k_in + self.k_out;
        if sum > 0.0 {
            self.k_in * self.k_out / sum
        } else {
            0.0
        }
    }
}

/// The solve's fixed data.
///
/// Kinematics (seed 003 eq. 3 with C = −ρ, film off): roller j at azimuth ψ_j sees the
/// inner ring's approach p = x cos ψ + y sin ψ; with s its outward radial position, a
/// slice with profile drop d_k has the inner approach δ_i = p + ρ − s − d_k and the outer
/// δ_o = s + ρ − d_k, so the roller's total radial approach at the straight part is
/// p + 2ρ (eq. 3's 2δ with ρ per contact): a diametral clearance P_d is ρ = −P_d/4.
/// The roller is in equilibrium when W_o = W_i + F_c.
struct Prepared {
    cos: Vec<f64>,
    sin: Vec<f64>,
    /// Distinct segments (the drops at their two ends, smaller first) and their
    /// multiplicities (symmetric pairs and the straight part share one evaluation: most
    /// of the solve's cost saved).
    drops: Vec<(f64, f64)>,
    counts: Vec<f64>,
    /// For each slice (end to end): its axial position, its profile drop at the centre
    /// (reported), and the drop indices of its [`SUB_LAMINAE`] sub-laminae.
    slice_axial: Vec<f64>,
    slice_drop: Vec<f64>,
    slice_groups: Vec<[usize; SUB_LAMINAE]>,
    width: f64,
    law_in: LaminaLaw,
    law_out: LaminaLaw,
    rho: f64,
    fc: f64,
    d_min: f64,
    d_max: f64,
}

impl Prepared {
    fn new(m: &QuasiStaticModel) -> Result<Self, QuasiStaticError> {
        let z = m.roller_count;
        let step = std::f64::consts::TAU / z as f64;
        let (sin, cos): (Vec<f64>, Vec<f64>) = (0..z)
            .map(|j| (m.first_azimuth_rad + step * j as f64).sin_cos())
            .unzip();
        let n = m.slices;
        let l = m.roller_length_m;
        let width = l / n as f64;
        let mut drops: Vec<(f64, f64)> = Vec::new();
        let mut counts: Vec<f64> = Vec::new();
        let mut slice_axial = Vec::with_capacity(n);
        let mut slice_drop = Vec::with_capacity(n);
        let mut slice_groups = Vec::with_capacity(n);
        let drop_at = |y_abs: f64| {
            let d = m.profile.drop_m(y_abs, l, m.roller_radius_m);
            // +∞ only at the very end of the logarithmic profile: that segment's contact
            // length is then zero.
            if d >= 0.0 {
                Ok(d)
            } else {
                Err(QuasiStaticError::Invalid(format!(
                    "the roller profile's drop at {y_abs:.4e} m from the middle is {d} m: not a finite relief"
                )))
            }
        };
        for k in 0..n {
            // Mirror-exact: both slices of a symmetric pair compute the same |y|, so the
            // pair shares its evaluations.
            let j = k.min(n - 1 - k);
            let y_abs = 0.5 * l - (j as f64 + 0.5) * width;
            let y = if k < n - 1 - k { -y_abs } else { y_abs };
            let mut groups = [0usize; SUB_LAMINAE];
            for (i, slot) in groups.iter_mut().enumerate() {
                let node = |i: usize| (j as f64 + i as f64 / SUB_LAMINAE as f64) * width;
                let da = drop_at(0.5 * l - node(i))?;
                let db = drop_at(0.5 * l - node(i + 1))?;
                let d = (da.min(db), da.max(db));
                *slot = match drops.iter().position(|&x| x == d) {
                    Some(g) => g,
                    None => {
                        drops.push(d);
                        counts.push(0.0);
                        drops.len() - 1
                    }
                };
                counts[*slot] += 1.0;
            }
            slice_axial.push(y);
            slice_drop.push(drop_at(y_abs)?);
            slice_groups.push(groups);
        }
        let l_eff = m.effective_length_m();
        let sub_width = width / SUB_LAMINAE as f64;
        let law_in = LaminaLaw::new(sub_width, l_eff, &m.roller, &m.inner);
        let law_out = LaminaLaw::new(sub_width, l_eff, &m.roller, &m.outer);
        let d_min = drops.iter().map(|d| d.0).fold(f64::INFINITY, f64::min);
        let d_max = drops
            .iter()
            .map(|d| d.1)
            .filter(|d| d.is_finite())
            .fold(0.0, f64::max);
        Ok(Prepared {
            cos,
            sin,
            drops,
            counts,
            slice_axial,
            slice_drop,
            slice_groups,
            width,
            law_in,
            law_out,
            rho: m.radial_interference_m,
            fc: m.centrifugal_n,
            d_min,
            d_max,
        })
    }

    /// Σ over slices of the law at approach base − d_k: (W, dW/dbase, U).
    #[inline]
    fn sum(&self, law: &LaminaLaw, base: f64) -> (f64, f64, f64) {
        let (mut w, mut k, mut u) = (0.0, 0.0, 0.0);
        for (&(da, db), c) in self.drops.iter().zip(&self.counts) {
            let (q, dq, e) = segment(law, base - da, base - db);
            w += c * q;
            k += c * dq;
            u += c * e;
        }
        (w, k, u)
    }

    /// The roller's radial equilibrium at ring approach `p`, starting from `guess`.
    fn roller(&self, p: f64, guess: f64) -> RollerEq {
        let rho = self.rho;
        let fc = self.fc;
        // W_o = 0 for s ≤ lo; W_i = 0 for s ≥ s_in_off.
        let lo = self.d_min - rho;
        let s_in_off = p + rho - self.d_min;
        let g = |s: f64| {
            let (wi, ki, ui) = self.sum(&self.law_in, p + rho - s);
            let (wo, ko, uo) = self.sum(&self.law_out, s + rho);
            (wo - wi - fc, ki + ko, wi, wo, ki, ko, ui + uo)
        };
        if s_in_off <= lo && fc == 0.0 {
            // Off both races: the roller floats in the gap and carries nothing.
            return RollerEq {
                s: 0.5 * (lo + s_in_off),
                ..RollerEq::default()
            };
        }
        // Bracket [a, b] with g(a) ≤ 0 ≤ g(b). g is non-decreasing in s.
        let a = lo;
        let mut b = s_in_off.max(lo);
        if g(b).0 < 0.0 {
            // Only the outer race can carry F_c: every slice at least at the largest drop
            // gives W_o(b) ≥ N·k·(b + ρ − d_max)^(10/9) = F_c.
            let n: f64 = self.counts.iter().sum();
            b = b.max(self.d_max - rho + (fc / (n * self.law_out.stiffness)).powf(0.9));
            // Round-off can leave g(b) a hair below zero; widen until it is not.
            let mut widen = (b - a).abs().max(1e-12);
            let mut tries = 0;
            while g(b).0 < 0.0 && tries < 60 {
                b += widen;
                widen *= 2.0;
                tries += 1;
            }
        }
        let (mut a, mut b) = (a, b);
        let mut s = if guess > a && guess < b {
            guess
        } else {
            0.5 * (a + b)
        };
        let mut best = g(s);
        for _ in 0..MAX_ROLLER_ITERATIONS {
            let (r, dr, wi, wo, ..) = best;
            let scale = wi + wo + fc;
            if r.abs() <= 1e-14 * scale || r == 0.0 {
                break;
            }
            if r < 0.0 {
                a = s;
            } else {
                b = s;
            }
            let newton = if dr > 0.0 { s - r / dr } else { f64::NAN };
            let next = if newton > a && newton < b {
                newton
            } else {
                0.5 * (a + b)
            };
            if next == s || !(b - a > 0.0) || next <= a && next >= b {
                break;
            }
            s = next;
            best = g(s);
        }
        let (_, _, w_in, w_out, k_in, k_out, u) = best;
        RollerEq {
            s,
            w_in,
            w_out,
            k_in,
            k_out,
            energy: u - fc * s,
        }
    }
}

/// Ring state: rollers in equilibrium at (x, y), the force residual, stiffness, potential.
struct RingEval {
    rollers: Vec<RollerEq>,
    residual: [f64; 2],
    stiffness: [[f64; 2]; 2],
    potential: f64,
}

fn evaluate(prep: &Prepared, load: [f64; 2], xy: [f64; 2], guesses: &[f64]) -> RingEval {
    let mut force = [0.0; 2];
    let mut k = [[0.0; 2]; 2];
    let mut potential = -(load[0] * xy[0] + load[1] * xy[1]);
    let rollers: Vec<RollerEq> = (0..prep.cos.len())
        .map(|j| {
            let (c, s) = (prep.cos[j], prep.sin[j]);
            let r = prep.roller(xy[0] * c + xy[1] * s, guesses[j]);
            force[0] += r.w_in * c;
            force[1] += r.w_in * s;
            let kj = r.stiffness();
            k[0][0] += kj * c * c;
            k[0][1] += kj * c * s;
            k[1][1] += kj * s * s;
            potential += r.energy;
            r
        })
        .collect();
    k[1][0] = k[0][1];
    RingEval {
        rollers,
        residual: [force[0] - load[0], force[1] - load[1]],
        stiffness: k,
        potential,
    }
}

fn norm(v: [f64; 2]) -> f64 {
    v[0].hypot(v[1])
}

/// Solves the ring equilibrium from `start` (a previous solution, for warm starts) or
/// from rest.
///
/// The contact forces on the inner ring, Σ_j W_i,j·(cos ψ_j, sin ψ_j), balance `load_n`.
/// They are the gradient of the convex potential Φ(x, y) = Σ_j E_j(p_j) − F·(x, y)
/// (E_j the roller's elastic energy minimised over its radial position, a partial
/// minimum of a jointly convex function), so Newton with the analytic stiffness and an
/// Armijo line search on Φ converges from any start; the stiffness is regularised by
/// 1e-12 of its trace where rollers are off (it is singular with one roller loaded).
/// Converged when |ΣW − F| ≤ tolerance·max(|F|, 1 N) (or the round-off floor, 1e-14 of
/// the summed roller loads, when that is larger).
pub fn solve(
    model: &QuasiStaticModel,
    start: Option<&QuasiStatic>,
    cancel: &Cancel,
) -> Result<QuasiStatic, QuasiStaticError> {
    validate(model)?;
    let prep = Prepared::new(model)?;
    let z = model.roller_count;
    let load = model.load_n;
    let load_abs = norm(load);
    let tol_n = model.tolerance * load_abs.max(1.0);
    // A roller's whole-length contact stiffness: the scale of a first step.
    let n_slices: f64 = prep.counts.iter().sum();
    let k_roller = n_slices * prep.law_in.stiffness.min(prep.law_out.stiffness);
    // Stribeck's W_max ≈ 4.1·F/Z at a per-contact approach (W/K)^(9/10), plus the gap.
    let delta_ref = (4.1 * load_abs / z as f64 / k_roller).powf(0.9);
    let reach = (2.0 * delta_ref + 2.0 * prep.d_min - 2.0 * prep.rho).max(0.0);
    let mut xy = match start {
        Some(s) if s.displacement_m.iter().all(|v| v.is_finite()) => s.displacement_m,
        _ if load_abs > 0.0 => [load[0] / load_abs * reach, load[1] / load_abs * reach],
        _ => [0.0, 0.0],
    };
    // Step-length scale: no Newton step longer than this (the potential's line search
    // shortens further).
    let step_cap = 10.0 * (reach + delta_ref + prep.rho.abs() + prep.d_max).max(1e-9);
    let mut guesses: Vec<f64> = (0..z)
        .map(|j| 0.5 * (xy[0] * prep.cos[j] + xy[1] * prep.sin[j]))
        .collect();
    let mut ring = evaluate(&prep, load, xy, &guesses);
    let mut iterations = 0;
    loop {
        let r = norm(ring.residual);
        // The round-off floor: the residual is a sum of roller loads, each exact to a few
        // ulp, so a preloaded bearing under no load cannot go below ~1e-14 of their sum.
        let floor = 1e-14 * ring.rollers.iter().map(|e| e.w_in).sum::<f64>();
        if r <= tol_n.max(floor) {
            break;
        }
        if iterations >= MAX_RING_ITERATIONS {
            return Err(QuasiStaticError::NotConverged {
                iterations,
                residual_n: r,
                tolerance_n: tol_n,
            });
        }
        if cancel.is_cancelled() {
            return Err(QuasiStaticError::Cancelled);
        }
        iterations += 1;
        let k = ring.stiffness;
        let trace = k[0][0] + k[1][1];
        let mut dir = if trace > 0.0 {
            let mu = 1e-12 * trace;
            let (a, b, d) = (k[0][0] + mu, k[0][1], k[1][1] + mu);
            let det = a * d - b * b;
            let (rx, ry) = (ring.residual[0], ring.residual[1]);
            [-(d * rx - b * ry) / det, -(a * ry - b * rx) / det]
        } else {
            // No roller touches: move along the unbalanced force.
            [
                -ring.residual[0] / r * step_cap,
                -ring.residual[1] / r * step_cap,
            ]
        };
        let len = norm(dir);
        if !(len.is_finite()) || len > step_cap {
            let f = if len.is_finite() { step_cap / len } else { 0.0 };
            dir = if f > 0.0 {
                [dir[0] * f, dir[1] * f]
            } else {
                [
                    -ring.residual[0] / r * step_cap,
                    -ring.residual[1] / r * step_cap,
                ]
            };
        }
        let slope = ring.residual[0] * dir[0] + ring.residual[1] * dir[1];
        for (g, roller) in guesses.iter_mut().zip(&ring.rollers) {
            *g = roller.s;
        }
        let mut alpha = 1.0;
        let mut accepted = None;
        for _ in 0..60 {
            let trial = [xy[0] + alpha * dir[0], xy[1] + alpha * dir[1]];
            let e = evaluate(&prep, load, trial, &guesses);
            // Armijo on the potential, or a smaller residual (near the solution the
            // potential's differences are lost to round-off; the residual's are not).
            if e.potential <= ring.potential + 1e-4 * alpha * slope || norm(e.residual) < 0.5 * r {
                accepted = Some((trial, e));
                break;
            }
            alpha *= 0.5;
        }
        match accepted {
            Some((trial, e)) => {
                xy = trial;
                ring = e;
            }
            None => {
                return Err(QuasiStaticError::NotConverged {
                    iterations,
                    residual_n: r,
                    tolerance_n: tol_n,
                })
            }
        }
    }
    Ok(report(model, &prep, xy, &ring, iterations))
}

/// Builds the reported state, slices and all, from a converged ring.
fn report(
    model: &QuasiStaticModel,
    prep: &Prepared,
    xy: [f64; 2],
    ring: &RingEval,
    iterations: usize,
) -> QuasiStatic {
    let elastic = |m: &Material| Elastic {
        youngs_modulus_pa: m.youngs_modulus_pa,
        poisson_ratio: m.poisson_ratio,
    };
    let r = model.roller_radius_m;
    // 1/R = 1/r + 1/R_i (convex inner race), 1/r − 1/R_o (concave outer; R_o > r checked).
    let radius_in = 1.0 / (1.0 / r + 1.0 / model.inner_raceway_radius_m);
    let radius_out = 1.0 / (1.0 / r - 1.0 / model.outer_raceway_radius_m);
    let e_in = reduced_modulus(elastic(&model.roller), elastic(&model.inner));
    let e_out = reduced_modulus(elastic(&model.roller), elastic(&model.outer));
    let step = std::f64::consts::TAU / model.roller_count as f64;
    let w = prep.width;
    let rollers = ring
        .rollers
        .iter()
        .enumerate()
        .map(|(j, eq)| {
            let p = xy[0] * prep.cos[j] + xy[1] * prep.sin[j];
            let base_in = p + prep.rho - eq.s;
            let base_out = eq.s + prep.rho;
            let slices = (0..prep.slice_axial.len())
                .map(|k| {
                    let (mut qi, mut qo) = (0.0, 0.0);
                    for &g in &prep.slice_groups[k] {
                        let (da, db) = prep.drops[g];
                        qi += segment(&prep.law_in, base_in - da, base_in - db).0;
                        qo += segment(&prep.law_out, base_out - da, base_out - db).0;
                    }
                    let ci = line_contact_reduced(qi / w, radius_in, e_in);
                    let co = line_contact_reduced(qo / w, radius_out, e_out);
                    SliceState {
                        axial_m: prep.slice_axial[k],
                        profile_drop_m: prep.slice_drop[k],
                        inner_load_n: qi,
                        outer_load_n: qo,
                        inner_half_width_m: ci.half_width_m,
                        outer_half_width_m: co.half_width_m,
                        inner_max_pressure_pa: ci.max_pressure_pa,
                        outer_max_pressure_pa: co.max_pressure_pa,
                    }
                })
                .collect();
            RollerState {
                azimuth_rad: model.first_azimuth_rad + step * j as f64,
                inner_load_n: eq.w_in,
                outer_load_n: eq.w_out,
                inner_approach_m: base_in,
                outer_approach_m: base_out,
                slices,
                tilt_rad: 0.0,
                axial_position_m: 0.0,
                inner_rib_load_n: 0.0,
                outer_rib_load_n: 0.0,
                rib_load_n: 0.0,
            }
        })
        .collect();
    QuasiStatic {
        displacement_m: xy,
        rollers,
        stiffness_n_m: ring.stiffness,
        iterations,
        residual_n: norm(ring.residual),
        axial_displacement_m: 0.0,
        stiffness_xyz_n_m: None,
    }
}

/// Central finite differences of the ring force Σ_j W_i,j (cos ψ_j, sin ψ_j) with every
/// roller re-solved (to 1e-14 of its load) at the ring displaced by ±h along x and y from
/// `q`'s solution: the check of the analytic 2×2 (issue 29), N/m, and the step h, m.
/// Step rule: h = 1e-5 of the ring offset |(x, y)| (floor 1e-12 m), as the spherical
/// roller's: the slice law's truncation ~ (h/δ)² ≈ 1e-10, round-off ~1e-14/1e-5 of K.
///
/// # Errors
/// The model's own ([`QuasiStaticError`]), as [`solve`].
pub fn finite_difference_stiffness(
    model: &QuasiStaticModel,
    q: &QuasiStatic,
) -> Result<([[f64; 2]; 2], f64), QuasiStaticError> {
    let prep = Prepared::new(model)?;
    let xy = q.displacement_m;
    let h = (1e-5 * norm(xy)).max(1e-12);
    let force = |d: [f64; 2]| -> [f64; 2] {
        let p = [xy[0] + d[0], xy[1] + d[1]];
        let guesses: Vec<f64> = (0..prep.cos.len())
            .map(|j| 0.5 * (p[0] * prep.cos[j] + p[1] * prep.sin[j]))
            .collect();
        // With no load the residual is the rollers' force on the ring.
        evaluate(&prep, [0.0, 0.0], p, &guesses).residual
    };
    let mut k = [[0.0; 2]; 2];
    for col in 0..2 {
        let mut d = [0.0; 2];
        d[col] = h;
        let fp = force(d);
        d[col] = -h;
        let fm = force(d);
        for row in 0..2 {
            k[row][col] = (fp[row] - fm[row]) / (2.0 * h);
        }
    }
    Ok((k, h))
}

#[cfg(test)]
#[path = "quasi_static_tests.rs"]
mod tests;
