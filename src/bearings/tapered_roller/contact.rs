//! One roller–race contact by slices (seed 004 eqs. 45–73, 84–87): the intrusion of the
//! crowned roller into the race (58–61), the contact extent (48–54), Lundberg's slice law
//! inverted for each slice's load per length (62–71), and the resultant load and moment
//! with their derivatives in the race approach Δᵢ and misalignment θᵢ (72–73, 84–87).
//!
//! Slices: `n` equal slices over the contact extent [X_B, X_A] itself, the domain of the
//! integrals (72)–(73), so they move with it: P = h·Σpₖ and M = h·Σ Xₖ·pₖ with
//! Xₖ = X_B + (k + ½)h, h = (X_A − X_B)/n (midpoint rule). A grid fixed on the effective
//! length instead lets the contact's ends cross slices one at a time, which made the
//! stiffness at 21 slices differ by 1 % from 161 slices and wobble by as much along a
//! speed sweep; on the moving grid the integrand vanishes smoothly at free ends and the
//! rule converges as h². X is positive toward the big end on both races, θᵢ positive
//! squeezes the big end harder (seed's convention).
//!
//! The derivatives are those of this discrete model, exact: besides ∂p/∂Δₓ of eq. 71 they
//! include the contact length's change in Lundberg's logarithm (∂p/∂L·∂L/∂(Δ, θ)), which
//! eqs. 84–87 leave out (without it the analytic stiffness differs from re-solved finite
//! differences by about a per cent), and the motion of the slices with the extent (the
//! intrusion's slope and the slice law's change along X).
//!
//! Eq. 48's radicand R_c² − (H cos θ − Δ)² is computed as (R_c − a)(R_c + a): R_c is 2.5 m
//! while Δ is micrometres. The crowned intrusion (59) is computed as
//! Δ + (l_F²/4 − X² + 2XH sin θ)/(√(R_c² − u²) + H cos θ), u = X − H sin θ, the same number
//! without subtracting two lengths of 2.5 m.

use thiserror::Error;

use super::geometry::RollerGeometry;
use super::input::{Geometry, Materials};
use crate::physics::contact::lundberg::{compliance, LundbergError, LundbergSlice, SliceLoad};

/// Which race.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Race {
    /// The cup (outer race), subscript 1, C = +1.
    Cup,
    /// The cone (inner race), subscript 2, C = −1.
    Cone,
}

impl Race {
    /// The race's name in messages.
    pub fn name(self) -> &'static str {
        match self {
            Race::Cup => "cup",
            Race::Cone => "cone",
        }
    }
}

/// A slice's Lundberg law failed.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("{} contact, slice {slice} (X = {x_m:.4e} m): {source}", race.name())]
pub struct ContactError {
    /// The race.
    pub race: Race,
    /// Slice index (0 at the small end).
    pub slice: usize,
    /// Slice position, m.
    pub x_m: f64,
    /// Why.
    pub source: LundbergError,
}

/// The roller profile seen from one race.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Profile {
    half_le: f64,
    half_flat: f64,
    rc: f64,
    h: f64,
    v: f64,
}

/// One race contact: the roller profile and the slice law along the roller.
#[derive(Debug, Clone, PartialEq)]
pub struct RaceContact {
    /// Which race.
    pub race: Race,
    profile: Profile,
    /// Slices over the contact extent.
    pub slices: usize,
    /// c = (η_R + η_r)/(2π), 1/Pa.
    compliance: f64,
    /// C of eq. 64 (+1 cup, −1 cone).
    c_sign: f64,
    d: f64,
    e: f64,
    sin_beta: f64,
    cos_beta: f64,
    cos_race: f64,
    cos_d_psi: f64,
    tan_t: f64,
    cos_t: f64,
}

/// The contact's extent [X_B, X_A] and the derivatives of its ends.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Extent {
    xb: f64,
    xa: f64,
    /// ∂X_B/∂(Δ, θ).
    dxb: [f64; 2],
    /// ∂X_A/∂(Δ, θ).
    dxa: [f64; 2],
    edge: bool,
}

