//! EHD film rheology and film temperature of seed 001 (S.-H. Chen 1989) ch. 4, SI:
//! viscosity with pressure and temperature (Barus 4-18, Roelands 4-19…4-22), the
//! limiting shear stress (4-17) with the Bair–Winer law (4-16), the film temperature of
//! a sheared film (4-3…4-7) and the traction curve µ(u_s) computed from them along the
//! rolling direction of a contact, to be tabulated before a bearing analysis ("the
//! traction curve, as suggested by Gupta, is better to be determined before performing
//! bearing analysis", ch. 4).
//!
//! Readings of the OCR'd seed (documented, each tested):
//! - **Convection factor E** (after 4-5 and 4-7): E = ρ c V h² / (8 k Δy). The seed
//!   leaves Δy as a step length. We take Δy = y + b, the distance the fluid has
//!   travelled from the inlet edge of the Hertz zone. Then the film-centre rise
//!   q h²/(8k(1+E)) of (4-7) tends to the conduction limit q h²/(8k) when E → 0 and to
//!   the adiabatic heating q (y+b)/(ρ c V) of a fluid sheared for (y+b)/V when E → ∞
//!   (both limits tested), so it does not depend on a grid. With it the hottest point of
//!   Chen's spinning contact lies at y ≈ 0.25 b, x ≈ ±0.68 a (seed ch. 6: 0.25 b and
//!   ±0.65 a).
//! - **Surface temperature**: Archard's moving source (4-3) with the flux conducted into
//!   each solid, −k ∂θ/∂z = τ·u_s/(2(1+E)) (the seed's expression after 4-7), integrated
//!   cell by cell from the inlet; with a constant flux it is (4-4),
//!   θ_s = (2 q/√π)·√((y+b)/(ρ_s c_s k_s V)).
//! - **Limiting shear stress** (4-17) printed "τ_L = C P − τ₀": we use τ_L = τ₀ + C·p
//!   with τ₀ ≥ 0 (a non-negative limit at every pressure); C = τ₀ = 0 means no limit
//!   (Newtonian with pressure and temperature, Chen's second curve of Fig. 6-19).
//! - **Bair–Winer** (4-16) without the elastic term: γ̇ = (τ_L/η)·artanh(τ/τ_L), i.e.
//!   τ = τ_L·tanh(η γ̇/τ_L), with γ̇ = u_s/h across the film (Couette).
//! - **Roelands** parameters Z and S₀ from the Barus α and β (4-20, 4-21); for SAE 30
//!   they give the seed's Z = 0.42, S₀ = 0.2 (tested).

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use super::traction_curve::TractionCurve;
use thiserror::Error;

/// Why a rheology calculation cannot be done.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RheologyError {
    /// An input is out of its physical range.
    #[error("rheology: {0}")]
    BadInput(String),
    /// The viscosity or stress overflowed (e.g. Barus at extreme pressure).
    #[error("rheology: non-finite {what} at p = {pressure_pa:.4e} Pa, θ = {temperature_k:.2} K")]
    NonFinite {
        /// What overflowed.
        what: &'static str,
        /// Pressure, Pa.
        pressure_pa: f64,
        /// Temperature, K.
        temperature_k: f64,
    },
}

/// Pressure–viscosity law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ViscosityModel {
    /// Barus (4-18): η = η₀ exp[α p + β(θ₀ − θ)].
    #[default]
    Barus,
    /// Roelands (4-22), Z and S₀ from α, β (4-20, 4-21).
    Roelands,
}

/// A lubricant's rheology (seed 001 ch. 4), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rheology {
    /// η₀ at the reference temperature and ambient pressure, Pa·s.
    pub viscosity_pa_s: f64,
    /// α, Barus pressure–viscosity coefficient, 1/Pa.
    pub pressure_viscosity_pa_inv: f64,
    /// β, temperature–viscosity coefficient, 1/K.
    pub temperature_viscosity_per_k: f64,
    /// θ₀, reference temperature of η₀, K.
    pub reference_temperature_k: f64,
    /// Barus or Roelands.
    pub model: ViscosityModel,
    /// Roelands's pressure index Z when given (the seed rounds it to 0.42 for SAE 30);
    /// `None`: from α by (4-20).
    pub roelands_z: Option<f64>,
    /// C of (4-17): the limiting shear stress's pressure coefficient, dimensionless.
    pub limiting_shear_coefficient: f64,
    /// τ₀ of (4-17): the limiting shear stress at zero pressure, Pa.
    pub limiting_shear_stress_pa: f64,
}

/// Constants of Roelands's formula (4-19…4-22): ln(η) at infinite temperature
/// (η_∞ = 6.31·10⁻⁵ Pa·s, ln = −9.67), p_r = 1/5.1·10⁻⁹ Pa = 196 MPa, and 135 °C.
const ROELANDS_LN_ETA_INF: f64 = 9.67;
const ROELANDS_P: f64 = 5.1e-9;
const ROELANDS_T: f64 = 135.0;
const ZERO_C: f64 = 273.15;

