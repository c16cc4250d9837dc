//! One roller–race contact by slices (seed 004 eqs. 45–73, 84–87): the intrusion of the
//! crowned roller into the race (58–61), the contact extent (48–54), Lundberg's slice law
//! inverted for each slice's load per length (62–71), and the resultant load and moment
//! with their derivatives in the race approach Δᵢ and misalignment θᵢ (72–73, 84–87).
//!
//! Slices: `n` equal slices over the effective length, centres Xₖ fixed at their θ = 0
//! positions (the projection cos θ and the V·sin θ shift of eqs. 52–53 move them by less
//! than 10⁻⁶ of the length at the misalignments of a bearing); the resultants are
//! P = w·Σpₖ and M = w·Σ Xₖ·pₖ (midpoint rule of eqs. 72–73). X is positive toward the
//! big end on both races, θᵢ positive squeezes the big end harder (seed's convention).
//!
//! The derivatives are those of this discrete model, exact: besides ∂p/∂Δₓ of eq. 71 they
//! include the contact length's change in Lundberg's logarithm (∂p/∂L·∂L/∂(Δ, θ)), which
//! eqs. 84–87 leave out; without it the analytic stiffness would differ from re-solved
//! finite differences by about a per cent.
//!
//! Eq. 48's radicand R_c² − (H cos θ − Δ)² is computed as (R_c − a)(R_c + a): R_c is 2.5 m
//! while Δ is micrometres. The crowned intrusion (59) is computed as
//! Δ + (l_F²/4 − X² + 2XH sin θ)/(√(R_c² − u²) + H cos θ), u = X − H sin θ, the same number
//! without subtracting two lengths of 2.5 m.

use thiserror::Error;

use super::geometry::RollerGeometry;
use super::input::{Geometry, Materials};
use crate::physics::contact::lundberg::{compliance, LundbergError, LundbergSlice};

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

/// One race contact: its slices' laws.
#[derive(Debug, Clone, PartialEq)]
pub struct RaceContact {
    /// Which race.
    pub race: Race,
    profile: Profile,
    /// Slice centres Xₖ, m.
    pub x_m: Vec<f64>,
    laws: Vec<LundbergSlice>,
    /// Slice width w, m.
    pub width_m: f64,
}

