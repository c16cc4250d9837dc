//! Fatigue life and static safety of the cylindrical roller bearing (issue 28 items 1–2),
//! from the solved lamina loads.
//!
//! **Reference life.** Per roller and raceway the slice loads combine by the product law
//! (seed 000 eq. 6.1, [`life::equivalent_roller_load_widths`]) and the raceways by
//! Lundberg–Palmgren line contact ([`rating::roller_reference_life`]), as the spherical
//! roller does. The raceway capacities use the length the slices span (the roller
//! length: every lamina counts in eq. 6.1's Γ, loaded or not, so the capacity must be of
//! that length; a load on part of it is then rated exactly as on the loaded part alone)
//! and the factor b_m·λ = 1.1·0.83 on Lundberg–Palmgren's 552: ISO 281's C_r carries both
//! (Table 7's f_c is λ = 0.83 times ISO/TR 1281-1's closed form 207.9 = 552·J_r/J_1, see
//! [`rating::ISO_LINE_CONTACT_REDUCTION`]), so the two methods rate an ideal bearing alike;
//! ISO/TS 16281's own text was not at hand (this is the reading, stated).
//!
//! **ISO 281.** C_r with L_we = the geometry's effective length (the straight, un-dubbed
//! part), D_pw = 2·pitch radius, α = 0; P = F_r = |applied load vector| (weight included);
//! an axial load on the ribs does not enter ISO 281's P of a radial roller bearing
//! (stated); κ from the lubricant's inlet viscosity over its density; e_C =
//! [`rating::DEFAULT_CONTAMINATION_FACTOR`]. **Static safety** s0 = (4 000 MPa/p_max)².

use super::analysis::CylindricalAnalysis;
use crate::physics::life::{self, CapacityGeometry};
use crate::physics::rating::{
    self, ContactKind, IsoLife, IsoLifeInputs, ReferenceLifeNumbers, RollerLifeInputs,
    RollerRatingGeometry,
};

/// Everything the life stage adds to a cylindrical analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct CylindricalLife {
    /// The load-distribution life.
    pub reference: ReferenceLifeNumbers,
    /// Λ of the inner and outer raceways (thinnest loaded slice film over σ).
    pub lambdas: (Option<f64>, Option<f64>),
    /// ISO 281 / ISO 76 numbers.
    pub iso: IsoLife,
}

/// Per roller, the eq. 6.1 equivalent loads [inner, outer], N, and the sliced length, m.
fn equivalent_loads(a: &CylindricalAnalysis) -> (Vec<f64>, Vec<f64>, f64) {
    let mut inner = Vec::with_capacity(a.statics.rollers.len());
    let mut outer = Vec::with_capacity(a.statics.rollers.len());
    let mut span = a.input.geometry.roller_length_m;
    for r in &a.statics.rollers {
        let s = &r.slices;
        // Uniform slicing (the solve's grid): the slice width is the spacing of the
        // centres, the span n·width (the whole length for one slice).
        let width = match s.len() {
            0 | 1 => a.input.geometry.roller_length_m,
            _ => (s[1].axial_m - s[0].axial_m).abs(),
        };
        span = width * s.len().max(1) as f64;
        let w = vec![width; s.len()];
        let qi: Vec<f64> = s.iter().map(|x| x.inner_load_n).collect();
        let qo: Vec<f64> = s.iter().map(|x| x.outer_load_n).collect();
        inner.push(life::equivalent_roller_load_widths(&qi, &w));
        outer.push(life::equivalent_roller_load_widths(&qo, &w));
    }
    (inner, outer, span)
}

