//! The deck mapped onto the 2-DOF tribodynamics (seed 003 eqs. 1–5, `super::dynamics`)
//! and, over the last steady cage cycle, the "formula" tier friction of every roller's
//! two contacts (eqs. 35–42, `physics::lubrication::mixed_friction`).
//!
//! Readings (documented defaults of issue 25, traps 3–5):
//! * k_n: the deck's `dynamics.contact_stiffness`, or with "lamina" the slice law of a
//!   straight roller of the effective length, two contacts in series
//!   (`quasi_static::effective_contact_stiffness`, ≈ 2.0e9 N/m^(10/9) for the truck).
//! * The film of eq. 4 and the Hertz strip use the lubricant's viscosity at the inlet
//!   (housing) temperature T_in of eq. 28, from η₀ given at the reference temperature
//!   T₀ of eq. 10 by the Houpert law at p = 0; the friction is evaluated isothermally at
//!   T_in (the formula tier: the contact's own heating is the thermal EHL's, issue 26).
//! * Friction per contact: the seed's Table 3 contact is roller–inner race with the film
//!   of eq. 4 (the dynamics' h_i, or with `film_in_deflection = false` the same law
//!   evaluated at the sampled load and squeeze velocity); the outer contact carries
//!   W_o = W_i + F_c with the steady Pan–Hamrock film of its own reduced radius; both at
//!   the deck's sliding speed ΔU (`contact.sliding_speed`).
//! * The bearing's friction is the mean over the last cage cycle of the sum over every
//!   roller and both contacts; µ = that sum over the sum of the contact loads.

use super::dynamics::{
    simulate, DynamicsError, DynamicsModel, DynamicsResult, FilmLaw, Span, Squeeze as FilmSqueeze,
};
use super::geometry::Derived;
use super::input::{CylindricalInput, Squeeze};
use super::quasi_static::effective_contact_stiffness;
use crate::numerics::cancel::Cancel;
use crate::physics::contact::line::{effective_modulus, reduced_modulus, Elastic};
use crate::physics::lubrication::film::{pan_hamrock_min, FilmInputs};
use crate::physics::lubrication::greenwood_tripp::Roughness;
use crate::physics::lubrication::houpert::Houpert;
use crate::physics::lubrication::mixed_friction::{
    mixed_friction, MixedContact, MixedFriction, DEFAULT_NODES,
};

/// Samples of the cage cycle at which the friction of every roller is evaluated (the
/// cycle is smooth at the cage frequency and its first harmonics: 128 samples resolve
/// up to the 60th harmonic; the budget is 25 ms for 1 000 × 12).
pub const FRICTION_SAMPLES: usize = 128;

/// The dynamics' sampling rate, Hz: 4 096 Hz resolves the base natural frequency
/// (≈ 0.9 kHz for the truck bearing) and its second harmonic below Nyquist.
pub const SAMPLE_RATE_HZ: f64 = 4096.0;

/// The friction of roller 1's contacts over the last cage cycle and the bearing's.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CycleFriction {
    /// Cage angle of roller 1, deg.
    pub cage_angle_deg: Vec<f64>,
    /// Roller 1's inner contact load, N.
    pub roller_load_n: Vec<f64>,
    /// Its film, m.
    pub film_m: Vec<f64>,
    /// Its squeeze velocity, m/s.
    pub squeeze_velocity_m_s: Vec<f64>,
    /// Its boundary friction (inner contact), N.
    pub boundary_friction_n: Vec<f64>,
    /// Its viscous friction (inner contact), N.
    pub viscous_friction_n: Vec<f64>,
    /// Its power loss f·ΔU (inner contact), W.
    pub power_w: Vec<f64>,
    /// Λ = h/σ (inner contact).
    pub lambda: Vec<f64>,
    /// Its outer contact's total friction, N.
    pub outer_friction_n: Vec<f64>,
}

/// The bearing's friction, the mean over the last cage cycle of every roller's two
/// contacts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingFriction {
    /// Total friction force, N.
    pub total_n: f64,
    /// Boundary (asperity) part, N.
    pub boundary_n: f64,
    /// Viscous part, N.
    pub viscous_n: f64,
    /// µ = total ÷ the summed contact loads.
    pub coefficient: f64,
    /// Power loss Σ f·ΔU, W.
    pub power_w: f64,
    /// The inner contacts' share of the total friction, N.
    pub inner_n: f64,
    /// The outer contacts' share, N.
    pub outer_n: f64,
    /// The inner contacts' boundary (asperity) part, N (issue 28: friction by mechanism
    /// at each race; the outer's is `boundary_n − inner_boundary_n`).
    pub inner_boundary_n: f64,
}

