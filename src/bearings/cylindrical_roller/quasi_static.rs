//! Quasi-static lamina load distribution of a radially loaded cylindrical roller bearing
//! and its 2×2 ring stiffness (issue 25, model item 1).
//!
//! API skeleton fixed first so that the system's wiring and the solver can be built side
//! by side; the solver body is the statics task's.

use crate::numerics::cancel::Cancel;
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

/// Solves the ring equilibrium from `start` (a previous solution, for warm starts) or
/// from rest.
pub fn solve(
    model: &QuasiStaticModel,
    start: Option<&QuasiStatic>,
    cancel: &Cancel,
) -> Result<QuasiStatic, QuasiStaticError> {
    let _ = (model, start, cancel);
    Err(QuasiStaticError::Invalid(
        "the cylindrical roller's lamina solver is not built yet".to_string(),
    ))
}