/// Resultants of one contact, SI.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactEval {
    /// Pᵢ, N (eq. 72).
    pub load_n: f64,
    /// Mᵢ, N·m (eq. 73).
    pub moment_nm: f64,
    /// ∂Pᵢ/∂Δᵢ (N/m), ∂Pᵢ/∂θᵢ (N/rad) (eqs. 84–85).
    pub dload: [f64; 2],
    /// ∂Mᵢ/∂Δᵢ (N), ∂Mᵢ/∂θᵢ (N·m/rad) (eqs. 86–87).
    pub dmoment: [f64; 2],
    /// Contact extent [X_B, X_A], m (zero when not in contact).
    pub extent_m: [f64; 2],
    /// The contact reaches an end of the effective length.
    pub edge_loaded: bool,
    /// Largest Hertz pressure over the slices, 2p/(πb), Pa.
    pub max_stress_pa: f64,
}

/// One slice's state at the solution, SI.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SliceResult {
    /// X, m.
    pub x_m: f64,
    /// Δₓ, intrusion, m.
    pub intrusion_m: f64,
    /// pₓ, N/m.
    pub load_n_m: f64,
    /// bₓ, m.
    pub half_width_m: f64,
    /// Hertz pressure 2p/(πb), Pa.
    pub stress_pa: f64,
}

impl RaceContact {
    /// The `n`-slice contact of `race`.
    pub fn new(
        race: Race,
        g: &Geometry,
        rg: &RollerGeometry,
        mats: &Materials,
        n: usize,
    ) -> Result<RaceContact, ContactError> {
        let t = rg.half_cone_rad;
        let beta = g.cup_angle_rad;
        let (c_sign, race_mat, race_angle) = match race {
            Race::Cup => (1.0, mats.cup, beta),
            Race::Cone => (-1.0, mats.cone, beta - 2.0 * t),
        };
        let rc = RaceContact {
            race,
            profile: Profile {
                half_le: 0.5 * g.effective_length_m,
                half_flat: 0.5 * g.flat_length_m,
                rc: rg.crown_radius_m,
                h: rg.crown_offset_m,
                v: rg.crown_drop_m,
            },
            slices: n.max(1),
            compliance: compliance(&mats.roller, &race_mat),
            c_sign,
            d: g.roller_diameter_m,
            e: g.pitch_diameter_m,
            sin_beta: beta.sin(),
            cos_beta: beta.cos(),
            cos_race: race_angle.cos(),
            cos_d_psi: g.roller_diameter_m * (beta - t).cos(),
            tan_t: t.tan(),
            cos_t: t.cos(),
        };
        // Every law along the effective length must exist (positive diameter and
        // conformity): checked at both ends, the law being monotone in X.
        for (k, x) in [(0, -rc.profile.half_le), (n, rc.profile.half_le)] {
            rc.law(x).map_err(|source| ContactError {
                race,
                slice: k,
                x_m: x,
                source,
            })?;
        }
        Ok(rc)
    }

    /// The slice law at X (eqs. 64–68) and d(width factor)/dX.
    #[inline]
    fn law(&self, x: f64) -> Result<(LundbergSlice, f64), LundbergError> {
        let dx = (self.d + 2.0 * x * self.tan_t * self.cos_t) / self.cos_t; // eq. 67
        let ddx = 2.0 * self.tan_t;
        let ex = self.e + 2.0 * x * self.sin_beta + self.cos_d_psi - dx * self.cos_beta; // eq. 68
        let dex = 2.0 * self.sin_beta - ddx * self.cos_beta;
        let gamma = dx * self.cos_race / ex; // eqs. 65–66
        let dgamma = self.cos_race * (ddx * ex - dx * dex) / (ex * ex);
        let conformity = 1.0 + self.c_sign * gamma;
        let law = LundbergSlice::new(self.compliance, dx, conformity)?;
        let dwf = self.compliance * (ddx * conformity + dx * self.c_sign * dgamma);
        Ok((law, dwf))
    }

    /// Intrusion Δₓ at X, ∂Δₓ/∂θ (eqs. 58–61; ∂Δₓ/∂Δ = 1) and ∂Δₓ/∂X.
    #[inline]
    fn intrusion(&self, x: f64, delta: f64, theta: f64) -> (f64, f64, f64) {
        let p = &self.profile;
        let (s, c) = theta.sin_cos();
        if x.abs() <= p.half_flat * c {
            let tan = s / c;
            return (delta + x * tan, x / (c * c), tan);
        }
        let u = x - p.h * s;
        let root = ((p.rc - u) * (p.rc + u)).sqrt();
        let num = p.half_flat * p.half_flat - x * x + 2.0 * x * p.h * s;
        (
            delta + num / (root + p.h * c),
            u * p.h * c / root + p.h * s,
            -u / root,
        )
    }