/// Friction at one of the deck's `contact.positions` (Table 3's A1, B1, C1): roller 1's
/// inner contact at that cage angle of the last cycle (nearest sample).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionFriction {
    /// The cage angle asked, deg.
    pub cage_angle_deg: f64,
    /// The contact's load, N.
    pub load_n: f64,
    /// The friction breakdown.
    pub friction: MixedFriction,
}

/// Everything the tribodynamics adds to a solved case.
#[derive(Debug, Clone, PartialEq)]
pub struct Tribodynamics {
    /// k_n in effect, N/m^n.
    pub contact_stiffness: f64,
    /// Where k_n came from: "lamina" (the slice law) or "deck".
    pub contact_stiffness_source: &'static str,
    /// The lubricant viscosity at the inlet temperature, Pa·s.
    pub inlet_viscosity_pa_s: f64,
    /// The dynamics.
    pub dynamics: DynamicsResult,
    /// Roller 1's cycle with its friction.
    pub cycle: CycleFriction,
    /// The bearing's friction.
    pub friction: BearingFriction,
    /// Table 3's positions.
    pub positions: Vec<PositionFriction>,
}

/// Why the tribodynamics failed: the dynamics' refusal or failure (naming the deck key),
/// or a friction input out of range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TribodynamicsError {
    /// From the 2-DOF dynamics.
    #[error("{0}")]
    Dynamics(#[from] DynamicsError),
    /// From the stiffness or friction inputs.
    #[error("{0}")]
    Input(String),
}

/// The lubricant of eqs. 10–11 (η₀ at the reference temperature T₀).
pub fn houpert(input: &CylindricalInput) -> Houpert {
    let l = &input.lubricant;
    Houpert {
        viscosity_pa_s: l.viscosity_pa_s,
        pressure_viscosity_pa_inv: l.pressure_viscosity_pa_inv,
        temperature_viscosity_per_k: l.temperature_viscosity_k_inv,
        reference_temperature_k: l.reference_temperature_k,
        density_kg_m3: l.density_kg_m3,
    }
}

/// η at the inlet temperature and ambient pressure, Pa·s (eq. 10 at p = 0).
pub fn inlet_viscosity_pa_s(input: &CylindricalInput) -> f64 {
    houpert(input).viscosity_pa_s(0.0, input.lubricant.inlet_temperature_k)
}

/// k_n in effect and its source.
pub fn contact_stiffness(
    input: &CylindricalInput,
    derived: &Derived,
) -> Result<(f64, &'static str), TribodynamicsError> {
    match input.dynamics.contact_stiffness {
        Some(k) => Ok((k, "deck")),
        None => effective_contact_stiffness(
            derived.effective_length_m,
            &input.materials.roller,
            &input.materials.inner,
            &input.materials.outer,
        )
        .map(|k| (k, "lamina"))
        .map_err(|e| TribodynamicsError::Input(e.to_string())),
    }
}

fn elastic(m: &crate::physics::material::Material) -> Elastic {
    Elastic {
        youngs_modulus_pa: m.youngs_modulus_pa,
        poisson_ratio: m.poisson_ratio,
    }
}

/// The film law of eq. 4 for the roller–inner race contact.
pub fn film_law(input: &CylindricalInput, derived: &Derived) -> FilmLaw {
    let m = &input.materials;
    FilmLaw {
        viscosity_pa_s: inlet_viscosity_pa_s(input),
        pressure_viscosity_pa_inv: input.lubricant.pressure_viscosity_pa_inv,
        reduced_modulus_pa: effective_modulus(elastic(&m.roller), elastic(&m.inner)),
        reduced_radius_m: derived.inner_reduced_radius_m,
        length_m: derived.effective_length_m,
        entrainment_speed_m_s: derived.entrainment_speed_m_s,
        squeeze: match input.dynamics.squeeze {
            Squeeze::Normalised => FilmSqueeze::Normalised,
            Squeeze::Printed => FilmSqueeze::Printed,
            Squeeze::None => FilmSqueeze::None,
        },
    }
}

/// The 2-DOF model of `input` with contact stiffness `k_n`.
pub fn dynamics_model(input: &CylindricalInput, derived: &Derived, k_n: f64) -> DynamicsModel {
    let d = &input.dynamics;
    DynamicsModel {
        mass_kg: d.system_mass_kg,
        roller_count: input.geometry.roller_count,
        contact_stiffness: k_n,
        load_exponent: d.load_exponent,
        clearance_m: -input.geometry.radial_interference_m,
        cage_speed_rad_s: derived.cage_speed_rad_s,
        first_azimuth_rad: 0.0,
        force_n: input.load_vector_n(),
        film: d.film_in_deflection.then(|| film_law(input, derived)),
        damping_ratio: d.damping_ratio,
        span: Span::Revolutions {
            shaft_speed_rad_s: input.operating.inner_speed_rad_s,
            revolutions: d.revolutions as f64,
            settle_revolutions: d.settle_revolutions as f64,
        },
        rtol: d.tolerance,
        sample_rate_hz: SAMPLE_RATE_HZ,
        initial_state: [0.0; 4],
    }
}