impl Rheology {
    /// Check the inputs.
    pub fn validate(&self) -> Result<(), RheologyError> {
        let bad = |s: &str| Err(RheologyError::BadInput(s.to_string()));
        if !(self.viscosity_pa_s.is_finite() && self.viscosity_pa_s > 0.0) {
            return bad("viscosity must be positive");
        }
        if !(self.pressure_viscosity_pa_inv.is_finite() && self.pressure_viscosity_pa_inv >= 0.0) {
            return bad("pressure-viscosity coefficient must be ≥ 0");
        }
        if !(self.temperature_viscosity_per_k.is_finite()
            && self.temperature_viscosity_per_k >= 0.0)
        {
            return bad("temperature-viscosity coefficient must be ≥ 0");
        }
        if !(self.reference_temperature_k.is_finite() && self.reference_temperature_k > 0.0) {
            return bad("reference temperature must be positive");
        }
        if !(self.limiting_shear_coefficient.is_finite() && self.limiting_shear_coefficient >= 0.0)
        {
            return bad("limiting shear coefficient must be ≥ 0");
        }
        if !(self.limiting_shear_stress_pa.is_finite() && self.limiting_shear_stress_pa >= 0.0) {
            return bad("limiting shear stress τ₀ must be ≥ 0");
        }
        if let Some(z) = self.roelands_z {
            if !(z.is_finite() && z > 0.0) {
                return bad("Roelands Z must be positive");
            }
        }
        if self.model == ViscosityModel::Roelands
            && self.viscosity_pa_s.ln() + ROELANDS_LN_ETA_INF <= 0.0
        {
            return bad("Roelands needs η₀ > 6.31e-5 Pa·s (ln η₀ + 9.67 > 0)");
        }
        Ok(())
    }

    /// Roelands's pressure index: the given Z, else Z = α / (5.1·10⁻⁹ (ln η₀ + 9.67))
    /// (4-20), dimensionless.
    pub fn roelands_z(&self) -> f64 {
        if let Some(z) = self.roelands_z {
            return z;
        }
        self.pressure_viscosity_pa_inv
            / (ROELANDS_P * (self.viscosity_pa_s.ln() + ROELANDS_LN_ETA_INF))
    }

    /// Roelands's temperature index S₀ = β (θ₀ + 135) / (ln η₀ + 9.67) (4-21), θ₀ in °C,
    /// dimensionless.
    pub fn roelands_s0(&self) -> f64 {
        self.temperature_viscosity_per_k * (self.reference_temperature_k - ZERO_C + ROELANDS_T)
            / (self.viscosity_pa_s.ln() + ROELANDS_LN_ETA_INF)
    }

    /// η(p, θ), Pa·s, at gauge pressure p (Pa) and temperature θ (K): Barus (4-18) or
    /// Roelands (4-22).
    pub fn viscosity_pa_s(&self, pressure_pa: f64, temperature_k: f64) -> f64 {
        let eta0 = self.viscosity_pa_s;
        match self.model {
            ViscosityModel::Barus => {
                eta0 * (self.pressure_viscosity_pa_inv * pressure_pa
                    + self.temperature_viscosity_per_k
                        * (self.reference_temperature_k - temperature_k))
                    .exp()
            }
            ViscosityModel::Roelands => {
                let l = eta0.ln() + ROELANDS_LN_ETA_INF;
                let t = ((temperature_k - ZERO_C + ROELANDS_T)
                    / (self.reference_temperature_k - ZERO_C + ROELANDS_T))
                    .max(f64::MIN_POSITIVE);
                let pr = (1.0 + ROELANDS_P * pressure_pa.max(0.0)).powf(self.roelands_z());
                eta0 * (l * (-1.0 + pr * t.powf(-self.roelands_s0()))).exp()
            }
        }
    }

    /// τ_L = τ₀ + C·p (4-17, see the module note), Pa; `None` when C = τ₀ = 0 (no limit).
    pub fn limiting_shear_stress_pa(&self, pressure_pa: f64) -> Option<f64> {
        if self.limiting_shear_coefficient == 0.0 && self.limiting_shear_stress_pa == 0.0 {
            None
        } else {
            Some(
                self.limiting_shear_stress_pa
                    + self.limiting_shear_coefficient * pressure_pa.max(0.0),
            )
        }
    }

    /// Shear stress of the film at pressure p (Pa), temperature θ (K) and shear rate γ̇
    /// (1/s): τ = τ_L tanh(η γ̇/τ_L) (4-16), or η γ̇ without a limit, Pa.
    pub fn shear_stress_pa(&self, pressure_pa: f64, temperature_k: f64, shear_rate: f64) -> f64 {
        let newtonian = self.viscosity_pa_s(pressure_pa, temperature_k) * shear_rate;
        match self.limiting_shear_stress_pa(pressure_pa) {
            Some(tl) if tl > 0.0 => tl * (newtonian / tl).tanh(),
            Some(_) => 0.0,
            None => newtonian,
        }
    }
}

