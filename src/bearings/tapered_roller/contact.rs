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
//!
//! **Logarithmic profile** (`geometry.profile = "logarithmic"`, issue 29 session 11): the
//! roller's drop below its straight generator is ISO/TS 16281:2008's for tapered rollers
//! (its eq. 44; eq. 42 is the cylindrical roller's with 0.00035, eq. 43 the long one's),
//! D(x) = 0.00045·D_we·ln[1/(1 − (2x/L_we)²)], x from the middle of the effective length
//! L_we, D_we the mean roller diameter. Source: the public ISO/TS 16281 implementation
//! minzhun/ISO16281 (`RollerBearing.py`, `__roller_profile`, "Equation 42 - 44", bearing
//! type 2 = tapered roller), the same form as Lundberg's and Johns–Gohar's logarithmic
//! crowns (the background) with ISO's fixed coefficient; rollbench's cylindrical system
//! uses eq. 42 (`cylindrical_roller::quasi_static`). The standard evaluates D only at
//! lamina centres x_k = (k − ½)·L_we/n_s − L_we/2, which never reach the ends, where D is
//! infinite: the outermost lamina's drop is finite, a·ln(n_s²/(2n_s − 1)) with a =
//! 0.00045·D_we. That is its end cutoff, and without one a tilted roller's contact is
//! pushed to within nanometres of the end (a tilt of 0.01 rad over the 32007's half
//! length needs a drop of 21a, ln(1/w) = 21) and the slices lose every digit. Here the
//! cutoff is made continuous: D is ISO's for |2x/L_we| ≤ u_c = 1 − 1/30 (the outermost
//! lamina centre at n_s = 30, a drop of 2.725a, 7.97 µm on the 32007) and continues
//! along its tangent to the ends (10.8 µm there on the 32007), so D stays convex and C¹
//! and the contact can reach the roller's ends (edge loaded, clamped there as the
//! crowned contact is, eqs. 52–53, in the small-tilt form X = ±l_e/2). The intrusion is
//! Δᵢ + X·tan θ − D(X) (the drop read at the race coordinate X; the crowned profile's
//! exact rotation differs by O(θ²)·D, 1e-6 of it at the 32007's tilts), concave in X, so
//! each end of the extent is found by Newton from the roller's end inward, which converges
//! monotonically; its derivatives follow from the implicit function theorem,
//! ∂X/∂(Δ, θ) = −(1, X/cos²θ)/∂ₓi, and a clamped end has none.
//!
//! **Short contacts** (issue 29 session 12): Lundberg's law (eq. 62) is inverted with the
//! contact's length L in its logarithm, and has an inverse only while the approach is
//! below δ_max(L) = c·L²·e^(2(K−½))/(8·wf) (eq. 71's L/(2b) = 0.25; wf = c·dₓ(1 + Cγ),
//! K = 1.8864). A contact that has only just started at a tilted roller's end is
//! short while its slices' intrusions are not (i ≈ slope·L against δ_max ∝ L²): the
//! 32007 roller at 0.01 rad has no inverse below L ≈ 30 µm, so every roller whose ring
//! state put its end contact there (1e-18 m, at round-off, up to micrometres) failed, and
//! with it the bearing's solve at many tilts. The length in the logarithm is therefore
//! floored at L_f = 2·L_v(i), L_v(i) = e^(−(K−½))·√(8·wf·i/c) the length whose δ_max is
//! the slice's intrusion i (so the slice sits at a quarter of the floored length's
//! δ_max, on the valid branch, L/(2b) ≈ 0.5), and capped at the effective length (a
//! roller too short for the law everywhere stays a typed error). The floor changes
//! nothing where the law held with a margin of 4 in approach; where it acts, the contact
//! is point-like rather than a strip, which the slice model does not describe, and its
//! load is small: 2.5e-5 N at L = 0.3 µm and 0.25 N at 26 µm
//! on the 32007 cup (test `short_edge_contacts_are_floored_not_refused`). With the floor
//! active ∂p/∂L = 0 and ∂p/∂δ, ∂p/∂wf gain the floor's ∂L_f/∂i = L_f/(2i),
//! ∂L_f/∂wf = L_f/(2wf).