/// The dynamics of `input` and the friction over its last cage cycle.
pub fn tribodynamics(
    input: &CylindricalInput,
    derived: &Derived,
    cancel: Cancel<'_>,
) -> Result<Tribodynamics, TribodynamicsError> {
    let (k_n, source) = contact_stiffness(input, derived)?;
    let model = dynamics_model(input, derived, k_n);
    let dynamics = simulate(&model, cancel)?;
    let (cycle, friction, positions) = cycle_friction(input, derived, &dynamics)?;
    Ok(Tribodynamics {
        contact_stiffness: k_n,
        contact_stiffness_source: source,
        inlet_viscosity_pa_s: inlet_viscosity_pa_s(input),
        dynamics,
        cycle,
        friction,
        positions,
    })
}

/// One contact's friction inputs, all but load and film.
struct ContactFriction {
    base: MixedContact,
}

impl ContactFriction {
    fn new(input: &CylindricalInput, derived: &Derived, outer: bool) -> Self {
        let m = &input.materials;
        let ring = if outer { &m.outer } else { &m.inner };
        let s = &input.surfaces;
        let l = &input.lubricant;
        ContactFriction {
            base: MixedContact {
                load_n: 0.0,
                effective_length_m: derived.effective_length_m,
                reduced_radius_m: if outer {
                    derived.outer_reduced_radius_m
                } else {
                    derived.inner_reduced_radius_m
                },
                reduced_modulus_pa: reduced_modulus(elastic(&m.roller), elastic(ring)),
                film_m: 0.0,
                roughness: Roughness {
                    composite_rms_m: s.composite_rms_m,
                    roughness_parameter: s.roughness_parameter,
                    asperity_slope: s.asperity_slope,
                },
                lubricant: houpert(input),
                temperature_k: l.inlet_temperature_k,
                limiting_shear_stress_pa: l.limiting_shear_pa,
                limiting_shear_slope: l.limiting_shear_slope,
                sliding_speed_m_s: input.contact.sliding_speed_m_s,
                rolling_speed_m_s: derived.entrainment_speed_m_s,
                nodes: DEFAULT_NODES,
            },
        }
    }

    fn at(&self, load_n: f64, film_m: f64) -> Result<MixedFriction, TribodynamicsError> {
        if load_n <= 0.0 {
            return Ok(MixedFriction::default());
        }
        mixed_friction(&MixedContact {
            load_n,
            film_m,
            ..self.base
        })
        .map_err(|e| TribodynamicsError::Input(e.to_string()))
    }
}

type CycleOut = (CycleFriction, BearingFriction, Vec<PositionFriction>);

