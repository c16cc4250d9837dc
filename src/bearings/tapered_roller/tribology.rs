//! Film, film parameter and friction by mechanism of the tapered roller bearing (issue 28
//! items 3–4), from the solved slices and flange loads; run only when the deck gives a
//! `[lubricant]` (`lubricant.viscosity` a number).
//!
//! **Kinematics (cage frame).** The rollers roll on apex (seed 004 eq. 16): the roller
//! axis makes ψ = β − t with the bearing axis, its apex on the bearing axis, and ω_R of
//! eq. 39 with Ω_E of eq. 38. A point of the roller axis at X from the midpoint (toward the
//! big end) lies at E/2 + X·sin ψ from the bearing axis and the roller's radius there is
//! ρ = d/2 + X·tan t; the cone's contact line is at r_i = E/2 + X sin ψ − ρ cos ψ, the
//! cup's at r_o = E/2 + X sin ψ + ρ cos ψ. Surface speeds: roller ω_R·ρ, cone
//! (Ω₂ − Ω_E)·r_i, cup (Ω_E − Ω₁)·r_o. With eq. 16 (tan t = (d/E) sin ψ) these are equal
//! at every X: the raceway sliding of this kinematic model vanishes along the whole line
//! (computed, not assumed: round-off, tested), so the raceways dissipate by EHL rolling
//! resistance; their sliding term is kept per slice for the day the kinematics gain skew.
//!
//! **Raceway film per slice**: Dowson–Higginson minimum and Pan–Hamrock central film
//! (`physics::lubrication::film`) with the slice's load per length p_x, the entraining
//! speed ½(u_roller + u_race), R = ρ·r_race/(r_race ± ρ)/… in the normal plane:
//! R = ρ_n·R_race,n/(R_race,n ± ρ_n) with the normal radii ρ/cos t of the roller and
//! r_race/cos(race angle) of the race (cone convex: +; cup concave: −), E′ = 2E*, at the
//! inlet viscosity; Λ = h_min/σ.
//!
//! **Roller end / flange (cone rib)**: the big end is a sphere of radius R_E centred on
//! the roller axis at H₂ − √(R_E² − r²) from the apex; it touches the cone's rib at P,
//! r from the roller axis at H₂ (eq. 33's point), on the cone's side. The rib face is
//! taken as a cone (straight generator in the axial plane, the usual ground rib): in the
//! axial plane it is flat, around the bearing axis its normal curvature is
//! κ = (n·r̂)/r_P (Meusnier) with n the rib's normal toward the roller and r_P the
//! distance of P from the bearing axis. Both surfaces move along the circumferential
//! direction ŷ at P: the roller at ω_R·r, the rib at (Ω₂ − Ω_E)·r_P; their difference is
//! the sliding speed, equal to (Ω₂ − Ω_E)·sin ψ·(R₂ − r)/tan t (closed form, tested).
//! Film: Hamrock–Dowson point-contact central and minimum film
//! (`physics::lubrication::film_point`) with R_x the circumferential reduced radius and
//! k ≈ 1.03(R_y/R_x)^0.64; the rib contact's k is often below the fit's range 1 ≤ k ≤ 8
//! (extrapolated, stated in the docs). Friction: mixed, the asperities carrying W_a
//! (Greenwood–Tripp, `surfaces.*`) at µ_b and the film the rest at the limiting-shear
//! bounded viscous stress τ = τ_L·tanh(η_p·Δu/(h_c·τ_L)), η_p = η·exp(α·p̄),
//! τ_L = τ₀ + γ·p̄, over the Hertz area; `lubricant.flange_friction` a number imposes µ.
//!
//! **Raceway rolling resistance** (EHL, Goksem & Hargreaves 1978, as quoted by Harris &
//! Kotzalas, *Rolling Bearing Analysis* 5th ed., vol. 2, §5): per slice
//! F_R = 4.318·(G·U)^0.658·W^0.0126·R·l/α, its power F_R·u_e. Raceway sliding per slice:
//! the same mixed law as the rib with the slice's Hertz strip 2b·l.
//!
//! **Cage and churning** (the deck's optional `[cage]` section, issue 28): Palmgren's
//! churning drag `viscous_drag` (f₀, seed 000 eq. 9.5) and, for a land-guided cage, the
//! rails' Petroff shear `cage_rails` (eqs. 9.3–9.4) at the cage speed Ω_E; the usual
//! roller-guided tapered cage has no rails (its pocket forces only balance its drag).
//! Without the section the friction is the contacts' and the ribs' alone. Heat: cone contacts → `InnerContacts`,
//! cup → `OuterContacts`, ribs → `Flanges`.

