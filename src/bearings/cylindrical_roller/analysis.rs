//! One solved cylindrical roller case: the quasi-static lamina load distribution
//! (`super::quasi_static`) built from the deck, and per slice the EHL film and Λ.

use super::geometry::{derive, Derived};
use super::input::{CylindricalInput, ProfileKind, Ribs};
use super::quasi_static::{Profile, QuasiStatic, QuasiStaticError, QuasiStaticModel};
use super::quasi_static_ribs::{solve_with, RibContact};
use super::tribodynamics::{tribodynamics, Tribodynamics, TribodynamicsError};
use crate::numerics::cancel::Cancel;
use crate::physics::contact::line::{effective_modulus, Elastic};
use crate::physics::lubrication::film::{pan_hamrock_min, FilmInputs};

/// The films of one slice, m (`None`: unloaded, no film to speak of).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SliceFilm {
    /// Inner contact minimum film (Pan–Hamrock), m.
    pub inner_m: Option<f64>,
    /// Outer contact minimum film (Pan–Hamrock), m.
    pub outer_m: Option<f64>,
}

/// One roller's film summary.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RollerFilm {
    /// Per slice, in the solve's slice order.
    pub slices: Vec<SliceFilm>,
    /// The thinnest film over its loaded slices and both contacts, m (`None`: unloaded).
    pub min_film_m: Option<f64>,
    /// Λ = h_min/σ (`None`: unloaded).
    pub lambda: Option<f64>,
    /// The largest Hertz pressure over its slices and both contacts, Pa.
    pub max_pressure_pa: f64,
}

/// A solved case, SI. The lead adds the dynamics and friction beside the statics.
#[derive(Debug, Clone)]
pub struct CylindricalAnalysis {
    /// The deck's name.
    pub name: String,
    /// The input.
    pub input: CylindricalInput,
    /// The derived geometry and kinematics.
    pub derived: Derived,
    /// The model handed to the lamina solve.
    pub model: QuasiStaticModel,
    /// The equilibrium.
    pub statics: QuasiStatic,
    /// Per roller, the films.
    pub films: Vec<RollerFilm>,
    /// What a reader should know (thin films, …), in words.
    pub warnings: Vec<String>,
    /// Wall time of the solve, s.
    pub wall_time_s: f64,
    /// The 2-DOF tribodynamics and the friction over a cage cycle; `None` when not run
    /// (`dynamics.revolutions = 0`, `run --no-transient`, sweeps).
    pub tribo: Option<Tribodynamics>,
}

impl CylindricalAnalysis {
    /// The largest roller load (inner or outer contact), N.
    pub fn max_roller_load_n(&self) -> f64 {
        self.statics
            .rollers
            .iter()
            .map(|r| r.inner_load_n.max(r.outer_load_n))
            .fold(0.0, f64::max)
    }

    /// The thinnest film over every loaded slice, m.
    pub fn min_film_m(&self) -> Option<f64> {
        self.films
            .iter()
            .filter_map(|f| f.min_film_m)
            .reduce(f64::min)
    }

    /// The largest Hertz pressure, Pa.
    pub fn max_pressure_pa(&self) -> f64 {
        self.films
            .iter()
            .map(|f| f.max_pressure_pa)
            .fold(0.0, f64::max)
    }
}

/// The lamina model of `input`: F = radial_load·(cos φ, sin φ) plus the weight
/// (−M·g, 0) with gravity on; roller 1 at azimuth 0 (θ_i = 2π(i−1)/m at t = 0, the
/// seed's eq. 2 convention); centrifugal force from the cage speed in effect.
pub fn model(input: &CylindricalInput) -> QuasiStaticModel {
    let d = derive(input);
    let g = &input.geometry;
    QuasiStaticModel {
        roller_count: g.roller_count,
        first_azimuth_rad: 0.0,
        roller_radius_m: d.roller_radius_m,
        inner_raceway_radius_m: d.inner_raceway_radius_m,
        outer_raceway_radius_m: d.outer_raceway_radius_m,
        roller_length_m: g.roller_length_m,
        profile: match g.profile {
            ProfileKind::DubOff => Profile::DubOff {
                radius_m: g.dub_off_radius_m,
                length_m: g.dub_off_length_m,
            },
            ProfileKind::Logarithmic => Profile::Logarithmic,
        },
        slices: input.solver.slices,
        radial_interference_m: g.radial_interference_m,
        centrifugal_n: d.centrifugal_n,
        roller: input.materials.roller,
        inner: input.materials.inner,
        outer: input.materials.outer,
        load_n: input.load_vector_n(),
        tolerance: input.solver.force_tolerance,
    }
}

