//! The resolved tapered roller bearing description in SI units: what the model reads.
//! The deck (`crate::deck::form`, US or SI units) fills a [`TaperedInput`]; nothing
//! below the deck sees deck units. Field names carry their unit.

use crate::physics::material::Material;
use crate::units::{INCH_M, LBF_N, RPM_RAD_S};

/// How the roller crown is given (seed 004 eqs. 17, 34–35).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Crown {
    /// The crown radius R_c, m.
    Radius(f64),
    /// The crown drop V′ (m) measured at the gauge distance G ([`Geometry::crown_gauge_m`])
    /// from each end of the effective length; R_c follows from eq. 35.
    Drop(f64),
}

/// The roller profile the race contacts see (issue 29, session 11).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RollerProfile {
    /// A flat middle `flat_length_m` long and circular crowns ([`Crown`]; seed 004
    /// eqs. 17, 58–61): the default, every deck before session 11.
    #[default]
    Crowned,
    /// ISO/TS 16281:2008's logarithmic profile for tapered rollers (its eq. 44),
    /// drop(x) = 0.00045·D_we·ln[1/(1 − (2x/L_we)²)] along the effective length L_we
    /// ([`crate::bearings::tapered_roller::contact::log_profile_drop`]). The crown keys
    /// then shape only the roller's end faces (eqs. 20–21) and mass, not the contacts.
    Logarithmic,
}

/// How the internal play is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Clearance {
    /// P_D, diametral clearance, m (negative: interference).
    Diametral(f64),
    /// e, axial end play, m: P_D = 2e·tan β.
    EndPlay(f64),
}

/// Which inertia the gyroscopic moment of eq. 37 uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GyroInertia {
    /// The polar (spin-axis) inertia I_p: the gyroscopic couple of a body spinning at ω_R
    /// whose axis precesses at Ω_E is I_p·ω_R·Ω_E·sin ψ (default).
    Polar,
    /// The inertia about the centre of gravity of eq. 29 (transverse), as printed in eq. 37.
    Transverse,
}

/// Internal geometry (seed 004 §2.4.2 and §3.1), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geometry {
    /// n, number of rollers.
    pub roller_count: usize,
    /// d, roller diameter at the midpoint of the effective length, m.
    pub roller_diameter_m: f64,
    /// E, pitch diameter at the midpoint of the effective length, m.
    pub pitch_diameter_m: f64,
    /// β, cup (outer race) contact angle, rad.
    pub cup_angle_rad: f64,
    /// l_e, effective length of the roller, m.
    pub effective_length_m: f64,
    /// l_F, length of the flat portion of the roller profile, m (0: fully crowned).
    pub flat_length_m: f64,
    /// The crown.
    pub crown: Crown,
    /// Which profile the contacts use (`geometry.profile`).
    pub profile: RollerProfile,
    /// G, distance from each end of the effective length to the crown drop's gauge point,
    /// m (eqs. 34–35).
    pub crown_gauge_m: f64,
    /// B₁, corner break at the small end, m.
    pub small_end_break_m: f64,
    /// B₂, corner break at the big end, m.
    pub big_end_break_m: f64,
    /// R_E/l_s: big-end spherical radius as a fraction of the roller cone's slant height
    /// (the seed's "0.8 in" is this ratio: in inches R_E would be shorter than the roller).
    pub big_end_radius_ratio: f64,
    /// r/R₂: radius of the flange contact point from the roller axis as a fraction of the
    /// big-end radius (the seed's "0.75 in" is this ratio: R₂ is 0.150 in).
    pub flange_contact_ratio: f64,
    /// The internal play before loading (eq. 40's P_D).
    pub clearance: Clearance,
}

impl Geometry {
    /// P_D, diametral clearance, m (an end play e gives 2e·tan β).
    pub fn diametral_clearance_m(&self) -> f64 {
        match self.clearance {
            Clearance::Diametral(p) => p,
            Clearance::EndPlay(e) => 2.0 * e * self.cup_angle_rad.tan(),
        }
    }

    /// e, axial end play, m (P_D/(2 tan β)).
    pub fn end_play_m(&self) -> f64 {
        match self.clearance {
            Clearance::Diametral(p) => p / (2.0 * self.cup_angle_rad.tan()),
            Clearance::EndPlay(e) => e,
        }
    }
}

/// Roller, cup and cone materials.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Materials {
    /// Roller.
    pub roller: Material,
    /// Cup (outer ring).
    pub cup: Material,
    /// Cone (inner ring).
    pub cone: Material,
}

