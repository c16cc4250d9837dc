//! Fatigue life and static safety of the tapered roller bearing (issue 28 items 1–2), from
//! the solved slice loads.
//!
//! **Reference life.** Each slice carries p_x (N/m) over its width (the spacing of the
//! slice centres); per roller and raceway the slice loads combine by the product law
//! (seed 000 eq. 6.1, [`life::equivalent_roller_load_widths`]) and the raceways by
//! Lundberg–Palmgren line contact ([`rating::roller_reference_life`]), as the spherical
//! roller does: the cone (inner) at its contact angle β − 2t, the cup (outer) at β, both
//! with the mean roller diameter, the sliced length (every lamina counts in eq. 6.1's Γ)
//! and the factor b_m·λ = 1.1·0.83 (see `cylindrical_roller::life` for why).
//!
//! **ISO 281.** C_r with α = the cup angle, L_we = the deck's effective length, the mean
//! roller diameter; P by Table 9's single-row form (e = 1.5·tan α; X = 0.4, Y = 0.4·cot α
//! above e). **κ and a_ISO** from the deck's lubricant at the inlet temperature (ν = η/ρ);
//! a deck without `[lubricant]` has neither, with that reason, not made up. **Static safety**
//! s0 = (4 000 MPa/p_max)² over every slice of both raceways.

use super::analysis::Analysis;
use super::contact::SliceResult;
use crate::physics::life::{self, CapacityGeometry};
use crate::physics::rating::{
    self, ContactKind, IsoLife, IsoLifeInputs, ReferenceLifeNumbers, RollerLifeInputs,
    RollerRatingGeometry,
};

/// Why the tapered system has no κ, a_ISO or Λ.
pub const NO_LUBRICANT: &str =
    "the deck gives no lubricant (lubricant.viscosity = \"none\"): no film, no Λ, no κ, no a_ISO";

/// Everything the life stage adds to a tapered analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct TaperedLife {
    /// Λ of the thinnest loaded cone and cup slice, or why there is none.
    pub lambdas: Result<(Option<f64>, Option<f64>), String>,
    /// The load-distribution life.
    pub reference: ReferenceLifeNumbers,
    /// ISO 281 / ISO 76 numbers.
    pub iso: IsoLife,
    /// The largest slice pressure over both raceways, Pa.
    pub max_contact_stress_pa: f64,
}

/// Eq. 6.1 over a raceway's slices (loads p_x·width), N, and the sliced length, m.
fn equivalent(slices: &[SliceResult], fallback_length_m: f64) -> (f64, f64) {
    let width = match slices.len() {
        0 | 1 => fallback_length_m,
        _ => (slices[1].x_m - slices[0].x_m).abs(),
    };
    let q: Vec<f64> = slices.iter().map(|s| s.load_n_m * width).collect();
    let w = vec![width; slices.len()];
    (
        life::equivalent_roller_load_widths(&q, &w),
        width * slices.len().max(1) as f64,
    )
}

/// The largest Hertz pressure over every slice of both raceways, Pa.
pub fn max_contact_stress_pa(a: &Analysis) -> f64 {
    a.slices
        .iter()
        .flat_map(|r| r.iter().flat_map(|s| s.iter().map(|x| x.stress_pa)))
        .fold(0.0, f64::max)
}

/// The life stage of `a`.
pub fn life(a: &Analysis) -> TaperedLife {
    let g = &a.bearing.input.geometry;
    let half_cone = a.bearing.geometry.half_cone_rad;
    let (mut inner, mut outer) = (Vec::new(), Vec::new());
    let mut span = g.effective_length_m;
    for [cup, cone] in &a.slices {
        let (o, s) = equivalent(cup, g.effective_length_m);
        let (i, _) = equivalent(cone, g.effective_length_m);
        outer.push(o);
        inner.push(i);
        span = s;
    }
    let cap = |angle: f64| CapacityGeometry {
        theta: g.roller_diameter_m * angle.cos() / g.pitch_diameter_m,
        contact_angle_rad: angle,
        roller_diameter_m: g.roller_diameter_m,
        effective_length_m: span,
        roller_count: g.roller_count,
        pitch_diameter_m: g.pitch_diameter_m,
    };
    let op = &a.bearing.input.operating;
    let (wi, wo) = (op.inner_speed_rad_s, op.outer_speed_rad_s);
    let reference = rating::roller_reference_life(&RollerLifeInputs {
        inner_equivalent_loads_n: &inner,
        outer_equivalent_loads_n: &outer,
        inner_geometry: cap(g.cup_angle_rad - 2.0 * half_cone),
        outer_geometry: cap(g.cup_angle_rad),
        capacity_factor: rating::B_M_TAPERED_ROLLER * rating::ISO_LINE_CONTACT_REDUCTION,
        inner_rotating: wi.abs() >= wo.abs(),
        relative_speed_rad_s: (wi - wo).abs(),
    });
    let rg = RollerRatingGeometry {
        rows: 1,
        roller_count: g.roller_count,
        roller_diameter_m: g.roller_diameter_m,
        effective_length_m: g.effective_length_m,
        pitch_diameter_m: g.pitch_diameter_m,
        contact_angle_rad: g.cup_angle_rad,
    };
    let max_p = max_contact_stress_pa(a);
    // κ from the inlet viscosity (ν = η/ρ) when the deck gives a lubricant (issue 28).
    let (kinematic, lambdas) = match &a.tribology {
        None => (Err(NO_LUBRICANT.to_string()), Err(NO_LUBRICANT.to_string())),
        Some(Err(e)) => (Err(e.to_string()), Err(e.to_string())),
        Some(Ok(t)) => (
            Ok(t.viscosity_pa_s / a.bearing.input.lubricant.density_kg_m3),
            Ok((
                t.min_race[0].map(|m| m.lambda),
                t.min_race[1].map(|m| m.lambda),
            )),
        ),
    };
    let iso = rating::iso_life(&IsoLifeInputs {
        kind: ContactKind::Roller,
        rating_direction: crate::physics::rating::RatingDirection::Radial,
        rating: rating::iso_radial_rating_roller(rating::B_M_TAPERED_ROLLER, &rg).ok_or_else(
            || {
                format!(
                    "ISO 281 C_r: D·cos α/D_pw = {:.4} is outside Table 7 (0.01–0.30)",
                    rg.gamma()
                )
            },
        ),
        equivalent_load: rating::equivalent_load_radial_roller(
            op.radial_load_n,
            op.axial_load_n,
            g.cup_angle_rad,
            1,
        )
        .ok_or_else(|| "ISO 281 P: no single-row form".to_string()),
        static_rating: Ok(rating::iso_static_radial_rating_roller(&rg)),
        pitch_diameter_m: g.pitch_diameter_m,
        relative_speed_rpm: (wi - wo).abs() * 30.0 / std::f64::consts::PI,
        kinematic_viscosity_m2_s: kinematic.clone(),
        contamination_factor: rating::DEFAULT_CONTAMINATION_FACTOR,
        max_contact_stress_pa: max_p,
    });
    TaperedLife {
        lambdas,
        reference,
        iso,
        max_contact_stress_pa: max_p,
    }
}

impl TaperedLife {
    /// The JSON `life` object ([`rating::life_json`]): Λ absent with its reason.
    pub fn json(&self) -> serde_json::Value {
        let mut v = rating::life_json(&Ok(self.reference), &self.lambdas, &self.iso);
        if let Some(m) = v.as_object_mut() {
            m.insert(
                "capacity_factor".into(),
                serde_json::json!(rating::B_M_TAPERED_ROLLER * rating::ISO_LINE_CONTACT_REDUCTION),
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
