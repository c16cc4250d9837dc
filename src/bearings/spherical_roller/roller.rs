//! Roller volume, mass and moments of inertia by integrating the crowned profile
//! (seed 000 App. A–B).

use super::input::Geometry;

/// Mass properties of one roller, SI.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RollerMass {
    /// Volume, m³ (eq. A.3).
    pub volume_m3: f64,
    /// Mass, kg.
    pub mass_kg: f64,
    /// Polar moment of inertia about the roller axis, kg·m² (eq. B.1).
    pub polar_inertia_kg_m2: f64,
    /// Transverse moment of inertia about a diameter through the centre, kg·m² (eq. B.2).
    pub transverse_inertia_kg_m2: f64,
}

/// Radius of the crowned profile at axial offset `x` from the mid-plane (eq. A.2):
/// y = √(R₀² − x²) + y₀ with y₀ = −(R₀ − D/2).
pub fn profile_radius(diameter_m: f64, crown_radius_m: f64, x_m: f64) -> f64 {
    let r0 = crown_radius_m;
    (r0 * r0 - x_m * x_m).max(0.0).sqrt() - (r0 - 0.5 * diameter_m)
}

/// 16-point Gauss–Legendre nodes and weights on [−1, 1]. The profile integrands are smooth
/// (analytic on the roller length since |x| ≤ L/2 < R₀), so two panels of 16 points
/// integrate them to round-off.
const GL16: [(f64, f64); 8] = [
    (0.095_012_509_837_637_44, 0.189_450_610_455_068_5),
    (0.281_603_550_779_258_9, 0.182_603_415_044_923_6),
    (0.458_016_777_657_227_4, 0.169_156_519_395_002_5),
    (0.617_876_244_402_643_8, 0.149_595_988_816_576_7),
    (0.755_404_408_355_003, 0.124_628_971_255_533_9),
    (0.865_631_202_387_831_7, 0.095_158_511_682_492_78),
    (0.944_575_023_073_232_6, 0.062_253_523_938_647_89),
    (0.989_400_934_991_649_9, 0.027_152_459_411_754_09),
];

/// Mass properties of the roller of `geometry` with density `density_kg_m3`.
///
/// App. B's eq. B.2 prints dI_Y = (½y² + x²) dm; a thin disk's moment about its own diameter
/// is ¼y² dm, so we integrate (¼y² + x²) dm (the cylinder limit m(3r² + L²)/12 then holds).
pub fn roller_mass(geometry: &Geometry, density_kg_m3: f64) -> RollerMass {
    let d = geometry.roller_diameter_m;
    let r0 = geometry.roller_crown_radius_m;
    let half = 0.5 * geometry.roller_length_m;
    let (mut v, mut ix, mut it) = (0.0, 0.0, 0.0);
    // Two panels [−L/2, 0] and [0, L/2].
    for (lo, hi) in [(-half, 0.0), (0.0, half)] {
        let mid = 0.5 * (lo + hi);
        let rad = 0.5 * (hi - lo);
        for &(node, weight) in &GL16 {
            for x in [mid - rad * node, mid + rad * node] {
                let y = profile_radius(d, r0, x);
                let y2 = y * y;
                let w = weight * rad;
                v += w * y2;
                ix += w * 0.5 * y2 * y2;
                it += w * (0.25 * y2 * y2 + x * x * y2);
            }
        }
    }
    let pi = std::f64::consts::PI;
    RollerMass {
        volume_m3: pi * v,
        mass_kg: density_kg_m3 * pi * v,
        polar_inertia_kg_m2: density_kg_m3 * pi * ix,
        transverse_inertia_kg_m2: density_kg_m3 * pi * it,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::spherical_roller::Bearing;

    fn geom(d: f64, l: f64, r0: f64) -> Geometry {
        let mut g = Bearing::example_aerospace().geometry;
        g.roller_diameter_m = d;
        g.roller_length_m = l;
        g.roller_crown_radius_m = r0;
        g
    }

    #[test]
    fn cylinder_limit() {
        // A crown radius of 1e6·D makes the sag over L/2 = L²/(8R₀) ≈ 1e-7·D: the roller is a
        // cylinder to 1e-6 relative in volume, so 1e-5 relative tolerance is ample.
        let (d, l) = (0.012, 0.015);
        let m = roller_mass(&geom(d, l, 1e6 * d), 1000.0);
        let r = d / 2.0;
        let v = std::f64::consts::PI * r * r * l;
        let mass = 1000.0 * v;
        assert!((m.volume_m3 / v - 1.0).abs() < 1e-5);
        assert!((m.polar_inertia_kg_m2 / (0.5 * mass * r * r) - 1.0).abs() < 1e-5);
        let it = mass * (3.0 * r * r + l * l) / 12.0;
        assert!((m.transverse_inertia_kg_m2 / it - 1.0).abs() < 1e-5);
    }

    #[test]
    fn sphere_segment() {
        // R₀ = D/2: the roller is a sphere of radius R truncated at ±h. Closed forms:
        // V = π(2R²h − 2h³/3); I_x = ρπ/2 ∫(R²−x²)² dx; I_t = ρπ ∫ [(R²−x²)²/4 + x²(R²−x²)] dx.
        // Quadrature of a polynomial of degree 4 with Gauss 16: exact to round-off (1e-12).
        let (d, l) = (0.02, 0.012);
        let (rr, h) = (d / 2.0, l / 2.0);
        let m = roller_mass(&geom(d, l, rr), 1.0);
        let pi = std::f64::consts::PI;
        let v = pi * (2.0 * rr * rr * h - 2.0 * h.powi(3) / 3.0);
        // ∫_{−h}^{h} (R²−x²)² dx = 2(R⁴h − 2R²h³/3 + h⁵/5)
        let i4 = 2.0 * (rr.powi(4) * h - 2.0 * rr * rr * h.powi(3) / 3.0 + h.powi(5) / 5.0);
        // ∫ x²(R²−x²) dx = 2(R²h³/3 − h⁵/5)
        let i22 = 2.0 * (rr * rr * h.powi(3) / 3.0 - h.powi(5) / 5.0);
        assert!((m.volume_m3 / v - 1.0).abs() < 1e-12);
        assert!((m.polar_inertia_kg_m2 / (pi * 0.5 * i4) - 1.0).abs() < 1e-12);
        assert!((m.transverse_inertia_kg_m2 / (pi * (0.25 * i4 + i22)) - 1.0).abs() < 1e-12);
    }
}