/// Thermal properties of the film and of the solids (taken equal for ball and race).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmThermal {
    /// Oil density, kg/m³.
    pub oil_density_kg_m3: f64,
    /// Oil specific heat, J/(kg·K).
    pub oil_specific_heat_j_kg_k: f64,
    /// Oil conductivity, W/(m·K).
    pub oil_conductivity_w_m_k: f64,
    /// Solid density, kg/m³.
    pub solid_density_kg_m3: f64,
    /// Solid specific heat, J/(kg·K).
    pub solid_specific_heat_j_kg_k: f64,
    /// Solid conductivity, W/(m·K).
    pub solid_conductivity_w_m_k: f64,
}

impl FilmThermal {
    fn validate(&self) -> Result<(), RheologyError> {
        for v in [
            self.oil_density_kg_m3,
            self.oil_specific_heat_j_kg_k,
            self.oil_conductivity_w_m_k,
            self.solid_density_kg_m3,
            self.solid_specific_heat_j_kg_k,
            self.solid_conductivity_w_m_k,
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(RheologyError::BadInput(
                    "thermal properties must be positive".into(),
                ));
            }
        }
        Ok(())
    }

    /// E = ρ c V h² / (8 k (y + b)) (after 4-7, with Δy = y + b, the distance from the
    /// inlet; see the module note): the heat convected over that conducted, dimensionless.
    pub fn convection_factor(&self, rolling_m_s: f64, film_m: f64, from_inlet_m: f64) -> f64 {
        self.oil_density_kg_m3 * self.oil_specific_heat_j_kg_k * rolling_m_s.abs() * film_m * film_m
            / (8.0 * self.oil_conductivity_w_m_k * from_inlet_m)
    }

    /// The film-centre temperature above the surfaces (4-7): τ·γ̇·h²/(8k(1+E)) with
    /// γ̇ = u_s/h, i.e. τ·u_s·h/(8k(1+E)), K.
    pub fn centre_rise_k(&self, tau_pa: f64, sliding_m_s: f64, film_m: f64, e: f64) -> f64 {
        tau_pa * sliding_m_s.abs() * film_m / (8.0 * self.oil_conductivity_w_m_k * (1.0 + e))
    }

    /// 1/√(π ρ_s c_s k_s V): the factor of Archard's moving-source integral (4-3),
    /// K·m^(1/2)·m²/W … so that θ_s = factor · ∫ q(s)/√(y − s) ds, with q in W/m².
    fn archard(&self, rolling_m_s: f64) -> f64 {
        1.0 / (std::f64::consts::PI
            * self.solid_density_kg_m3
            * self.solid_specific_heat_j_kg_k
            * self.solid_conductivity_w_m_k
            * rolling_m_s.abs())
        .sqrt()
    }
}

/// The centre strip of a contact along the rolling direction, and its inlet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactStrip {
    /// p₀, maximum Hertz pressure, Pa.
    pub max_pressure_pa: f64,
    /// b, semi-axis in the rolling direction, m.
    pub semi_width_m: f64,
    /// h, film thickness (central), m.
    pub film_m: f64,
    /// V, rolling (entrainment) speed, m/s.
    pub rolling_speed_m_s: f64,
    /// θ of the oil and surfaces at the inlet, K.
    pub inlet_temperature_k: f64,
}

impl ContactStrip {
    fn validate(&self) -> Result<(), RheologyError> {
        for (v, what) in [
            (self.max_pressure_pa, "maximum pressure"),
            (self.semi_width_m, "contact semi-width"),
            (self.film_m, "film thickness"),
            (self.rolling_speed_m_s, "rolling speed"),
            (self.inlet_temperature_k, "inlet temperature"),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(RheologyError::BadInput(format!(
                    "{what} must be positive (got {v:e})"
                )));
            }
        }
        Ok(())
    }
}

/// Cells along the rolling direction of a strip.
pub const STRIP_CELLS: usize = 200;

/// One strip marched from the inlet: cell j spans [y_j − Δ/2, y_j + Δ/2]; the surface
/// temperature at a cell centre is Archard's integral (4-3) of the piecewise-constant
/// fluxes of the cells upstream and of the upstream half of the cell itself.
struct Strip {
    n: usize,
    b: f64,
    dy: f64,
}

impl Strip {
    fn new(b: f64, n: usize) -> Self {
        Strip {
            n,
            b,
            dy: 2.0 * b / n as f64,
        }
    }
    /// y of cell i's centre, m.
    fn y(&self, i: usize) -> f64 {
        -self.b + (i as f64 + 0.5) * self.dy
    }
    /// ∫ ds/√(y_i − s) over cell j's part upstream of y_i, m^(1/2).
    fn kernel(&self, i: usize, j: usize) -> f64 {
        let yi = self.y(i);
        let a = -self.b + j as f64 * self.dy;
        let e = if j == i { yi } else { a + self.dy };
        2.0 * ((yi - a).max(0.0).sqrt() - (yi - e).max(0.0).sqrt())
    }
}

