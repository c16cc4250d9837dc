//! The SI input of the angular-contact ball bearing system (what a deck of
//! `type = "angular-contact-ball"` becomes), and Chen's Bearings A and B (seed 001 ch. 5)
//! as constructors for tests and decks.

use crate::physics::contact::point::HertzMethod;
use crate::physics::lubrication::rheology::{Rheology, ViscosityModel};
use crate::physics::lubrication::traction_curve::TractionCurve;
use crate::physics::material::Material;

/// Internal geometry (seed 001 ch. 3, Fig. 3-1), SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    /// Z, number of balls.
    pub ball_count: usize,
    /// D, ball diameter, m.
    pub ball_diameter_m: f64,
    /// d_m, pitch diameter, m.
    pub pitch_diameter_m: f64,
    /// f_i, inner groove radius over D (> ½).
    pub inner_groove_curvature: f64,
    /// f_o, outer groove radius over D (> ½).
    pub outer_groove_curvature: f64,
    /// α₀, free (unloaded) contact angle, rad; used when [`Geometry::clearance_m`] is
    /// `None`.
    pub free_contact_angle_rad: f64,
    /// P_d, diametral clearance, m, when the deck gives it instead of α₀
    /// (`geometry.clearance`): α₀ = acos(1 − P_d/(2(f_i + f_o − 1)D)) (Harris; seed 001
    /// Fig. 3-1). `None`: α₀ as given.
    pub clearance_m: Option<f64>,
    /// How κ, K, E of the contact ellipse are found (exact, or the Brewe–Hamrock fits
    /// A-17 that Chen used).
    pub hertz_method: HertzMethod,
}

/// Ball and ring materials (the project's [`Material`]: E, ν, density, c, k).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Materials {
    /// The balls.
    pub ball: Material,
    /// Both rings.
    pub rings: Material,
}

/// How the axial load of the deck is applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PreloadMode {
    /// The seed's reading (default): the axial load fixes the axial displacement of the
    /// inner ring **at rest**; at speed that displacement is held (a rigidly preloaded
    /// spindle pair) and the axial force follows from equilibrium.
    #[default]
    Displacement,
    /// The axial load is a force held at every speed (a spring preload).
    Force,
}

/// Which raceway the race-control theory lets the ball roll on without spin (2-9).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RaceControl {
    /// No spin on the outer race (Chen's choice in ch. 6).
    #[default]
    Outer,
    /// No spin on the inner race.
    Inner,
    /// The race with the larger spin resistance controls (Jones/Harris criterion:
    /// outer when Q_o·a_o·E(k_o)·cos(α_i − α_o) > Q_i·a_i·E(k_i)).
    Auto,
}

impl RaceControl {
    /// The deck spelling.
    pub fn name(self) -> &'static str {
        match self {
            RaceControl::Outer => "outer",
            RaceControl::Inner => "inner",
            RaceControl::Auto => "auto",
        }
    }
}

/// The direction of the contact friction that resists the gyroscopic moment, in the
/// ball equilibrium (2-5a, b).
///
/// The seed prints (2-5a) as Q_i sin α_i − Q_o sin α_o − µQ_i cos α_i + µQ_o cos α_o = 0
/// (Harris's form with a positive M_g). Working the statics out in vectors (see
/// `load_distribution`), the couple that supplies the precession moment J·ω_m·ω_r along
/// the rolling direction has the *opposite* signs; Chen's printed load distribution of
/// ch. 6 is reproduced only with the printed signs. Default: the resisting direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GyroscopicFriction {
    /// Friction forces whose couple about the ball centre equals the gyroscopic moment
    /// J·ω_m·ω_r (physically consistent).
    #[default]
    Resisting,
    /// The signs as printed in eq. 2-5 (reproduces the seed's ch. 6 numbers).
    SeedSign,
}

/// Which traction curve (seed ch. 6, Fig. 6-20).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TractionPreset {
    /// Coulomb friction with [`Traction::mu`].
    Constant,
    /// Chen's curve 1 (µ_m = µ_∞ = 0.054 from 0.2 m/s).
    #[default]
    Curve1,
    /// Chen's curve 2 (0.075 at 0.2 m/s, 0.035 beyond 3 m/s).
    Curve2,
    /// Chen's curve 3 (0.075 at 0.2 m/s, 0.035 beyond 2 m/s).
    Curve3,
    /// The deck's table of (sliding speed m/s, µ) points (`[traction_table] points`),
    /// piecewise linear, constant beyond the last point.
    Table,
    /// Generated from the ch. 4 rheology of `[lubricant]` at a contact of the solve
    /// (`physics::lubrication::rheology`), tabulated before the run and then used as a
    /// table ([`Traction::tabulated`]).
    Rheology,
}

