//! Lamina geometry of an angular-contact spherical roller bearing in the plane of one roller
//! (seed 000 §3.3–3.4, eq. 3.4–3.5, made exact as `sashbean-notes.md` suggests).
//!
//! Frame: x along the bearing axis, r radially outward through the nominal roller centre,
//! origin at the nominal roller centre (pitch radius). β is measured from the radial plane,
//! so the nominal contact normal (roller centre → outer raceway) is n = (sin β, cos β) and the
//! roller axis is a = (cos β, −sin β).
//!
//! Each raceway crown is a circle (centre, radius) in this plane; each lamina is a body
//! point on the roller's crown circle (App. A) at offset d_l along the roller axis. A
//! lamina's approach is the distance from the raceway's centre of curvature to the point
//! minus the raceway radius (positive = interference), and its normal is the direction of
//! that distance. Ring and roller displacements move centres and points rigidly, so the
//! initial clearances of eq. 3.4 come out of the geometry by themselves.

use super::input::Geometry;

/// 2-vector in the (x, r) roller plane, m.
pub type V2 = [f64; 2];

/// One lamina of the roller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lamina {
    /// d_l, offset from the roller mid-plane along the roller axis, m (d_l = w·(l − l_m)).
    pub offset_m: f64,
    /// w, lamina width, m.
    pub width_m: f64,
    /// Width relative to the mean width L_eff/Γ (1 for uniform slicing): scales the lamina's
    /// stiffness, since the law Q = k·δ^(10/9) is per unit width (eq. 3.3).
    pub weight: f64,
    /// Surface point facing the inner raceway, relative to the roller centre (nominal), m.
    pub inner_point: V2,
    /// Surface point facing the outer raceway, relative to the roller centre (nominal), m.
    pub outer_point: V2,
    /// Nominal vectors from the raceway crown centres (without clearance) to the points, m.
    pub inner_v0: V2,
    pub outer_v0: V2,
    /// |v₀|² − R_race², m², evaluated without cancellation (see [`LaminaGeometry::approach`]).
    pub inner_k0: f64,
    pub outer_k0: f64,
}

/// sin α and cos α − 1 of a roller pitch α (the latter as −2 sin²(α/2), accurate for small α).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pitch {
    pub sin: f64,
    pub cos_minus_one: f64,
}

impl Pitch {
    /// Trigonometry of pitch `alpha` (rad).
    #[inline]
    pub fn new(alpha: f64) -> Self {
        Pitch {
            sin: alpha.sin(),
            cos_minus_one: -2.0 * (0.5 * alpha).sin().powi(2),
        }
    }
}

/// One lamina's contact state: approach δ (m, > 0 = interference), unit normal from the
/// raceway's crown centre to the point, the distance ρ (m) and the rotated point p (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Approach {
    pub delta: f64,
    pub normal: V2,
    pub rho: f64,
    /// 1/ρ, 1/m: one division shared by the normal and the solver's curvature term.
    pub inv_rho: f64,
    pub point: V2,
}

/// Precomputed geometry shared by every roller.
#[derive(Debug, Clone, PartialEq)]
pub struct LaminaGeometry {
    pub laminae: Vec<Lamina>,
    /// Nominal contact normal n (roller centre → outer raceway).
    pub normal: V2,
    /// Roller axis a.
    pub axis: V2,
    /// Inner raceway crown centre relative to the nominal roller centre (inner ring at rest), m.
    pub inner_centre: V2,
    /// Inner raceway crown radius, m.
    pub inner_radius_m: f64,
    /// Outer raceway crown centre relative to the nominal roller centre, m; includes half the
    /// diametral clearance as a radial shift of the outer raceway.
    pub outer_centre: V2,
    /// Outer raceway crown radius, m.
    pub outer_radius_m: f64,
    /// Radial shift of the outer raceway by half the diametral clearance, m.
    pub outer_shift: V2,
    /// Pitch radius P_t/2, m.
    pub pitch_radius_m: f64,
}

impl LaminaGeometry {
    /// Build the lamina geometry for `laminae` slices of the effective length.
    pub fn new(g: &Geometry, laminae: usize) -> Self {
        Self::with_slicing(g, laminae, super::input::Slicing::Uniform)
    }