/// The film state in one cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CellState {
    /// Shear stress, Pa.
    pub tau_pa: f64,
    /// Surface temperature rise above the inlet, K.
    pub surface_rise_k: f64,
    /// Film-centre temperature rise above the inlet, K.
    pub centre_rise_k: f64,
}

/// March a strip from the inlet: in cell i the stress is `tau(i, p_i, θ_centre)` given
/// the film-centre temperature, solved with the temperature it causes (bisection: the
/// stress falls with the temperature and the temperature rises with the stress, so the
/// fixed point is unique). Returns the cell states.
fn march(
    thermal: &FilmThermal,
    strip: &ContactStrip,
    sliding_m_s: f64,
    cells: usize,
    tau: &dyn Fn(f64, f64) -> Result<f64, RheologyError>,
) -> Result<Vec<CellState>, RheologyError> {
    let s = Strip::new(strip.semi_width_m, cells);
    let arch = thermal.archard(strip.rolling_speed_m_s);
    let u = sliding_m_s.abs();
    let mut flux: Vec<f64> = Vec::with_capacity(cells);
    let mut out = Vec::with_capacity(cells);
    for i in 0..s.n {
        let y = s.y(i);
        let p = strip.max_pressure_pa * (1.0 - (y / s.b).powi(2)).max(0.0).sqrt();
        let e = thermal.convection_factor(strip.rolling_speed_m_s, strip.film_m, y + s.b);
        let upstream: f64 = (0..i).map(|j| flux[j] * s.kernel(i, j)).sum::<f64>() * arch;
        let own = s.kernel(i, i) * arch;
        // Temperatures caused by a stress t in this cell.
        let temps = |t: f64| {
            let q = t * u / (2.0 * (1.0 + e));
            let surf = upstream + q * own;
            (q, surf, surf + thermal.centre_rise_k(t, u, strip.film_m, e))
        };
        let g = |t: f64| -> Result<f64, RheologyError> {
            let (_, _, c) = temps(t);
            Ok(t - tau(p, strip.inlet_temperature_k + c)?)
        };
        let hi0 = tau(p, strip.inlet_temperature_k + temps(0.0).1)?;
        let (mut lo, mut hi) = (0.0, hi0);
        if hi > 0.0 {
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if g(mid)? > 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
        }
        let t = 0.5 * (lo + hi);
        let (q, surf, centre) = temps(t);
        if !(t.is_finite() && centre.is_finite()) {
            return Err(RheologyError::NonFinite {
                what: "shear stress",
                pressure_pa: p,
                temperature_k: strip.inlet_temperature_k + centre,
            });
        }
        flux.push(q);
        out.push(CellState {
            tau_pa: t,
            surface_rise_k: surf,
            centre_rise_k: centre,
        });
    }
    Ok(out)
}

/// µ at the sliding speed u_s (m/s) of the contact's centre strip: Σ τ / Σ p over the
/// cells, τ from the rheology at each cell's pressure and film-centre temperature
/// (thermal Bair–Winer, see the module note), dimensionless.
pub fn traction_coefficient(
    rheology: &Rheology,
    thermal: &FilmThermal,
    strip: &ContactStrip,
    sliding_m_s: f64,
) -> Result<f64, RheologyError> {
    rheology.validate()?;
    thermal.validate()?;
    strip.validate()?;
    let u = sliding_m_s.abs();
    if !u.is_finite() {
        return Err(RheologyError::BadInput(
            "sliding speed must be finite".into(),
        ));
    }
    if u == 0.0 {
        return Ok(0.0);
    }
    let rate = u / strip.film_m;
    let tau = |p: f64, theta: f64| {
        let t = rheology.shear_stress_pa(p, theta, rate);
        if t.is_finite() {
            Ok(t)
        } else {
            Err(RheologyError::NonFinite {
                what: "viscosity",
                pressure_pa: p,
                temperature_k: theta,
            })
        }
    };
    let cells = march(thermal, strip, u, STRIP_CELLS, &tau)?;
    let s = Strip::new(strip.semi_width_m, STRIP_CELLS);
    let sum_p: f64 = (0..STRIP_CELLS)
        .map(|i| strip.max_pressure_pa * (1.0 - (s.y(i) / s.b).powi(2)).max(0.0).sqrt())
        .sum();
    let sum_t: f64 = cells.iter().map(|c| c.tau_pa).sum();
    Ok(sum_t / sum_p)
}

/// The sliding speeds at which a rheology curve is tabulated, m/s: 0, then 48 points
/// geometric from 1 mm/s to 20 m/s (the traction curve's linear, non-linear and thermal
/// regions, Fig. 2-10, all resolved).
pub fn tabulation_speeds() -> Vec<f64> {
    let n = 48;
    let (lo, hi): (f64, f64) = (1e-3, 20.0);
    std::iter::once(0.0)
        .chain((0..n).map(|k| lo * (hi / lo).powf(k as f64 / (n - 1) as f64)))
        .collect()
}

