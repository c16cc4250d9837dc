//! Derived geometry and kinematics of a cylindrical roller bearing (seed 003): pitch
//! radius, effective length, the reduced radii of eq. (8), roller mass, cage speed,
//! centrifugal force and the entrainment speed.

use super::input::{CylindricalInput, ProfileKind};

/// What the model derives from the deck before any solve, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Derived {
    /// Roller radius r, m.
    pub roller_radius_m: f64,
    /// Inner raceway radius r_i, m.
    pub inner_raceway_radius_m: f64,
    /// Outer raceway radius r_o, m.
    pub outer_raceway_radius_m: f64,
    /// Pitch radius r_m = (r_i + r_o)/2, m.
    pub pitch_radius_m: f64,
    /// Effective (load-carrying) length, m: l − 2·l_d for the dub-off profile, l for the
    /// logarithmic one (the deck has no end chamfer).
    pub effective_length_m: f64,
    /// R_zx of the inner contact, m (eq. 8: r·r_i/(r + r_i), both convex).
    pub inner_reduced_radius_m: f64,
    /// R_zx of the outer contact, m (eq. 8: r·r_o/(r_o − r), the race concave).
    pub outer_reduced_radius_m: f64,
    /// Roller mass m_r = ρπr²l, kg (the dub-off's few µm of drop neglected).
    pub roller_mass_kg: f64,
    /// The kinematic cage speed ω_i·r_i/(r_i + r_o), rad/s.
    pub kinematic_cage_speed_rad_s: f64,
    /// The cage speed in effect (the deck's, else the kinematic), rad/s.
    pub cage_speed_rad_s: f64,
    /// Centrifugal force on one roller m_r·ω_c²·r_m, N.
    pub centrifugal_n: f64,
    /// Entrainment speed U = (ω_i − ω_c)·r_i, m/s (pure rolling: the inner race's and
    /// the roller's surface speeds relative to the cage are equal, so their mean is this).
    pub entrainment_speed_m_s: f64,
    /// Cage (fundamental train) frequency ω_c/2π, Hz.
    pub cage_frequency_hz: f64,
    /// Roller-pass frequency m·ω_c/2π, Hz.
    pub roller_pass_frequency_hz: f64,
}

/// The kinematic cage speed of a stationary outer ring, rad/s: the cage (roller centre at
/// the pitch radius (r_i + r_o)/2) moves at half the inner race's surface speed, so
/// ω_c = ω_i·r_i/(2·r_m) = ω_i·r_i/(r_i + r_o) (epicyclic pure rolling).
pub fn kinematic_cage_speed(inner_speed_rad_s: f64, r_i: f64, r_o: f64) -> f64 {
    inner_speed_rad_s * r_i / (r_i + r_o)
}

/// The derived geometry of `input`.
pub fn derive(input: &CylindricalInput) -> Derived {
    let g = &input.geometry;
    let r = 0.5 * g.roller_diameter_m;
    let r_i = 0.5 * g.inner_raceway_diameter_m;
    let r_o = 0.5 * g.outer_raceway_diameter_m;
    let r_m = 0.5 * (r_i + r_o);
    let w_i = input.operating.inner_speed_rad_s;
    let kinematic = kinematic_cage_speed(w_i, r_i, r_o);
    let cage = input.operating.cage_speed_rad_s.unwrap_or(kinematic);
    let mass =
        input.materials.roller.density_kg_m3 * std::f64::consts::PI * r * r * g.roller_length_m;
    let effective = match g.profile {
        ProfileKind::DubOff => g.roller_length_m - 2.0 * g.dub_off_length_m,
        ProfileKind::Logarithmic => g.roller_length_m,
    };
    let tau = 2.0 * std::f64::consts::PI;
    Derived {
        roller_radius_m: r,
        inner_raceway_radius_m: r_i,
        outer_raceway_radius_m: r_o,
        pitch_radius_m: r_m,
        effective_length_m: effective,
        inner_reduced_radius_m: r * r_i / (r + r_i),
        outer_reduced_radius_m: r * r_o / (r_o - r),
        roller_mass_kg: mass,
        kinematic_cage_speed_rad_s: kinematic,
        cage_speed_rad_s: cage,
        centrifugal_n: mass * cage * cage * r_m,
        entrainment_speed_m_s: (w_i - cage) * r_i,
        cage_frequency_hz: cage.abs() / tau,
        roller_pass_frequency_hz: g.roller_count as f64 * cage.abs() / tau,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs()
    }

    /// Hand numbers for the truck deck (seed 003 Tables A1/A2), to 1e-4 (the hand values
    /// are rounded to 5 digits): r_m = (25 + 37.7)/2 = 31.35 mm; l_e = 22 − 6 = 16 mm;
    /// R_i = 6.35·25/31.35 = 5.0638 mm; R_o = 6.35·37.7/31.35 = 7.6362 mm;
    /// m_r = 7850·π·6.35²e-6·0.022 = 0.021877 kg; kinematic ω_c = 209·25/62.7 =
    /// 83.333 rad/s (the deck's 83.26 overrides it); F_c = 0.021877·83.26²·0.03135 =
    /// 4.7544 N; U = (209 − 83.26)·0.025 = 3.1435 m/s; f_c = 13.251 Hz (the issue's
    /// 13.25 Hz), roller pass 12·f_c = 159.01 Hz.
    #[test]
    fn truck_hand_numbers() {
        let d = derive(&CylindricalInput::truck());
        for (got, want) in [
            (d.pitch_radius_m, 0.03135),
            (d.effective_length_m, 0.016),
            (d.inner_reduced_radius_m, 5.0638e-3),
            (d.outer_reduced_radius_m, 7.6362e-3),
            (d.roller_mass_kg, 0.021877),
            (d.kinematic_cage_speed_rad_s, 83.333),
            (d.cage_speed_rad_s, 83.26),
            (d.centrifugal_n, 4.7544),
            (d.entrainment_speed_m_s, 3.1435),
            (d.cage_frequency_hz, 13.251),
            (d.roller_pass_frequency_hz, 159.01),
        ] {
            assert!(close(got, want, 1e-4), "{got} vs {want}");
        }
        let mut k = CylindricalInput::truck();
        k.operating.cage_speed_rad_s = None;
        assert_eq!(derive(&k).cage_speed_rad_s, d.kinematic_cage_speed_rad_s);
    }
}
