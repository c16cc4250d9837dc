//! Traction and sliding heat at a lamina contact (seed 000 §9.1–9.2), SI.
//!
//! # The Allen–Townsend–Zaretsky law and the reading chosen here
//!
//! Eq. 9.1 gives the Newtonian (Barus) film stress τ_N = η₀·exp(α·p)·|v|/h "when
//! τ < τ_tr and τ < μ·p", and eq. 9.2 gives τ = μ·p "when τ > τ_tr and τ > μ·p"; the band
//! between the two is left undefined. ATZ's model is Newtonian below the transition
//! stress and limited above it, so we use
//!
//! τ = τ_N                              for τ_N ≤ τ_tr,
//! τ = min(τ_N, max(τ_tr, μ·p))         otherwise,
//!
//! which is the same as τ = min(τ_N, max(τ_tr, μ·p)) everywhere, with the sign of v.
//! It is continuous in |v| (at τ_N = τ_tr both branches give τ_tr) and non-decreasing
//! in |v| (the limit max(τ_tr, μ·p) does not depend on v). Where μ·p ≥ τ_tr (the
//! loaded Hertz zone) it agrees with eqs. 9.1 and 9.2 wherever they are defined. Where
//! μ·p < τ_tr (the low-pressure fringe, p < τ_tr/μ ≈ 115 MPa for the defaults) the fluid
//! stays Newtonian up to τ_tr and is then held at τ_tr, rather than dropping to μ·p as a
//! literal eq. 9.2 would: that literal reading makes τ fall as |v| grows. (The only law
//! matching 9.1 and 9.2 literally everywhere would be min(τ_N, μ·p), in which τ_tr plays
//! no role at all.)
//!
//! Lost lubrication (§9.2, last paragraph): τ = μ·p with a user constant μ, so a
//! lamina's traction force is exactly μ·Q.
//!
//! # Sign
//!
//! v is the sliding velocity of [`crate::physics::kinematics::sliding_velocity`]: raceway
//! minus roller. The traction on the *roller* acts along +v (the raceway drags it); the
//! raceway receives the opposite force. Heat = |F·v| (eq. "rate of work done"; the seed's
//! 2.5933 is only the in-lb/s → Btu/hr factor, see `crate::physics::heat`).

use serde::{Deserialize, Serialize};

use crate::physics::lubrication::Lubricant;

/// Traction law at a concentrated contact (seed 000 §9.2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum TractionModel {
    /// Allen–Townsend–Zaretsky EHD traction, eqs. 9.1–9.2 with the reading in the module
    /// notes: τ = min(η₀·e^{αp}·|v|/h, max(τ_tr, μ_fl·p)).
    Ehd {
        /// η₀, absolute viscosity at ambient pressure, Pa·s.
        viscosity_pa_s: f64,
        /// α (seed's ζ), Barus pressure–viscosity coefficient, 1/Pa.
        pressure_viscosity_pa_inv: f64,
        /// τ_tr, transition shear stress, Pa.
        transition_shear_stress_pa: f64,
        /// μ_fl, limiting (pseudo) traction coefficient, dimensionless.
        limiting_traction_coefficient: f64,
    },
    /// Lost lubrication: τ = μ·p (constant traction coefficient), dimensionless μ.
    Constant {
        /// μ, traction coefficient, dimensionless.
        mu: f64,
    },
}

/// A Hertz strip (one lamina's line contact) as traction reads it: load and strip
/// dimensions. (The spherical roller's `contacts::LaminaContact` is the contact geometry of
/// a lamina; this is its Hertz strip.)
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct HertzStrip {
    /// q, normal load carried by the lamina, N.
    pub load_n: f64,
    /// b, Hertz semi-width in the rolling direction, m.
    pub half_width_m: f64,
    /// w, lamina width along the roller axis, m.
    pub width_m: f64,
}

impl HertzStrip {
    /// Peak Hertz pressure p₀ = 2q/(π·b·w), Pa, so that w·∫p dx = q for the semi-ellipse
    /// p(x) = p₀·√(1 − x²/b²). Zero for an unloaded or degenerate strip.
    pub fn peak_pressure_pa(&self) -> f64 {
        let (q, b, w) = (self.load_n, self.half_width_m, self.width_m);
        if q.is_finite() && b.is_finite() && w.is_finite() && q > 0.0 && b > 0.0 && w > 0.0 {
            2.0 * q / (std::f64::consts::PI * b * w)
        } else {
            0.0
        }
    }
}

/// Traction and heat of one lamina contact.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct LaminaTraction {
    /// Traction force on the roller along +v (the sliding direction), N.
    pub force_n: f64,
    /// Heat generated, |F·v|, W.
    pub heat_w: f64,
}

/// Allen–Townsend–Zaretsky film shear stress, Pa (seed 000 eqs. 9.1–9.2, continuous
/// reading in the module notes): τ = min(τ_N, max(τ_tr, μ·p))·sign(v) with the Barus
/// Newtonian stress τ_N = η₀·exp(α·p)·|v|/h.
///
/// `pressure_pa` p (negative values are clamped to 0), `sliding_velocity_m_s` v,
/// `film_thickness_m` h, `viscosity_pa_s` η₀, `pressure_viscosity_pa_inv` α,
/// `transition_shear_stress_pa` τ_tr, `limiting_traction_coefficient` μ.
///
/// Guards: v = 0 (or non-finite) gives 0; h ≤ 0 or non-finite (no film: zero speed or an
/// unloaded contact) treats τ_N as infinite, so the stress is the limit; an overflowing
/// exp(α·p) likewise. Never NaN for finite inputs.
pub fn atz_shear_stress(
    pressure_pa: f64,
    sliding_velocity_m_s: f64,
    film_thickness_m: f64,
    viscosity_pa_s: f64,
    pressure_viscosity_pa_inv: f64,
    transition_shear_stress_pa: f64,
    limiting_traction_coefficient: f64,
) -> f64 {
    let v = sliding_velocity_m_s;
    if !v.is_finite() || v == 0.0 {
        return 0.0;
    }
    let p = if pressure_pa.is_finite() {
        pressure_pa.max(0.0)
    } else {
        0.0
    };
    let limit = transition_shear_stress_pa.max(limiting_traction_coefficient * p);
    let newtonian = if film_thickness_m.is_finite() && film_thickness_m > 0.0 {
        viscosity_pa_s * (pressure_viscosity_pa_inv * p).exp() * v.abs() / film_thickness_m
    } else {
        f64::INFINITY
    };
    let tau = if newtonian.is_nan() {
        limit
    } else {
        newtonian.min(limit)
    };
    tau.max(0.0) * v.signum()
}

/// 8-point Gauss–Legendre nodes on [−1, 1] (positive half; symmetric).
const GL8_X: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
/// Weights matching [`GL8_X`].
const GL8_W: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];

impl TractionModel {
    /// The EHD (ATZ) model with the lubricant's η₀, α, τ_tr and μ_fl.
    pub fn ehd(lubricant: &Lubricant) -> TractionModel {
        TractionModel::Ehd {
            viscosity_pa_s: lubricant.viscosity_pa_s,
            pressure_viscosity_pa_inv: lubricant.pressure_viscosity_pa_inv,
            transition_shear_stress_pa: lubricant.transition_shear_stress_pa,
            limiting_traction_coefficient: lubricant.limiting_traction_coefficient,
        }
    }

