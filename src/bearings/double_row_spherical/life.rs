//! ISO 281 ratings, the raceway lives of both rows, a_ISO and static safety of the
//! double-row spherical roller bearing (issue 28 items 1–2). The load-distribution life
//! itself is the single-row spherical roller's per row (`stages::life`, seed 000 §6, with
//! this system's ξ = 1) combined over the rows by Lundberg–Palmgren's product law
//! (`statics::combine_l10`, e = 9/8): `life.l10_bearing_mrev` is unchanged. Added here:
//! the raceway lives over both rows (the same product law per raceway), the capacities
//! (both rows have the same geometry: row 1's), the smallest Λ of either row, and the ISO
//! numbers: C_r (ISO 281 eq. 9 with b_m = 1.15, [`super::load_sweep::dynamic_rating_n`]),
//! P by Table 9's double-row form (e = 1.5·tan α; X = 1, Y = 0.45·cot α below e;
//! X = 0.67, Y = 0.67·cot α above), C_0r by ISO 76, κ from the lubricant's viscosity at the
//! operating temperature the single-row stages use (`heat::kinematic_viscosity_m2_s`),
//! e_C = [`rating::DEFAULT_CONTAMINATION_FACTOR`], s0 = (4 000 MPa/σ_max)².

use super::statics::{combine_l10, DoubleRowAnalysis};
use crate::physics::heat;
use crate::physics::rating::{
    self, ContactKind, IsoLife, IsoLifeInputs, ReferenceLifeNumbers, RollerRatingGeometry,
};

/// What the life stage adds to a double-row analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct DoubleRowLife {
    /// Raceway lives over both rows, capacities, the bearing life (= `l10_mrev`).
    pub reference: ReferenceLifeNumbers,
    /// Smallest Λ of either row at the inner and outer raceways.
    pub lambdas: (Option<f64>, Option<f64>),
    /// ISO 281 / ISO 76 numbers.
    pub iso: IsoLife,
}

/// The life stage of `a`.
pub fn life(a: &DoubleRowAnalysis) -> DoubleRowLife {
    let lives: Vec<_> = a.rows.iter().filter_map(|r| r.life.as_ref()).collect();
    let inner: Vec<Option<f64>> = lives.iter().map(|l| l.result.l10_inner_mrev).collect();
    let outer: Vec<Option<f64>> = lives.iter().map(|l| l.result.l10_outer_mrev).collect();
    let lambda = |f: fn(&crate::bearings::spherical_roller::stages::Films) -> f64| {
        a.rows
            .iter()
            .filter_map(|r| r.films.as_ref().map(f))
            .filter(|x| x.is_finite())
            .reduce(f64::min)
    };
    let reference = ReferenceLifeNumbers {
        capacity_inner_n: lives.first().map(|l| l.result.capacity_inner_n),
        capacity_outer_n: lives.first().map(|l| l.result.capacity_outer_n),
        l10_inner_mrev: combine_l10(&inner),
        l10_outer_mrev: combine_l10(&outer),
        l10_bearing_mrev: a.l10_mrev,
        l10_bearing_h: a.l10_h,
    };
    let g = &a.input.geometry;
    let rg = RollerRatingGeometry {
        rows: g.rows,
        roller_count: g.roller_count,
        roller_diameter_m: g.roller_diameter_m,
        effective_length_m: g.effective_length_m,
        pitch_diameter_m: g.pitch_diameter_m,
        contact_angle_rad: g.contact_angle_rad,
    };
    let op = &a.input.operating;
    let nu = heat::kinematic_viscosity_m2_s(&a.row_bearing.lubricant);
    let iso = rating::iso_life(&IsoLifeInputs {
        kind: ContactKind::Roller,
        rating_direction: crate::physics::rating::RatingDirection::Radial,
        rating: super::load_sweep::dynamic_rating_n(&a.input).ok_or_else(|| {
            format!(
                "ISO 281 C_r: D·cos α/D_pw = {:.4} is outside Table 7 (0.01–0.30)",
                rg.gamma()
            )
        }),
        equivalent_load: rating::equivalent_load_radial_roller(
            op.radial_load_n,
            op.axial_load_n,
            g.contact_angle_rad,
            g.rows.clamp(1, 2),
        )
        .ok_or_else(|| "ISO 281 P: more than two rows".to_string()),
        static_rating: Ok(rating::iso_static_radial_rating_roller(&rg)),
        pitch_diameter_m: g.pitch_diameter_m,
        relative_speed_rpm: op.inner_speed_rad_s.abs() * 30.0 / std::f64::consts::PI,
        kinematic_viscosity_m2_s: (nu > 0.0).then_some(nu).ok_or_else(|| {
            "the lubricant's kinematic viscosity is not positive: no κ, no a_ISO".to_string()
        }),
        contamination_factor: rating::DEFAULT_CONTAMINATION_FACTOR,
        max_contact_stress_pa: a.max_stress_pa(),
    });
    DoubleRowLife {
        reference,
        lambdas: (lambda(|f| f.lambda_inner), lambda(|f| f.lambda_outer)),
        iso,
    }
}