impl TractionPreset {
    /// The deck spelling.
    pub fn name(self) -> &'static str {
        match self {
            TractionPreset::Constant => "constant",
            TractionPreset::Curve1 => "curve-1",
            TractionPreset::Curve2 => "curve-2",
            TractionPreset::Curve3 => "curve-3",
            TractionPreset::Table => "table",
            TractionPreset::Rheology => "rheology",
        }
    }
}

/// The traction law of the contacts.
#[derive(Debug, Clone, PartialEq)]
pub struct Traction {
    /// The curve.
    pub preset: TractionPreset,
    /// µ of the constant law (unused by the seed's curves); for `rheology`, the Coulomb
    /// µ of the first load solve that finds the contact the curve is tabulated at.
    pub mu: f64,
    /// The deck's (sliding speed m/s, µ) points for `table` (empty otherwise).
    pub table: Vec<(f64, f64)>,
    /// For `rheology`: the curve tabulated by the analysis (empty before it runs).
    pub tabulated: Vec<(f64, f64)>,
}

impl Traction {
    /// The curve as a function µ(u_s). `table` gives the deck's points and `rheology`
    /// the tabulated curve (an empty table, refused by [`TractionCurve::validate`],
    /// before the analysis tabulates it).
    pub fn curve(&self) -> TractionCurve {
        let points = match self.preset {
            TractionPreset::Constant => return TractionCurve::Constant { mu: self.mu },
            TractionPreset::Table => self.table.clone(),
            TractionPreset::Rheology => self.tabulated.clone(),
            TractionPreset::Curve1 => vec![(0.0, 0.0), (0.2, 0.054)],
            TractionPreset::Curve2 => vec![(0.0, 0.0), (0.2, 0.075), (3.0, 0.035)],
            TractionPreset::Curve3 => vec![(0.0, 0.0), (0.2, 0.075), (2.0, 0.035)],
        };
        TractionCurve::Table { points }
    }
}

/// Operating conditions, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Operating {
    /// Inner ring speed, rad/s.
    pub inner_speed_rad_s: f64,
    /// Outer ring speed, rad/s.
    pub outer_speed_rad_s: f64,
    /// Axial load (the preload), N.
    pub axial_load_n: f64,
    /// How the axial load is held.
    pub preload_mode: PreloadMode,
    /// Radial load, N.
    pub radial_load_n: f64,
    /// Moment on the inner ring about the axis across the radial load, N·m; `None`: the
    /// tilt is held at `misalignment_rad` (issue 29).
    pub moment_nm: Option<f64>,
    /// The inner ring's tilt when no moment is given, rad (0: the model before issue 29).
    pub misalignment_rad: f64,
}

/// How the friction that resists the gyroscopic moment is shared between the races in
/// the ball equilibrium (2-5; issue 29).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FrictionSplit {
    /// Chen's reading (seed 001, 2-7, the default): one coefficient µ = 2M_g/(D(Q_i + Q_o))
    /// at both contacts, so each race gives friction in proportion to its normal load.
    #[default]
    Proportional,
    /// Harris's (Harris & Kotzalas vol. 2 §3.2, λ_i, λ_o; OpenJones): the whole friction
    /// 2M_g/D at the controlling race of race control (λ = 2), none at the other (λ = 0).
    /// With `race_control = "auto"` the race that control picks for each ball.
    ControllingRace,
}

impl FrictionSplit {
    /// The deck spelling.
    pub fn name(self) -> &'static str {
        match self {
            FrictionSplit::Proportional => "proportional",
            FrictionSplit::ControllingRace => "controlling-race",
        }
    }
}

/// How the stiffness matrix is computed (`solver.stiffness`, issue 29).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StiffnessMethod {
    /// From the ring Newton's Jacobian (default).
    #[default]
    Analytic,
    /// Central differences of the re-solved ball equilibria.
    FiniteDifference,
    /// Both: the analytic matrix, checked by the finite differences.
    Both,
}

impl StiffnessMethod {
    /// The deck spelling.
    pub fn name(self) -> &'static str {
        match self {
            StiffnessMethod::Analytic => "analytic",
            StiffnessMethod::FiniteDifference => "finite-difference",
            StiffnessMethod::Both => "both",
        }
    }
}