use thiserror::Error;

use super::geometry::RollerGeometry;
use super::input::{Geometry, Materials, RollerProfile};
use crate::physics::contact::lundberg::{
    compliance, LundbergError, LundbergSlice, SliceLoad, LUNDBERG_CONSTANT,
};

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

/// ISO/TS 16281:2008's coefficient of the tapered roller's logarithmic profile (eq. 44):
/// D(x) = 0.00045·D_we·ln[1/(1 − (2x/L_we)²)].
pub const ISO_16281_TAPERED_LOG_COEFFICIENT: f64 = 0.00045;

/// Where the logarithmic profile's ISO form stops and its tangent takes over, as a
/// fraction of the half length: the outermost lamina centre of n_s = 30 laminae (module
/// notes).
pub const LOG_PROFILE_CUTOFF: f64 = 1.0 - 1.0 / 30.0;

/// The logarithmic profile's drop D(x) (m) at `x_m` from the middle of the effective
/// length `effective_length_m` of a roller of mean diameter `diameter_m`: ISO/TS 16281
/// eq. 44, a·ln[1/(1 − (2x/L_we)²)] with a = 0.00045·D_we, for |2x/L_we| ≤
/// [`LOG_PROFILE_CUTOFF`], its tangent beyond (module notes).
pub fn log_profile_drop(x_m: f64, effective_length_m: f64, diameter_m: f64) -> f64 {
    let a = ISO_16281_TAPERED_LOG_COEFFICIENT * diameter_m;
    log_drop(a, x_m / (0.5 * effective_length_m)).0
}

/// The drop (m) of the cut-off logarithmic profile at u = 2x/L_we and dD/du, for
/// a = 0.00045·D_we (module notes).
#[inline]
fn log_drop(a: f64, u: f64) -> (f64, f64) {
    let uc = LOG_PROFILE_CUTOFF;
    let v = u.abs();
    if v <= uc {
        let w = (1.0 - u) * (1.0 + u);
        (-a * w.ln(), 2.0 * a * u / w)
    } else {
        let wc = (1.0 - uc) * (1.0 + uc);
        let slope = 2.0 * a * uc / wc;
        (-a * wc.ln() + slope * (v - uc), slope * u.signum())
    }
}

/// The right end u_A ∈ (u*, 1] (as a fraction of the half length) of the logarithmic
/// contact i(u) = Δ + k·u − D(u) > 0 (k = (l_e/2)·tan θ, D cut off as in
/// [`log_drop`]), given i(u*) > 0 at its maximum u*: the roller's end u = 1 when
/// i(1) ≥ 0 (edge loaded), else Newton from u = 1 inward: i is concave, so every step
/// stays outside the root and moves toward it (monotone). Returns (u_A, at the end).
fn log_right_end(delta: f64, k: f64, a: f64, u_star: f64) -> (f64, bool) {
    let g = |u: f64| {
        let (d, dd) = log_drop(a, u);
        (delta + k * u - d, k - dd)
    };
    if g(1.0).0 >= 0.0 {
        return (1.0, true);
    }
    let mut u = 1.0_f64;
    for _ in 0..200 {
        let (gu, dg) = g(u);
        if !(gu < 0.0) || !(dg < 0.0) {
            break;
        }
        let next = (u - gu / dg).max(u_star);
        let step = u - next;
        u = next;
        if step <= 1e-16 * u.abs().max(1e-300) {
            break;
        }
    }
    (u, false)
}

/// How many times the shortest length at which Lundberg's strip still carries approach
/// δ the logarithm's length is floored at (module notes, "Short contacts").
pub const SHORT_CONTACT_FACTOR: f64 = 2.0;

/// The floor of the length in Lundberg's logarithm at slice approach `delta_m` (m):
/// [`SHORT_CONTACT_FACTOR`] times L_v(δ) = e^(−(K − ½))·√(8·wf·δ/c), the length whose
/// largest approach (eq. 71's validity limit L/(2b) = e^(−(K − ½)) ≈ 0.25) is δ
/// (module notes, "Short contacts").
#[inline]
fn short_contact_length(law: &LundbergSlice, delta_m: f64) -> f64 {
    SHORT_CONTACT_FACTOR
        * (-(LUNDBERG_CONSTANT - 0.5)).exp()
        * (8.0 * law.width_factor * delta_m / law.compliance).sqrt()
}

