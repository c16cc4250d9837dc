//! Derived geometry of an angular-contact ball bearing (seed 001 ch. 3, Fig. 3-1; ch. 5),
//! SI: the distance between the groove curvature centres, the ball's mass and inertia,
//! and the Hertz contact of each raceway at a given contact angle (App. A).

use super::error::BallError;
use super::input::BallInput;
use crate::physics::contact::point::{
    ball_race_curvature, reduced_modulus, HertzMethod, HertzPointContact, Race,
};

/// What the analysis needs of the geometry and materials.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallGeometry {
    /// Z, number of balls.
    pub ball_count: usize,
    /// D, m.
    pub ball_diameter_m: f64,
    /// d_m, m.
    pub pitch_diameter_m: f64,
    /// f_i.
    pub inner_groove_curvature: f64,
    /// f_o.
    pub outer_groove_curvature: f64,
    /// α₀, rad.
    pub free_contact_angle_rad: f64,
    /// (f_i − ½)·D: ball centre to inner groove centre when just touching, m.
    pub inner_offset_m: f64,
    /// (f_o − ½)·D, m.
    pub outer_offset_m: f64,
    /// A = (f_i + f_o − 1)·D, distance between the groove centres unloaded (Chen's d_io), m.
    pub centre_distance_m: f64,
    /// Radius of the outer groove's curvature centre O', d_m/2 − (f_o − ½)·D·cos α₀, m.
    pub outer_centre_radius_m: f64,
    /// P_d = 2A(1 − cos α₀), the diametral clearance that gives α₀, m.
    pub diametral_clearance_m: f64,
    /// m = ρπD³/6, kg (Chen: 0.007 kg).
    pub ball_mass_kg: f64,
    /// J = mD²/10, kg·m² (Chen: 1.02·10⁻⁷ kg·m²).
    pub ball_inertia_kg_m2: f64,
    /// E* of ball against ring, Pa.
    pub reduced_modulus_pa: f64,
    /// κ, K, E method.
    pub hertz_method: HertzMethod,
}

impl BallGeometry {
    /// Derive the geometry; errors name the offending input.
    pub fn new(input: &BallInput) -> Result<Self, BallError> {
        let g = &input.geometry;
        let bad = |s: &str| Err(BallError::InvalidInput(s.to_string()));
        let d = g.ball_diameter_m;
        let dm = g.pitch_diameter_m;
        if g.ball_count < 1 {
            return bad("geometry: at least one ball");
        }
        if !(d.is_finite() && dm.is_finite() && d > 0.0 && dm > d) {
            return bad("geometry: need 0 < ball diameter < pitch diameter");
        }
        for f in [g.inner_groove_curvature, g.outer_groove_curvature] {
            if !(f.is_finite() && f > 0.5) {
                return bad("geometry: groove curvature f must exceed 0.5");
            }
        }
        if let Some(pd) = g.clearance_m {
            let two_a = 2.0 * (g.inner_groove_curvature + g.outer_groove_curvature - 1.0) * d;
            if !(pd.is_finite() && pd >= 0.0 && pd < two_a) {
                return Err(BallError::InvalidInput(format!(
                    "geometry: clearance {pd:e} m must be in [0, 2(f_i+f_o−1)D = {two_a:e} m) (α₀ < 90°)"
                )));
            }
        }
        // α₀ from the clearance when the deck gives one (cos α₀ = 1 − P_d/(2A)).
        let a0 = g.free_contact_angle();
        if !(a0.is_finite() && (0.0..std::f64::consts::FRAC_PI_2).contains(&a0)) {
            return bad("geometry: free contact angle must be in [0°, 90°)");
        }
        let (b, r) = (input.materials.ball, input.materials.rings);
        if !(b.density_kg_m3.is_finite() && b.density_kg_m3 > 0.0) {
            return bad("materials: ball density must be positive");
        }
        let e_star = reduced_modulus(
            b.youngs_modulus_pa,
            b.poisson_ratio,
            r.youngs_modulus_pa,
            r.poisson_ratio,
        )
        .map_err(|e| BallError::InvalidInput(format!("materials: {e}")))?;
        let inner_offset = (g.inner_groove_curvature - 0.5) * d;
        let outer_offset = (g.outer_groove_curvature - 0.5) * d;
        let a = inner_offset + outer_offset;
        let mass = b.density_kg_m3 * std::f64::consts::PI * d.powi(3) / 6.0;
        Ok(BallGeometry {
            ball_count: g.ball_count,
            ball_diameter_m: d,
            pitch_diameter_m: dm,
            inner_groove_curvature: g.inner_groove_curvature,
            outer_groove_curvature: g.outer_groove_curvature,
            free_contact_angle_rad: a0,
            inner_offset_m: inner_offset,
            outer_offset_m: outer_offset,
            centre_distance_m: a,
            outer_centre_radius_m: 0.5 * dm - outer_offset * a0.cos(),
            diametral_clearance_m: 2.0 * a * (1.0 - a0.cos()),
            ball_mass_kg: mass,
            ball_inertia_kg_m2: 0.1 * mass * d * d,
            reduced_modulus_pa: e_star,
            hertz_method: g.hertz_method,
        })
    }