use super::analysis::Analysis;
use super::contact::SliceResult;
use super::input::{Lubricant, Surfaces};
use crate::bearings::friction::{CageState, FrictionBreakdown, Mechanism};
use crate::physics::contact::point::{CurvatureSum, HertzMethod, HertzPointContact};
use crate::physics::lubrication::film::{dowson_higginson_min, pan_hamrock_central, FilmInputs};
use crate::physics::lubrication::film_point::{hamrock_dowson_ellipticity, PointFilmInputs};
use crate::physics::lubrication::greenwood_tripp::Roughness;
use crate::physics::lubrication::rolling_resistance;
use crate::thermal::HeatSource;

/// One raceway slice's film and friction, SI.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SliceFilm {
    /// X, m (as [`SliceResult::x_m`]).
    pub x_m: f64,
    /// Entraining speed ½(u_roller + u_race), m/s.
    pub entrainment_m_s: f64,
    /// Sliding speed u_roller − u_race, m/s.
    pub sliding_m_s: f64,
    /// Pan–Hamrock central film, m (0 unloaded).
    pub central_film_m: f64,
    /// Dowson–Higginson minimum film, m (0 unloaded).
    pub min_film_m: f64,
    /// Λ = h_min/σ (0 unloaded).
    pub lambda: f64,
    /// EHL rolling resistance power, W.
    pub rolling_w: f64,
    /// Sliding power, W.
    pub sliding_w: f64,
}

/// The roller end / rib contact of one roller, SI.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FlangeFilm {
    /// P₃, rib load, N.
    pub load_n: f64,
    /// Sliding speed rib − roller end, m/s.
    pub sliding_m_s: f64,
    /// Entraining speed, m/s.
    pub entrainment_m_s: f64,
    /// Hertz maximum pressure, Pa (0 unloaded).
    pub max_pressure_pa: f64,
    /// Hamrock–Dowson central film, m (0 unloaded).
    pub central_film_m: f64,
    /// Hamrock–Dowson minimum film, m (0 unloaded).
    pub min_film_m: f64,
    /// Λ = h_min/σ.
    pub lambda: f64,
    /// Ellipticity k = a_transverse/b_rolling used by the film formulas.
    pub ellipticity: f64,
    /// µ = friction force / load.
    pub friction_coefficient: f64,
    /// Sliding power, W.
    pub power_w: f64,
}

/// One roller's films.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RollerFilm {
    /// Cup slices.
    pub cup: Vec<SliceFilm>,
    /// Cone slices.
    pub cone: Vec<SliceFilm>,
    /// Roller end / rib.
    pub flange: FlangeFilm,
}

/// Where the thinnest film is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmMin {
    /// Film, m.
    pub film_m: f64,
    /// Λ.
    pub lambda: f64,
    /// Roller index (0-based).
    pub roller: usize,
    /// "cup", "cone" or "flange".
    pub contact: &'static str,
    /// Slice index (0 for the flange).
    pub slice: usize,
}