/// The roller profile seen from one race.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Profile {
    half_le: f64,
    half_flat: f64,
    rc: f64,
    h: f64,
    v: f64,
    /// a = 0.00045·D_we of the logarithmic profile; `None`: flat and circular crowns.
    log: Option<f64>,
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
                log: match g.profile {
                    RollerProfile::Crowned => None,
                    RollerProfile::Logarithmic => {
                        Some(ISO_16281_TAPERED_LOG_COEFFICIENT * g.roller_diameter_m)
                    }
                },
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
        if let Some(a) = p.log {
            // Δ + X·tan θ − D(X), D of ISO/TS 16281 eq. 44 cut off (module notes).
            let tan = s / c;
            let (d, dd) = log_drop(a, x / p.half_le);
            return (delta + x * tan - d, x / (c * c), tan - dd / p.half_le);
        }
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
        if let Some(a) = p.log {
            return self.log_extent(a, delta, theta);
        }
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

    /// The logarithmic profile's contact extent (module notes): i(u) = Δ + k·u − D(u)
    /// with u = X/(l_e/2), k = (l_e/2)·tan θ, is concave with its maximum at u* where
    /// D′(u*) = k: on the ISO part u* = k/(a + √(a² + k²)) (the root of k·u² + 2a·u − k
    /// = 0), and at the end u = ±1 when that lies beyond the cutoff (the tangent's slope
    /// is below |k| there). No contact unless i(u*) > 0.
    fn log_extent(&self, a: f64, delta: f64, theta: f64) -> Option<Extent> {
        let hl = self.profile.half_le;
        let tan = theta.tan();
        let k = hl * tan;
        let mut u_star = k / (a + a.hypot(k));
        if u_star.abs() > LOG_PROFILE_CUTOFF {
            u_star = u_star.signum();
        }
        let peak = delta + k * u_star - log_drop(a, u_star).0;
        if !(peak > 0.0) {
            return None;
        }
        let (ua, edge_a) = log_right_end(delta, k, a, u_star);
        let (ub, edge_b) = log_right_end(delta, -k, a, -u_star);
        let ub = -ub;
        if !(ua > ub) {
            return None;
        }
        let (xa, xb) = (hl * ua, hl * ub);
        let ends = |x: f64, edge: bool| {
            if edge {
                return [0.0, 0.0];
            }
            let (_, di_dtheta, di_dx) = self.intrusion(x, delta, theta);
            [-1.0 / di_dx, -di_dtheta / di_dx]
        };
        Some(Extent {
            xb,
            xa,
            dxb: ends(xb, edge_b),
            dxa: ends(xa, edge_a),
            edge: edge_a || edge_b,
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
                // The length in Lundberg's logarithm, floored for a contact too short to be
                // a strip at this approach (module notes, "Short contacts").
                let floor = short_contact_length(&law, i);
                let l_e = 2.0 * self.profile.half_le;
                let l_log = length.max(floor.min(l_e));
                sl = law.load(i, l_log).map_err(fail)?;
                let (p, mut pd, mut pl) = (sl.load_n_m, sl.dload_dapproach, sl.dload_dlength);
                // ∂p/∂(b² factor) at fixed δ, L: δ has −c·p/(2·wf) per unit wf.
                let mut pw = pd * law.compliance * p / (2.0 * law.width_factor);
                if l_log > length {
                    if floor < l_e {
                        // The floor ∝ √(wf·δ): its share of ∂p/∂δ and ∂p/∂wf.
                        pd += pl * floor / (2.0 * i);
                        pw += pl * floor / (2.0 * law.width_factor);
                    }
                    // Floored (or at the effective length): none of ∂p/∂L.
                    pl = 0.0;
                }
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
    use crate::bearings::tapered_roller::input::{Crown, RollerProfile, TaperedInput};
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

    /// The 32007-X-XL roller of decks/trb_32007.toml (d 6.5 mm, l_e 12.445 mm) with the
    /// given profile.
    fn roller_32007(profile: RollerProfile) -> (TaperedInput, RollerGeometry) {
        let mut s = TaperedInput::afapl_sample();
        let g = &mut s.geometry;
        g.roller_count = 20;
        g.roller_diameter_m = 0.0065;
        g.pitch_diameter_m = 0.048;
        g.cup_angle_rad = 16.70_f64.to_radians();
        g.effective_length_m = 0.012445;
        g.flat_length_m = 0.008;
        g.crown = Crown::Radius(0.5);
        g.small_end_break_m = 0.0005;
        g.big_end_break_m = 0.0005;
        g.profile = profile;
        let rg = RollerGeometry::new(&s.geometry, &s.materials.roller).unwrap();
        (s, rg)
    }

    /// The logarithmic profile's drop against ISO/TS 16281 eq. 44 in closed form,
    /// 0.00045·D_we·ln[1/(1 − (2x/L_we)²)], at a few points inside the cutoff
    /// 2x/L_we ≤ 29/30 (1e-12 relative), and its tangent beyond it (1e-12); the intrusion
    /// the contact uses is Δ + X·tan θ − D(X) at those points (1e-12 of Δ) and the
    /// extent's ends are where it vanishes. Fails if the coefficient, the argument, the
    /// cutoff or the sign of the drop changes.
    #[test]
    fn log_profile_drop_is_iso_16281_eq_44() {
        let (s, rg) = roller_32007(RollerProfile::Logarithmic);
        let (d, le) = (s.geometry.roller_diameter_m, s.geometry.effective_length_m);
        let a = 0.00045 * 0.0065;
        let uc: f64 = 29.0 / 30.0;
        let wc = 1.0 - uc * uc;
        // Closed-form values, D_we = 6.5 mm, L_we = 12.445 mm: 2x/L_we = 0, 0.5, −0.9,
        // 29/30 (the cutoff), then 0.99 and 1 on the tangent.
        for (r, want) in [
            (0.0, 0.0),
            (0.5, a * (4.0_f64 / 3.0).ln()),
            (-0.9, a * (1.0 / 0.19_f64).ln()),
            (uc, a * (1.0 / wc).ln()),
            (0.99, a * (1.0 / wc).ln() + 2.0 * a * uc / wc * (0.99 - uc)),
            (-1.0, a * (1.0 / wc).ln() + 2.0 * a * uc / wc * (1.0 - uc)),
        ] {
            let x = r * 0.5 * le;
            let got = log_profile_drop(x, le, d);
            assert!(
                (got - want).abs() <= 1e-12 * want.abs().max(1e-30),
                "x {x}: {got} vs {want}"
            );
        }
        // At 2x/L = 0.9: 2.925 µm·ln(1/0.19) = 4.858 µm; at the cutoff 7.97 µm, at the
        // ends 10.85 µm (the numbers the docs quote).
        assert!((log_profile_drop(0.45 * le, le, d) - 4.8577e-6).abs() < 1e-9);
        assert!((log_profile_drop(0.5 * uc * le, le, d) - 7.970e-6).abs() < 1e-9);
        assert!((log_profile_drop(0.5 * le, le, d) - 10.846e-6).abs() < 1e-9);
        let cup = RaceContact::new(Race::Cup, &s.geometry, &rg, &s.materials, 21).unwrap();
        let (delta, theta) = (4e-6, 3e-4);
        for r in [-0.8, -0.3, 0.0, 0.6, 0.95, 0.99] {
            let x = r * 0.5 * le;
            let (i, _, _) = cup.intrusion(x, delta, theta);
            let want = delta + x * theta.tan() - log_profile_drop(x, le, d);
            assert!((i - want).abs() <= 1e-12 * delta, "{x}: {i} vs {want}");
        }
        // The extent's ends are where that intrusion vanishes (to 1e-12 of Δ), inside the
        // effective length.
        let e = cup.eval(delta, theta, None).unwrap();
        assert!(!e.edge_loaded);
        for x in e.extent_m {
            assert!(x.abs() < 0.5 * le);
            let want = delta + x * theta.tan() - log_profile_drop(x, le, d);
            assert!(want.abs() <= 1e-12 * delta, "{x}: {want}");
        }
    }

    /// The logarithmic contact's derivatives against central differences (as
    /// `contact_derivatives_match_differences` for the crown), aligned and tilted both
    /// ways, light and heavy (1e-6 of the row's scale).
    #[test]
    fn log_contact_derivatives_match_differences() {
        let (s, rg) = roller_32007(RollerProfile::Logarithmic);
        for race in [Race::Cup, Race::Cone] {
            let c = RaceContact::new(race, &s.geometry, &rg, &s.materials, 21).unwrap();
            for (delta, theta) in [
                (5e-6, 0.0),
                (5e-6, 2e-4),
                (2e-6, -5e-4),
                (3e-5, 1e-3),
                (1e-6, 3e-3),
                (4e-6, -1e-2),
                (2e-5, 1e-2),
            ] {
                let e = c.eval(delta, theta, None).unwrap();
                let fd = |dd: f64, dt: f64| {
                    let a = c.eval(delta + dd, theta + dt, None).unwrap();
                    let b = c.eval(delta - dd, theta - dt, None).unwrap();
                    [
                        (a.load_n - b.load_n) / (2.0 * (dd + dt)),
                        (a.moment_nm - b.moment_nm) / (2.0 * (dd + dt)),
                    ]
                };
                let [pd, md] = fd(1e-6 * delta, 0.0);
                let [pt, mt] = fd(0.0, 1e-9);
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
                    "{race:?} {delta} {theta} dM/dΔ {md} {}",
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

    /// A uniformly loaded (aligned) roller of the 32007 deck at the same contact load, on
    /// the cup, with either profile. The edge-to-centre ratio is max(p₀, p₂₀)/p₁₀ over
    /// the 21 slices. The logarithmic profile never loads an end slice above the middle
    /// one (no spike: ratio < 1 at every load; its end slices are edge loaded from about
    /// 6 kN, where the approach passes its 10.85 µm end drop). It does **not** load its
    /// ends less than the deck's assumed crown: that crown (flat 8 mm, R_c 0.5 m) drops
    /// 22.7 µm at the ends, twice the ISO profile's 10.85 µm, and a slice model (no
    /// coupling between slices, no edge factors) carries each slice by its own intrusion.
    /// Measured (crowned, logarithmic): 2 kN 0.260, 0.259 (neither edge loaded); 6 kN
    /// 0.146, 0.578 (the log edge loaded); 9 kN 0.247, 0.698 (both). Fails if a log end
    /// slice exceeded the middle, or if these numbers moved by more than 1e-3.
    #[test]
    fn log_profile_relieves_the_edges() {
        let ratio = |profile: RollerProfile, load: f64| {
            let (s, rg) = roller_32007(profile);
            let c = RaceContact::new(Race::Cup, &s.geometry, &rg, &s.materials, 21).unwrap();
            // Bisect Δ for the load (P increases with Δ).
            let (mut lo, mut hi) = (0.0, 1e-4);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if c.eval(mid, 0.0, None).unwrap().load_n < load {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let mut sl = Vec::new();
            let e = c.eval(hi, 0.0, Some(&mut sl)).unwrap();
            assert!((e.load_n / load - 1.0).abs() < 1e-9);
            let end = sl[0].load_n_m.max(sl[20].load_n_m);
            (end / sl[10].load_n_m, e.edge_loaded)
        };
        for (load, want_c, want_l, edges) in [
            (2_000.0, 0.2601, 0.2589, (false, false)),
            (6_000.0, 0.1459, 0.5776, (false, true)),
            (9_000.0, 0.2473, 0.6977, (true, true)),
        ] {
            let (rc, edge_c) = ratio(RollerProfile::Crowned, load);
            let (rl, edge_l) = ratio(RollerProfile::Logarithmic, load);
            eprintln!("load {load} N: edge/centre crowned {rc:.4} (edge {edge_c}), logarithmic {rl:.4} (edge {edge_l})");
            assert!(rl < 1.0, "{load}: a log end slice above the middle: {rl}");
            assert!(
                (rc - want_c).abs() < 1e-3 && (rl - want_l).abs() < 1e-3,
                "{load}: {rc} {rl}"
            );
            assert_eq!((edge_c, edge_l), edges, "{load}");
        }
    }

    /// Issue 29 session 12, short contacts: the 32007 roller (crowned, and logarithmic)
    /// tilted 0.02 rad on the cup, its big end just touching. At contact lengths from
    /// about 1e-8 to 1e-4 m Lundberg's law at the contact's own length has no inverse for
    /// the end slice (L/(2b) ≤ 0.25: the error these evaluations ended in before), while
    /// the contact with the floored logarithm evaluates: its load is positive, rises with
    /// the approach and vanishes with the length (P ≤ 1e-3 N at L ≤ 1e-6 m), and its
    /// derivatives equal central differences to 1e-5 of the row's scale (steps 1e-4 of the
    /// approach past the onset: the round-off of Δ ≈ 1e-5 m over those steps is ~1e-6).
    /// Fails if the floor is removed (error) or its derivative terms are (differences).
    #[test]
    fn short_edge_contacts_are_floored_not_refused() {
        for profile in [RollerProfile::Crowned, RollerProfile::Logarithmic] {
            let (s, rg) = roller_32007(profile);
            let c = RaceContact::new(Race::Cup, &s.geometry, &rg, &s.materials, 21).unwrap();
            let theta = 0.02;
            // The approach at which the big end starts to touch, by bisection.
            let (mut lo, mut hi) = (-1e-3, 1e-3);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if c.touches(mid, theta) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            let mut last_p = 0.0;
            let mut refused = 0;
            for eps in [1e-8, 1e-7, 1e-6, 1e-5] {
                let delta = hi + eps * theta;
                let mut sl = Vec::new();
                let e = c.eval(delta, theta, Some(&mut sl)).unwrap();
                let length = e.extent_m[1] - e.extent_m[0];
                let end = sl.last().unwrap();
                let (law, _) = c.law(end.x_m).unwrap();
                if law.load(end.intrusion_m, length).is_err() {
                    refused += 1;
                }
                assert!(e.load_n > last_p, "{profile:?} {eps}: {} N", e.load_n);
                if length <= 1e-6 {
                    assert!(e.load_n <= 1e-3, "{profile:?} {eps}: {} N", e.load_n);
                }
                last_p = e.load_n;
                let fd = |dd: f64, dt: f64| {
                    let a = c.eval(delta + dd, theta + dt, None).unwrap();
                    let b = c.eval(delta - dd, theta - dt, None).unwrap();
                    [
                        (a.load_n - b.load_n) / (2.0 * (dd + dt)),
                        (a.moment_nm - b.moment_nm) / (2.0 * (dd + dt)),
                    ]
                };
                let [pd, md] = fd(1e-4 * eps * theta, 0.0);
                let [pt, mt] = fd(0.0, 1e-4 * eps);
                let l = 0.5 * s.geometry.effective_length_m;
                let scale_p = e.dload[0].abs().max(e.dload[1].abs() / l);
                let scale_m = e.dmoment[0].abs().max(e.dmoment[1].abs() / l);
                eprintln!(
                    "{profile:?} L {length:.3e} m: P {:.3e} N, dP/dΔ {pd:.6e} vs {:.6e}, dP/dθ {pt:.6e} vs {:.6e}",
                    e.load_n, e.dload[0], e.dload[1]
                );
                for (got, want, scale, what) in [
                    (pd, e.dload[0], scale_p, "dP/dΔ"),
                    (pt / l, e.dload[1] / l, scale_p, "dP/dθ"),
                    (md, e.dmoment[0], scale_m, "dM/dΔ"),
                    (mt / l, e.dmoment[1] / l, scale_m, "dM/dθ"),
                ] {
                    assert!(
                        (got - want).abs() < 1e-5 * scale,
                        "{profile:?} L {length:.3e}: {what} {got:.8e} vs {want:.8e}"
                    );
                }
            }
            assert!(refused >= 2, "{profile:?}: {refused}");
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