/// The contact's extent [X_B, X_A] and the derivatives of its length.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Extent {
    xb: f64,
    xa: f64,
    dl: [f64; 2],
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
        let (beta, d, e) = (g.cup_angle_rad, g.roller_diameter_m, g.pitch_diameter_m);
        let (c_sign, race_mat, race_angle) = match race {
            Race::Cup => (1.0, mats.cup, beta),
            Race::Cone => (-1.0, mats.cone, beta - 2.0 * t),
        };
        let c = compliance(&mats.roller, &race_mat);
        let le = g.effective_length_m;
        let w = le / n as f64;
        let mut x_m = Vec::with_capacity(n);
        let mut laws = Vec::with_capacity(n);
        for k in 0..n {
            let x = -0.5 * le + (k as f64 + 0.5) * w;
            let dx = (d + 2.0 * x * t.sin()) / t.cos(); // eq. 67
            let ex = e + 2.0 * x * beta.sin() + d * (beta - t).cos() - dx * beta.cos(); // eq. 68
            let gamma = dx * race_angle.cos() / ex; // eqs. 65–66
            let law =
                LundbergSlice::new(c, dx, 1.0 + c_sign * gamma).map_err(|source| ContactError {
                    race,
                    slice: k,
                    x_m: x,
                    source,
                })?;
            x_m.push(x);
            laws.push(law);
        }
        Ok(RaceContact {
            race,
            profile: Profile {
                half_le: 0.5 * le,
                half_flat: 0.5 * g.flat_length_m,
                rc: rg.crown_radius_m,
                h: rg.crown_offset_m,
                v: rg.crown_drop_m,
            },
            x_m,
            laws,
            width_m: w,
        })
    }

    /// Intrusion Δₓ at X and ∂Δₓ/∂θ (eqs. 58–61; ∂Δₓ/∂Δ = 1).
    #[inline]
    fn intrusion(&self, x: f64, delta: f64, theta: f64) -> (f64, f64) {
        let p = &self.profile;
        let (s, c) = theta.sin_cos();
        if x.abs() <= p.half_flat * c {
            let tan = s / c;
            return (delta + x * tan, x / (c * c));
        }
        let u = x - p.h * s;
        let root = ((p.rc - u) * (p.rc + u)).sqrt();
        let num = p.half_flat * p.half_flat - x * x + 2.0 * x * p.h * s;
        (delta + num / (root + p.h * c), u * p.h * c / root + p.h * s)
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
        let dlim = -p.half_le * s + p.v * c;
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
            dxa = [0.0, dlim];
            edge = true;
        }
        if xb < xb_min {
            xb = xb_min;
            dxb = [0.0, dlim];
            edge = true;
        }
        if !(xa > xb) {
            return None;
        }
        Some(Extent {
            xb,
            xa,
            dl: [dxa[0] - dxb[0], dxa[1] - dxb[1]],
            edge,
        })
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
            if let Some(out) = slices {
                for &x in &self.x_m {
                    let (i, _) = self.intrusion(x, delta, theta);
                    out.push(SliceResult {
                        x_m: x,
                        intrusion_m: i,
                        load_n_m: 0.0,
                        half_width_m: 0.0,
                        stress_pa: 0.0,
                    });
                }
            }
            return Ok(ContactEval::default());
        };
        let length = ext.xa - ext.xb;
        let mut r = ContactEval {
            extent_m: [ext.xb, ext.xa],
            edge_loaded: ext.edge,
            ..ContactEval::default()
        };
        let (mut sp, mut sm) = (0.0, 0.0);
        let (mut dp, mut dm) = ([0.0; 2], [0.0; 2]);
        for (k, (&x, law)) in self.x_m.iter().zip(&self.laws).enumerate() {
            let (i, di_dtheta) = self.intrusion(x, delta, theta);
            let mut stress = 0.0;
            let mut sl = Default::default();
            if i > 0.0 {
                sl = law.load(i, length).map_err(|source| ContactError {
                    race: self.race,
                    slice: k,
                    x_m: x,
                    source,
                })?;
                let crate::physics::contact::lundberg::SliceLoad {
                    load_n_m: p,
                    dload_dapproach: pd,
                    dload_dlength: pl,
                    half_width_m: b,
                } = sl;
                let d0 = pd + pl * ext.dl[0];
                let d1 = pd * di_dtheta + pl * ext.dl[1];
                sp += p;
                sm += x * p;
                dp[0] += d0;
                dp[1] += d1;
                dm[0] += x * d0;
                dm[1] += x * d1;
                stress = 2.0 * p / (std::f64::consts::PI * b);
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
        let w = self.width_m;
        r.load_n = w * sp;
        r.moment_nm = w * sm;
        r.dload = [w * dp[0], w * dp[1]];
        r.dmoment = [w * dm[0], w * dm[1]];
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
        for (sl, law) in slices.iter().zip(&cup.laws) {
            let (d, _, _) = law.approach(sl.load_n_m, le);
            assert!((d / delta - 1.0).abs() < 1e-10, "{d}");
        }
        // The middle slice's law (the roller's mid diameter) with the mean load per length.
        let mid = cup.laws[10];
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
                        "{race:?} {delta} {theta} dM/dθ {mt} {}",
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
        let half = cup.x_m.last().unwrap() + 0.5 * cup.width_m;
        assert!(e.load_n > 0.0 && e.moment_nm > 0.0);
        assert!(e.moment_nm < 1e-3 * e.load_n * half);
        assert!(!e.edge_loaded);
        assert!(cup.eval(5e-6, 1e-4, None).unwrap().moment_nm > 0.0);
        assert_eq!(cup.eval(-1e-6, 0.0, None).unwrap(), ContactEval::default());
        assert_eq!(cup.eval(0.0, 0.0, None).unwrap().load_n, 0.0);
    }
}
