//! The result types of a ball-bearing analysis that the stages below the driver
//! (`analysis`) build or read: one contact, one ball, the skidding threshold and where a
//! rheology traction curve was tabulated. In their own module so that `dynamics` and
//! `load_track` (which read [`BallResult`]) and the driver import them downwards, with
//! no import circle through `analysis`.

use super::race_control::ContactKinematics;
use crate::physics::contact::point::{PointContact, Race};
use crate::physics::lubrication::rheology::ContactStrip;

/// One contact of one ball, everything a report shows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactResult {
    /// Q, N.
    pub load_n: f64,
    /// α, rad.
    pub angle_rad: f64,
    /// δ, m.
    pub deflection_m: f64,
    /// The Hertz contact (semi-axes, p₀).
    pub hertz: PointContact,
    /// E(k), Chen's E₂.
    pub second_kind: f64,
    /// Race-control kinematics.
    pub kinematics: ContactKinematics,
    /// Spin moment (2-13a) with the Coulomb µ_m of the traction curve, N·m.
    pub spin_moment_nm: f64,
    /// Spin heat M_s·|ω_s|, W (2-13b).
    pub spin_heat_w: f64,
    /// Central film, m (4-11); `None` without entrainment.
    pub central_film_m: Option<f64>,
    /// Minimum film, m (4-10).
    pub min_film_m: Option<f64>,
    /// Largest film-centre temperature rise above the inlet in the contact from the
    /// race-control spin (4-3…4-7, `rheology::spin_film_temperature`, traction curve
    /// µ(|ω_s x|)·p), K; `None` without a film.
    pub film_temperature_rise_k: Option<f64>,
    /// Largest surface temperature rise (4-3) of the same calculation, K.
    pub surface_temperature_rise_k: Option<f64>,
    /// EHL rolling resistance F_R of the contact, N (Goksem–Hargreaves by strips,
    /// `physics::lubrication::rolling_resistance`); `None` without load, rolling or α.
    pub rolling_resistance_n: Option<f64>,
    /// Its power F_R·|u|, W (u the race-control entrainment speed); 0 W where `None`.
    pub rolling_resistance_w: f64,
}

/// Where a `traction.curve = "rheology"` curve was tabulated.
#[derive(Debug, Clone, PartialEq)]
pub struct RheologyContact {
    /// Ball index (0-based) and race of the contact.
    pub ball: usize,
    /// Its race.
    pub race: Race,
    /// The strip the curve was computed on (p₀, b, h, V, inlet temperature).
    pub strip: ContactStrip,
}

/// One ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallResult {
    /// ψ, rad.
    pub azimuth_rad: f64,
    /// F_c, N.
    pub centrifugal_n: f64,
    /// M_g = J ω_m ω_r, N·m.
    pub gyroscopic_moment_nm: f64,
    /// 0.5·µ_m·D·(Q_i + Q_o), N·m (2-4, 2-7).
    pub resisting_moment_nm: f64,
    /// |M_g| > resisting moment.
    pub skidding: bool,
    /// Spin heat of the ball, W.
    pub heat_w: f64,
    /// Orbital speed, rad/s.
    pub cage_rad_s: f64,
    /// Ball rotation speed relative to the cage, rad/s.
    pub ball_spin_rad_s: f64,
    /// ω_a, axial component of the ball's absolute angular velocity by race control,
    /// rad/s.
    pub ball_axial_rad_s: f64,
    /// ω_r, its radial component, rad/s.
    pub ball_radial_rad_s: f64,
    /// Controlling race.
    pub control: Race,
    /// Inner contact.
    pub inner: ContactResult,
    /// Outer contact.
    pub outer: ContactResult,
}

/// The skidding threshold.
#[derive(Debug, Clone, PartialEq)]
pub struct SkidThreshold {
    /// Relative ring speed at which |M_g| first reaches 0.5·µ_m·D·(Q_i + Q_o) on some
    /// ball, rad/s; `None` below the search limit.
    pub speed_rad_s: Option<f64>,
    /// Why there is none: no crossing below the limit, or the search failed.
    pub reason: Option<String>,
    /// Whether the search itself failed (a load solve at a sampled speed, or a root it
    /// could not isolate): `reason` says which; the run's other results stand.
    pub search_failed: bool,
    /// The search limit, rad/s.
    pub limit_rad_s: f64,
    /// Load solves spent.
    pub evaluations: usize,
    /// Every speed the search solved, ascending: (relative ring speed rad/s, |M_g| N·m,
    /// resisting moment N·m) of the ball nearest to skidding (the Skid pane's curves,
    /// Figs. 6-4/6-5).
    pub samples: Vec<(f64, f64, f64)>,
}

/// One speed of the skidding search: (relative ring speed rad/s, |M_g| N·m, resisting
/// moment N·m) of the ball nearest to skidding.
pub type SkidSample = (f64, f64, f64);