    /// The lost-lubrication model with the lubricant's constant traction coefficient.
    pub fn lost_lubrication(lubricant: &Lubricant) -> TractionModel {
        TractionModel::Constant {
            mu: lubricant.lost_lubrication_traction_coefficient,
        }
    }

    /// Film shear stress, Pa, at pressure `pressure_pa` (Pa), sliding velocity
    /// `sliding_velocity_m_s` (m/s) and film thickness `film_thickness_m` (m); sign of v.
    /// EHD: [`atz_shear_stress`]; constant: μ·p (h is not used). Seed 000 eqs. 9.1–9.2.
    pub fn shear_stress(
        &self,
        pressure_pa: f64,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
    ) -> f64 {
        match *self {
            TractionModel::Ehd {
                viscosity_pa_s,
                pressure_viscosity_pa_inv,
                transition_shear_stress_pa,
                limiting_traction_coefficient,
            } => atz_shear_stress(
                pressure_pa,
                sliding_velocity_m_s,
                film_thickness_m,
                viscosity_pa_s,
                pressure_viscosity_pa_inv,
                transition_shear_stress_pa,
                limiting_traction_coefficient,
            ),
            TractionModel::Constant { mu } => {
                let v = sliding_velocity_m_s;
                if !v.is_finite() || v == 0.0 || !pressure_pa.is_finite() {
                    0.0
                } else {
                    mu * pressure_pa.max(0.0) * v.signum()
                }
            }
        }
    }

    /// Which branch of the law is active at pressure p (Pa), sliding speed v (m/s) and
    /// film h (m).
    fn regime(&self, p: f64, v: f64, h: f64) -> Regime {
        match *self {
            TractionModel::Constant { mu } => Regime::Coulomb(mu),
            TractionModel::Ehd {
                viscosity_pa_s,
                pressure_viscosity_pa_inv,
                transition_shear_stress_pa,
                limiting_traction_coefficient,
            } => {
                let newtonian = if h > 0.0 {
                    viscosity_pa_s * exp_fast(pressure_viscosity_pa_inv * p) * v.abs() / h
                } else {
                    f64::INFINITY
                };
                let mu_p = limiting_traction_coefficient * p;
                if newtonian <= transition_shear_stress_pa.max(mu_p) {
                    Regime::Newtonian
                } else if transition_shear_stress_pa >= mu_p {
                    Regime::Transition(transition_shear_stress_pa)
                } else {
                    Regime::Coulomb(limiting_traction_coefficient)
                }
            }
        }
    }

    /// Traction force and heat of one lamina contact (seed 000 §9.2: "integrating the
    /// shear stress over the entire contact area of this lamina contact").
    ///
    /// F = w·∫_{−b}^{b} τ(p(x), v, h) dx with p(x) = p₀·√(1 − x²/b²),
    /// p₀ = [`HertzStrip::peak_pressure_pa`]; v (m/s) is taken uniform across the
    /// strip's rolling direction and h (m) is the film thickness. Heat = |F·v| (W).
    ///
    /// Quadrature: the substitution x = b·sin φ turns the integral into
    /// 2·w·b·∫_0^{π/2} τ(p₀ cos φ)·cos φ dφ, whose integrand is analytic on each branch of
    /// the law (in x the semi-ellipse has an infinite slope at ±b, where Gauss–Legendre
    /// converges only algebraically). The law's kinks are found in closed form in p
    /// ([`TractionModel::kinks`]) and mapped to φ = acos(p/p₀), which splits [0, π/2] into
    /// pieces with one branch each. Limited pieces integrate exactly:
    /// ∫τ_tr·cos φ dφ = τ_tr·[sin φ] and ∫μp₀cos²φ dφ = μp₀·[φ/2 + sin 2φ/4]
    /// (the constant model's F = μ·Q to round-off). Newtonian pieces, e^{αp₀ cos φ}·cos φ,
    /// use composite 8-point Gauss–Legendre with the panel count set by α·p₀ and the piece
    /// length ([`TractionModel::newtonian_piece`]): ~1e-12 for α·p₀ up to 80 (tested against
    /// an independent reference).
    ///
    /// Guards: unloaded or degenerate strips, v = 0 and h ≤ 0 give finite results (zero
    /// force, or the limited stress when h ≤ 0), never NaN.
    pub fn lamina_traction(
        &self,
        contact: &HertzStrip,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
    ) -> LaminaTraction {
        self.prepared()
            .lamina_traction(contact, sliding_velocity_m_s, film_thickness_m)
    }

    /// This law with its contact-independent constants computed once
    /// ([`PreparedTraction`]): what a caller integrating many laminae with one law keeps.
    pub fn prepared(&self) -> PreparedTraction {
        let (ln_mu, ln_tr, s_lo, s_min) = match *self {
            TractionModel::Ehd {
                pressure_viscosity_pa_inv: alpha,
                transition_shear_stress_pa: tr,
                limiting_traction_coefficient: mu,
                ..
            } => (
                mu.ln(),
                tr.ln(),
                if tr > 0.0 {
                    (tr / mu).ln()
                } else {
                    f64::NEG_INFINITY
                },
                -alpha.ln(),
            ),
            TractionModel::Constant { .. } => (f64::NAN, f64::NAN, f64::NAN, f64::NAN),
        };
        PreparedTraction {
            model: *self,
            ln_mu,
            ln_tr,
            s_lo,
            s_min,
        }
    }

    /// [`TractionModel::lamina_traction`] and its slope ∂F/∂v, N/(m/s). On a Newtonian
    /// piece τ_N ∝ |v| at fixed p, so that piece's share of F is linear in v; the limited
    /// pieces (τ_tr, μ·p) do not depend on v, and the law is continuous at its kinks, so
    /// the kinks' motion with v adds no boundary term (Leibniz): ∂F/∂v = 2·w·b·I_N/|v|
    /// with I_N the Newtonian pieces' integral, exact to the quadrature. At v = 0 the
    /// whole strip is Newtonian (τ_N → 0 below τ_tr): the slope is the Newtonian
    /// integral over [0, π/2] per unit speed. h ≤ 0 (limited stress only) has slope 0.
    pub fn lamina_traction_and_slope(
        &self,
        contact: &HertzStrip,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
    ) -> (LaminaTraction, f64) {
        self.prepared()
            .lamina_traction_and_slope(contact, sliding_velocity_m_s, film_thickness_m)
    }