/// Solver options (issue 29).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Solver {
    /// How the stiffness matrix is computed.
    pub stiffness: StiffnessMethod,
}

/// Kinematic assumptions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kinematics {
    /// The controlling race.
    pub race_control: RaceControl,
    /// Sign convention of the gyroscopic friction in eq. 2-5.
    pub gyroscopic_friction: GyroscopicFriction,
    /// How that friction is shared between the races.
    pub friction_split: FrictionSplit,
}

/// The lubricant (seed 001 ch. 4), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lubricant {
    /// η₀, viscosity at the supply temperature and ambient pressure, Pa·s.
    pub viscosity_pa_s: f64,
    /// α, Barus pressure–viscosity coefficient, 1/Pa.
    pub pressure_viscosity_pa_inv: f64,
    /// β, temperature–viscosity coefficient, 1/K (eq. 4-18).
    pub temperature_viscosity_per_k: f64,
    /// Density, kg/m³.
    pub density_kg_m3: f64,
    /// Specific heat, J/(kg·K).
    pub specific_heat_j_kg_k: f64,
    /// Thermal conductivity, W/(m·K).
    pub conductivity_w_m_k: f64,
    /// Oil flow rate through the bearing, m³/s (eq. 4-1).
    pub flow_rate_m3_s: f64,
    /// Oil supply temperature, K.
    pub supply_temperature_k: f64,
    /// Pressure–viscosity law of the rheology traction curve: Barus (4-18) or Roelands
    /// (4-22).
    pub viscosity_model: ViscosityModel,
    /// Roelands's Z; 0: from α by (4-20).
    pub roelands_z: f64,
    /// C of the limiting shear stress τ_L = τ₀ + C·p (4-17); C = τ₀ = 0: no limit.
    pub limiting_shear_coefficient: f64,
    /// τ₀ of (4-17), Pa.
    pub limiting_shear_stress_pa: f64,
}

impl Lubricant {
    /// The rheology of ch. 4 with η₀ at the supply temperature.
    pub fn rheology(&self) -> Rheology {
        Rheology {
            viscosity_pa_s: self.viscosity_pa_s,
            pressure_viscosity_pa_inv: self.pressure_viscosity_pa_inv,
            temperature_viscosity_per_k: self.temperature_viscosity_per_k,
            reference_temperature_k: self.supply_temperature_k,
            model: self.viscosity_model,
            roelands_z: (self.roelands_z > 0.0).then_some(self.roelands_z),
            limiting_shear_coefficient: self.limiting_shear_coefficient,
            limiting_shear_stress_pa: self.limiting_shear_stress_pa,
        }
    }
}

/// Which analysis runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Load distribution with race-control kinematics (ch. 2–3, 6).
    #[default]
    RaceControl,
    /// Quasi-static ball dynamics: per ball, the angular velocity at which the slice
    /// traction moments balance the gyroscopic term at its loads (`dynamics`).
    QuasiStatic,
    /// Time simulation of each ball's angular velocity over its orbit (2-3, 2-14…2-18;
    /// `dynamics`).
    TimeSimulation,
}

impl Method {
    /// The deck spelling.
    pub fn name(self) -> &'static str {
        match self {
            Method::RaceControl => "race-control",
            Method::QuasiStatic => "quasi-static",
            Method::TimeSimulation => "time-simulation",
        }
    }
}

/// The time simulation's integrator (issue 16: an adaptive explicit one with error
/// control and an implicit one, chosen automatically by the stiffness estimate).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Integrator {
    /// DOPRI5, switching once for good to Rodas4 when Hairer's stiffness test fires.
    #[default]
    Auto,
    /// DOPRI5 throughout (explicit, 5(4) with error control).
    Dopri5,
    /// Rodas4 throughout (linearly implicit, L-stable, analytic Jacobian per ball).
    Rodas4,
}

impl Integrator {
    /// The deck spelling.
    pub fn name(self) -> &'static str {
        match self {
            Integrator::Auto => "auto",
            Integrator::Dopri5 => "dopri5",
            Integrator::Rodas4 => "rodas4",
        }
    }
}