    /// Build the lamina geometry with the chosen spacing.
    pub fn with_slicing(g: &Geometry, laminae: usize, slicing: super::input::Slicing) -> Self {
        let beta = g.contact_angle_rad;
        let n = [beta.sin(), beta.cos()];
        let a = [beta.cos(), -beta.sin()];
        let half_d = 0.5 * g.roller_diameter_m;
        let r0 = g.roller_crown_radius_m;
        let count = laminae.max(1);
        let w = g.effective_length_m / count as f64;
        let half_l = 0.5 * g.effective_length_m;
        // Lamina boundaries along the roller axis.
        let bounds: Vec<f64> = (0..=count)
            .map(|k| match slicing {
                super::input::Slicing::Uniform => -half_l + w * k as f64,
                super::input::Slicing::Cosine => {
                    -half_l * (std::f64::consts::PI * k as f64 / count as f64).cos()
                }
            })
            .collect();
        // Roller crown centres (App. A: y₀ = −(R₀ − D/2) below the centre for the outer side).
        let sag = r0 - half_d;
        let laminae = (0..count)
            .map(|l| {
                // Uniform: d_l = w·(l − l_m) with l_m the middle (possibly half-integer) lamina;
                // in general the lamina's mid-point.
                let (lo, hi) = (bounds[l], bounds[l + 1]);
                let d = match slicing {
                    super::input::Slicing::Uniform => w * (l as f64 - 0.5 * (count as f64 - 1.0)),
                    super::input::Slicing::Cosine => 0.5 * (lo + hi),
                };
                let width = match slicing {
                    super::input::Slicing::Uniform => w,
                    super::input::Slicing::Cosine => hi - lo,
                };
                let h = (r0 * r0 - d * d).max(0.0).sqrt();
                // Outer side: crown centre at −sag·n, point at centre + h·n + d·a.
                let outer = [(h - sag) * n[0] + d * a[0], (h - sag) * n[1] + d * a[1]];
                let inner = [-(h - sag) * n[0] + d * a[0], -(h - sag) * n[1] + d * a[1]];
                // Crown sag s₀ = R₀ − √(R₀² − d²) = d²/(R₀ + h), free of cancellation. With the
                // raceway centre on the normal through the roller centre, |v₀|² − R² =
                // −2·s₀·(R_race − R₀) exactly (from d² = 2R₀s₀ − s₀²).
                let s0 = d * d / (r0 + h);
                let ri = g.inner_crown_radius_m;
                let ro = g.outer_crown_radius_m;
                let vi = [
                    (ri - r0 + h) * -n[0] + d * a[0],
                    (ri - r0 + h) * -n[1] + d * a[1],
                ];
                let vo = [
                    (ro - r0 + h) * n[0] + d * a[0],
                    (ro - r0 + h) * n[1] + d * a[1],
                ];
                Lamina {
                    offset_m: d,
                    width_m: width,
                    weight: width / w,
                    inner_point: inner,
                    outer_point: outer,
                    inner_v0: vi,
                    outer_v0: vo,
                    inner_k0: -2.0 * s0 * (ri - r0),
                    outer_k0: -2.0 * s0 * (ro - r0),
                }
            })
            .collect();
        let ri = g.inner_crown_radius_m;
        let ro = g.outer_crown_radius_m;
        // Inner raceway contact point −(D/2)n; its concave crown centre lies R_i further along +n.
        let ci = (ri - half_d, ri - half_d);
        let co = half_d - ro;
        LaminaGeometry {
            laminae,
            normal: n,
            axis: a,
            inner_centre: [ci.0 * n[0], ci.1 * n[1]],
            inner_radius_m: ri,
            outer_centre: [co * n[0], co * n[1] + 0.5 * g.diametral_clearance_m],
            outer_radius_m: ro,
            outer_shift: [0.0, 0.5 * g.diametral_clearance_m],
            pitch_radius_m: 0.5 * g.pitch_diameter_m,
        }
    }

    /// Approach of lamina `lam` at the inner (`inner = true`) or outer raceway for roller
    /// displacement `q` = (axial, radial, pitch) and inner-raceway centre shift `shift`
    /// (the ring deflection projected at the roller's azimuth; ignored for the outer).
    ///
    /// Computed as δ = (K₀ + 2v₀·e + e·e)/(|v₀ + e| + R) with e the relative displacement of
    /// point and centre, so that crowns of any radius (up to the flat "no crown" limit, where
    /// |v₀| ≈ R is metres while δ is nanometres) lose no digits to cancellation.
    #[inline]
    pub fn approach(&self, lam: &Lamina, inner: bool, q: [f64; 3], shift: V2) -> Approach {
        self.approach_with(lam, inner, q, shift, Pitch::new(q[2]))
    }

    /// [`Self::approach`] with the pitch's trigonometry computed once per roller.
    #[inline]
    pub fn approach_with(
        &self,
        lam: &Lamina,
        inner: bool,
        q: [f64; 3],
        shift: V2,
        pitch: Pitch,
    ) -> Approach {
        let (p0, v0, k0, r, dc) = if inner {
            (
                lam.inner_point,
                lam.inner_v0,
                lam.inner_k0,
                self.inner_radius_m,
                shift,
            )
        } else {
            (
                lam.outer_point,
                lam.outer_v0,
                lam.outer_k0,
                self.outer_radius_m,
                self.outer_shift,
            )
        };
        let (sa, cm1) = (pitch.sin, pitch.cos_minus_one);
        let dp = [cm1 * p0[0] - sa * p0[1], sa * p0[0] + cm1 * p0[1]];
        let e = [q[0] + dp[0] - dc[0], q[1] + dp[1] - dc[1]];
        let v = [v0[0] + e[0], v0[1] + e[1]];
        let rho = (v[0] * v[0] + v[1] * v[1]).sqrt();
        let inv_rho = 1.0 / rho;
        let delta =
            (k0 + 2.0 * (v0[0] * e[0] + v0[1] * e[1]) + e[0] * e[0] + e[1] * e[1]) / (rho + r);
        Approach {
            delta,
            normal: [v[0] * inv_rho, v[1] * inv_rho],
            rho,
            inv_rho,
            point: [p0[0] + dp[0], p0[1] + dp[1]],
        }
    }