    /// ∫_a^b τ_N(p₀ cos φ)·cos φ dφ on a Newtonian piece by composite 8-point
    /// Gauss–Legendre. The panel count follows the integrand e^{κ cos φ}·cos φ (κ = α·p₀):
    /// near φ = 0 it is a Gaussian of width 1/√κ, further out its exponent falls by
    /// κ·(cos a − cos b) over the piece, so the count is
    /// ⌈max((b−a)/(π/2), √κ·(b−a)/2.2, κ·(cos a − cos b)/8)⌉, at most 64. Against a
    /// 128-panel rule over κ = 0.1…120 and pieces inside [0, π/2] the relative error stays
    /// below 1e-9 (tested against the series below): the quadrature budget. It sits five
    /// orders below the slicing error of the heat at the default Γ = 81 (1.6e-4,
    /// `rollbench bench`),
    /// so a tighter rule would buy no accuracy, only time (a full-contact lamina at
    /// α·p₀ = 16 takes 3 panels; 4 would reach 5e-13).
    /// `start` is (a, cos a, sin a). The nodes' cosines come from the angle-addition formula:
    /// the node offsets' sines and cosines (shared by the panels) from a short Taylor
    /// series, the panel centres by rotation from a; no libm trigonometry at all. The exponential is taken relative to its largest value on the piece (at φ = a),
    /// so no node overflows whatever κ is; that factor returns as τ_N(p₀ cos a).
    fn newtonian_piece(
        &self,
        p0: f64,
        v: f64,
        h: f64,
        start: (f64, f64, f64),
        end: (f64, f64),
    ) -> f64 {
        let TractionModel::Ehd {
            viscosity_pa_s: eta,
            pressure_viscosity_pa_inv: alpha,
            ..
        } = *self
        else {
            return 0.0;
        };
        if h.is_nan() || h <= 0.0 {
            return 0.0;
        }
        let ((a, ca, sa), (b, cb)) = (start, end);
        let kappa = alpha * p0;
        let peak = eta * v.abs() / h * (kappa * ca).exp();
        let len = b - a;
        let panels = (len / std::f64::consts::FRAC_PI_2)
            .max(kappa.sqrt() * len / 2.2)
            .max(kappa * (ca - cb) / 8.0)
            .ceil()
            .clamp(1.0, 64.0) as usize;
        // half ≤ π/4: every angle below is small enough for the short Taylor series.
        let half = 0.5 * len / panels as f64;
        let offsets: [(f64, f64); 4] = std::array::from_fn(|i| small_sin_cos(half * GL8_X[i]));
        let (sh, ch) = small_sin_cos(half);
        let (sr, cr) = (2.0 * sh * ch, 1.0 - 2.0 * sh * sh);
        let mut sum = 0.0;
        // Panel centres a + (2k+1)·half by rotating from a through half, then 2·half.
        let (mut sm, mut cm) = (sa * ch + ca * sh, ca * ch - sa * sh);
        for _ in 0..panels {
            for (&(so, co), w) in offsets.iter().zip(GL8_W.iter()) {
                // cos(mid ∓ off) = cos mid·cos off ± sin mid·sin off
                let c1 = (cm * co + sm * so).max(0.0);
                let c2 = (cm * co - sm * so).max(0.0);
                sum += w * (exp_fast(kappa * (c1 - ca)) * c1 + exp_fast(kappa * (c2 - ca)) * c2);
            }
            (sm, cm) = (sm * cr + cm * sr, cm * cr - sm * sr);
        }
        peak * half * sum
    }
}

#[cfg(test)]
thread_local! {
    /// Lamina traction integrations ([`PreparedTraction::lamina_traction_parts`]) on this
    /// thread: the cost counts the double-row roller's `losses_stage_cost_print` reports.
    pub(crate) static TRACTION_CALLS: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// A traction law with what does not depend on the contact computed once (issue 31: four
/// logarithms per lamina contact were a tenth of the friction stage): ln μ, ln τ_tr,
/// ln(τ_tr/μ) and −ln α, the constants of the kink search ([`PreparedTraction::kinks`]).
/// The same numbers as computing them per contact, so the same answer bit for bit (every
/// system's traction goes through it: the double-row roller's cage balance reacts to
/// round-off, so nothing here may change a bit); the spherical roller's friction stage
/// prepares it once per solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreparedTraction {
    model: TractionModel,
    /// ln μ (EHD), NaN for the constant law (unused there).
    ln_mu: f64,
    /// ln τ_tr.
    ln_tr: f64,
    /// ln(τ_tr/μ): the limit's kink in s = ln p (−∞ without a transition stress).
    s_lo: f64,
    /// −ln α: where the kink function g(s) has its minimum.
    s_min: f64,
}

impl PreparedTraction {
    /// [`TractionModel::lamina_traction`] of this law.
    pub fn lamina_traction(
        &self,
        contact: &HertzStrip,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
    ) -> LaminaTraction {
        self.lamina_traction_parts(contact, sliding_velocity_m_s, film_thickness_m)
            .0
    }

    /// [`TractionModel::lamina_traction_and_slope`] of this law (the same arithmetic: the
    /// model's method prepares the law and calls this).
    pub fn lamina_traction_and_slope(
        &self,
        contact: &HertzStrip,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
    ) -> (LaminaTraction, f64) {
        let v = sliding_velocity_m_s;
        let p0 = contact.peak_pressure_pa();
        if v == 0.0 && p0 > 0.0 && film_thickness_m.is_finite() {
            let i = match self.model {
                TractionModel::Ehd { .. } => self.model.newtonian_piece(
                    p0,
                    1.0,
                    film_thickness_m,
                    (0.0, 1.0, 0.0),
                    (std::f64::consts::FRAC_PI_2, 0.0),
                ),
                TractionModel::Constant { .. } => 0.0,
            };
            let slope = 2.0 * contact.width_m * contact.half_width_m * i;
            return (LaminaTraction::default(), slope);
        }
        let (t, newtonian) = self.lamina_traction_parts(contact, v, film_thickness_m);
        let slope = if v.is_finite() && v != 0.0 {
            2.0 * contact.width_m * contact.half_width_m * newtonian / v.abs()
        } else {
            0.0
        };
        (t, slope)
    }

    /// [`PreparedTraction::lamina_traction_and_slope`] with the kink search of this contact
    /// started from `hint`, the roots a previous call on the same strip found (and its
    /// ln p₀), and the hint updated: for a caller that integrates one strip at many nearby
    /// sliding speeds (the double-row roller's spin and cage balances: ~60 calls per
    /// lamina) the τ_N = μp crossing's Newton then takes one or two steps instead of ~5,
    /// and the peak's logarithm is taken once. The roots are the same to the search's
    /// round-off (it stops on a step below 1e-9, after which the quadratic convergence has
    /// put the root at round-off), so the force agrees with the unhinted call to round-off,
    /// not bit for bit (tested). A hint from another strip is detected by its p₀ and
    /// ignored.
    pub fn lamina_traction_and_slope_hinted(
        &self,
        contact: &HertzStrip,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
        hint: &std::cell::Cell<KinkHint>,
    ) -> (LaminaTraction, f64) {
        let v = sliding_velocity_m_s;
        let p0 = contact.peak_pressure_pa();
        if v == 0.0 && p0 > 0.0 && film_thickness_m.is_finite() {
            return self.lamina_traction_and_slope(contact, v, film_thickness_m);
        }
        let (t, newtonian) = self.parts(contact, v, film_thickness_m, Some(hint));
        let slope = if v.is_finite() && v != 0.0 {
            2.0 * contact.width_m * contact.half_width_m * newtonian / v.abs()
        } else {
            0.0
        };
        (t, slope)
    }

    /// The force and heat, and the Newtonian pieces' share of the φ-integral (Pa).
    fn lamina_traction_parts(
        &self,
        contact: &HertzStrip,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
    ) -> (LaminaTraction, f64) {
        self.parts(contact, sliding_velocity_m_s, film_thickness_m, None)
    }