/// How the ball dynamics finds each ball's orbital speed ω_m (seed 001, eq. 2-14a).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Orbit {
    /// Held at race control's cage speed (a cage-guided ball set: the cage supplies
    /// whatever tangential force that needs; its power enters the ball's energy).
    Cage,
    /// Integrated per ball (2-14a, m R_b θ̈ = Σ traction in the rolling direction, with
    /// F_cage = F_drag = 0): each ball orbits at its own speed and its loads follow its
    /// own azimuth θ = ∫ω_m dt. The default: it is Chen's model (the four unknowns of
    /// 2-14a…d), and the one that reproduces his radial-load result (Bearing B, 500 N:
    /// peak 124 W per ball, 2.35 × the axial case, against the seed's ≈ 100 W, ≈ 2 ×;
    /// the held cage gives 176 W, 3.0 ×: forcing every ball to race control's cage
    /// speed makes it slide in the rolling direction). A real cage is driven by the
    /// balls, not the other way round.
    #[default]
    Free,
}

impl Orbit {
    /// The deck spelling.
    pub fn name(self) -> &'static str {
        match self {
            Orbit::Cage => "cage",
            Orbit::Free => "free",
        }
    }
}

/// Analysis options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dynamics {
    /// The method.
    pub method: Method,
    /// The skidding threshold is searched for up to this relative ring speed, rad/s.
    pub skid_search_limit_rad_s: f64,
    /// Slices across each contact ellipse (along its major axis) for the ball dynamics.
    pub slices: usize,
    /// Orbits of each ball simulated by the time simulation.
    pub orbits: f64,
    /// Relative tolerance of the ball-dynamics integrator (absolute: this times the
    /// initial |ω|).
    pub tolerance: f64,
    /// The time simulation's integrator.
    pub integrator: Integrator,
    /// How the ball's orbital speed is found (time simulation and quasi-static).
    pub orbit: Orbit,
}

/// A whole angular-contact ball bearing case, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct BallInput {
    /// Geometry.
    pub geometry: Geometry,
    /// Materials.
    pub materials: Materials,
    /// Operating conditions.
    pub operating: Operating,
    /// Kinematics.
    pub kinematics: Kinematics,
    /// Solver options.
    pub solver: Solver,
    /// Traction curve.
    pub traction: Traction,
    /// Lubricant.
    pub lubricant: Lubricant,
    /// Analysis options.
    pub dynamics: Dynamics,
    /// Surface finish (Λ).
    pub surfaces: Surfaces,
    /// The optional `[cage]` section: churning drag and cage-rail losses (issue 28).
    pub cage: crate::bearings::friction::CageLosses,
}

/// Surface finish of balls and races (issue 28 item 3: Λ at every contact).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Surfaces {
    /// σ, composite rms roughness of ball and race √(σ_b² + σ_r²), m; `None`: not given,
    /// so no Λ (the life says why).
    pub composite_rms_m: Option<f64>,
}

impl Surfaces {
    /// Λ = h_min/σ of one contact; `None` without σ or without a film.
    pub fn lambda(&self, min_film_m: Option<f64>) -> Option<f64> {
        let sigma = self.composite_rms_m.filter(|s| *s > 0.0)?;
        min_film_m.map(|h| h / sigma)
    }
}

/// rpm → rad/s.
pub fn rpm(n: f64) -> f64 {
    n * std::f64::consts::PI / 30.0
}

impl Geometry {
    /// A = (f_i + f_o − 1)·D, the distance between the groove centres when the ball
    /// touches both grooves unloaded, m.
    pub fn centre_distance_m(&self) -> f64 {
        (self.inner_groove_curvature + self.outer_groove_curvature - 1.0) * self.ball_diameter_m
    }

    /// The free contact angle, rad: from the clearance when given,
    /// cos α₀ = 1 − P_d/(2A) (P_d clamped to [0, 2A]; the deck's cross-check refuses
    /// P_d ≥ 2A), else α₀ as given.
    pub fn free_contact_angle(&self) -> f64 {
        match self.clearance_m {
            Some(pd) => {
                let a = self.centre_distance_m();
                (1.0 - (pd / (2.0 * a)).clamp(0.0, 1.0)).acos()
            }
            None => self.free_contact_angle_rad,
        }
    }

    /// The diametral clearance, m: as given, else P_d = 2A(1 − cos α₀).
    pub fn clearance(&self) -> f64 {
        match self.clearance_m {
            Some(pd) => pd,
            None => 2.0 * self.centre_distance_m() * (1.0 - self.free_contact_angle_rad.cos()),
        }
    }
}