    /// The Hertz contact of the ball with `race` at the contact angle α (rad): the
    /// raceway's rolling radius is taken in the plane of the contact normal (Harris;
    /// `point::ball_race_curvature`), the transverse radius is the groove's.
    pub fn contact(&self, race: Race, alpha_rad: f64) -> Result<HertzPointContact, BallError> {
        self.contact_from(race, alpha_rad, None)
    }

    /// [`Self::contact`] with the ellipse's κ iteration started from the κ of `near` (a
    /// contact of the same race at a nearby angle; `HertzPointContact::new_near`): the
    /// same contact to round-off, in one or two Newton steps instead of five or six.
    pub fn contact_near(
        &self,
        race: Race,
        alpha_rad: f64,
        near: &HertzPointContact,
    ) -> Result<HertzPointContact, BallError> {
        self.contact_from(race, alpha_rad, Some(near.shape().ellipticity))
    }

    fn contact_from(
        &self,
        race: Race,
        alpha_rad: f64,
        ellipticity_guess: Option<f64>,
    ) -> Result<HertzPointContact, BallError> {
        let (f, name) = match race {
            Race::Inner => (self.inner_groove_curvature, "inner"),
            Race::Outer => (self.outer_groove_curvature, "outer"),
        };
        let wrap = |source| BallError::Contact { race: name, source };
        let c = ball_race_curvature(
            race,
            self.ball_diameter_m,
            self.pitch_diameter_m,
            alpha_rad,
            f,
        )
        .map_err(wrap)?;
        match ellipticity_guess {
            Some(k) => {
                HertzPointContact::new_near(c, self.reduced_modulus_pa, self.hertz_method, k)
            }
            None => HertzPointContact::new(c, self.reduced_modulus_pa, self.hertz_method),
        }
        .map_err(wrap)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Chen's ch. 5 ball data: m = 0.007 kg, J = 1.02·10⁻⁷ kg·m² (printed to 1 and 3
    /// figures: tolerances 1 % and 0.5 %), and the Hertz numbers of Bearing A's inner
    /// race at 15° with the Brewe–Hamrock fits (κ 8.8051, E₁ 3.556, E₂ 1.0209, a* 3.6935,
    /// b* 0.4195, δ* 0.6129). Chen forms the rolling radius in the radial plane
    /// ((d_m − D cos α)/2 = 51.7 mm) where we use the contact-normal plane (53.5 mm): the
    /// shape numbers then differ by up to 0.4 % (tolerance 0.5 %; the print-exact check
    /// with Chen's radius is `point::tests::chen_bearing_a_inner_race_printed_numbers`).
    #[test]
    fn chen_ball_and_hertz_numbers() {
        let mut input = BallInput::chen_a();
        input.geometry.hertz_method = HertzMethod::BreweHamrock;
        let g = BallGeometry::new(&input).unwrap();
        assert!(
            (g.ball_mass_kg / 0.007 - 1.0).abs() < 0.01,
            "{}",
            g.ball_mass_kg
        );
        assert!((g.ball_inertia_kg_m2 / 1.02e-7 - 1.0).abs() < 0.005);
        assert!((g.centre_distance_m - 0.48e-3).abs() < 1e-15);
        let s = g.contact(Race::Inner, 15f64.to_radians()).unwrap().shape();
        for (got, printed) in [
            (s.ellipticity, 8.8051),
            (s.first_kind, 3.556),
            (s.second_kind, 1.0209),
            (s.a_star, 3.6935),
            (s.b_star, 0.4195),
            (s.delta_star, 0.6129),
        ] {
            assert!((got / printed - 1.0).abs() < 5e-3, "{got} vs {printed}");
        }
    }

    #[test]
    fn bad_geometry_is_refused() {
        let mut i = BallInput::chen_a();
        i.geometry.inner_groove_curvature = 0.5;
        assert!(BallGeometry::new(&i).is_err());
        let mut i = BallInput::chen_a();
        i.geometry.free_contact_angle_rad = 95f64.to_radians();
        assert!(BallGeometry::new(&i).is_err());
        let mut i = BallInput::chen_a();
        i.geometry.ball_count = 0;
        assert!(BallGeometry::new(&i).is_err());
    }
}

#[cfg(test)]
mod clearance_tests {
    use super::*;
    use crate::bearings::angular_ball::analysis::analyse;
    use crate::numerics::cancel::Cancel;