    /// [`PreparedTraction::lamina_traction_parts`], the kink search hinted or not.
    #[inline(always)]
    fn parts(
        &self,
        contact: &HertzStrip,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
        hint: Option<&std::cell::Cell<KinkHint>>,
    ) -> (LaminaTraction, f64) {
        #[cfg(test)]
        TRACTION_CALLS.with(|c| c.set(c.get() + 1));
        let p0 = contact.peak_pressure_pa();
        let v = sliding_velocity_m_s;
        if p0 <= 0.0 || !v.is_finite() || v == 0.0 {
            return (LaminaTraction::default(), 0.0);
        }
        let h = if film_thickness_m.is_finite() {
            film_thickness_m
        } else {
            0.0
        };
        // Pieces in p, from p₀ down to 0, split at the law's kinks, each with its branch
        // (any interior pressure identifies it: the branch is constant between kinks).
        // Adjacent pieces on the same branch are merged: a kink of one branch's formula inside
        // another branch's range (the limit's kink τ_tr/μ where the film is Newtonian, say)
        // is no break of the law, and splitting there only cost a quadrature panel and an
        // acos (on the aerospace deck 3.8 Newtonian pieces per contact before, ~1 after).
        let mut kinks = self.kinks(v, h, p0, hint);
        let mut bounds = [0.0f64; 6];
        let mut branch = [Regime::Newtonian; 5];
        bounds[0] = p0;
        let mut n = 0;
        let interior = kinks
            .sorted_descending()
            .iter()
            .copied()
            .filter(|&pk| pk > 0.0 && pk < p0);
        for pk in interior.chain(std::iter::once(0.0)) {
            let hi = bounds[n];
            if pk >= hi {
                continue; // a repeated kink
            }
            let r = self.model.regime(0.5 * (hi + pk), v, h);
            if n > 0 && branch[n - 1] == r {
                bounds[n] = pk;
            } else {
                branch[n] = r;
                n += 1;
                bounds[n] = pk;
            }
        }
        // The pieces in φ (p = p₀ cos φ): (φ, cos φ = p/p₀ exactly, sin φ = √(1 − cos²)), so
        // one acos per real break and no trigonometric call per piece.
        let at = |i: usize| {
            if i == 0 {
                (0.0, 1.0, 0.0)
            } else if i == n {
                (std::f64::consts::FRAC_PI_2, 0.0, 1.0)
            } else {
                let c = bounds[i] / p0;
                (c.acos(), c, (1.0 - c * c).max(0.0).sqrt())
            }
        };
        let mut integral = 0.0;
        let mut newtonian = 0.0;
        let mut start = at(0);
        for (i, r) in branch[..n].iter().enumerate() {
            let end = at(i + 1);
            let ((a, ca, sa), (b, cb, sb)) = (start, end);
            integral += match *r {
                Regime::Newtonian => {
                    let piece = self.model.newtonian_piece(p0, v, h, (a, ca, sa), (b, cb));
                    newtonian += piece;
                    piece
                }
                Regime::Transition(tau) => tau * (sb - sa),
                Regime::Coulomb(mu) => {
                    // ∫cos²φ dφ = φ/2 + sin φ·cos φ/2
                    mu * p0 * 0.5 * ((b - a) + (sb * cb - sa * ca))
                }
            };
            start = end;
        }
        let force = 2.0 * contact.width_m * contact.half_width_m * integral * v.signum();
        (
            LaminaTraction {
                force_n: force,
                heat_w: (force * v).abs(),
            },
            newtonian,
        )
    }

    /// Pressures (Pa) where the law τ(p) = min(τ_N, max(τ_tr, μp)) can change branch at
    /// sliding speed v and film h: p = τ_tr/μ (kink of the limit), the crossing
    /// τ_N = τ_tr, p = ln(τ_tr/A)/α with A = η₀|v|/h, and the crossings τ_N = μp, the roots
    /// of g(p) = ln A + αp − ln(μp), which is convex with its minimum at p = 1/α (zero or
    /// two roots); only those below `p_max` (the peak pressure) are searched. A superfluous break only splits a smooth
    /// piece; NaN and infinite values are dropped by the caller's range test.
    fn kinks(&self, v: f64, h: f64, p_max: f64, hint: Option<&std::cell::Cell<KinkHint>>) -> Kinks {
        let TractionModel::Ehd {
            viscosity_pa_s: eta,
            pressure_viscosity_pa_inv: alpha,
            transition_shear_stress_pa: tr,
            limiting_traction_coefficient: mu,
        } = self.model
        else {
            return Kinks::default();
        };
        let mut out = Kinks::default();
        if mu > 0.0 {
            out.push(tr / mu);
        }
        if h <= 0.0 || eta.is_nan() || eta <= 0.0 || alpha.is_nan() || alpha <= 0.0 {
            // τ_N is infinite (h ≤ 0), zero, or independent of p: the limit's kink only.
            if eta > 0.0 && alpha == 0.0 && mu > 0.0 {
                // τ_N constant: it meets μp at p = τ_N/μ.
                out.push(eta * v.abs() / h / mu);
            }
            return out;
        }
        let ln_a = (eta * v.abs() / h).ln();
        if tr > 0.0 {
            out.push((self.ln_tr - ln_a) / alpha);
        }
        // Both root searches below look only above the limit's kink (s > s_lo): a strip whose
        // peak is at or below τ_tr/μ has none to find, and skips the logarithm of its peak.
        if mu > 0.0 && !(tr > 0.0 && p_max <= tr / mu) {
            // In s = ln p, g(s) = ln A − ln μ + α·eˢ − s is convex with its minimum at
            // s = −ln α. Its roots are branch changes of the law only above the limit's kink
            // p = τ_tr/μ (below it the limit is τ_tr, and where τ_N meets μp does not
            // matter), so only roots in (ln(τ_tr/μ), ln p_max) are searched: on the aerospace
            // deck that skips most searches. Left root (falling side): Newton from
            // max(ln(A/μ), ln(τ_tr/μ)), where g > 0 (at ln(A/μ), the root without the α term,
            // g = α·p), climbs monotonically to it. Right root: from ln p_max on the rising
            // side (g > 0 there), monotonically down to it. A search runs only when g changes
            // sign on its side. Three-digit accuracy would do (a misplaced kink costs only
            // second order); the step test stops at 1e-9, after which the quadratic
            // convergence has already put the root at round-off.
            let c = ln_a - self.ln_mu;
            let g = |s: f64| c + alpha * exp_fast(s) - s;
            let (s_min, s_lo) = (self.s_min, self.s_lo);
            // The hint's roots and ln p₀ when it is this strip's (same p₀).
            let mut known = hint.map(std::cell::Cell::get).filter(|k| k.p_max == p_max);
            let s_max = match known {
                Some(k) => k.s_max,
                None => p_max.ln(),
            };
            let newton = |mut s: f64| {
                for _ in 0..100 {
                    let e = alpha * exp_fast(s);
                    let next = s - (c + e - s) / (e - 1.0);
                    if !next.is_finite() {
                        return None;
                    }
                    if (next - s).abs() <= 1e-9 * s.abs().max(1.0) {
                        return Some((exp_fast(next), next));
                    }
                    s = next;
                }
                None
            };
            // From the hint's root when it lies inside the root's interval (one or two
            // steps: the root moved a little with v), else from the cold start above; a
            // hinted search that fails falls back to the cold one.
            let hinted = |start: f64, cold: f64, inside: bool| {
                if inside && start.is_finite() {
                    newton(start).or_else(|| newton(cold))
                } else {
                    newton(cold)
                }
            };
            let mut found = [f64::NAN; 2];
            let s_top = s_min.min(s_max);
            if s_lo < s_top && g(s_top) < 0.0 && (s_lo.is_infinite() || g(s_lo) > 0.0) {
                let start = known.map_or(f64::NAN, |k| k.s_left);
                if let Some((p, s)) =
                    hinted(start, c.max(s_lo).min(s_top), start > s_lo && start < s_top)
                {
                    out.push(p);
                    found[0] = s;
                }
            }
            let s_right = s_min.max(s_lo);
            if s_max > s_right && g(s_max) > 0.0 && g(s_right) < 0.0 {
                let start = known.map_or(f64::NAN, |k| k.s_right);
                if let Some((p, s)) = hinted(start, s_max, start > s_right && start < s_max) {
                    out.push(p);
                    found[1] = s;
                }
            }
            if let Some(cell) = hint {
                let k = known.get_or_insert(KinkHint {
                    p_max,
                    s_max,
                    s_left: f64::NAN,
                    s_right: f64::NAN,
                });
                // Keep a root the search did not need this time (the next call may).
                if found[0].is_finite() {
                    k.s_left = found[0];
                }
                if found[1].is_finite() {
                    k.s_right = found[1];
                }
                cell.set(*k);
            }
        }
        out
    }
}