    /// Initial clearance of lamina `l` at the inner and outer raceway with rings and roller
    /// at rest (m; positive = gap). The geometric counterpart of eq. 3.4.
    pub fn initial_clearance(&self, l: usize) -> (f64, f64) {
        let lam = &self.laminae[l];
        let di = self.approach(lam, true, [0.0; 3], [0.0; 2]).delta;
        let dout = self.approach(lam, false, [0.0; 3], [0.0; 2]).delta;
        (-di, -dout)
    }
}

/// Eq. 3.4: C = R_o − √(R_o² − d²) − [R_i − √(R_i² − d²)] with R_o the roller crown and R_i the raceway crown
/// (difference of the two crowns' sags at offset d), m.
pub fn sag_clearance(race_radius_m: f64, roller_radius_m: f64, offset_m: f64) -> f64 {
    let s = |r: f64| r - (r * r - offset_m * offset_m).max(0.0).sqrt();
    s(roller_radius_m) - s(race_radius_m)
}

#[cfg(test)]
pub(crate) fn dist(p: V2, c: V2) -> f64 {
    ((p[0] - c[0]).powi(2) + (p[1] - c[1]).powi(2)).sqrt()
}

#[cfg(test)]
pub(crate) mod tests_support {
    pub fn rotate(alpha: f64, p: super::V2) -> super::V2 {
        let (s, c) = alpha.sin_cos();
        [c * p[0] - s * p[1], s * p[0] + c * p[1]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::spherical_roller::Bearing;

    #[test]
    fn clearances_follow_eq_3_4() {
        // The exact geometry and eq. 3.4's sag difference agree to second order in the crown
        // mismatch: for the aerospace bearing (crowns 1.90/1.95/1.937 in) the difference is
        // below 1 % of the clearance plus 1 nm over the whole effective length.
        let mut b = Bearing::example_aerospace();
        b.geometry.diametral_clearance_m = 0.0;
        let g = LaminaGeometry::new(&b.geometry, 21);
        for (l, lam) in g.laminae.iter().enumerate() {
            let (ci, co) = g.initial_clearance(l);
            let d = lam.offset_m;
            let ei = sag_clearance(
                b.geometry.inner_crown_radius_m,
                b.geometry.roller_crown_radius_m,
                d,
            );
            let eo = sag_clearance(
                b.geometry.outer_crown_radius_m,
                b.geometry.roller_crown_radius_m,
                d,
            );
            assert!(
                (ci - ei).abs() < 0.01 * ei.abs() + 1e-9,
                "inner l={l}: {ci} vs {ei}"
            );
            assert!(
                (co - eo).abs() < 0.01 * eo.abs() + 1e-9,
                "outer l={l}: {co} vs {eo}"
            );
        }
        // The cancellation-free approach equals the plain distance formula (1e-12 m: the plain
        // formula's round-off on |v₀| ≈ 50 mm).
        for lam in &g.laminae {
            let a = g.approach(lam, false, [1e-6, 2e-6, 1e-4], [0.0; 2]);
            let p = super::super::geometry::tests_support::rotate(1e-4, lam.outer_point);
            let plain = dist([1e-6 + p[0], 2e-6 + p[1]], g.outer_centre) - g.outer_radius_m;
            assert!((a.delta - plain).abs() < 1e-12, "{} vs {plain}", a.delta);
        }
        // Middle lamina of an odd count touches both raceways exactly (round-off).
        let (ci, co) = g.initial_clearance(10);
        assert!(ci.abs() < 1e-15 && co.abs() < 1e-15);
    }

    #[test]
    fn clearance_shifts_outer_raceway() {
        // Diametral clearance c opens c/2 radially at the outer raceway: along the normal at
        // β the gap is (c/2)·cos β to first order (c ≪ R): 1e-3 relative tolerance.
        let b = Bearing::example_aerospace();
        let g = LaminaGeometry::new(&b.geometry, 21);
        let (_, co) = g.initial_clearance(10);
        let c = b.geometry.diametral_clearance_m;
        let expect = 0.5 * c * b.geometry.contact_angle_rad.cos();
        assert!((co / expect - 1.0).abs() < 1e-3, "{co} vs {expect}");
    }
}