/// Loads, speeds, initial displacements and misalignment, SI. The inner ring (cone) is
/// loaded and displaced; the cup is fixed. Axis z along the bearing axis (positive
/// seats the bearing), x toward the radial load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Operating {
    /// Ω₂, inner ring (cone) angular velocity, rad/s.
    pub inner_speed_rad_s: f64,
    /// Ω₁, outer ring (cup) angular velocity, rad/s.
    pub outer_speed_rad_s: f64,
    /// F_z, axial (thrust) load on the cone, N; positive seats the bearing.
    pub axial_load_n: f64,
    /// F_x, radial load on the cone, N, along x.
    pub radial_load_n: f64,
    /// δ″, initial displacements (x, y, z) of the cone, m (eq. 40).
    pub initial_displacement_m: [f64; 3],
    /// θ, prescribed rotations (θx, θy) of the cone, rad: misalignment held by the shaft
    /// (eqs. 40, 42); the moments that hold them are reported.
    pub misalignment_rad: [f64; 2],
    /// M_y, the moment applied to the cone about y (the axis perpendicular to the radial
    /// load), N·m, in the reactions' sign (a positive moment loads the rollers at φ = 0,
    /// where the radial load does): the bearing Newton then solves θy for it (issue 29).
    /// NaN (the deck's `"held"`, the default): θy is held at `misalignment_rad[1]`,
    /// the behaviour before moments.
    pub moment_nm: f64,
}

impl Operating {
    /// The applied moment about y, when the deck gives one (θy is then solved).
    pub fn applied_moment_nm(&self) -> Option<f64> {
        self.moment_nm.is_finite().then_some(self.moment_nm)
    }
}

/// How stiffness is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StiffnessMethod {
    /// Analytic (eqs. 88–91, 107–120).
    Analytic,
    /// Central differences of re-solved roller equilibria.
    FiniteDifference,
    /// Both, the analytic reported and the difference stated.
    Both,
}

/// Solver settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solver {
    /// Slices per contact along the effective length.
    pub slices: usize,
    /// Force tolerance of the bearing equilibrium, relative to the applied load.
    pub force_tolerance: f64,
    /// Largest number of bearing Newton iterations.
    pub max_iterations: usize,
    /// Largest number of Newton iterations of one roller.
    pub max_roller_iterations: usize,
    /// Stiffness method.
    pub stiffness: StiffnessMethod,
    /// The inertia of the gyroscopic moment.
    pub gyroscopic_inertia: GyroInertia,
}

/// A whole tapered roller bearing case, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TaperedInput {
    /// Geometry.
    pub geometry: Geometry,
    /// Materials.
    pub materials: Materials,
    /// Operating conditions.
    pub operating: Operating,
    /// Solver settings.
    pub solver: Solver,
    /// The pedestal the cup sits in (seed 004 eq. 9).
    pub pedestal: Pedestal,
    /// The lubricant (issue 28 item 3); `viscosity_pa_s` NaN (the deck's `"none"`): no
    /// lubricant, no film, no friction, no heat.
    pub lubricant: Lubricant,
    /// The surfaces' roughness.
    pub surfaces: Surfaces,
    /// The optional `[cage]` section: churning drag and cage-rail losses (issue 28).
    pub cage: crate::bearings::friction::CageLosses,
}

/// The lubricant and the friction laws' constants, SI (issue 28 item 3). The key names
/// are the cylindrical deck's where the meaning is the same.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lubricant {
    /// η₀, dynamic viscosity at `reference_temperature_k` and ambient pressure, Pa·s;
    /// NaN: the deck has no lubricant (`lubricant.viscosity = "none"`, the default).
    pub viscosity_pa_s: f64,
    /// T₀, the temperature at which η₀ is given, K.
    pub reference_temperature_k: f64,
    /// α, pressure–viscosity coefficient, 1/Pa.
    pub pressure_viscosity_pa_inv: f64,
    /// β, temperature–viscosity coefficient, 1/K: η(T) = η₀·exp(−β(T − T₀)).
    pub temperature_viscosity_k_inv: f64,
    /// ρ, density at the inlet, kg/m³ (the kinematic viscosity of ISO 281's κ).
    pub density_kg_m3: f64,
    /// Inlet (supply) temperature, K: the film's and the friction's temperature.
    pub inlet_temperature_k: f64,
    /// µ_b, boundary friction coefficient of the asperity contacts (mixed lubrication).
    pub boundary_friction: f64,
    /// τ₀, atmospheric limiting shear stress, Pa (τ_L = τ₀ + γ·p).
    pub limiting_shear_pa: f64,
    /// γ, pressure coefficient of the limiting shear stress.
    pub limiting_shear_slope: f64,
    /// The roller-end/flange friction coefficient: NaN (`"film"`, the default) takes it
    /// from the flange film (mixed boundary/viscous); a number imposes it.
    pub flange_friction: f64,
}

/// Surface roughness, SI (the cylindrical deck's `[surfaces]` keys).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surfaces {
    /// σ, composite RMS roughness √(σ₁² + σ₂²) of roller and race (and flange), m.
    pub composite_rms_m: f64,
    /// ξβσ, Greenwood–Tripp roughness parameter.
    pub roughness_parameter: f64,
    /// σ/β, Greenwood–Tripp asperity slope measure.
    pub asperity_slope: f64,
}