/// e^x for the quadrature nodes: measured 3.6 ns against 5.6 ns for libm's exp, within
/// 4.5e-16 relative over [−708, 709] (tested against libm), and inlined, so the two node
/// exponentials of a Gauss–Legendre pair overlap (the Newtonian pieces are the traction's
/// cost: 24 exponentials per fully loaded lamina at α·p₀ = 16).
///
/// x = k·ln2/32 + r with |r| ≤ ln2/64 (k by the round-to-nearest shift trick, r with
/// ln2/32 split in a 32-bit head, exact in k·head, and a tail); e^x = 2^(k div 32)·
/// 2^((k mod 32)/32)·e^r, the middle factor from a table and e^r from its Taylor polynomial
/// to r⁶ (first omitted term r⁷/7! < 2e-18). Outside [−708, 709] (underflow, overflow,
/// NaN) libm's exp.
#[inline(always)]
fn exp_fast(x: f64) -> f64 {
    if !(-708.0..=709.0).contains(&x) {
        return x.exp();
    }
    const SHIFT: f64 = 6_755_399_441_055_744.0; // 1.5·2^52: adding it rounds to an integer
    let kf = (x * INV_LN2_32 + SHIFT) - SHIFT;
    let k = kf as i64;
    let r = (x - kf * LN2_32_HI) - kf * LN2_32_LO;
    let r2 = r * r;
    let p = (1.0 + r)
        + r2 * ((0.5 + r * (1.0 / 6.0))
            + r2 * ((1.0 / 24.0 + r * (1.0 / 120.0)) + r2 * (1.0 / 720.0)));
    // k div 32 ≥ −1022 for x ≥ −708: 2^(k div 32) is a normal number.
    let scale = f64::from_bits((((k >> 5) + 1023) as u64) << 52);
    EXP2_TABLE[(k & 31) as usize] * p * scale
}

// Tables of [`exp_fast`], from 50-digit decimal arithmetic (checked in `exp_fast_tables`):
// 2^(i/32), and ln2/32 as a 32-bit head plus its tail, and 32/ln2.
const EXP2_TABLE: [f64; 32] = [
    1.0,
    1.0218971486541166,
    1.0442737824274138,
    1.0671404006768237,
    1.0905077326652577,
    1.1143867425958924,
    1.1387886347566916,
    1.1637248587775775,
    1.189207115002721,
    1.215247359980469,
    1.241857812073484,
    1.2690509571917332,
    1.2968395546510096,
    1.3252366431597413,
    1.3542555469368927,
    1.383909881963832,
    std::f64::consts::SQRT_2,
    1.4451808069770467,
    1.4768261459394993,
    1.5091644275934228,
    1.5422108254079407,
    1.5759808451078865,
    1.6104903319492543,
    1.645755478153965,
    1.681792830507429,
    1.718619298122478,
    1.7562521603732995,
    1.7947090750031072,
    1.8340080864093424,
    1.8741676341103,
    1.9152065613971474,
    1.9571441241754002,
];
const LN2_32_HI: f64 = 0.02166084938653512;
const LN2_32_LO: f64 = 5.9631716539705866e-12;
const INV_LN2_32: f64 = 46.16624130844683;

/// sin t and cos t for |t| ≤ π/4 by their Taylor series to t¹⁵ and t¹⁶ (Estrin's scheme:
/// short independent chains instead of one 8-deep Horner chain): the first omitted terms are
/// below 5e-17 there, under the rounding of the result. A libm call costs about 20 ns; this
/// costs a few multiply-adds. Larger |t| falls back to libm.
#[inline]
fn small_sin_cos(t: f64) -> (f64, f64) {
    if t.abs() > std::f64::consts::FRAC_PI_4 {
        return t.sin_cos();
    }
    // Polynomials in t² with the coefficients (−1)^k/(2k+1)! and (−1)^k/(2k)! as constants
    // (a division per term would cost more than the rest together).
    const S: [f64; 7] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
    ];
    const C: [f64; 8] = [
        -1.0 / 2.0,
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
    ];
    let t2 = t * t;
    let t4 = t2 * t2;
    let t8 = t4 * t4;
    // Σ_{k<7} S[k]·t2^(k+1) and Σ_{k<8} C[k]·t2^(k+1), in pairs joined by t⁴ and t⁸.
    let s_low = (S[0] + t2 * S[1]) + t4 * (S[2] + t2 * S[3]);
    let s_high = (S[4] + t2 * S[5]) + t4 * S[6];
    let c_low = (C[0] + t2 * C[1]) + t4 * (C[2] + t2 * C[3]);
    let c_high = (C[4] + t2 * C[5]) + t4 * (C[6] + t2 * C[7]);
    let s = t + t * (t2 * (s_low + t8 * s_high));
    let c = 1.0 + t2 * (c_low + t8 * c_high);
    (s, c)
}

/// What [`PreparedTraction::lamina_traction_and_slope_hinted`] remembers of a strip between
/// calls: its peak pressure and ln p₀, and the τ_N = μp crossings its kink search found,
/// as ln p (NaN: none yet). `KinkHint::default()` is empty.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KinkHint {
    p_max: f64,
    s_max: f64,
    s_left: f64,
    s_right: f64,
}

impl Default for KinkHint {
    fn default() -> Self {
        KinkHint {
            p_max: f64::NAN,
            s_max: f64::NAN,
            s_left: f64::NAN,
            s_right: f64::NAN,
        }
    }
}

/// Up to four branch pressures of the traction law (no allocation on the hot path).
#[derive(Default)]
struct Kinks {
    p: [f64; 4],
    n: usize,
}

impl Kinks {
    fn push(&mut self, p: f64) {
        if self.n < self.p.len() {
            self.p[self.n] = p;
            self.n += 1;
        }
    }

    /// The pressures in descending `total_cmp` order: an insertion sort of at most four
    /// (the library sort's set-up cost 9 % of the losses stage in perf; same order, so the
    /// same pieces bit for bit).
    fn sorted_descending(&mut self) -> &[f64] {
        let k = &mut self.p[..self.n];
        for i in 1..k.len() {
            let mut j = i;
            while j > 0 && k[j - 1].total_cmp(&k[j]).is_lt() {
                k.swap(j - 1, j);
                j -= 1;
            }
        }
        k
    }
}

/// Branch of the traction law on a piece of the contact.
#[derive(Clone, Copy, PartialEq)]
enum Regime {
    /// τ = τ_N (integrated by quadrature).
    Newtonian,
    /// τ = τ_tr, Pa.
    Transition(f64),
    /// τ = μ·p with this μ.
    Coulomb(f64),
}