    /// A diametral clearance sets the free contact angle by cos α₀ = 1 − P_d/(2(f_i+f_o−1)D)
    /// (Harris): Chen's A (A = 0.04·12 mm = 0.48 mm) with P_d = 2A(1 − cos 15°) = 32.7 µm
    /// is Bearing A (α₀ 15° to 1e-12, the whole analysis' loads to 1e-9 relative); a
    /// larger clearance, 50 µm, gives α₀ = acos(1 − 50/960) = 18.6° and larger loaded
    /// contact angles at rest.
    #[test]
    fn clearance_sets_the_free_contact_angle() {
        let a = BallInput::chen_a();
        let two_a = 2.0 * 0.04 * 12e-3;
        let pd = two_a * (1.0 - 15f64.to_radians().cos());
        assert!((pd - 32.7e-6).abs() < 0.05e-6, "{pd}");
        let mut c = a.clone();
        c.geometry.clearance_m = Some(pd);
        c.geometry.free_contact_angle_rad = 40f64.to_radians(); // not used
        let g = BallGeometry::new(&c).unwrap();
        assert!((g.free_contact_angle_rad - 15f64.to_radians()).abs() < 1e-12);
        assert!((g.diametral_clearance_m / pd - 1.0).abs() < 1e-12);
        let (x, y) = (
            analyse(&a, Cancel::NONE).unwrap(),
            analyse(&c, Cancel::NONE).unwrap(),
        );
        for (p, q) in x.balls.iter().zip(&y.balls) {
            assert!((p.inner.load_n / q.inner.load_n - 1.0).abs() < 1e-9);
            assert!((p.outer.angle_rad - q.outer.angle_rad).abs() < 1e-9);
        }
        c.geometry.clearance_m = Some(50e-6);
        let g = BallGeometry::new(&c).unwrap();
        let expect = (1.0 - 50e-6 / two_a).acos();
        assert!((g.free_contact_angle_rad - expect).abs() < 1e-12);
        assert!((expect.to_degrees() - 18.6).abs() < 0.05);
        let mut rest = c.clone();
        rest.operating.inner_speed_rad_s = 0.0;
        let mut rest0 = a.clone();
        rest0.operating.inner_speed_rad_s = 0.0;
        let (r1, r0) = (
            analyse(&rest, Cancel::NONE).unwrap(),
            analyse(&rest0, Cancel::NONE).unwrap(),
        );
        assert!(r1.balls[0].inner.angle_rad > r0.balls[0].inner.angle_rad);
        // A clearance at or beyond 2A (α₀ ≥ 90°) is a typed error.
        c.geometry.clearance_m = Some(1.0001 * two_a);
        assert!(BallGeometry::new(&c).is_err());
    }
}
