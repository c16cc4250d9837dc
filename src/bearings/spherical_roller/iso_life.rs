//! ISO 281 / ISO 76 numbers of the single-row spherical roller bearing (issue 28 item 1:
//! every system reports `basic_dynamic_rating_n`, `basic_l10_mrev`, `modified_l10_mrev`,
//! `a_iso`, `kappa` beside its load-distribution life). Seed 000's own lives (the
//! reference L-10 of §6 and its ASME or ISO lubrication-adjusted life) are untouched:
//! these numbers are added beside them.
//!
//! The same rules as the double row (`double_row_spherical::life`) with one row:
//! C_r by ISO 281 eq. 9 with b_m = 1.15 (spherical roller bearings, Table 2) and f_c from
//! Table 7; P by Table 9's single-row form with e = 1.5·tan α (X = 1, Y = 0 for
//! F_a/F_r ≤ e; X = 0.4, Y = 0.4·cot α above); C_0r by ISO 76; κ = ν/ν₁ with ν the lubricant's
//! kinematic viscosity at the temperature the stages use (`heat::kinematic_viscosity_m2_s`,
//! the deck's viscosity, or the thermal loop's when it iterates); e_C the deck's
//! `life.iso_contamination_factor` (the key seed 000's ISO adjustment already reads);
//! s0 = (4 000 MPa/σ_max)² from the largest lamina stress.

use super::pipeline::Analysis;
use crate::physics::heat;
use crate::physics::rating::{
    self, ContactKind, IsoLife, IsoLifeInputs, RollerRatingGeometry, B_M_SPHERICAL_ROLLER,
};

/// The rating geometry of the deck's bearing (one row).
fn rating_geometry(a: &Analysis) -> RollerRatingGeometry {
    let g = &a.input.geometry;
    RollerRatingGeometry {
        rows: 1,
        roller_count: g.roller_count,
        roller_diameter_m: g.roller_diameter_m,
        effective_length_m: g.effective_length_m,
        pitch_diameter_m: g.pitch_diameter_m,
        contact_angle_rad: g.contact_angle_rad,
    }
}

/// ISO 281 / ISO 76 numbers of `a` (absent ones carry their reason in `reasons`).
pub fn iso_life(a: &Analysis) -> IsoLife {
    let g = &a.input.geometry;
    let op = &a.input.operating;
    let rg = rating_geometry(a);
    let nu = heat::kinematic_viscosity_m2_s(&a.input.lubricant);
    let stress = super::answer::max_stress(a).map_or(0.0, |(_, _, s)| s);
    rating::iso_life(&IsoLifeInputs {
        kind: ContactKind::Roller,
        rating_direction: crate::physics::rating::RatingDirection::Radial,
        rating: rating::iso_radial_rating_roller(B_M_SPHERICAL_ROLLER, &rg).ok_or_else(|| {
            format!(
                "ISO 281 C_r: D·cos α/D_pw = {:.4} is outside Table 7 (0.01–0.30)",
                rg.gamma()
            )
        }),
        equivalent_load: rating::equivalent_load_radial_roller(
            op.radial_load_n,
            op.axial_load_n,
            g.contact_angle_rad,
            1,
        )
        .ok_or_else(|| "ISO 281 P: no equivalent load for this load and angle".to_string()),
        static_rating: Ok(rating::iso_static_radial_rating_roller(&rg)),
        pitch_diameter_m: g.pitch_diameter_m,
        relative_speed_rpm: (op.inner_speed_rad_s - op.outer_speed_rad_s).abs() * 30.0
            / std::f64::consts::PI,
        kinematic_viscosity_m2_s: (nu > 0.0).then_some(nu).ok_or_else(|| {
            "the lubricant's kinematic viscosity is not positive: no κ, no a_ISO".to_string()
        }),
        contamination_factor: a.input.life.iso_contamination_factor,
        max_contact_stress_pa: stress,
    })
}