#[cfg(test)]
pub(crate) mod reference;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::spherical_roller::Bearing;

    use crate::units::PSI_PA;

    fn ehd(eta: f64, alpha: f64, tau_tr: f64, mu: f64) -> TractionModel {
        TractionModel::Ehd {
            viscosity_pa_s: eta,
            pressure_viscosity_pa_inv: alpha,
            transition_shear_stress_pa: tau_tr,
            limiting_traction_coefficient: mu,
        }
    }

    /// Newtonian branch by hand: η₀ = 0.0045 Pa·s, α = 1.1e-8 /Pa, p = 100 MPa,
    /// v = 0.01 m/s, h = 0.5 µm → τ = 0.0045·e^{1.1}·0.01/0.5e-6 = 270.4 kPa < τ_tr.
    /// Tolerance 1e-12: same formula, independent arithmetic. Sign follows v.
    #[test]
    fn newtonian_branch() {
        let want = 0.0045 * 1.1f64.exp() * 0.01 / 0.5e-6;
        let tau = atz_shear_stress(100e6, 0.01, 0.5e-6, 0.0045, 1.1e-8, 1000.0 * PSI_PA, 0.06);
        assert!((tau - want).abs() < 1e-12 * want);
        let neg = atz_shear_stress(100e6, -0.01, 0.5e-6, 0.0045, 1.1e-8, 1000.0 * PSI_PA, 0.06);
        assert_eq!(neg, -tau);
    }

    /// Limited branches: at p = 1.5 GPa and v = 5 m/s the Newtonian stress is enormous,
    /// so τ = μ·p = 90 MPa (μp > τ_tr); at p = 50 MPa (μp = 3 MPa < τ_tr = 6.89 MPa)
    /// with v/h = 50/0.03e-6 (τ_N = 13 MPa), τ = τ_tr. Exact (min/max of computed values).
    #[test]
    fn limited_branches() {
        let tr = 1000.0 * PSI_PA;
        let tau = atz_shear_stress(1.5e9, 5.0, 0.3e-6, 0.0045, 1.1e-8, tr, 0.06);
        assert!((tau - 0.06 * 1.5e9).abs() < 1e-6);
        let tau = atz_shear_stress(50e6, 50.0, 0.03e-6, 0.0045, 1.1e-8, tr, 0.06);
        assert_eq!(tau, tr);
    }

    /// Continuity and monotonicity in |v| across the switch: scan v through the point
    /// where τ_N = τ_tr (p = 50 MPa) and where τ_N = μ·p (p = 1 GPa); consecutive values
    /// differ by at most the Newtonian slope × Δv (continuity), never decrease, and the
    /// value at the switch equals the limit to 1e-9 relative.
    #[test]
    fn switch_is_continuous_and_monotone() {
        let (eta, alpha, tr, mu, h): (f64, f64, f64, f64, f64) =
            (0.0045, 1.1e-8, 1000.0 * PSI_PA, 0.06, 0.4e-6);
        for p in [50e6, 1e9] {
            let k = eta * (alpha * p).exp() / h; // dτ_N/dv
            let limit = f64::max(tr, mu * p);
            let v_switch = limit / k;
            let n = 2000;
            let dv = 2.0 * v_switch / n as f64;
            let mut prev = 0.0;
            for i in 0..=n {
                let v = i as f64 * dv;
                let tau = atz_shear_stress(p, v, h, eta, alpha, tr, mu);
                assert!(tau >= prev, "monotone");
                assert!(tau - prev <= k * dv * (1.0 + 1e-9), "continuous");
                prev = tau;
            }
            let at = atz_shear_stress(p, v_switch, h, eta, alpha, tr, mu);
            assert!((at - limit).abs() < 1e-9 * limit);
        }
    }

    /// Guards: h = 0 gives the limit (no NaN), v = 0 gives 0, non-finite inputs give 0 or
    /// the limit. Exact.
    #[test]
    fn guards_never_nan() {
        let tr = 1000.0 * PSI_PA;
        assert_eq!(
            atz_shear_stress(1e9, 1.0, 0.0, 0.0045, 1.1e-8, tr, 0.06),
            6e7
        );
        assert_eq!(
            atz_shear_stress(1e9, 0.0, 0.0, 0.0045, 1.1e-8, tr, 0.06),
            0.0
        );
        assert_eq!(
            atz_shear_stress(1e12, 1.0, 1e-6, 0.0045, 1.0, tr, 0.06),
            6e10
        );
        assert_eq!(
            atz_shear_stress(f64::NAN, 1.0, 1e-6, 0.0045, 1.1e-8, tr, 0.06),
            0.0045 * 1.0 / 1e-6
        );
        let m = ehd(0.0045, 1.1e-8, tr, 0.06);
        let c = HertzStrip {
            load_n: 500.0,
            half_width_m: 50e-6,
            width_m: 0.5e-3,
        };
        for (v, h) in [(0.0, 0.0), (1.0, 0.0), (f64::NAN, 1e-6), (1.0, f64::NAN)] {
            let t = m.lamina_traction(&c, v, h);
            assert!(t.force_n.is_finite() && t.heat_w.is_finite());
        }
        let unloaded = HertzStrip { load_n: 0.0, ..c };
        assert_eq!(
            m.lamina_traction(&unloaded, 1.0, 0.0),
            LaminaTraction::default()
        );
        // h = 0 with sliding: every point is limited: F = ∫ max(τ_tr, μp) > μQ.
        let t = m.lamina_traction(&c, 1.0, 0.0);
        assert!(t.force_n >= 0.06 * 500.0);
    }

    /// Lost lubrication: F = μ·Q exactly and heat = μ·Q·|v|. The semi-ellipse integrates
    /// to round-off with the φ-substitution; tolerance 1e-13 relative.
    #[test]
    fn constant_mode_gives_mu_q() {
        let lub = Bearing::example_aerospace().lubricant;
        let m = TractionModel::lost_lubrication(&lub);
        let c = HertzStrip {
            load_n: 873.2,
            half_width_m: 61e-6,
            width_m: 0.55e-3,
        };
        for v in [2.5, -0.7] {
            let t = m.lamina_traction(&c, v, 0.3e-6);
            let want = 0.1 * 873.2 * v.signum();
            assert!(
                (t.force_n - want).abs() < 1e-13 * want.abs(),
                "{}",
                t.force_n
            );
            assert!((t.heat_w - 0.1 * 873.2 * v.abs()).abs() < 1e-13 * 87.32 * v.abs());
        }
    }

    /// Independent reference for ∫_{−b}^{b} g(p(x)) dx: composite Simpson in x on a
    /// graded mesh x = b·(1 − (1 − s)²) (clusters at the edge where √ is singular).
    fn reference_integral<G: Fn(f64) -> f64>(g: G, p0: f64, b: f64) -> f64 {
        let n = 200_000; // even
        let f = |s: f64| {
            let x = b * (1.0 - (1.0 - s) * (1.0 - s));
            let dxds = 2.0 * b * (1.0 - s);
            let p = p0 * (1.0 - (x / b) * (x / b)).max(0.0).sqrt();
            g(p) * dxds
        };
        let hs = 1.0 / n as f64;
        let mut sum = f(0.0) + f(1.0);
        for i in 1..n {
            sum += if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * hs);
        }
        2.0 * sum * hs / 3.0
    }

    /// Newtonian low-pressure lamina (p₀ = 200 MPa, α·p₀ = 2.2, τ_N ≤ 1.02 kPa ≪ τ_tr):
    /// F = w·∫η₀·e^{αp(x)}·v/h dx, evaluated independently by graded Simpson in x.
    /// Tolerance 1e-8 relative: the reference's own error (Simpson with 2·10⁵ intervals).
    #[test]
    fn newtonian_lamina_against_closed_form() {
        let (eta, alpha, v, h) = (0.0045, 1.1e-8, 0.02, 0.8e-6);
        let m = ehd(eta, alpha, 1000.0 * PSI_PA, 0.06);
        let (b, w) = (40e-6, 0.5e-3);
        let p0 = 200e6;
        let q = p0 * std::f64::consts::PI * b * w / 2.0;
        let c = HertzStrip {
            load_n: q,
            half_width_m: b,
            width_m: w,
        };
        assert!((c.peak_pressure_pa() - p0).abs() < 1e-6);
        let got = m.lamina_traction(&c, v, h).force_n;
        let want = w * reference_integral(|p| eta * (alpha * p).exp() * v / h, p0, b);
        assert!((got - want).abs() < 1e-8 * want, "{got} vs {want}");
        // α = 0: F = η₀·v·2b·w/h exactly (constant stress over the strip), tolerance 1e-14.
        let m0 = ehd(eta, 0.0, 1000.0 * PSI_PA, 0.06);
        let f0 = m0.lamina_traction(&c, v, h).force_n;
        let want0 = eta * v * 2.0 * b * w / h;
        assert!((f0 - want0).abs() < 1e-14 * want0);
    }

    /// The Newtonian integral in closed form, as a series: with x = b·sin φ,
    /// ∫_{−b}^{b} e^{a√(1−x²/b²)} dx = b·Σ_k a^k/k!·W_{k+1}, W_n = ∫_{−π/2}^{π/2} cosⁿφ dφ
    /// (Wallis: W₀ = π, W₁ = 2, W_n = (n−1)/n·W_{n−2}); all terms positive, summed until
    /// they stop contributing. Checks the quadrature for a = α·p₀ up to 80 (the
    /// documented range); τ_tr and μ set huge so the whole strip is Newtonian.
    /// Tolerance 1e-9 relative: the quadrature budget of [`TractionModel::newtonian_piece`]
    /// (the series itself is exact to round-off).
    #[test]
    fn newtonian_lamina_against_series() {
        let (eta, v, h, b, w) = (0.0045, 0.01, 1e-6, 50e-6, 0.5e-3);
        let m = ehd(eta, 1e-8, 1e30, 1e30);
        for a in [0.5f64, 2.2, 10.0, 20.0, 40.0, 80.0] {
            let p0 = a / 1e-8;
            let c = HertzStrip {
                load_n: p0 * std::f64::consts::PI * b * w / 2.0,
                half_width_m: b,
                width_m: w,
            };
            // Σ_k a^k/k!·W_{k+1}
            let (mut w_prev, mut w_cur) = (std::f64::consts::PI, 2.0); // W_0, W_1
            let mut term_coef = 1.0; // a^k/k!
            let mut sum = w_cur; // k = 0
            for k in 1..400 {
                let n = (k + 1) as f64; // W_{k+1} = k/(k+1)·W_{k−1}
                let w_next = (n - 1.0) / n * w_prev;
                w_prev = w_cur;
                w_cur = w_next;
                term_coef *= a / k as f64;
                sum += term_coef * w_cur;
            }
            let want = w * eta * v / h * b * sum;
            let got = m.lamina_traction(&c, v, h).force_n;
            assert!((got - want).abs() < 1e-9 * want, "a = {a}: {got} vs {want}");
        }
    }

    /// Mixed laminae against the independent reference: (v, h) = (0.5 m/s, 0.3 µm) and
    /// (0.02, 0.3 µm) have a Newtonian fringe and a μ·p core; (3, 0.5 µm) has a τ_tr
    /// plateau at the fringe (p < τ_tr/μ) and a μ·p core. Tolerance 1e-7 relative: the reference's
    /// error near the kinks (graded Simpson does not resolve them exactly); the
    /// production quadrature splits at the kinks.
    #[test]
    fn mixed_lamina_against_reference() {
        let (eta, alpha, tr, mu) = (0.0045, 1.1e-8, 1000.0 * PSI_PA, 0.06);
        let m = ehd(eta, alpha, tr, mu);
        let (b, w, p0) = (60e-6, 0.55e-3, 1.2e9);
        let c = HertzStrip {
            load_n: p0 * std::f64::consts::PI * b * w / 2.0,
            half_width_m: b,
            width_m: w,
        };
        for (v, h) in [(0.5, 0.3e-6), (0.02, 0.3e-6), (3.0, 0.5e-6)] {
            let got = m.lamina_traction(&c, v, h);
            let want = w * reference_integral(|p| m.shear_stress(p, v, h), p0, b);
            assert!(
                (got.force_n - want).abs() < 1e-7 * want,
                "{} vs {want}",
                got.force_n
            );
            assert!((got.heat_w - want * v).abs() < 1e-7 * want * v);
        }
    }

    /// The short Taylor sine/cosine against libm over |t| ≤ π/4: 2 ulp (4.5e-16 absolute;
    /// both are accurate to within rounding, their difference is the two roundings plus the
    /// Horner evaluation's).
    #[test]
    fn exp_fast_matches_libm() {
        // libm's exp is correctly rounded in practice: 4.5e-16 (two ulp) over the whole
        // normal range, densely, and at the ends and out of range (libm itself).
        for i in 0..=400_000 {
            let x = -708.0 + 1417.0 * i as f64 / 400_000.0;
            let r = exp_fast(x) / x.exp() - 1.0;
            assert!(r.abs() <= 4.5e-16, "{x}: {r:e}");
        }
        for x in [-708.0, 709.0, -1e-300, 0.0, 1e-300, -745.0, 710.0, -1e4] {
            let (a, b) = (exp_fast(x), x.exp());
            assert!(a == b || (a / b - 1.0).abs() <= 4.5e-16, "{x}");
        }
        assert!(exp_fast(f64::NAN).is_nan());
    }

    #[test]
    fn exp_fast_tables() {
        for (i, &v) in EXP2_TABLE.iter().enumerate() {
            assert!(
                (v / 2f64.powf(i as f64 / 32.0) - 1.0).abs() <= 2.3e-16,
                "{i}"
            );
        }
        let ln2_32 = std::f64::consts::LN_2 / 32.0;
        assert!(((LN2_32_HI + LN2_32_LO) / ln2_32 - 1.0).abs() <= 1.2e-16);
        // The head has at most 32 significant bits, so k·head is exact for |k| < 2^21.
        assert_eq!(LN2_32_HI.to_bits() & ((1 << 21) - 1), 0);
        assert!((INV_LN2_32 * ln2_32 - 1.0).abs() <= 2.3e-16);
    }

    #[test]
    fn small_sin_cos_matches_libm() {
        for i in -1000..=1000 {
            let t = std::f64::consts::FRAC_PI_4 * i as f64 / 1000.0;
            let (s, c) = small_sin_cos(t);
            assert!((s - t.sin()).abs() <= 4.5e-16, "sin {t}");
            assert!((c - t.cos()).abs() <= 4.5e-16, "cos {t}");
        }
    }

    /// The closed-form branch points over a sweep of speeds, films and peak pressures (every
    /// branch order the law allows: all Newtonian, a τ_tr plateau, a μ·p core, h = 0)
    /// against the independent graded-Simpson reference. Tolerance 1e-7 relative, as above.
    #[test]
    fn kinks_found_over_a_sweep() {
        // τ_tr = 0 (no flat limit: every μp crossing is a branch change), the deck's 1000 psi
        // (limit kink τ_tr/μ = 115 MPa) and 10 000 psi (1.15 GPa, above most crossings):
        // the μp crossings are searched only above τ_tr/μ, which must lose no branch change.
        let (eta, alpha, mu) = (0.0045, 1.1e-8, 0.06);
        for tr in [0.0, 1000.0 * PSI_PA, 10_000.0 * PSI_PA] {
            kinks_sweep(ehd(eta, alpha, tr, mu));
        }
    }

    fn kinks_sweep(m: TractionModel) {
        let (b, w) = (60e-6, 0.55e-3);
        for p0 in [50e6, 150e6, 600e6, 1.2e9, 2.5e9] {
            let c = HertzStrip {
                load_n: p0 * std::f64::consts::PI * b * w / 2.0,
                half_width_m: b,
                width_m: w,
            };
            for v in [1e-5, 1e-3, 0.05, 1.0, 20.0] {
                for h in [0.0, 0.05e-6, 0.5e-6] {
                    let got = m.lamina_traction(&c, v, h).force_n;
                    let want = w * reference_integral(|p| m.shear_stress(p, v, h), p0, b);
                    assert!(
                        (got - want).abs() <= 1e-7 * want.abs(),
                        "p0 {p0} v {v} h {h}: {got} vs {want}"
                    );
                }
            }
        }
    }

    /// The lamina force is continuous in v across the regime switches (no jump larger
    /// than the local slope allows), and bounded by the fully limited value.
    #[test]
    fn lamina_force_continuous_in_v() {
        let m = ehd(0.0045, 1.1e-8, 1000.0 * PSI_PA, 0.06);
        let c = HertzStrip {
            load_n: 1.2e9 * std::f64::consts::PI * 60e-6 * 0.55e-3 / 2.0,
            half_width_m: 60e-6,
            width_m: 0.55e-3,
        };
        let limited = m.lamina_traction(&c, 1.0, 0.0).force_n;
        let mut prev = 0.0;
        let n = 400;
        for i in 1..=n {
            let v = 1e-4 * (1e4f64).powf(i as f64 / n as f64); // 1e-4 .. 1 m/s
            let f = m.lamina_traction(&c, v, 0.3e-6).force_n;
            assert!(f >= prev * (1.0 - 1e-12) && f <= limited * (1.0 + 1e-12));
            assert!(f - prev < 0.05 * limited, "jump at v = {v}");
            prev = f;
        }
    }

    /// Issue 31's hoisting changes no number: the prepared law against the lamina integral
    /// as it stood before ([`super::reference`], libm's exp at the piece's peak and every
    /// logarithm per contact), over peaks from 10 MPa to 3 GPa, sliding speeds from 1e-6 to
    /// 30 m/s of both signs and films from none to 2 µm, with and without a transition
    /// stress (every branch order of the law), and the constant law: bit for bit (the
    /// hoisted constants are the same numbers).
    #[test]
    fn prepared_law_matches_the_reference_over_a_sweep() {
        let (b, w) = (60e-6, 0.55e-3);
        let mut worst = 0.0f64;
        let mut compared = 0;
        for m in [
            ehd(0.0045, 1.1e-8, 0.0, 0.06),
            ehd(0.0045, 1.1e-8, 1000.0 * PSI_PA, 0.06),
            ehd(0.0045, 1.1e-8, 10_000.0 * PSI_PA, 0.06),
            ehd(0.05, 2.2e-8, 1000.0 * PSI_PA, 0.09),
            TractionModel::Constant { mu: 0.1 },
        ] {
            let law = m.prepared();
            for p0 in [10e6, 50e6, 115e6, 150e6, 600e6, 1.2e9, 2.5e9, 3e9] {
                let c = HertzStrip {
                    load_n: p0 * std::f64::consts::PI * b * w / 2.0,
                    half_width_m: b,
                    width_m: w,
                };
                for v in [-3.0, -1e-4, 1e-6, 1e-4, 1e-3, 0.05, 0.4, 1.0, 7.0, 30.0] {
                    for h in [0.0, 0.02e-6, 0.1e-6, 0.5e-6, 2e-6] {
                        let got = law.lamina_traction(&c, v, h);
                        let via_model = m.lamina_traction(&c, v, h);
                        let want = reference::lamina_traction(&m, &c, v, h);
                        assert_eq!(got, via_model, "p0 {p0} v {v} h {h}");
                        for (g, r) in [(got.force_n, want.force_n), (got.heat_w, want.heat_w)] {
                            let rel = (g - r).abs() / r.abs().max(f64::MIN_POSITIVE);
                            assert!(g == r, "{m:?} p0 {p0} v {v} h {h}: {g} vs {r}");
                            worst = worst.max(rel);
                        }
                        compared += 1;
                    }
                }
            }
        }
        assert_eq!(compared, 5 * 8 * 10 * 5);
        eprintln!("prepared law against the reference: worst relative difference {worst:.1e}");
    }

    /// The hinted kink search (srb12) gives the unhinted force and slope to 1e-13 relative
    /// (the roots agree to the search's round-off; a misplaced root would move a piece
    /// boundary and the force by far more: the law's pieces differ by O(1)) over the sweep
    /// above, each strip walked through its sliding speeds with one hint in both directions
    /// (the hint from the previous speed, as the spin solves use it) and a hint carried
    /// over from another strip (ignored: another p₀).
    #[test]
    fn hinted_kinks_match_the_unhinted_law() {
        let (b, w) = (60e-6, 0.55e-3);
        let mut worst = 0.0f64;
        let stranger = std::cell::Cell::new(KinkHint::default());
        for m in [
            ehd(0.0045, 1.1e-8, 0.0, 0.06),
            ehd(0.0045, 1.1e-8, 1000.0 * PSI_PA, 0.06),
            ehd(0.0045, 1.1e-8, 10_000.0 * PSI_PA, 0.06),
            ehd(0.05, 2.2e-8, 1000.0 * PSI_PA, 0.09),
        ] {
            let law = m.prepared();
            for p0 in [10e6, 50e6, 115e6, 150e6, 600e6, 1.2e9, 2.5e9, 3e9] {
                let c = HertzStrip {
                    load_n: p0 * std::f64::consts::PI * b * w / 2.0,
                    half_width_m: b,
                    width_m: w,
                };
                for h in [0.02e-6, 0.1e-6, 0.5e-6, 2e-6] {
                    let hint = std::cell::Cell::new(KinkHint::default());
                    let vs = [-3.0, -1e-4, 1e-6, 1e-4, 1e-3, 0.05, 0.4, 1.0, 7.0, 30.0];
                    for v in vs.iter().chain(vs.iter().rev()).copied() {
                        let (t0, s0) = law.lamina_traction_and_slope(&c, v, h);
                        for k in [&hint, &stranger] {
                            let (t1, s1) = law.lamina_traction_and_slope_hinted(&c, v, h, k);
                            for (g, r) in [(t1.force_n, t0.force_n), (s1, s0)] {
                                let rel = (g - r).abs() / r.abs().max(f64::MIN_POSITIVE);
                                assert!(
                                    rel <= 1e-13 || g == r,
                                    "{m:?} p0 {p0} v {v} h {h}: {g} vs {r}"
                                );
                                worst = worst.max(rel);
                            }
                        }
                    }
                }
            }
        }
        eprintln!("hinted kinks against the unhinted law: worst relative difference {worst:.1e}");
    }
}