impl BallInput {
    /// Chen's Bearing A (seed 001 ch. 5): a 7018-size spindle bearing, ball 12 mm, pitch
    /// diameter 115 mm, f_i = f_o = 0.52, 20 balls, free contact angle 15°, steel
    /// E = 2.08·10¹¹ Pa, ν = 0.3, 7800 kg/m³; 1000 N preload held as displacement,
    /// 10 000 rpm inner ring; SAE 30 oil (η₀ = 0.071 Pa·s at 40 °C, α = 1.5·10⁻⁸ 1/Pa,
    /// β = 0.008 1/°C, ch. 4), 800 kg/m³, 2000 J/(kg·K), 0.14 W/(m·K), 0.1 l/min
    /// (ch. 6); traction curve 1.
    pub fn chen_a() -> Self {
        // Ch. 5 steel; specific heat and conductivity from ch. 6's thermal data.
        let steel = Material {
            youngs_modulus_pa: 2.08e11,
            poisson_ratio: 0.3,
            density_kg_m3: 7800.0,
            specific_heat_j_kg_k: 470.0,
            conductivity_w_m_k: 43.0,
        };
        BallInput {
            geometry: Geometry {
                ball_count: 20,
                ball_diameter_m: 12e-3,
                pitch_diameter_m: 115e-3,
                inner_groove_curvature: 0.52,
                outer_groove_curvature: 0.52,
                free_contact_angle_rad: 15f64.to_radians(),
                clearance_m: None,
                hertz_method: HertzMethod::Exact,
            },
            materials: Materials {
                ball: steel,
                rings: steel,
            },
            operating: Operating {
                inner_speed_rad_s: rpm(10_000.0),
                outer_speed_rad_s: 0.0,
                axial_load_n: 1000.0,
                preload_mode: PreloadMode::Displacement,
                radial_load_n: 0.0,
                moment_nm: None,
                misalignment_rad: 0.0,
            },
            kinematics: Kinematics {
                race_control: RaceControl::Outer,
                gyroscopic_friction: GyroscopicFriction::Resisting,
                friction_split: FrictionSplit::Proportional,
            },
            solver: Solver {
                stiffness: StiffnessMethod::Analytic,
            },
            traction: Traction {
                preset: TractionPreset::Curve1,
                mu: 0.054,
                table: Vec::new(),
                tabulated: Vec::new(),
            },
            lubricant: Lubricant {
                viscosity_pa_s: 0.071,
                pressure_viscosity_pa_inv: 1.5e-8,
                temperature_viscosity_per_k: 0.008,
                density_kg_m3: 800.0,
                specific_heat_j_kg_k: 2000.0,
                conductivity_w_m_k: 0.14,
                flow_rate_m3_s: 0.1e-3 / 60.0,
                supply_temperature_k: 313.15,
                viscosity_model: ViscosityModel::Barus,
                roelands_z: 0.0,
                // Chen's Fig. 6-19, first curve: τ_L = 0.054·p.
                limiting_shear_coefficient: 0.054,
                limiting_shear_stress_pa: 0.0,
            },
            dynamics: Dynamics {
                method: Method::RaceControl,
                skid_search_limit_rad_s: rpm(15_000.0),
                slices: 41,
                orbits: 5.0,
                tolerance: 1e-8,
                integrator: Integrator::Auto,
                orbit: Orbit::Free,
            },
            surfaces: Surfaces::default(),
            cage: crate::bearings::friction::CageLosses::default(),
        }
    }

    /// Chen's Bearing B: Bearing A with a 60° free contact angle, at 9 500 rpm.
    pub fn chen_b() -> Self {
        let mut b = Self::chen_a();
        b.geometry.free_contact_angle_rad = 60f64.to_radians();
        b.operating.inner_speed_rad_s = rpm(9_500.0);
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The presets are the seed's curves of `traction_curve` (same points).
    #[test]
    fn presets_are_the_seed_curves() {
        for (p, n) in [
            (TractionPreset::Curve1, 1),
            (TractionPreset::Curve2, 2),
            (TractionPreset::Curve3, 3),
        ] {
            let t = Traction {
                preset: p,
                mu: 0.0,
                table: Vec::new(),
                tabulated: Vec::new(),
            };
            assert_eq!(t.curve(), TractionCurve::seed_curve(n).unwrap());
        }
        let t = Traction {
            preset: TractionPreset::Constant,
            mu: 0.07,
            table: vec![(0.0, 0.0), (1.0, 0.1)],
            tabulated: Vec::new(),
        };
        assert_eq!(t.curve().max_mu(), 0.07);
    }
}