impl Lubricant {
    /// True when the deck gives a lubricant.
    pub fn is_given(&self) -> bool {
        self.viscosity_pa_s.is_finite()
    }

    /// η at `temperature_k`, Pa·s (Barus in temperature: η₀·exp(−β(T − T₀))).
    pub fn viscosity_at_pa_s(&self, temperature_k: f64) -> f64 {
        self.viscosity_pa_s
            * (-self.temperature_viscosity_k_inv * (temperature_k - self.reference_temperature_k))
                .exp()
    }

    /// η at the inlet temperature, Pa·s.
    pub fn inlet_viscosity_pa_s(&self) -> f64 {
        self.viscosity_at_pa_s(self.inlet_temperature_k)
    }
}

impl Default for Lubricant {
    /// No lubricant (η₀ NaN); the other constants are a MIL-PRF-23699-type polyol-ester
    /// turbine oil's (see `decks/trb_afapl_lubricated.toml` for their sources), ready for
    /// a deck that sets only `lubricant.viscosity`.
    fn default() -> Self {
        Lubricant {
            viscosity_pa_s: f64::NAN,
            reference_temperature_k: 313.15,
            pressure_viscosity_pa_inv: 1.1e-8,
            temperature_viscosity_k_inv: 0.0268,
            density_kg_m3: 990.0,
            inlet_temperature_k: 313.15,
            boundary_friction: 0.1,
            limiting_shear_pa: 2.3e6,
            limiting_shear_slope: 0.047,
            flange_friction: f64::NAN,
        }
    }
}

impl Default for Surfaces {
    fn default() -> Self {
        Surfaces {
            composite_rms_m: 0.15e-6,
            roughness_parameter: 0.055,
            asperity_slope: 1e-3,
        }
    }
}

/// The pedestal's stiffness in the coordinates of the 5×5 matrix (x, y, z, θx, θy), SI
/// (N/m, N·m/rad); 0 stands for a rigid pedestal in that coordinate (no compliance
/// added). Seed 004 eq. (9) combines bearing and pedestal as impedances in series:
/// Z = (Z_b⁻¹ + Z_p⁻¹)⁻¹; the bearing model has no damping, so here Z = K.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pedestal {
    /// k_x, k_y, k_z (N/m), k_θx, k_θy (N·m/rad); 0: rigid.
    pub stiffness: [f64; 5],
}

impl Pedestal {
    /// True when any coordinate has a finite pedestal stiffness.
    pub fn is_compliant(&self) -> bool {
        self.stiffness.iter().any(|&k| k > 0.0)
    }
}

impl Default for Solver {
    fn default() -> Self {
        Solver {
            slices: 21,
            force_tolerance: 1e-9,
            max_iterations: 60,
            max_roller_iterations: 60,
            stiffness: StiffnessMethod::Analytic,
            gyroscopic_inertia: GyroInertia::Polar,
        }
    }
}

impl TaperedInput {
    /// The seed's §3.1 sample bearing (AFAPL-TR-78-6 Part III) with Load Condition 1
    /// (3 000 lbf thrust) at 20 000 rpm of the cone; steel everywhere (the sample names no
    /// material), zero clearance (the derivation starts with the end play taken up).
    pub fn afapl_sample() -> TaperedInput {
        TaperedInput {
            geometry: Geometry {
                roller_count: 37,
                roller_diameter_m: 0.2913 * INCH_M,
                pitch_diameter_m: 5.0 * INCH_M,
                cup_angle_rad: (14.0 + 40.0 / 60.0_f64).to_radians(),
                effective_length_m: 0.6001 * INCH_M,
                flat_length_m: 0.0,
                crown: Crown::Radius(100.0 * INCH_M),
                profile: RollerProfile::Crowned,
                crown_gauge_m: 0.03 * INCH_M,
                small_end_break_m: 0.02 * INCH_M,
                big_end_break_m: 0.03 * INCH_M,
                big_end_radius_ratio: 0.8,
                flange_contact_ratio: 0.75,
                clearance: Clearance::Diametral(0.0),
            },
            materials: Materials {
                roller: Material::STEEL,
                cup: Material::STEEL,
                cone: Material::STEEL,
            },
            operating: Operating {
                inner_speed_rad_s: 20_000.0 * RPM_RAD_S,
                outer_speed_rad_s: 0.0,
                axial_load_n: 3_000.0 * LBF_N,
                radial_load_n: 0.0,
                initial_displacement_m: [0.0; 3],
                misalignment_rad: [0.0; 2],
                moment_nm: f64::NAN,
            },
            solver: Solver::default(),
            pedestal: Pedestal::default(),
            lubricant: Lubricant::default(),
            surfaces: Surfaces::default(),
            cage: crate::bearings::friction::CageLosses::default(),
        }
    }
}