    /// Contact extent (eqs. 48–54) and ∂L/∂(Δ, θ); `None` when the roller does not touch.
    fn extent(&self, delta: f64, theta: f64) -> Option<Extent> {
        let p = &self.profile;
        let (s, c) = theta.sin_cos();
        let a = p.h * c - delta;
        // R_c − a = Δ + (R_c − H) + H(1 − cos θ), with R_c − H = (l_F/2)²/(R_c + H):
        // no difference of two crown-sized lengths.
        let half_theta = 0.5 * theta;
        let rc_minus_a = delta
            + p.half_flat * p.half_flat / (p.rc + p.h)
            + 2.0 * p.h * half_theta.sin() * half_theta.sin();
        let rad = rc_minus_a * (p.rc + a);
        if !(rad > 0.0) {
            return None;
        }
        let sq = rad.sqrt();
        let mut xa = sq + p.h * s;
        let mut xb = -sq + p.h * s;
        let mut dxa = [a / sq, a * p.h * s / sq + p.h * c];
        let mut dxb = [-a / sq, -a * p.h * s / sq + p.h * c];
        let xa_max = p.half_le * c + p.v * s; // eq. 52
        let xb_min = -p.half_le * c + p.v * s; // eq. 53
        let dlim_a = -p.half_le * s + p.v * c;
        let dlim_b = p.half_le * s + p.v * c;
        if xa <= xb_min || xb >= xa_max {
            return None;
        }
        // Eq. 54 and its mirror: an end of the crown's chord falls on the flat, where the
        // flat's own root −Δ/tan θ bounds the contact.
        let f = p.half_flat * c;
        if f > 0.0 && theta != 0.0 {
            let root = -delta * c / s;
            let droot = [-c / s, delta / (s * s)];
            if xb > -f && xb < f && xa > f && root > xb && root < xa {
                xb = root;
                dxb = droot;
            }
            if xa > -f && xa < f && xb < -f && root > xb && root < xa {
                xa = root;
                dxa = droot;
            }
        }
        let mut edge = false;
        if xa > xa_max {
            xa = xa_max;
            dxa = [0.0, dlim_a];
            edge = true;
        }
        if xb < xb_min {
            xb = xb_min;
            dxb = [0.0, dlim_b];
            edge = true;
        }
        if !(xa > xb) {
            return None;
        }
        Some(Extent {
            xb,
            xa,
            dxb,
            dxa,
            edge,
        })
    }

    /// The order of magnitude of the force (N) that an approach `approach_m` along
    /// `length_m` of line contact carries: length·approach/c, c the contact's compliance
    /// (the line contact's stiffness per length is of order 1/c, to a logarithm).
    pub fn line_force_scale(&self, length_m: f64, approach_m: f64) -> f64 {
        length_m * approach_m / self.compliance
    }

    /// Whether the roller touches the race at all at approach `delta` and misalignment
    /// `theta` (a contact extent exists: the slices inside it then have positive
    /// intrusion); no slice is evaluated.
    pub fn touches(&self, delta: f64, theta: f64) -> bool {
        self.extent(delta, theta).is_some()
    }