impl DoubleRowLife {
    /// The fields this stage adds to the existing JSON `life` object (which keeps its
    /// `l10_bearing_mrev`, `l10_bearing_h` and `rows`): inserted only where absent.
    pub fn extend_json(&self, life: &mut serde_json::Value) {
        let add = rating::life_json(&Ok(self.reference), &Ok(self.lambdas), &self.iso);
        if let (Some(m), serde_json::Value::Object(add)) = (life.as_object_mut(), add) {
            for (k, v) in add {
                m.entry(k).or_insert(v);
            }
            m.entry("capacity_factor")
                .or_insert(serde_json::json!(CAPACITY_FACTOR));
        }
    }

    /// The text report's LIFE section, forces in `units`.
    pub fn text(&self, units: crate::units::Units) -> String {
        rating::life_text(&Ok(self.reference), &self.iso, units)
    }
}

/// ξ of the rows' Lundberg–Palmgren capacities (`DoubleRowInput::row_bearing`'s 1.0).
const CAPACITY_FACTOR: f64 = 1.0;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::double_row_spherical::input::DoubleRowInput;
    use crate::bearings::double_row_spherical::statics::analyse;

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    /// The illustrative 22308: the bearing life is the existing combined one (unchanged),
    /// the raceway lives combine the rows' by (Σ L^(−9/8))^(−8/9) (1e-12), ISO's C_r is the
    /// load sweep's, P follows Table 9's double-row form by hand (1e-12), L10 = (C/P)^(10/3),
    /// a_ISO and κ present (the deck has a lubricant), s0 = (4 GPa/σ_max)².
    #[test]
    fn example_22308_life() {
        let inp = DoubleRowInput::example_22308();
        let a = analyse(&inp, "22308", None).unwrap();
        let l = life(&a);
        assert_eq!(l.reference.l10_bearing_mrev, a.l10_mrev);
        let li: Vec<f64> = a
            .rows
            .iter()
            .map(|r| r.life.as_ref().unwrap().result.l10_inner_mrev.unwrap())
            .collect();
        let want = li
            .iter()
            .map(|x| x.powf(-9.0 / 8.0))
            .sum::<f64>()
            .powf(-8.0 / 9.0);
        assert!(rel(l.reference.l10_inner_mrev.unwrap(), want) < 1e-12);
        let c = super::super::load_sweep::dynamic_rating_n(&inp).unwrap();
        assert_eq!(l.iso.basic_dynamic_rating_n, Some(c));
        let (fr, fa) = (inp.operating.radial_load_n, inp.operating.axial_load_n);
        let a0 = inp.geometry.contact_angle_rad;
        let cot = 1.0 / a0.tan();
        let p = if fa / fr <= 1.5 * a0.tan() {
            fr + 0.45 * cot * fa
        } else {
            0.67 * fr + 0.67 * cot * fa
        };
        assert!(rel(l.iso.equivalent_load_n.unwrap(), p) < 1e-12);
        assert!(rel(l.iso.basic_l10_mrev.unwrap(), (c / p).powf(10.0 / 3.0)) < 1e-12);
        assert!(
            l.iso.kappa.is_some() && l.iso.a_iso.is_some(),
            "{:?}",
            l.iso.reasons
        );
        assert!(
            rel(
                l.iso.static_safety.unwrap(),
                (4e9 / a.max_stress_pa()).powi(2)
            ) < 1e-12
        );
        // The existing JSON fields keep their values; the new ones are added beside them.
        let mut j = serde_json::json!({"l10_bearing_mrev": 1.0, "rows": []});
        l.extend_json(&mut j);
        assert_eq!(j["l10_bearing_mrev"], serde_json::json!(1.0));
        assert!(j.get("basic_l10_mrev").is_some() && j.get("static_safety").is_some());
    }
}