/// The ISO fields added to the spherical roller's JSON `life` object, inserted only where
/// the object lacks them (its seed-000 fields, `static_safety` included, stay as they are).
pub fn extend_json(a: &Analysis, life: &mut serde_json::Value) {
    let iso = iso_life(a);
    if let (Some(m), Ok(serde_json::Value::Object(add))) =
        (life.as_object_mut(), serde_json::to_value(&iso))
    {
        for (k, v) in add {
            m.entry(k).or_insert(v);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::spherical_roller::pipeline::{run, Request};
    use crate::bearings::spherical_roller::Bearing;

    /// Against an independent evaluation of ISO 281 eq. 9 and Table 9 from the deck's
    /// geometry (the formulas written out here, not the rating module's), 1e-12: C_r =
    /// b_m·f_c·(L_we·cos α)^(7/9)·Z^(3/4)·D_we^(29/27) in N and mm; P = X·F_r + Y·F_a
    /// (Table 9, single row);
    /// L10 = (C/P)^(10/3). f_c is taken from the rating module (Table 7 interpolation,
    /// tested against the table there).
    #[test]
    fn basic_life_is_iso_281_of_the_deck_geometry() {
        let b = Bearing::example_aerospace();
        let a = run(&b, &Request::default(), None).expect("the aerospace example solves");
        let iso = iso_life(&a);
        let g = &b.geometry;
        let mm = 1e3;
        let gamma = g.roller_diameter_m * g.contact_angle_rad.cos() / g.pitch_diameter_m;
        let fc = rating::iso_fc_radial_roller(gamma).expect("in Table 7");
        let c = 1.15
            * fc
            * (g.effective_length_m * mm * g.contact_angle_rad.cos()).powf(7.0 / 9.0)
            * (g.roller_count as f64).powf(0.75)
            * (g.roller_diameter_m * mm).powf(29.0 / 27.0);
        let cr = iso.basic_dynamic_rating_n.expect("C_r");
        assert!((cr - c).abs() < 1e-12 * c, "C_r {cr} vs {c}");
        let (fr, fa) = (b.operating.radial_load_n, b.operating.axial_load_n);
        let e = 1.5 * g.contact_angle_rad.tan();
        let cot = 1.0 / g.contact_angle_rad.tan();
        // Table 9, single row, α ≠ 0.
        let p = if fa / fr <= e {
            fr
        } else {
            0.4 * fr + 0.4 * cot * fa
        };
        let pl = iso.equivalent_load_n.expect("P");
        assert!((pl - p).abs() < 1e-12 * p, "P {pl} vs {p}");
        let l10 = (c / p).powf(10.0 / 3.0);
        let got = iso.basic_l10_mrev.expect("L10");
        assert!((got - l10).abs() < 1e-9 * l10, "L10 {got} vs {l10}");
        // The deck gives a viscosity: κ and a_ISO exist, and L10m = a_ISO·L10.
        let (a_iso, lm) = (
            iso.a_iso.expect("a_ISO"),
            iso.modified_l10_mrev.expect("L10m"),
        );
        assert!((lm - a_iso * got).abs() < 1e-12 * lm);
        assert_eq!(iso.contamination_factor, b.life.iso_contamination_factor);
    }

    /// The JSON gains the ISO fields without touching seed 000's: every field the life
    /// object had keeps its value (static_safety included), the ISO names are added.
    #[test]
    fn json_gains_iso_fields_and_keeps_seed_fields() {
        let b = Bearing::example_aerospace();
        let a = run(&b, &Request::default(), None).expect("solves");
        let before = serde_json::to_value(a.life.as_ref().expect("life").result).expect("json");
        let mut after = before.clone();
        after["static_safety"] = serde_json::json!(1.2345);
        extend_json(&a, &mut after);
        for (k, v) in before.as_object().expect("object") {
            assert_eq!(&after[k], v, "{k} moved");
        }
        assert_eq!(after["static_safety"], serde_json::json!(1.2345));
        for k in [
            "basic_dynamic_rating_n",
            "basic_l10_mrev",
            "modified_l10_mrev",
            "a_iso",
            "kappa",
        ] {
            assert!(after[k].as_f64().is_some(), "{k}: {}", after[k]);
        }
    }
}