    /// Resultants and derivatives at race approach `delta` (m) and misalignment `theta`
    /// (rad); `slices`, if given, receives every slice's state.
    pub fn eval(
        &self,
        delta: f64,
        theta: f64,
        mut slices: Option<&mut Vec<SliceResult>>,
    ) -> Result<ContactEval, ContactError> {
        if let Some(out) = slices.as_deref_mut() {
            out.clear();
        }
        let Some(ext) = self.extent(delta, theta) else {
            return Ok(ContactEval::default());
        };
        let n = self.slices;
        let length = ext.xa - ext.xb;
        let h = length / n as f64;
        let dl = [ext.dxa[0] - ext.dxb[0], ext.dxa[1] - ext.dxb[1]];
        let mut r = ContactEval {
            extent_m: [ext.xb, ext.xa],
            edge_loaded: ext.edge,
            ..ContactEval::default()
        };
        let (mut sp, mut sm) = (0.0, 0.0);
        let (mut dp, mut dm) = ([0.0; 2], [0.0; 2]);
        for k in 0..n {
            let u = (k as f64 + 0.5) / n as f64;
            let x = ext.xb + u * length;
            let dxk = [ext.dxb[0] + u * dl[0], ext.dxb[1] + u * dl[1]];
            let (i, di_dtheta, di_dx) = self.intrusion(x, delta, theta);
            let fail = |source| ContactError {
                race: self.race,
                slice: k,
                x_m: x,
                source,
            };
            let (law, dwf) = self.law(x).map_err(fail)?;
            let mut stress = 0.0;
            let mut sl = SliceLoad::default();
            if i > 0.0 {
                sl = law.load(i, length).map_err(fail)?;
                let (p, pd, pl) = (sl.load_n_m, sl.dload_dapproach, sl.dload_dlength);
                // ∂p/∂(b² factor) at fixed δ, L: δ has −c·p/(2·wf) per unit wf.
                let pw = pd * law.compliance * p / (2.0 * law.width_factor);
                let along = pd * di_dx + pw * dwf;
                let d0 = pd + pl * dl[0] + along * dxk[0];
                let d1 = pd * di_dtheta + pl * dl[1] + along * dxk[1];
                sp += p;
                sm += x * p;
                dp[0] += d0;
                dp[1] += d1;
                dm[0] += x * d0 + dxk[0] * p;
                dm[1] += x * d1 + dxk[1] * p;
                stress = 2.0 * p / (std::f64::consts::PI * sl.half_width_m);
                r.max_stress_pa = r.max_stress_pa.max(stress);
            }
            if let Some(out) = slices.as_deref_mut() {
                out.push(SliceResult {
                    x_m: x,
                    intrusion_m: i,
                    load_n_m: sl.load_n_m,
                    half_width_m: sl.half_width_m,
                    stress_pa: stress,
                });
            }
        }
        let dh = [dl[0] / n as f64, dl[1] / n as f64];
        r.load_n = h * sp;
        r.moment_nm = h * sm;
        r.dload = [h * dp[0] + dh[0] * sp, h * dp[1] + dh[1] * sp];
        r.dmoment = [h * dm[0] + dh[0] * sm, h * dm[1] + dh[1] * sm];
        Ok(r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::tapered_roller::input::{Crown, TaperedInput};
    use crate::physics::contact::lundberg::LundbergSlice;

    fn sample(n: usize) -> (TaperedInput, RollerGeometry, RaceContact, RaceContact) {
        let s = TaperedInput::afapl_sample();
        let rg = RollerGeometry::new(&s.geometry, &s.materials.roller).unwrap();
        let cup = RaceContact::new(Race::Cup, &s.geometry, &rg, &s.materials, n).unwrap();
        let cone = RaceContact::new(Race::Cone, &s.geometry, &rg, &s.materials, n).unwrap();
        (s, rg, cup, cone)
    }

    /// A straight roller (no crown: R_c = 1e12 m, a drop of 3e-17 m over the length),
    /// aligned and pushed in uniformly, has every slice at the same approach; the contact
    /// is the whole effective length and each slice's load per length inverts Lundberg's
    /// eq. 62 for that length. Summed, P/l_e put back into (62) gives the approach to 1e-10.
    #[test]
    fn uniform_straight_roller_reproduces_lundberg() {
        let mut s = TaperedInput::afapl_sample();
        s.geometry.crown = Crown::Radius(1e12);
        let rg = RollerGeometry::new(&s.geometry, &s.materials.roller).unwrap();
        let cup = RaceContact::new(Race::Cup, &s.geometry, &rg, &s.materials, 21).unwrap();
        let delta = 2e-6;
        let mut slices = Vec::new();
        let c = cup.eval(delta, 0.0, Some(&mut slices)).unwrap();
        assert!(c.edge_loaded);
        let le = s.geometry.effective_length_m;
        assert!(((c.extent_m[1] - c.extent_m[0]) / le - 1.0).abs() < 1e-12);
        assert_eq!(slices.len(), 21);
        for sl in &slices {
            let (law, _) = cup.law(sl.x_m).unwrap();
            let (d, _, _) = law.approach(sl.load_n_m, le);
            assert!((d / delta - 1.0).abs() < 1e-10, "{d}");
        }
        // The middle slice's law (the roller's mid diameter) with the mean load per length.
        let (mid, _) = cup.law(0.0).unwrap();
        assert!(slices[10].x_m.abs() < 1e-15);
        let (d, _, _) = mid.approach(c.load_n / le, le);
        assert!((d / delta - 1.0).abs() < 2e-3, "{d}");
        // And with a law of the mid diameter exactly, the slice is Lundberg to 1e-10.
        let law =
            LundbergSlice::new(mid.compliance, mid.width_factor / mid.compliance, 1.0).unwrap();
        let (d2, _, _) = law.approach(slices[10].load_n_m, le);
        assert!((d2 / delta - 1.0).abs() < 1e-10);
    }

    /// The analytic derivatives of P and M in Δ and θ against central differences of the
    /// discrete model, for aligned, misaligned, partly and edge-loaded contacts (1e-6
    /// relative of the largest entry: h = 1e-6 of the variable's scale).
    #[test]
    fn contact_derivatives_match_differences() {
        for flat in [0.0, 0.2 * crate::units::INCH_M] {
            let mut s = TaperedInput::afapl_sample();
            s.geometry.flat_length_m = flat;
            let rg = RollerGeometry::new(&s.geometry, &s.materials.roller).unwrap();
            for race in [Race::Cup, Race::Cone] {
                let c = RaceContact::new(race, &s.geometry, &rg, &s.materials, 21).unwrap();
                for (delta, theta) in [
                    (5e-6, 0.0),
                    (5e-6, 2e-4),
                    (2e-6, -5e-4),
                    (3e-5, 1e-3),
                    (1e-6, 3e-3),
                ] {
                    let e = c.eval(delta, theta, None).unwrap();
                    let hd = 1e-6 * delta;
                    let ht = 1e-9;
                    let fd = |dd: f64, dt: f64| {
                        let a = c.eval(delta + dd, theta + dt, None).unwrap();
                        let b = c.eval(delta - dd, theta - dt, None).unwrap();
                        [
                            (a.load_n - b.load_n) / (2.0 * (dd + dt)),
                            (a.moment_nm - b.moment_nm) / (2.0 * (dd + dt)),
                        ]
                    };
                    let [pd, md] = fd(hd, 0.0);
                    let [pt, mt] = fd(0.0, ht);
                    let l = 0.5 * s.geometry.effective_length_m;
                    let scale_p = e.dload[0].abs().max(e.dload[1].abs() / l);
                    let scale_m = e.dmoment[0].abs().max(e.dmoment[1].abs() / l);
                    assert!(
                        (pd - e.dload[0]).abs() < 1e-6 * scale_p,
                        "{race:?} {delta} {theta} dP/dΔ {pd} {}",
                        e.dload[0]
                    );
                    assert!(
                        (pt - e.dload[1]).abs() / l < 1e-6 * scale_p,
                        "{race:?} {delta} {theta} dP/dθ {pt} {}",
                        e.dload[1]
                    );
                    assert!(
                        (md - e.dmoment[0]).abs() < 1e-6 * scale_m,
                        "{race:?} dM/dΔ {md} {}",
                        e.dmoment[0]
                    );
                    assert!(
                        (mt - e.dmoment[1]).abs() / l < 1e-6 * scale_m,
                        "{race:?} {flat} {delta} {theta} dM/dθ {mt} {} {e:?}",
                        e.dmoment[1]
                    );
                }
            }
        }
    }

    /// An aligned crowned roller's load is centred but for the taper: the slices toward
    /// the big end are wider (larger dₓ, larger b, smaller logarithm in eq. 62) and carry a
    /// little more, a centre offset M/P of 1.6 µm here, under 1e-3 of the half length.
    /// Misalignment θ > 0 puts the load toward the big end (M > 0); no approach, no load,
    /// never NaN.
    #[test]
    fn contact_signs_and_limits() {
        let (_, _, cup, _) = sample(21);
        let e = cup.eval(5e-6, 0.0, None).unwrap();
        let half = 0.5 * TaperedInput::afapl_sample().geometry.effective_length_m;
        assert!(e.load_n > 0.0 && e.moment_nm > 0.0);
        assert!(e.moment_nm < 1e-3 * e.load_n * half);
        assert!(!e.edge_loaded);
        assert!(cup.eval(5e-6, 1e-4, None).unwrap().moment_nm > 0.0);
        assert_eq!(cup.eval(-1e-6, 0.0, None).unwrap(), ContactEval::default());
        assert_eq!(cup.eval(0.0, 0.0, None).unwrap().load_n, 0.0);
    }
}