/// Friction of every roller over the last cage cycle of `dynamics`.
fn cycle_friction(
    input: &CylindricalInput,
    derived: &Derived,
    dynamics: &DynamicsResult,
) -> Result<CycleOut, TribodynamicsError> {
    let s = &dynamics.series;
    let m = input.geometry.roller_count;
    let n = s.t_s.len();
    let per_cycle = if derived.cage_speed_rad_s > 0.0 && s.dt_s > 0.0 {
        ((std::f64::consts::TAU / derived.cage_speed_rad_s) / s.dt_s).round() as usize
    } else {
        n
    };
    let per_cycle = per_cycle.clamp(1, n.max(1));
    if n == 0 || s.roller_load_n.len() != m {
        return Err(TribodynamicsError::Input(
            "the dynamics recorded no samples after settling: raise dynamics.revolutions above dynamics.settle_revolutions".to_string(),
        ));
    }
    let start = n - per_cycle;
    let stride = per_cycle.div_ceil(FRICTION_SAMPLES).max(1);
    let idx: Vec<usize> = (start..n).step_by(stride).collect();
    let inner = ContactFriction::new(input, derived, false);
    let outer = ContactFriction::new(input, derived, true);
    let law = film_law(input, derived);
    let coeffs = law.coefficients().ok_or_else(|| {
        TribodynamicsError::Input(format!(
            "no EHL film for the inlet viscosity {:.4e} Pa·s and entrainment speed {:.4} m/s: check lubricant.viscosity and operating.inner_speed",
            law.viscosity_pa_s, law.entrainment_speed_m_s
        ))
    })?;
    let outer_film = |load: f64| {
        pan_hamrock_min(&FilmInputs {
            viscosity_pa_s: law.viscosity_pa_s,
            pressure_viscosity_pa_inv: law.pressure_viscosity_pa_inv,
            entrainment_speed_m_s: law.entrainment_speed_m_s,
            reduced_radius_m: derived.outer_reduced_radius_m,
            load_per_length_n_m: load / derived.effective_length_m,
            effective_modulus_pa: law.reduced_modulus_pa,
        })
        .unwrap_or(0.0)
    };
    // The film of roller i at sample k: the dynamics' when the film is in the deflection,
    // else eq. 4 evaluated at the sampled load and squeeze velocity.
    let film_of = |i: usize, k: usize| -> f64 {
        let load = s.roller_load_n[i][k];
        if input.dynamics.film_in_deflection {
            s.film_m[i][k]
        } else {
            let w = s
                .squeeze_velocity_m_s
                .get(i)
                .and_then(|v| v.get(k))
                .copied();
            coeffs
                .film_unclamped(load, coeffs.squeeze_factor(w.unwrap_or(0.0)))
                .max(0.0)
        }
    };
    let mut cycle = CycleFriction::default();
    let mut total = BearingFriction::default();
    let mut load_sum = 0.0;
    let sigma = input.surfaces.composite_rms_m;
    for &k in &idx {
        let mut row = BearingFriction::default();
        for i in 0..m {
            let w_i = s.roller_load_n[i][k];
            let h_i = film_of(i, k);
            let fi = inner.at(w_i, h_i)?;
            let w_o = if w_i > 0.0 {
                w_i + derived.centrifugal_n
            } else {
                derived.centrifugal_n
            };
            let fo = outer.at(w_o, outer_film(w_o))?;
            row.boundary_n += fi.boundary_n + fo.boundary_n;
            row.inner_boundary_n += fi.boundary_n;
            row.viscous_n += fi.viscous_n + fo.viscous_n;
            row.inner_n += fi.total_n;
            row.outer_n += fo.total_n;
            row.power_w += fi.power_w + fo.power_w;
            load_sum += w_i + w_o;
            if i == 0 {
                let t = s.t_s[k];
                let angle = (derived.cage_speed_rad_s * t)
                    .to_degrees()
                    .rem_euclid(360.0);
                cycle.cage_angle_deg.push(angle);
                cycle.roller_load_n.push(w_i);
                cycle.film_m.push(h_i);
                cycle.squeeze_velocity_m_s.push(
                    s.squeeze_velocity_m_s
                        .first()
                        .and_then(|v| v.get(k))
                        .copied()
                        .unwrap_or(0.0),
                );
                cycle.boundary_friction_n.push(fi.boundary_n);
                cycle.viscous_friction_n.push(fi.viscous_n);
                cycle.power_w.push(fi.power_w);
                cycle.lambda.push(if sigma > 0.0 {
                    h_i / sigma
                } else {
                    f64::INFINITY
                });
                cycle.outer_friction_n.push(fo.total_n);
            }
        }
        total.boundary_n += row.boundary_n;
        total.inner_boundary_n += row.inner_boundary_n;
        total.viscous_n += row.viscous_n;
        total.inner_n += row.inner_n;
        total.outer_n += row.outer_n;
        total.power_w += row.power_w;
    }
    let count = idx.len().max(1) as f64;
    total.boundary_n /= count;
    total.inner_boundary_n /= count;
    total.viscous_n /= count;
    total.inner_n /= count;
    total.outer_n /= count;
    total.power_w /= count;
    total.total_n = total.inner_n + total.outer_n;
    load_sum /= count;
    total.coefficient = if load_sum > 0.0 {
        total.total_n / load_sum
    } else {
        0.0
    };
    // Table 3's positions: roller 1's inner contact at the nearest sample of the cycle.
    let mut positions = Vec::new();
    for &p in &input.contact.positions_rad {
        let want = p.to_degrees().rem_euclid(360.0);
        let nearest = cycle
            .cage_angle_deg
            .iter()
            .enumerate()
            .min_by(|a, b| {
                angle_gap(*a.1, want)
                    .partial_cmp(&angle_gap(*b.1, want))
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .map(|(j, _)| j);
        if let Some(j) = nearest {
            let load = cycle.roller_load_n[j];
            positions.push(PositionFriction {
                cage_angle_deg: want,
                load_n: load,
                friction: inner.at(load, cycle.film_m[j])?,
            });
        }
    }
    Ok((cycle, total, positions))
}

fn angle_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}