/// The traction curve of the rheology at this contact, tabulated at
/// [`tabulation_speeds`] (piecewise linear between them, constant beyond 20 m/s).
pub fn traction_curve(
    rheology: &Rheology,
    thermal: &FilmThermal,
    strip: &ContactStrip,
) -> Result<TractionCurve, RheologyError> {
    let points = tabulation_speeds()
        .into_iter()
        .map(|u| traction_coefficient(rheology, thermal, strip, u).map(|m| (u, m)))
        .collect::<Result<Vec<_>, _>>()?;
    TractionCurve::table(points).map_err(|e| RheologyError::BadInput(e.to_string()))
}

/// The film temperature of a contact with spin ω_s (rad/s) about its normal, under a
/// given traction curve (seed ch. 6, Figs. 6-16…6-18: sliding u_s = |ω_s·x| across the
/// major axis; τ = µ(u_s)·p; film-centre temperature by 4-7 over the surfaces' by 4-4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinFilmTemperature {
    /// Largest film-centre temperature rise above the inlet, K.
    pub max_rise_k: f64,
    /// Where: x/a (transverse), y/b (rolling).
    pub at: (f64, f64),
    /// Largest surface temperature rise above the inlet, K.
    pub max_surface_rise_k: f64,
}

/// [`SpinFilmTemperature`] of an ellipse with semi-axes a (transverse, m) and b (rolling,
/// m), p₀ (Pa), film h (m), rolling speed V (m/s), spin ω_s (rad/s), on a grid of
/// `rows` strips across x (at x_k = −a + (k+½)·2a/rows) × `cells` cells along y.
#[allow(clippy::too_many_arguments)]
pub fn spin_film_temperature(
    thermal: &FilmThermal,
    curve: &TractionCurve,
    semi_major_m: f64,
    semi_minor_m: f64,
    max_pressure_pa: f64,
    film_m: f64,
    rolling_speed_m_s: f64,
    spin_rad_s: f64,
    rows: usize,
    cells: usize,
) -> Result<SpinFilmTemperature, RheologyError> {
    thermal.validate()?;
    let mut best = SpinFilmTemperature {
        max_rise_k: 0.0,
        at: (0.0, 0.0),
        max_surface_rise_k: 0.0,
    };
    if spin_rad_s == 0.0 || max_pressure_pa <= 0.0 {
        return Ok(best);
    }
    if !(semi_major_m > 0.0
        && semi_minor_m > 0.0
        && spin_rad_s.is_finite()
        && film_m > 0.0
        && rolling_speed_m_s.is_finite()
        && rolling_speed_m_s != 0.0)
    {
        return Err(RheologyError::BadInput(
            "contact semi-axes, film and rolling speed must be positive and the spin finite".into(),
        ));
    }
    let rows = rows.max(1);
    let cells = cells.max(1);
    let s = Strip::new(semi_minor_m, cells);
    for k in 0..rows {
        let xr = -1.0 + (k as f64 + 0.5) * 2.0 / rows as f64;
        let c = (1.0 - xr * xr).max(0.0);
        let u = (spin_rad_s * xr * semi_major_m).abs();
        if c == 0.0 || u == 0.0 {
            continue;
        }
        // The row is a strip of half-width b√c and pressure p₀√c (Hertz ellipse). As
        // the seed does for Figs. 6-17/18 ("Using … Eq. (4-4), and Eq. (4-6)"), the
        // surface temperature is (4-4), the constant-flux form of (4-3), with the local
        // flux; τ = µ(u_s)·p does not depend on the temperature here, so each cell is
        // explicit (no march).
        let half = semi_minor_m * c.sqrt();
        let p_row = max_pressure_pa * c.sqrt();
        let mu = curve.mu(u);
        let arch = thermal.archard(rolling_speed_m_s);
        let rs = Strip::new(half, cells);
        for i in 0..cells {
            let y = rs.y(i);
            let from_inlet = y + half;
            let tau = mu * p_row * (1.0 - (y / half).powi(2)).max(0.0).sqrt();
            let e = thermal.convection_factor(rolling_speed_m_s, film_m, from_inlet);
            let q = tau * u / (2.0 * (1.0 + e));
            let surface = 2.0 * q * from_inlet.sqrt() * arch;
            let centre = surface + thermal.centre_rise_k(tau, u, film_m, e);
            if !centre.is_finite() {
                return Err(RheologyError::NonFinite {
                    what: "film temperature",
                    pressure_pa: tau / mu.max(f64::MIN_POSITIVE),
                    temperature_k: centre,
                });
            }
            if centre > best.max_rise_k {
                best.max_rise_k = centre;
                best.at = (xr, y / s.b);
            }
            best.max_surface_rise_k = best.max_surface_rise_k.max(surface);
        }
    }
    Ok(best)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// SAE 30 of seed ch. 4: η₀ = 0.071 Pa·s at 40 °C, α = 1.5e-8 1/Pa, β = 0.008 1/°C.
    fn sae30(model: ViscosityModel) -> Rheology {
        Rheology {
            viscosity_pa_s: 0.071,
            pressure_viscosity_pa_inv: 1.5e-8,
            temperature_viscosity_per_k: 0.008,
            reference_temperature_k: 313.15,
            model,
            roelands_z: None,
            limiting_shear_coefficient: 0.0,
            limiting_shear_stress_pa: 0.0,
        }
    }

    /// Ch. 6 thermal data: oil 800 kg/m³, 2000 J/(kg·K), 0.14 W/(m·K); steel 7800,
    /// 470, 43.
    fn chen_thermal() -> FilmThermal {
        FilmThermal {
            oil_density_kg_m3: 800.0,
            oil_specific_heat_j_kg_k: 2000.0,
            oil_conductivity_w_m_k: 0.14,
            solid_density_kg_m3: 7800.0,
            solid_specific_heat_j_kg_k: 470.0,
            solid_conductivity_w_m_k: 43.0,
        }
    }

    /// Table 4-2 of the seed (40 °C): Barus η/η₀ = 1808, 3.36e6, 1.07e13 and Roelands
    /// 139, 2947, 92 900 at 0.5, 1, 2 GPa (printed to 3–4 digits: ±0.5 %), the Roelands
    /// column with the seed's rounded Z = 0.42 (with Z from 4-20 unrounded, 0.4187, the
    /// 0.5 GPa value is 136.4: the table used the rounded Z). Z = 0.42, S₀ = 0.2 from
    /// (4-20, 4-21) (printed to 2 digits: ±0.005). The Barus column is exp(αp) (1e-12);
    /// its 1 GPa entry is misprinted: e¹⁵ = 3.27e6, printed 3.36e6 (so 3 % there). The
    /// Roelands 2 GPa entry, 92 900, is not what (4-22) gives with the seed's own Z and S₀
    /// (2.32e5; 92 900 would need p ≈ 1.76 GPa) while its 0.5 and 1 GPa entries are
    /// reproduced, so it is left out as a misprint. At the
    /// reference point both give η₀; both fall with temperature.
    #[test]
    fn viscosity_matches_table_4_2() {
        let b = sae30(ViscosityModel::Barus);
        let derived = sae30(ViscosityModel::Roelands);
        let mut r = derived;
        r.roelands_z = Some(0.42);
        let t = 313.15;
        for (p, barus, tol, roelands) in [
            (0.5e9, 1808.0, 5e-3, 139.0),
            (1e9, 3.36e6, 0.03, 2947.0),
            (2e9, 1.07e13, 5e-3, 92_900.0),
        ] {
            let rb = b.viscosity_pa_s(p, t) / 0.071;
            let rr = r.viscosity_pa_s(p, t) / 0.071;
            assert!((rb / (1.5e-8 * p).exp() - 1.0).abs() < 1e-12);
            assert!((rb / barus - 1.0).abs() < tol, "Barus {p}: {rb}");
            if p < 1.5e9 {
                assert!((rr / roelands - 1.0).abs() < 5e-3, "Roelands {p}: {rr}");
            } else {
                assert!(
                    (rr / 2.317e5 - 1.0).abs() < 1e-3 && rr > 2.0 * roelands,
                    "{rr}"
                );
            }
        }
        assert!(
            (derived.roelands_z() - 0.42).abs() < 5e-3,
            "{}",
            derived.roelands_z()
        );
        assert!(
            (derived.roelands_s0() - 0.2).abs() < 5e-3,
            "{}",
            derived.roelands_s0()
        );
        let d = derived.viscosity_pa_s(0.5e9, t) / 0.071;
        assert!((d - 136.35).abs() < 0.05, "{d}");
        assert!((b.viscosity_pa_s(0.0, t) / 0.071 - 1.0).abs() < 1e-15);
        assert!((r.viscosity_pa_s(0.0, t) / 0.071 - 1.0).abs() < 1e-14);
        assert!(b.viscosity_pa_s(0.0, 373.15) < 0.071);
        assert!(r.viscosity_pa_s(0.0, 373.15) < 0.071);
        // Barus's temperature factor is exactly exp(−β Δθ).
        let ratio = b.viscosity_pa_s(1e8, 323.15) / b.viscosity_pa_s(1e8, 313.15);
        assert!((ratio - (-0.08f64).exp()).abs() < 1e-14);
    }

    /// (4-7) limits with E = ρcVh²/(8k(y+b)): E → 0 gives the conduction rise
    /// τu_s h/(8k); E ≫ 1 the adiabatic rise q(y+b)/(ρcV) of a fluid sheared at
    /// q = τu_s/h for (y+b)/V (1e-3 relative at E = 1000; exact algebra otherwise).
    #[test]
    fn film_centre_rise_limits() {
        let th = chen_thermal();
        let (tau, us, h) = (3e7, 0.5, 2.6e-6);
        let cond = th.centre_rise_k(tau, us, h, 0.0);
        assert!((cond - tau * us * h / (8.0 * 0.14)).abs() < 1e-12 * cond);
        let v = 30.0;
        let s =
            th.oil_density_kg_m3 * th.oil_specific_heat_j_kg_k * v * h * h / (8.0 * 0.14 * 1000.0);
        let e = th.convection_factor(v, h, s);
        assert!((e - 1000.0).abs() < 1e-9);
        let adiabatic = (tau * us / h) * s / (800.0 * 2000.0 * v);
        let rise = th.centre_rise_k(tau, us, h, e);
        assert!(
            (rise / adiabatic - 1.0).abs() < 1.1e-3,
            "{rise} {adiabatic}"
        );
    }

    /// A constant flux q into a surface moving at V gives Archard's (4-4),
    /// θ_s = (2q/√π)·√((y+b)/(ρ_s c_s k_s V)), at every cell centre (exact integral of
    /// each cell: 1e-12 relative).
    #[test]
    fn surface_temperature_is_archard_for_constant_flux() {
        let th = chen_thermal();
        let s = Strip::new(1e-4, 50);
        let q = 1e6;
        let arch = th.archard(30.0);
        for i in [0, 10, 49] {
            let theta: f64 = (0..=i).map(|j| q * s.kernel(i, j)).sum::<f64>() * arch;
            let exact = 2.0 * q / std::f64::consts::PI.sqrt()
                * ((s.y(i) + 1e-4) / (7800.0 * 470.0 * 43.0 * 30.0)).sqrt();
            assert!((theta / exact - 1.0).abs() < 1e-12, "{i}");
        }
    }

    fn strip() -> ContactStrip {
        // Chen's Fig. 6-19 inputs: h = 2.6 µm, V = 30 m/s, b = 0.1 mm; p₀ = 1 GPa (not
        // printed; Bearing A's inner contact has 1.0 GPa).
        ContactStrip {
            max_pressure_pa: 1e9,
            semi_width_m: 1e-4,
            film_m: 2.6e-6,
            rolling_speed_m_s: 30.0,
            inlet_temperature_k: 313.15,
        }
    }

    /// Newtonian, isothermal limit (β = 0, no limiting shear): µ = (u_s/h)·Σ η(p)/Σ p,
    /// and with α = 0 too, µ = 4η₀u_s/(π h p₀) (the Hertz strip's mean pressure π p₀/4;
    /// midpoint rule on 200 cells: 1e-3).
    #[test]
    fn newtonian_isothermal_limit() {
        let mut r = sae30(ViscosityModel::Barus);
        r.temperature_viscosity_per_k = 0.0;
        r.pressure_viscosity_pa_inv = 0.0;
        let th = chen_thermal();
        let st = strip();
        let us = 1e-3;
        let mu = traction_coefficient(&r, &th, &st, us).unwrap();
        let exact = 4.0 * 0.071 * us / (std::f64::consts::PI * 2.6e-6 * 1e9);
        assert!((mu / exact - 1.0).abs() < 1e-3, "{mu} {exact}");
        assert_eq!(traction_coefficient(&r, &th, &st, 0.0).unwrap(), 0.0);
        // Linear in u_s (first region of Fig. 2-10).
        let mu2 = traction_coefficient(&r, &th, &st, 2.0 * us).unwrap();
        assert!((mu2 / mu - 2.0).abs() < 1e-9);
    }

    /// Limiting-shear limit: isothermal (β = 0), τ_L = 0.054·p: µ < 0.054 at every
    /// speed, rising with the sliding speed towards 0.054 as every cell reaches its limit
    /// (the low-pressure edge cells last): at 1 000 m/s η₀γ̇/τ_L ≥ 5.8 in every cell, so
    /// tanh ≥ 0.99998 and µ is 0.054 to 1e-6.
    #[test]
    fn limiting_shear_caps_mu() {
        let mut r = sae30(ViscosityModel::Barus);
        r.temperature_viscosity_per_k = 0.0;
        r.limiting_shear_coefficient = 0.054;
        let mu = |u| traction_coefficient(&r, &chen_thermal(), &strip(), u).unwrap();
        let (m5, m50, m1000) = (mu(5.0), mu(50.0), mu(1000.0));
        assert!(
            m5 < m50 && m50 < m1000 && m1000 <= 0.054 + 1e-15,
            "{m5} {m50} {m1000}"
        );
        assert!((m1000 - 0.054).abs() < 1e-6, "{m1000}");
    }

    /// Chen's Fig. 6-19 (η₀ = 0.08 Pa·s, α = 2e-8 1/Pa, β = 0.04 1/°C, h = 2.6 µm,
    /// V = 30 m/s, b = 0.1 mm; Roelands): with τ_L = 0.054·p the curve rises to a
    /// maximum below 0.054 at a sliding speed of order 0.2 m/s (we accept 0.02–1 m/s:
    /// p₀ is not printed) and falls beyond it (thermal region, negative slope); without
    /// the limiting shear stress the maximum is higher ("the limiting shear stress
    /// significantly affects the maximum value").
    #[test]
    fn fig_6_19_shapes() {
        let mut r = sae30(ViscosityModel::Roelands);
        r.viscosity_pa_s = 0.08;
        r.pressure_viscosity_pa_inv = 2e-8;
        r.temperature_viscosity_per_k = 0.04;
        let th = chen_thermal();
        let st = strip();
        let peak = |r: &Rheology| {
            let c = traction_curve(r, &th, &st).unwrap();
            let TractionCurve::Table { points } = c else {
                unreachable!()
            };
            let (i, _) =
                points
                    .iter()
                    .enumerate()
                    .fold((0, 0.0), |a, (i, p)| if p.1 > a.1 { (i, p.1) } else { a });
            (points[i], *points.last().unwrap())
        };
        r.limiting_shear_coefficient = 0.054;
        let (top, last) = peak(&r);
        eprintln!("limited: peak {top:?} last {last:?}");
        assert!(top.1 < 0.054 && top.1 > 0.02, "{top:?}");
        assert!(top.0 > 0.02 && top.0 < 1.0, "{top:?}");
        assert!(last.1 < 0.8 * top.1, "{last:?} {top:?}");
        r.limiting_shear_coefficient = 0.0;
        let (free, _) = peak(&r);
        eprintln!("no limit: peak {free:?}");
        assert!(free.1 > top.1, "{free:?} {top:?}");
    }

    /// Chen's spinning contact (seed ch. 6, Figs. 6-16…6-18): Bearing A inner at
    /// 10 000 rpm, a = 0.8259 mm, b = 0.0938 mm, Q = 163.7 N (p₀ = 3Q/(2πab)),
    /// V = 29.8 m/s, h = 2.6 µm, ω_s = 938.1 rad/s, µ = 0.054. The seed: hottest at
    /// x = ±0.65a, y = 0.25b, film far hotter than the surfaces. Ours (80 rows × 200
    /// cells): x/a = ±0.61, y/b = 0.34; we accept ±0.06 in x/a and ±0.1 in y/b (the
    /// seed's step Δy is not printed; our Δy is the distance from the row's inlet edge).
    /// Magnitude: at the hot spot the film-centre rise equals the formulas by hand
    /// (1e-9): (4-4) θ_s = (2q/√π)√(s/(ρ_s c_s k_s V)) with q = τu_s/(2(1+E)), plus
    /// (4-7) τu_s h/(8k(1+E)), where p = p₀√(1−x²/a²−y²/b²), τ = µp, u_s = ω_s x,
    /// s = y + b√(1−x²/a²) and E = ρcVh²/(8ks): 11.95 K.
    #[test]
    fn chen_spin_contact_hot_spot() {
        let (a, b, q) = (0.8259e-3, 0.0938e-3, 163.7);
        let p0 = 3.0 * q / (2.0 * std::f64::consts::PI * a * b);
        let mu = TractionCurve::Constant { mu: 0.054 };
        let th = chen_thermal();
        let t = spin_film_temperature(&th, &mu, a, b, p0, 2.6e-6, 29.8, 938.1, 80, 200).unwrap();
        assert!((t.at.0.abs() - 0.65).abs() < 0.06, "{t:?}");
        assert!((t.at.1 - 0.25).abs() < 0.1, "{t:?}");
        assert!(t.max_rise_k > 10.0 * t.max_surface_rise_k, "{t:?}");
        let (x, y) = t.at;
        let p = p0 * (1.0 - x * x - y * y).sqrt();
        let us = 938.1 * x.abs() * a;
        let s = (y + (1.0 - x * x).sqrt()) * b;
        let e = th.convection_factor(29.8, 2.6e-6, s);
        let tau = 0.054 * p;
        let q = tau * us / (2.0 * (1.0 + e));
        let surface =
            2.0 * q / std::f64::consts::PI.sqrt() * (s / (7800.0 * 470.0 * 43.0 * 29.8)).sqrt();
        let hand = surface + tau * us * 2.6e-6 / (8.0 * 0.14 * (1.0 + e));
        assert!((t.max_rise_k / hand - 1.0).abs() < 1e-9, "{t:?} {hand}");
        assert!((t.max_rise_k - 12.0).abs() < 0.1, "{t:?}");
        // No spin: no heat.
        let z = spin_film_temperature(&th, &mu, a, b, p0, 2.6e-6, 29.8, 0.0, 80, 200).unwrap();
        // The grid the analysis uses (40 rows × 60 cells) is within 2 % of 80 × 200.
        let coarse =
            spin_film_temperature(&th, &mu, a, b, p0, 2.6e-6, 29.8, 938.1, 40, 60).unwrap();
        assert!(
            (coarse.max_rise_k / t.max_rise_k - 1.0).abs() < 0.02,
            "{coarse:?} {t:?}"
        );
        assert_eq!(z.max_rise_k, 0.0);
    }

    #[test]
    fn bad_inputs_are_typed_errors() {
        let r = sae30(ViscosityModel::Barus);
        let mut st = strip();
        st.film_m = 0.0;
        assert!(traction_coefficient(&r, &chen_thermal(), &st, 1.0).is_err());
        let mut r2 = r;
        r2.viscosity_pa_s = -1.0;
        assert!(traction_coefficient(&r2, &chen_thermal(), &strip(), 1.0).is_err());
        assert!(traction_coefficient(&r, &chen_thermal(), &strip(), f64::NAN).is_err());
    }
}