/// The roller end–rib contacts of `input` when its ribs carry axial load (ribs on both
/// rings and a non-zero `operating.axial_load`); `None` otherwise (the radial solve).
pub fn rib_contact(input: &CylindricalInput) -> Option<RibContact> {
    let g = &input.geometry;
    (g.ribs == Ribs::Both && input.operating.axial_load_n != 0.0).then(|| RibContact {
        angle_rad: g.rib_angle_rad,
        contact_height_m: g.rib_contact_height(),
        axial_load_n: input.operating.axial_load_n,
    })
}

/// Solve `input` (named `name`) from rest.
pub fn analyse(
    input: &CylindricalInput,
    name: &str,
    cancel: &Cancel,
) -> Result<CylindricalAnalysis, QuasiStaticError> {
    analyse_from(input, name, None, cancel)
}

/// Solve `input` with the ring equilibrium started from `start` (a neighbouring
/// solution), falling back to rest when that fails.
pub fn analyse_from(
    input: &CylindricalInput,
    name: &str,
    start: Option<&QuasiStatic>,
    cancel: &Cancel,
) -> Result<CylindricalAnalysis, QuasiStaticError> {
    let t0 = std::time::Instant::now();
    let derived = derive(input);
    let model = model(input);
    let ribs = rib_contact(input);
    let ribs = ribs.as_ref();
    let statics = match start {
        Some(s) => match solve_with(&model, ribs, Some(s), cancel) {
            Ok(q) => q,
            Err(QuasiStaticError::Cancelled) => return Err(QuasiStaticError::Cancelled),
            Err(_) => solve_with(&model, ribs, None, cancel)?,
        },
        None => solve_with(&model, ribs, None, cancel)?,
    };
    let films = films(input, &derived, &statics);
    let mut warnings = Vec::new();
    let sigma = input.surfaces.composite_rms_m;
    let min_lambda = films.iter().filter_map(|f| f.lambda).reduce(f64::min);
    if let Some(l) = min_lambda {
        if l < 1.0 {
            warnings.push(format!(
                "the thinnest film is {l:.2} times the composite roughness ({:.3} µm): boundary contact (Λ < 1)",
                sigma * 1e6
            ));
        }
    }
    if statics
        .rollers
        .iter()
        .all(|r| r.inner_load_n <= 0.0 && r.outer_load_n <= 0.0)
    {
        warnings.push("no roller carries load".to_string());
    }
    Ok(CylindricalAnalysis {
        name: name.to_string(),
        input: input.clone(),
        derived,
        model,
        statics,
        films,
        warnings,
        wall_time_s: t0.elapsed().as_secs_f64(),
        tribo: None,
    })
}

/// `a` with its tribodynamics (`super::tribodynamics`) when the deck asks for it
/// (`dynamics.revolutions > 0`); the dynamics' warnings (lost contacts, clamped films)
/// join the statics'.
pub fn with_tribodynamics(
    mut a: CylindricalAnalysis,
    cancel: Cancel<'_>,
) -> Result<CylindricalAnalysis, TribodynamicsError> {
    if a.input.dynamics.revolutions == 0 {
        return Ok(a);
    }
    let t0 = std::time::Instant::now();
    let t = tribodynamics(&a.input, &a.derived, cancel)?;
    let d = &t.dynamics;
    if d.loss_of_contact {
        a.warnings.push(format!(
            "rollers lose contact in the steady orbit (smallest roller load {:.1} N, {} losses after settling): the load zone does not cover the ring, roller-pass lines appear in the spectra",
            d.min_roller_load_n, d.stats.contact_losses_after_settle
        ));
    }
    if d.stats.film_clamps > 0 {
        a.warnings.push(format!(
            "the film of eq. 4 was clamped at 0 in {} evaluations (dynamics.squeeze = \"printed\" gives a negative film under fast approach)",
            d.stats.film_clamps
        ));
    }
    if a.input.operating.axial_load_n != 0.0 {
        // Seed eqs. 1–5 are planar: the dynamics carries the radial load only.
        a.warnings.push(format!(
            "the 2-DOF dynamics (seed eqs. 1–5) is radial only: the {:.1} N axial load, the rib loads and the roller tilts of the statics are not in the orbit, spectra or friction",
            a.input.operating.axial_load_n
        ));
    }
    a.wall_time_s += t0.elapsed().as_secs_f64();
    a.tribo = Some(t);
    Ok(a)
}