/// The tribology stage's answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Tribology {
    /// Per roller.
    pub rollers: Vec<RollerFilm>,
    /// Friction by mechanism.
    pub friction: FrictionBreakdown,
    /// Inlet viscosity, Pa·s.
    pub viscosity_pa_s: f64,
    /// Thinnest loaded film over every contact.
    pub min: Option<FilmMin>,
    /// Thinnest loaded raceway film on the cone and on the cup (Λ of the life), m.
    pub min_race: [Option<FilmMin>; 2],
}

/// Mechanism names (JSON `friction.by_mechanism`, a contract).
pub const INNER_ROLLING: &str = "inner_raceway_rolling";
/// Cup EHL rolling resistance.
pub const OUTER_ROLLING: &str = "outer_raceway_rolling";
/// Cone raceway sliding.
pub const INNER_SLIDING: &str = "inner_raceway_sliding";
/// Cup raceway sliding.
pub const OUTER_SLIDING: &str = "outer_raceway_sliding";
/// Roller end / rib sliding.
pub const FLANGE_SLIDING: &str = "flange_sliding";

/// Why the stage cannot run, for a person.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct TribologyError(pub String);

/// Mixed-lubrication friction force of a contact of load `load_n` and apparent area
/// `area_m2` (N): asperities carry W_a (Greenwood–Tripp at λ = h_c/σ) at µ_b, the rest of
/// the area shears the film at τ = τ_L·tanh(η_p·|Δu|/(h_c·τ_L)).
#[allow(clippy::too_many_arguments)]
fn mixed_force_n(
    lub: &Lubricant,
    rough: &Roughness,
    eta: f64,
    e_star_pa: f64,
    load_n: f64,
    area_m2: f64,
    central_m: f64,
    sliding_m_s: f64,
) -> f64 {
    if !(load_n > 0.0 && area_m2 > 0.0) || sliding_m_s == 0.0 {
        return 0.0;
    }
    let sigma = rough.composite_rms_m;
    let wa = if central_m > 0.0 {
        rough
            .asperity_load_n(e_star_pa, area_m2, central_m / sigma)
            .min(load_n)
    } else {
        load_n
    };
    let share = 1.0 - wa / load_n;
    let p_mean = load_n / area_m2;
    let tau_l = lub.limiting_shear_pa + lub.limiting_shear_slope * p_mean;
    // exp(α·p̄) bounded at e^50: τ is already at τ_L long before (tanh saturates).
    let eta_p = eta * (lub.pressure_viscosity_pa_inv * p_mean).min(50.0).exp();
    let fluid = if central_m > 0.0 && tau_l > 0.0 {
        tau_l * (eta_p * sliding_m_s.abs() / (central_m * tau_l)).tanh()
    } else {
        0.0
    };
    lub.boundary_friction * wa + share * fluid * area_m2
}

/// Goksem–Hargreaves EHL rolling resistance of a line contact, N:
/// F_R = 4.318·(G·U)^0.658·W^0.0126·R·l/α (`physics::lubrication::rolling_resistance`);
/// 0 N for an unloaded or non-rolling slice (it dissipates nothing) and for α = 0.
pub fn rolling_force_n(inputs: &FilmInputs, length_m: f64) -> f64 {
    rolling_resistance::line_force_n(inputs, length_m).unwrap_or(0.0)
}

/// Sliding speed at the rib in closed form, m/s: (Ω₂ − Ω_E)·sin ψ·(R₂ − r)/tan t.
pub fn flange_sliding_closed_form_m_s(a: &Analysis) -> f64 {
    let rg = &a.bearing.geometry;
    let op = &a.bearing.input.operating;
    (op.inner_speed_rad_s - a.bearing.dynamics.cage_rad_s)
        * rg.axis_angle_rad.sin()
        * (rg.r2_m - rg.flange_contact_radius_m)
        / rg.half_cone_rad.tan()
}

/// The stage: `None` without a lubricant; an error names what cannot be evaluated.
pub fn tribology(a: &Analysis) -> Option<Result<Tribology, TribologyError>> {
    let input = &a.bearing.input;
    input.lubricant.is_given().then(|| run(a))
}

