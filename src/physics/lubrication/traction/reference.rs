//! The lamina traction integral exactly as it stood before issue 31's hoisting (commit
//! c5f188b): the reference the fast path ([`super::PreparedTraction`]) is proven against
//! (test `stages::friction_matches_the_reference_on_every_spherical_deck` and this file's
//! sweep). Test-only; never called by the program.

use super::HertzStrip;
use super::{exp_fast, small_sin_cos, Kinks, LaminaTraction, Regime, TractionModel, GL8_W, GL8_X};

/// The old path's [`TractionModel::lamina_traction`].
pub(crate) fn lamina_traction(
    m: &TractionModel,
    contact: &HertzStrip,
    sliding_velocity_m_s: f64,
    film_thickness_m: f64,
) -> LaminaTraction {
    Reference(*m)
        .lamina_traction_parts(contact, sliding_velocity_m_s, film_thickness_m)
        .0
}

/// The model, so the old methods read as they did.
struct Reference(TractionModel);

impl std::ops::Deref for Reference {
    type Target = TractionModel;
    fn deref(&self) -> &TractionModel {
        &self.0
    }
}

impl Reference {
    /// The force and heat, and the Newtonian pieces' share of the φ-integral (Pa).
    fn lamina_traction_parts(
        &self,
        contact: &HertzStrip,
        sliding_velocity_m_s: f64,
        film_thickness_m: f64,
    ) -> (LaminaTraction, f64) {
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
        let mut kinks = self.kinks(v, h, p0);
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
            let r = self.regime(0.5 * (hi + pk), v, h);
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
                    let piece = self.newtonian_piece(p0, v, h, (a, ca, sa), (b, cb));
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
        } = self.0
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

    /// Pressures (Pa) where the law τ(p) = min(τ_N, max(τ_tr, μp)) can change branch at
    /// sliding speed v and film h: p = τ_tr/μ (kink of the limit), the crossing
    /// τ_N = τ_tr, p = ln(τ_tr/A)/α with A = η₀|v|/h, and the crossings τ_N = μp, the roots
    /// of g(p) = ln A + αp − ln(μp), which is convex with its minimum at p = 1/α (zero or
    /// two roots); only those below `p_max` (the peak pressure) are searched. A superfluous break only splits a smooth
    /// piece; NaN and infinite values are dropped by the caller's range test.
    fn kinks(&self, v: f64, h: f64, p_max: f64) -> Kinks {
        let TractionModel::Ehd {
            viscosity_pa_s: eta,
            pressure_viscosity_pa_inv: alpha,
            transition_shear_stress_pa: tr,
            limiting_traction_coefficient: mu,
        } = self.0
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
            out.push((tr.ln() - ln_a) / alpha);
        }
        if mu > 0.0 {
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
            let c = ln_a - mu.ln();
            let g = |s: f64| c + alpha * exp_fast(s) - s;
            let s_min = -alpha.ln();
            let s_max = p_max.ln();
            let s_lo = if tr > 0.0 {
                (tr / mu).ln()
            } else {
                f64::NEG_INFINITY
            };
            let newton = |mut s: f64| {
                for _ in 0..100 {
                    let e = alpha * exp_fast(s);
                    let next = s - (c + e - s) / (e - 1.0);
                    if !next.is_finite() {
                        return None;
                    }
                    if (next - s).abs() <= 1e-9 * s.abs().max(1.0) {
                        return Some(exp_fast(next));
                    }
                    s = next;
                }
                None
            };
            let s_top = s_min.min(s_max);
            if s_lo < s_top && g(s_top) < 0.0 && (s_lo.is_infinite() || g(s_lo) > 0.0) {
                if let Some(p) = newton(c.max(s_lo).min(s_top)) {
                    out.push(p);
                }
            }
            let s_right = s_min.max(s_lo);
            if s_max > s_right && g(s_max) > 0.0 && g(s_right) < 0.0 {
                if let Some(p) = newton(s_max) {
                    out.push(p);
                }
            }
        }
        out
    }
}