/// Each slice's Pan–Hamrock minimum film at the inner and outer contacts (flooded,
/// isothermal at the inlet viscosity; E′ = 2E* of the pair), the load per length being
/// the slice load over the slice width (the spacing of the slice centres, uniform
/// slicing; the whole length for one slice).
fn films(input: &CylindricalInput, d: &Derived, q: &QuasiStatic) -> Vec<RollerFilm> {
    let m = &input.materials;
    let el = |x: &crate::physics::material::Material| Elastic {
        youngs_modulus_pa: x.youngs_modulus_pa,
        poisson_ratio: x.poisson_ratio,
    };
    let e_inner = effective_modulus(el(&m.roller), el(&m.inner));
    let e_outer = effective_modulus(el(&m.roller), el(&m.outer));
    let lub = &input.lubricant;
    let film = |load_n: f64, width_m: f64, r: f64, e: f64| {
        if !(load_n > 0.0 && width_m > 0.0) {
            return None;
        }
        pan_hamrock_min(&FilmInputs {
            viscosity_pa_s: super::tribodynamics::inlet_viscosity_pa_s(input),
            pressure_viscosity_pa_inv: lub.pressure_viscosity_pa_inv,
            entrainment_speed_m_s: d.entrainment_speed_m_s,
            reduced_radius_m: r,
            load_per_length_n_m: load_n / width_m,
            effective_modulus_pa: e,
        })
    };
    q.rollers
        .iter()
        .map(|roller| {
            let s = &roller.slices;
            let width = match s.len() {
                0 => 0.0,
                1 => input.geometry.roller_length_m,
                _ => (s[1].axial_m - s[0].axial_m).abs(),
            };
            let slices: Vec<SliceFilm> = s
                .iter()
                .map(|sl| SliceFilm {
                    inner_m: film(sl.inner_load_n, width, d.inner_reduced_radius_m, e_inner),
                    outer_m: film(sl.outer_load_n, width, d.outer_reduced_radius_m, e_outer),
                })
                .collect();
            let min_film_m = slices
                .iter()
                .flat_map(|f| [f.inner_m, f.outer_m])
                .flatten()
                .reduce(f64::min);
            let sigma = input.surfaces.composite_rms_m;
            let max_pressure_pa = s
                .iter()
                .map(|sl| sl.inner_max_pressure_pa.max(sl.outer_max_pressure_pa))
                .fold(0.0, f64::max);
            RollerFilm {
                slices,
                min_film_m,
                lambda: min_film_m.map(|h| h / sigma),
                max_pressure_pa,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The model carries the deck's numbers: the seed's 1 990.5 N along −x, the
    /// centrifugal force of the deck's cage speed, the dub-off (exact copies, or 1e-9
    /// for the load: cos π round-off).
    #[test]
    fn model_from_the_truck_deck() {
        let t = CylindricalInput::truck();
        let m = model(&t);
        assert_eq!(m.roller_count, 12);
        assert!((m.load_n[0] + 1990.5).abs() < 1e-9 && m.load_n[1].abs() < 1e-9);
        assert_eq!(
            m.profile,
            Profile::DubOff {
                radius_m: 0.05,
                length_m: 0.003
            }
        );
        assert_eq!(m.radial_interference_m, 5e-6);
        assert_eq!(m.centrifugal_n, derive(&t).centrifugal_n);
        assert_eq!(m.slices, 21);
        assert_eq!(m.first_azimuth_rad, 0.0);
    }

    /// Once the lamina solve exists: loads balance the applied force (within the solve's
    /// tolerance, 1e-6 relative here), the films are of Pan–Hamrock magnitude
    /// (0.1–1 µm: the 0.25–0.46 µm steady film) and Λ = h/σ. Until then the
    /// solve's own error comes through unchanged (never a panic).
    #[test]
    fn truck_solves_or_reports() {
        let t = CylindricalInput::truck();
        match analyse(&t, "truck", &Cancel::NONE) {
            Ok(a) => {
                let sum: f64 = a
                    .statics
                    .rollers
                    .iter()
                    .map(|r| r.inner_load_n * r.azimuth_rad.cos())
                    .sum();
                // The rollers push the ring back: Σ W_i·cos θ_i equals F_x (−1 990.5 N).
                assert!((sum - a.model.load_n[0]).abs() < 1e-6 * 1990.5, "{sum}");
                let h = a.min_film_m().unwrap_or(0.0);
                assert!((1e-7..1e-6).contains(&h), "{h}");
                let f = &a.films[0];
                if let (Some(h), Some(l)) = (f.min_film_m, f.lambda) {
                    assert!((l - h / 0.6e-6).abs() < 1e-12 * l);
                }
            }
            Err(e) => assert!(!e.to_string().is_empty()),
        }
    }
}