/// The life stage of `a`.
pub fn life(a: &CylindricalAnalysis) -> CylindricalLife {
    let g = &a.input.geometry;
    let d = &a.derived;
    let dpw = 2.0 * d.pitch_radius_m;
    let (inner, outer, span) = equivalent_loads(a);
    let cap = CapacityGeometry {
        theta: g.roller_diameter_m / dpw,
        contact_angle_rad: 0.0,
        roller_diameter_m: g.roller_diameter_m,
        effective_length_m: span,
        roller_count: g.roller_count,
        pitch_diameter_m: dpw,
    };
    let wi = a.input.operating.inner_speed_rad_s;
    let reference = rating::roller_reference_life(&RollerLifeInputs {
        inner_equivalent_loads_n: &inner,
        outer_equivalent_loads_n: &outer,
        inner_geometry: cap,
        outer_geometry: cap,
        capacity_factor: rating::B_M_CYLINDRICAL_ROLLER * rating::ISO_LINE_CONTACT_REDUCTION,
        // The outer ring is fixed (seed 003): the inner ring turns under the load.
        inner_rotating: true,
        relative_speed_rad_s: wi,
    });
    let sigma = a.input.surfaces.composite_rms_m;
    let min_over = |f: fn(&super::analysis::SliceFilm) -> Option<f64>| {
        a.films
            .iter()
            .flat_map(|r| r.slices.iter().filter_map(f))
            .reduce(f64::min)
            .map(|h| h / sigma)
    };
    let lambdas = (min_over(|s| s.inner_m), min_over(|s| s.outer_m));
    let rg = RollerRatingGeometry {
        rows: 1,
        roller_count: g.roller_count,
        roller_diameter_m: g.roller_diameter_m,
        effective_length_m: d.effective_length_m,
        pitch_diameter_m: dpw,
        contact_angle_rad: 0.0,
    };
    let fr = a.model.load_n[0].hypot(a.model.load_n[1]);
    let fa = a.input.operating.axial_load_n;
    let lub = &a.input.lubricant;
    let nu = super::tribodynamics::inlet_viscosity_pa_s(&a.input) / lub.density_kg_m3;
    let mut iso = rating::iso_life(&IsoLifeInputs {
        kind: ContactKind::Roller,
        rating_direction: crate::physics::rating::RatingDirection::Radial,
        rating: rating::iso_radial_rating_roller(rating::B_M_CYLINDRICAL_ROLLER, &rg).ok_or_else(
            || {
                format!(
                    "ISO 281 C_r: D·cos α/D_pw = {:.4} is outside Table 7 (0.01–0.30)",
                    rg.gamma()
                )
            },
        ),
        equivalent_load: rating::equivalent_load_radial_roller(fr, fa, 0.0, 1)
            .ok_or_else(|| "ISO 281 P: no radial roller form".to_string()),
        static_rating: Ok(rating::iso_static_radial_rating_roller(&rg)),
        pitch_diameter_m: dpw,
        relative_speed_rpm: wi.abs() * 30.0 / std::f64::consts::PI,
        kinematic_viscosity_m2_s: (nu.is_finite() && nu > 0.0).then_some(nu).ok_or_else(|| {
            format!(
                "the lubricant's kinematic viscosity {nu:e} m²/s is not positive: no κ, no a_ISO"
            )
        }),
        contamination_factor: rating::DEFAULT_CONTAMINATION_FACTOR,
        max_contact_stress_pa: a.max_pressure_pa(),
    });
    if fa != 0.0 {
        iso.reasons.push(format!(
            "ISO 281's P of a radial roller bearing (α = 0) is F_r: the {fa:.1} N axial load on the ribs is not in it"
        ));
    }
    CylindricalLife {
        reference,
        lambdas,
        iso,
    }
}

impl CylindricalLife {
    /// The JSON `life` object ([`rating::life_json`]) with the capacity factor used.
    pub fn json(&self) -> serde_json::Value {
        let mut v = rating::life_json(&Ok(self.reference), &Ok(self.lambdas), &self.iso);
        if let Some(m) = v.as_object_mut() {
            m.insert(
                "capacity_factor".into(),
                serde_json::json!(
                    rating::B_M_CYLINDRICAL_ROLLER * rating::ISO_LINE_CONTACT_REDUCTION
                ),
            );
        }
        v
    }

    /// The text report's LIFE section, forces in `units`.
    pub fn text(&self, units: crate::units::Units) -> String {
        rating::life_text(&Ok(self.reference), &self.iso, units)
    }
}

#[cfg(test)]
#[path = "life_tests.rs"]
mod tests;