fn run(a: &Analysis) -> Result<Tribology, TribologyError> {
    let input = &a.bearing.input;
    let lub = &input.lubricant;
    let surf: &Surfaces = &input.surfaces;
    if !(lub.pressure_viscosity_pa_inv > 0.0) {
        return Err(TribologyError(format!(
            "lubricant.pressure_viscosity = {:e} 1/Pa: the EHL rolling resistance needs a positive pressure-viscosity coefficient",
            lub.pressure_viscosity_pa_inv
        )));
    }
    let g = &input.geometry;
    let rg = &a.bearing.geometry;
    let dy = &a.bearing.dynamics;
    let op = &input.operating;
    let eta = lub.inlet_viscosity_pa_s();
    let rough = Roughness {
        composite_rms_m: surf.composite_rms_m,
        roughness_parameter: surf.roughness_parameter,
        asperity_slope: surf.asperity_slope,
    };
    let sigma = surf.composite_rms_m;
    let m = &input.materials;
    let e_star = |race: &crate::physics::material::Material| {
        1.0 / ((1.0 - m.roller.poisson_ratio.powi(2)) / m.roller.youngs_modulus_pa
            + (1.0 - race.poisson_ratio.powi(2)) / race.youngs_modulus_pa)
    };
    let (es_cup, es_cone) = (e_star(&m.cup), e_star(&m.cone));
    let (t, psi) = (rg.half_cone_rad, rg.axis_angle_rad);
    let (sin_psi, cos_psi) = psi.sin_cos();
    let (beta, cone_angle) = (g.cup_angle_rad, g.cup_angle_rad - 2.0 * t);
    let half_e = 0.5 * g.pitch_diameter_m;
    let w_r = dy.roller_spin_rad_s;
    let w_cone = op.inner_speed_rad_s - dy.cage_rad_s;
    let w_cup = dy.cage_rad_s - op.outer_speed_rad_s;

    // One raceway's slices. `cup`: the race is concave in the normal plane.
    let race = |slices: &[SliceResult], cup: bool| -> Vec<SliceFilm> {
        let width = match slices.len() {
            0 | 1 => g.effective_length_m,
            _ => (slices[1].x_m - slices[0].x_m).abs(),
        };
        slices
            .iter()
            .map(|s| {
                let x = s.x_m;
                let rho = 0.5 * g.roller_diameter_m + x * t.tan();
                let axis_r = half_e + x * sin_psi;
                let (r_race, w_race, angle, es) = if cup {
                    (axis_r + rho * cos_psi, w_cup, beta, es_cup)
                } else {
                    (axis_r - rho * cos_psi, w_cone, cone_angle, es_cone)
                };
                let u_roller = w_r * rho;
                let u_race = w_race * r_race;
                let sliding = u_roller - u_race;
                let ue = 0.5 * (u_roller + u_race);
                // Normal-plane radii: roller ρ/cos t, race r/cos(angle).
                let (rr, rw) = (rho / t.cos(), r_race / angle.cos());
                let reduced = if cup {
                    rr * rw / (rw - rr)
                } else {
                    rr * rw / (rw + rr)
                };
                let fi = FilmInputs {
                    viscosity_pa_s: eta,
                    pressure_viscosity_pa_inv: lub.pressure_viscosity_pa_inv,
                    entrainment_speed_m_s: ue,
                    reduced_radius_m: reduced,
                    load_per_length_n_m: s.load_n_m,
                    effective_modulus_pa: 2.0 * es,
                };
                let hc = pan_hamrock_central(&fi).unwrap_or(0.0);
                let hm = dowson_higginson_min(&fi).unwrap_or(0.0);
                let load = s.load_n_m * width;
                let rolling_w = rolling_force_n(&fi, width) * ue.abs();
                let area = 2.0 * s.half_width_m * width;
                let sliding_w =
                    mixed_force_n(lub, &rough, eta, es, load, area, hc, sliding) * sliding.abs();
                SliceFilm {
                    x_m: x,
                    entrainment_m_s: ue,
                    sliding_m_s: sliding,
                    central_film_m: hc,
                    min_film_m: hm,
                    lambda: if load > 0.0 { hm / sigma } else { 0.0 },
                    rolling_w,
                    sliding_w,
                }
            })
            .collect()
    };

    // The rib contact's geometry, the same for every roller.
    let (re, r) = (rg.big_end_radius_m, rg.flange_contact_radius_m);
    let s_off = (re * re - r * r).sqrt();
    // P = H₂·a − r·n with a = (sin ψ, cos ψ) and n = (cos ψ, −sin ψ) in (radial, axial).
    let p_x = rg.h2_m * sin_psi - r * cos_psi;
    // The rib's normal toward the roller: (O_s − P)/R_E = (−s_off·a + r·n)/R_E.
    let n_x = (-s_off * sin_psi + r * cos_psi) / re;
    let rolling_curv = 1.0 / re + n_x / p_x;
    let transverse_curv = 1.0 / re;
    let hertz = CurvatureSum::new(rolling_curv, transverse_curv)
        .and_then(|c| HertzPointContact::new(c, es_cone, HertzMethod::Exact))
        .map_err(|e| {
            TribologyError(format!(
                "roller end / rib contact (R_E = {re:.4e} m, rib curvature around the axis {:.4e} 1/m): {e}",
                n_x / p_x
            ))
        })?;
    let k = hamrock_dowson_ellipticity(1.0 / rolling_curv, 1.0 / transverse_curv)
        .map_err(|e| TribologyError(format!("roller end / rib film: {e}")))?;
    let u_end = w_r * r;
    let u_rib = w_cone * p_x;
    let flange_sliding = u_rib - u_end;
    let flange_ue = 0.5 * (u_rib + u_end);
    let flange = |load: f64| -> Result<FlangeFilm, TribologyError> {
        if !(load > 0.0) {
            return Ok(FlangeFilm {
                load_n: load.max(0.0),
                sliding_m_s: flange_sliding,
                entrainment_m_s: flange_ue,
                max_pressure_pa: 0.0,
                central_film_m: 0.0,
                min_film_m: 0.0,
                lambda: 0.0,
                ellipticity: k,
                friction_coefficient: 0.0,
                power_w: 0.0,
            });
        }
        let c = hertz.solve(load).map_err(|e| {
            TribologyError(format!("roller end / rib contact at {load:.4e} N: {e}"))
        })?;
        let pf = PointFilmInputs {
            viscosity_pa_s: eta,
            pressure_viscosity_pa_inv: lub.pressure_viscosity_pa_inv,
            entrainment_speed_m_s: flange_ue,
            reduced_radius_rolling_m: 1.0 / rolling_curv,
            load_n: load,
            effective_modulus_pa: 2.0 * es_cone,
            ellipticity: k,
        };
        let err = |e| TribologyError(format!("roller end / rib film: {e}"));
        let hc = pf.central_film_thickness_m().map_err(err)?;
        let hm = pf.minimum_film_thickness_m().map_err(err)?;
        let area = std::f64::consts::PI * c.semi_major_m * c.semi_minor_m;
        let force = if lub.flange_friction.is_finite() {
            lub.flange_friction * load
        } else {
            mixed_force_n(lub, &rough, eta, es_cone, load, area, hc, flange_sliding)
        };
        Ok(FlangeFilm {
            load_n: load,
            sliding_m_s: flange_sliding,
            entrainment_m_s: flange_ue,
            max_pressure_pa: c.max_pressure_pa,
            central_film_m: hc,
            min_film_m: hm,
            lambda: hm / sigma,
            ellipticity: k,
            friction_coefficient: force / load,
            power_w: force * flange_sliding.abs(),
        })
    };

    let mut rollers = Vec::with_capacity(a.slices.len());
    for (q, [cup, cone]) in a.slices.iter().enumerate() {
        let load = a
            .solution
            .rollers
            .get(q)
            .map(|r| r.0.flange_n)
            .unwrap_or(0.0);
        rollers.push(RollerFilm {
            cup: race(cup, true),
            cone: race(cone, false),
            flange: flange(load)?,
        });
    }
    let sum = |f: &dyn Fn(&RollerFilm) -> f64| rollers.iter().map(f).sum::<f64>();
    let slice_sum = |s: &[SliceFilm], f: fn(&SliceFilm) -> f64| s.iter().map(f).sum::<f64>();
    let mech = |name, power_w, heat| Mechanism {
        name,
        power_w,
        heat: Some(heat),
    };
    // The `[cage]` section: churning drag and a land-guided cage's rails (issue 28,
    // `bearings::friction::CageLosses`), at the inlet viscosity and the cage speed Ω_E.
    let cage = input
        .cage
        .mechanisms(&CageState {
            viscosity_pa_s: eta,
            density_kg_m3: lub.density_kg_m3,
            inner_rad_s: op.inner_speed_rad_s,
            outer_rad_s: op.outer_speed_rad_s,
            cage_rad_s: dy.cage_rad_s,
            pitch_diameter_m: g.pitch_diameter_m,
        })
        .map_err(TribologyError)?;
    let friction = FrictionBreakdown::from_mechanisms(
        op.inner_speed_rad_s - op.outer_speed_rad_s,
        vec![
            mech(
                INNER_ROLLING,
                sum(&|r| slice_sum(&r.cone, |s| s.rolling_w)),
                HeatSource::InnerContacts,
            ),
            mech(
                OUTER_ROLLING,
                sum(&|r| slice_sum(&r.cup, |s| s.rolling_w)),
                HeatSource::OuterContacts,
            ),
            mech(
                INNER_SLIDING,
                sum(&|r| slice_sum(&r.cone, |s| s.sliding_w)),
                HeatSource::InnerContacts,
            ),
            mech(
                OUTER_SLIDING,
                sum(&|r| slice_sum(&r.cup, |s| s.sliding_w)),
                HeatSource::OuterContacts,
            ),
            mech(
                FLANGE_SLIDING,
                sum(&|r| r.flange.power_w),
                HeatSource::Flanges,
            ),
        ]
        .into_iter()
        .chain(cage)
        .collect(),
    );
    let mut min: Option<FilmMin> = None;
    let mut min_race: [Option<FilmMin>; 2] = [None, None];
    let consider = |slot: &mut Option<FilmMin>, c: FilmMin| {
        if slot.is_none_or(|m| c.film_m < m.film_m) {
            *slot = Some(c);
        }
    };
    for (q, r) in rollers.iter().enumerate() {
        for (ri, (name, s)) in [("cone", &r.cone), ("cup", &r.cup)].into_iter().enumerate() {
            for (k, sl) in s.iter().enumerate() {
                if sl.min_film_m > 0.0 {
                    let c = FilmMin {
                        film_m: sl.min_film_m,
                        lambda: sl.lambda,
                        roller: q,
                        contact: name,
                        slice: k,
                    };
                    consider(&mut min, c);
                    consider(&mut min_race[ri], c);
                }
            }
        }
        if r.flange.min_film_m > 0.0 {
            consider(
                &mut min,
                FilmMin {
                    film_m: r.flange.min_film_m,
                    lambda: r.flange.lambda,
                    roller: q,
                    contact: "flange",
                    slice: 0,
                },
            );
        }
    }
    Ok(Tribology {
        rollers,
        friction,
        viscosity_pa_s: eta,
        min,
        min_race,
    })
}

#[cfg(test)]
#[path = "tribology_tests.rs"]
mod tests;
