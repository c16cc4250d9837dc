//! The film solve of eqs. (2)–(4) tabulated once per run for the hot loop.
//!
//! Above the load floor the film law is h = a·f·W^(−e) (f the squeeze factor, fixed
//! for a roller at one evaluation) and W = k·δ^n, so eq. (3) reads
//!
//!   δ − A·δ^(−q) = s0,   A = a·f·k^(−e),   q = n·e,   s0 = p/2 − C.
//!
//! With δ = L·u and L = A^(1/(1+q)) this is the one-parameter equation
//! u − u^(−q) = σ with σ = s0/L, whose root u(σ) is increasing and analytic in σ (its
//! nearest complex singularities lie about one unit of σ from the real axis). The table
//! holds g(σ) = u(σ)^n, so that W = k·L^n·g(σ): a Chebyshev series of degree 8 on
//! segments of 1/32 octave of z = σ − σ_lo + 1 (segment found from z's exponent and
//! top mantissa bits, as the lamina law's `ninth_root` finds its interval), fitted at
//! exact roots. Relative error < 1e-14 (tested against the Newton solve); outside the
//! table's range the caller falls back to [`super::film::ContactLaw::contact`]'s Newton.
//!
//! This replaces 3–5 safeguarded Newton steps, each a `powf` and a `ninth_root`, by one
//! series evaluation per roller per right-hand side. A second series per segment holds
//! u(σ) itself, so that the sampled outputs (load, film h = L·u − s0 and squeeze
//! velocity of every roller at every sample) come from the table too
//! ([`FastFilm::contact`]). In the right-hand side the rollers go through
//! [`FastFilm::sums`] in structure-of-arrays passes, the squeeze factor's powers by
//! their Taylor series in z = 1.32·w/U (issue 25, Speed).

use super::film::{
    Contact, ContactLaw, FilmCoefficients, Squeeze, LOAD_EXPONENT, LOAD_FLOOR_N, SQUEEZE_RATE,
};

/// Chebyshev coefficients per segment (degree 8).
const COEFFS: usize = 9;
/// Segments per octave of z.
const PER_OCTAVE: usize = 32;
/// Octaves at most (z < 2^40 covers any load a valid deck can give).
const MAX_OCTAVES: usize = 40;
/// Newton's cap for the exact roots at the nodes (bisection-safeguarded: ≤ 60 halvings
/// of the bracket reach rounding).
const MAX_NODE_ITERATIONS: usize = 200;

/// u(σ)^n in Chebyshev pieces (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct FilmTable {
    /// q = n·e.
    pub q: f64,
    /// n.
    pub n: f64,
    /// The table's lowest σ.
    sigma_lo: f64,
    /// Number of segments.
    segments: usize,
    /// Each segment's series in powers of τ ∈ [−1, 1] (its Chebyshev series c_0..c_8
    /// converted once, see [`chebyshev_to_monomial`]), evaluated by Estrin's scheme: a
    /// dependency chain of four multiplications instead of Clenshaw's eight
    /// multiply-adds, so the rollers' evaluations overlap.
    coeffs: Vec<[f64; COEFFS]>,
    /// The root u(σ) itself on the same segments (for the sampled outputs' film
    /// h = L·u − s0, see [`FastFilm::contact`]), fitted at the same exact roots.
    root_coeffs: Vec<[f64; COEFFS]>,
}

/// The coefficients m_j of Σ_k c_k T_k(τ) = Σ_j m_j τ^j (degree 8), by the recurrence
/// T_{k+1} = 2τ T_k − T_{k−1} on the monomial coefficients of each T_k (exact small
/// integers up to 2^7), summed over k from the highest degree down. On a segment of
/// 1/32 octave the c_k fall by about two decades per degree, so every m_j is the sum of
/// terms far below |m_0| and the conversion and the power form round like Clenshaw (the
/// 1e-14 test of the table holds both).
fn chebyshev_to_monomial(c: &[f64; COEFFS]) -> [f64; COEFFS] {
    let mut t_prev = [0.0; COEFFS];
    let mut t_cur = [0.0; COEFFS];
    t_prev[0] = 1.0; // T_0
    t_cur[1] = 1.0; // T_1
    let mut basis = [[0.0; COEFFS]; COEFFS];
    basis[0] = t_prev;
    basis[1] = t_cur;
    for b in basis.iter_mut().skip(2) {
        let mut next = [0.0; COEFFS];
        for j in 0..COEFFS {
            let shifted = if j > 0 { 2.0 * t_cur[j - 1] } else { 0.0 };
            next[j] = shifted - t_prev[j];
        }
        *b = next;
        t_prev = t_cur;
        t_cur = next;
    }
    std::array::from_fn(|j| {
        (0..COEFFS)
            .rev()
            .map(|k| c[k] * basis[k][j])
            .fold(0.0, |acc, v| acc + v)
    })
}

/// The root u > 0 of u − u^(−q) = σ (bisection-safeguarded Newton on a bracket that
/// holds it: σ ≥ 0 ⇒ u ∈ [max(σ, 1), σ + 1]; σ < 0 ⇒ u ∈ [(1 − σ)^(−1/q), min(1,
/// (−σ)^(−1/q))]), to rounding.
pub(crate) fn exact_root(sigma: f64, q: f64) -> f64 {
    let (mut lo, mut hi) = if sigma >= 0.0 {
        (sigma.max(1.0), sigma + 1.0)
    } else {
        (
            (1.0 - sigma).powf(-1.0 / q),
            (-sigma).powf(-1.0 / q).min(1.0),
        )
    };
    let mut u = 0.5 * (lo + hi);
    for _ in 0..MAX_NODE_ITERATIONS {
        let r = u.powf(-q);
        let g = u - r - sigma;
        if g == 0.0 {
            break;
        }
        if g > 0.0 {
            hi = u;
        } else {
            lo = u;
        }
        let next = u - g / (1.0 + q * r / u);
        let next = if next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
        if (next - u).abs() <= 2.0 * f64::EPSILON * u || hi - lo <= 2.0 * f64::EPSILON * hi {
            u = next;
            break;
        }
        u = next;
    }
    u
}

impl FilmTable {
    /// A table of u(σ)^n for σ from `sigma_lo` up to at least `sigma_hi`, or `None` if
    /// the range is not finite or needs more than `MAX_OCTAVES` octaves.
    pub(crate) fn new(q: f64, n: f64, sigma_lo: f64, sigma_hi: f64) -> Option<Self> {
        if !(q > 0.0 && q.is_finite() && sigma_lo.is_finite() && sigma_hi > sigma_lo) {
            return None;
        }
        let z_hi = sigma_hi - sigma_lo + 1.0;
        let octaves = (z_hi.log2().floor() as usize) + 1;
        if !z_hi.is_finite() || octaves > MAX_OCTAVES {
            return None;
        }
        let segments = octaves * PER_OCTAVE;
        let nodes: [f64; COEFFS] = std::array::from_fn(|j| {
            (std::f64::consts::PI * (j as f64 + 0.5) / COEFFS as f64).cos()
        });
        let mut coeffs = Vec::with_capacity(segments);
        let mut root_coeffs = Vec::with_capacity(segments);
        let fit = |values: &[f64; COEFFS]| -> [f64; COEFFS] {
            let c: [f64; COEFFS] = std::array::from_fn(|k| {
                let s: f64 = (0..COEFFS)
                    .map(|j| {
                        values[j]
                            * (std::f64::consts::PI * k as f64 * (j as f64 + 0.5) / COEFFS as f64)
                                .cos()
                    })
                    .sum();
                let w = if k == 0 { 1.0 } else { 2.0 };
                w * s / COEFFS as f64
            });
            chebyshev_to_monomial(&c)
        };
        for seg in 0..segments {
            let octave = (seg / PER_OCTAVE) as i32;
            let sub = (seg % PER_OCTAVE) as f64;
            let width = 2f64.powi(octave) / PER_OCTAVE as f64;
            let z0 = 2f64.powi(octave) + sub * width;
            let roots: [f64; COEFFS] = std::array::from_fn(|j| {
                let z = z0 + 0.5 * (nodes[j] + 1.0) * width;
                exact_root(z - 1.0 + sigma_lo, q)
            });
            coeffs.push(fit(&roots.map(|u| u.powf(n))));
            root_coeffs.push(fit(&roots));
        }
        Some(FilmTable {
            q,
            n,
            sigma_lo,
            segments,
            coeffs,
            root_coeffs,
        })
    }

    /// The segment of σ and τ ∈ [−1, 1) within it, or `None` outside the table.
    #[inline(always)]
    fn locate(&self, sigma: f64) -> Option<(usize, f64)> {
        let z = sigma - self.sigma_lo + 1.0;
        if !(z >= 1.0) {
            return None;
        }
        let bits = z.to_bits();
        let octave = ((bits >> 52) & 0x7ff) as usize;
        let octave = octave.checked_sub(1023)?;
        let sub = ((bits >> 47) & 31) as usize;
        let seg = octave * PER_OCTAVE + sub;
        if seg >= self.segments {
            return None;
        }
        // z's mantissa in [1, 2): (m − 1)·32 − sub ∈ [0, 1) exactly, then τ ∈ [−1, 1).
        let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
        let tau = 2.0 * ((m - 1.0) * PER_OCTAVE as f64 - sub as f64) - 1.0;
        Some((seg, tau))
    }

    /// A segment's series at τ by Estrin's scheme.
    #[inline(always)]
    fn estrin(c: &[f64; COEFFS], tau: f64) -> f64 {
        let t2 = tau * tau;
        let t4 = t2 * t2;
        let low = (c[0] + c[1] * tau) + (c[2] + c[3] * tau) * t2;
        let high = (c[4] + c[5] * tau) + (c[6] + c[7] * tau) * t2;
        low + (high + c[8] * t4) * t4
    }

    /// u(σ)^n, or `None` outside the table.
    #[inline]
    pub(crate) fn g(&self, sigma: f64) -> Option<f64> {
        let (seg, tau) = self.locate(sigma)?;
        Some(Self::estrin(self.coeffs.get(seg)?, tau))
    }

    /// (u(σ)^n, u(σ)), or `None` outside the table.
    #[inline]
    pub(crate) fn g_and_root(&self, sigma: f64) -> Option<(f64, f64)> {
        let (seg, tau) = self.locate(sigma)?;
        Some((
            Self::estrin(self.coeffs.get(seg)?, tau),
            Self::estrin(self.root_coeffs.get(seg)?, tau),
        ))
    }

    /// Segments in use (for the tests' account of the setup cost).
    #[cfg(test)]
    pub(crate) fn segments(&self) -> usize {
        self.segments
    }
}

/// Terms of the binomial series of (1 + u)^e (degree 11).
const SERIES_TERMS: usize = 12;
/// The series is used for |u| ≤ this (a squeeze factor within 1/32 of 1: the squeeze
/// velocities of a loaded bearing, |w|/U ≲ 1e-3, give |u| ≈ 4|w|/U).
const SERIES_RADIUS: f64 = 1.0 / 32.0;
/// The largest tail of the series accepted, relative (below the ulp of 1).
const SERIES_TAIL: f64 = 1e-17;

/// (1 + u)^e for |u| ≤ [`SERIES_RADIUS`] by its binomial series Σ C(e, j) u^j to degree
/// 11, evaluated by Estrin's scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
struct PowerSeries {
    c: [f64; SERIES_TERMS],
}

impl PowerSeries {
    /// The series of (1 + u)^e, or `None` if its tail past degree 11 can exceed
    /// [`SERIES_TAIL`] on |u| ≤ [`SERIES_RADIUS`]: C(e, j+1)/C(e, j) = (e − j)/(j + 1) has
    /// magnitude ≤ 1 for j ≥ 12 when −1 < e ≤ 25, so the tail is below
    /// |C(e, 12)|·r^12/(1 − r).
    fn new(e: f64) -> Option<Self> {
        if !(e > -1.0 && e <= 25.0) {
            return None;
        }
        let mut c = [0.0; SERIES_TERMS];
        let mut ck = 1.0;
        for (j, cj) in c.iter_mut().enumerate() {
            *cj = ck;
            ck *= (e - j as f64) / (j as f64 + 1.0);
        }
        let tail = ck.abs() * SERIES_RADIUS.powi(SERIES_TERMS as i32) / (1.0 - SERIES_RADIUS);
        (tail <= SERIES_TAIL).then_some(PowerSeries { c })
    }

    #[inline(always)]
    fn eval(&self, u: f64) -> f64 {
        let c = &self.c;
        let u2 = u * u;
        let u4 = u2 * u2;
        let u8 = u4 * u4;
        let q0 = (c[0] + c[1] * u) + (c[2] + c[3] * u) * u2;
        let q1 = (c[4] + c[5] * u) + (c[6] + c[7] * u) * u2;
        let q2 = (c[8] + c[9] * u) + (c[10] + c[11] * u) * u2;
        q0 + q1 * u4 + q2 * u8
    }
}

/// The hot loop's film solve: [`FilmTable`] plus the run's constants.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct FastFilm {
    table: FilmTable,
    /// δ at the load floor, (LOAD_FLOOR_N/k)^(1/n), m.
    delta_floor_m: f64,
    /// L at f = 1: (a·k^(−e))^(1/(1+q)), m.
    l0_m: f64,
    /// k·L0^n, N.
    k_l0n: f64,
    /// 1/(1 + q).
    inv_1pq: f64,
    /// f^(1/(1+q)) and f^(n/(1+q)) near f = 1 (the squeeze factor's scaling of L and of
    /// k·L^n) by series instead of a `powf` and a root per roller (`None`: `powf`).
    near_one: Option<(PowerSeries, PowerSeries)>,
    /// z/w = 1.32/U, s/m (the normalised squeeze factor's exponent per squeeze velocity).
    z_per_w: f64,
    /// The lane kernel's constants ([`FastFilm::sums`]; `None`: the printed reading, or
    /// series whose tail bound fails: the roller-by-roller [`FastFilm::load`]).
    lanes: Option<LaneConstants>,
}

/// |z| up to which the lane kernel takes f(z)^a by its Taylor series in z (f = 4 − 3e^z,
/// the normalised squeeze factor; z = 1.32 w/U). 1/256 covers |w| ≤ 9.3 mm/s on the
/// truck bearing (U = 3.14 m/s), the squeeze velocities once the release has decayed;
/// outside, the roller-by-roller path.
const Z_RADIUS: f64 = 1.0 / 256.0;
/// Degree of the series in z (Estrin).
const Z_DEGREE: usize = 8;
/// Terms summed for the tail bound of the series past [`Z_DEGREE`].
const Z_TAIL_TERMS: usize = 40;
/// The largest tail accepted on |z| ≤ [`Z_RADIUS`] (f^a ≈ 1 there: relative).
const Z_TAIL: f64 = 1e-17;

/// The Taylor coefficients F_0..F_(terms−1) of f(z)^a for f(z) = 4 − 3e^z (f(0) = 1,
/// f_k = −3/k! for k ≥ 1; `scale` 0: f ≡ 1), by J. C. P. Miller's recurrence for a
/// power of a series, from f·F′ = a·f′·F: F_m = (1/m) Σ_{k=1..m} ((a + 1)k − m) f_k F_(m−k).
fn power_of_squeeze_series(a: f64, terms: usize, scale: f64) -> Vec<f64> {
    let mut f = vec![0.0; terms];
    let mut fact = 1.0;
    for (k, fk) in f.iter_mut().enumerate().skip(1) {
        fact *= k as f64;
        *fk = -3.0 * scale / fact;
    }
    let mut big = vec![0.0; terms];
    big[0] = 1.0;
    for m in 1..terms {
        let mut acc = 0.0;
        for k in 1..=m {
            acc += ((a + 1.0) * k as f64 - m as f64) * f[k] * big[m - k];
        }
        big[m] = acc / m as f64;
    }
    big
}

/// f(z)^a to degree [`Z_DEGREE`] and whether its tail on |z| ≤ [`Z_RADIUS`] is below
/// [`Z_TAIL`] (terms to [`Z_TAIL_TERMS`], then a geometric bound on the rest from the
/// last two).
fn squeeze_power_series(a: f64, scale: f64) -> Option<[f64; Z_DEGREE + 1]> {
    let c = power_of_squeeze_series(a, Z_TAIL_TERMS, scale);
    if !c.iter().all(|x| x.is_finite()) {
        return None;
    }
    let term = |j: usize| c[j].abs() * Z_RADIUS.powi(j as i32);
    let mut tail: f64 = (Z_DEGREE + 1..Z_TAIL_TERMS).map(term).sum();
    let (last, before) = (term(Z_TAIL_TERMS - 1), term(Z_TAIL_TERMS - 2));
    let ratio = if before > 0.0 { last / before } else { 0.0 };
    if ratio >= 0.5 {
        return None;
    }
    tail += last * ratio / (1.0 - ratio);
    (tail <= Z_TAIL).then(|| std::array::from_fn(|j| c[j]))
}

/// Constants of [`FastFilm::sums`], hoisted out of the right-hand side.
#[derive(Debug, Clone, Copy, PartialEq)]
struct LaneConstants {
    /// z per unit ṗ: z = 1.32·w/U with w = −½ṗ (0 for the steady film).
    z_per_p_dot: f64,
    /// f(z)^(−1/(1+q)) / L0: σ = s0 times this series.
    inv_l: [f64; Z_DEGREE + 1],
    /// k·L0^n·f(z)^(n/(1+q)): W = g(σ) times this series.
    k_ln: [f64; Z_DEGREE + 1],
}

/// Estrin's scheme for a degree-8 series.
#[inline(always)]
fn estrin8(c: &[f64; Z_DEGREE + 1], z: f64) -> f64 {
    let z2 = z * z;
    let z4 = z2 * z2;
    let low = (c[0] + c[1] * z) + (c[2] + c[3] * z) * z2;
    let high = (c[4] + c[5] * z) + (c[6] + c[7] * z) * z2;
    low + (high + c[8] * z4) * z4
}

/// Rollers per block of [`FastFilm::sums`] (as the dry kernel's).
const BLOCK: usize = 16;

/// |z| up to which the normalised squeeze factor's e^z − 1 is summed as a series.
const EXP_SERIES_RADIUS: f64 = 1.0 / 128.0;
/// (e^z − 1)/z = Σ z^j/(j + 1)!, j = 0..=7.
const EXPM1_OVER_Z: [f64; 8] = [
    1.0,
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5040.0,
    1.0 / 40320.0,
];

impl FastFilm {
    /// The table for contact law `law` (with a film) and loads up to `load_hi_n`, or
    /// `None` (no film, or a range the table cannot hold: the Newton solve is used).
    pub(crate) fn new(law: &ContactLaw, load_hi_n: f64) -> Option<Self> {
        let film = law.film?;
        let (k, n) = (law.stiffness, law.exponent);
        let q = n * LOAD_EXPONENT;
        let inv_1pq = 1.0 / (1.0 + q);
        let l0_m = (film.scale * k.powf(-LOAD_EXPONENT)).powf(inv_1pq);
        let delta_floor_m = (LOAD_FLOOR_N / k).powf(1.0 / n);
        // The lowest σ of the floor over the squeeze factors the reading allows (the
        // normalised factor reaches 4, the others 1), with a margin of 2 in u.
        let f_max: f64 = match film.squeeze {
            Squeeze::Normalised => 4.0,
            Squeeze::Printed | Squeeze::None => 1.0,
        };
        let u_lo = 0.5 * delta_floor_m / (l0_m * f_max.powf(inv_1pq));
        let u_hi = (load_hi_n / k).powf(1.0 / n) / l0_m;
        let table = FilmTable::new(q, n, u_lo - u_lo.powf(-q), u_hi - u_hi.powf(-q))?;
        let fast = FastFilm {
            table,
            delta_floor_m,
            l0_m,
            k_l0n: k * law.power(l0_m),
            inv_1pq,
            near_one: PowerSeries::new(inv_1pq).zip(PowerSeries::new(n * inv_1pq)),
            z_per_w: SQUEEZE_RATE / film.entrainment_speed_m_s,
            lanes: None,
        };
        let mut fast = fast;
        // The lane kernel: the normalised reading (f = 4 − 3e^z) or the steady film
        // (f ≡ 1, z ≡ 0).
        let z_scale = match film.squeeze {
            Squeeze::Normalised => Some(1.0),
            Squeeze::None => Some(0.0),
            Squeeze::Printed => None,
        };
        fast.lanes = z_scale.and_then(|zs| {
            let inv = squeeze_power_series(-inv_1pq, zs)?;
            let pow = squeeze_power_series(n * inv_1pq, zs)?;
            Some(LaneConstants {
                z_per_p_dot: -0.5 * zs * fast.z_per_w,
                inv_l: inv.map(|c| c / fast.l0_m),
                k_ln: pow.map(|c| c * fast.k_l0n),
            })
        });
        (fast.l0_m.is_finite()
            && fast.k_l0n.is_finite()
            && fast.l0_m > 0.0
            && fast.z_per_w.is_finite())
        .then_some(fast)
    }

    /// The squeeze factor f of eq. (4) at approach rate `p_dot_m_s` (squeeze velocity
    /// w = −½ṗ) and u = f − 1. The normalised reading's f = 4 − 3·e^z, z = 1.32 w/U,
    /// near w = 0 (|z| ≤ 1/128, the loaded bearing's squeeze velocities) as
    /// u = −3·(e^z − 1) by the Taylor series of e^z − 1 to degree 8 (truncation below
    /// 1e-21 relative; no `exp` call); elsewhere [`FilmCoefficients::squeeze_factor`].
    #[inline(always)]
    fn squeeze(&self, film: &FilmCoefficients, p_dot_m_s: f64) -> (f64, f64) {
        let w = -0.5 * p_dot_m_s;
        if film.squeeze == Squeeze::Normalised {
            let z = self.z_per_w * w;
            if z.abs() <= EXP_SERIES_RADIUS {
                let z2 = z * z;
                let z4 = z2 * z2;
                let e = &EXPM1_OVER_Z;
                let low = (e[0] + e[1] * z) + (e[2] + e[3] * z) * z2;
                let high = (e[4] + e[5] * z) + (e[6] + e[7] * z) * z2;
                let u = -3.0 * (z * (low + high * z4));
                return (1.0 + u, u);
            }
        }
        let factor = film.squeeze_factor(w);
        (factor, factor - 1.0)
    }

    /// Roller load W of eqs. (2)–(4) for approach `p_m` and its rate, and whether the
    /// film was clamped at 0: [`ContactLaw::contact`]'s `load_n` and `clamped` (the
    /// same branches: separated, below the load floor, clamped film), the loaded branch
    /// from the table instead of Newton.
    #[inline]
    pub(crate) fn load(&self, law: &ContactLaw, p_m: f64, p_dot_m_s: f64) -> (f64, bool) {
        let Some(film) = law.film else {
            return (law.contact(p_m, p_dot_m_s).load_n, false);
        };
        let k = law.stiffness;
        let s0 = 0.5 * p_m - law.clearance_m;
        let (factor, u) = self.squeeze(&film, p_dot_m_s);
        // h at the floor: a·f·(1 N)^(−e) = a·f (film_unclamped(LOAD_FLOOR_N, f)).
        let h_floor_raw = film.scale * factor;
        let clamped = h_floor_raw < 0.0;
        let h_floor = h_floor_raw.max(0.0);
        let gap = s0 + h_floor;
        if gap <= 0.0 {
            return (0.0, clamped);
        }
        if h_floor == 0.0 || gap <= self.delta_floor_m {
            // Below the floor the film is held: δ = gap.
            return (k * law.power(gap), clamped);
        }
        let (l, k_ln) = if factor == 1.0 {
            (self.l0_m, self.k_l0n)
        } else if let Some((root, power)) = self.near_one.filter(|_| u.abs() <= SERIES_RADIUS) {
            // L = L0·f^(1/(1+q)) and k·L^n = k·L0^n·f^(n/(1+q)).
            (self.l0_m * root.eval(u), self.k_l0n * power.eval(u))
        } else {
            let lf = factor.powf(self.inv_1pq);
            (self.l0_m * lf, self.k_l0n * law.power(lf))
        };
        match self.table.g(s0 / l) {
            Some(g) => (k_ln * g, false),
            None => (law.contact(p_m, p_dot_m_s).load_n, false),
        }
    }

    /// Σ W_i cos θ_i, Σ W_i sin θ_i, Σ W_i (y cos θ_i − x sin θ_i) over the rollers
    /// whose phases' sines and cosines are `sp`, `cp`, at (x, y, ẋ, ẏ) and cage angle
    /// (sin, cos ω_c t) = (`s0`, `c0`), and the film clamps: eqs. (2)–(4) per roller
    /// as [`Self::load`] gives them, in structure-of-arrays passes over blocks of
    /// rollers (issue 25, Speed). The first pass has no branch and vectorises: θ_i by
    /// rotation, p, ṗ, s0 = p/2 − C, z = 1.32·w/U, and σ = s0/L and k·L^n from the
    /// Taylor series of the squeeze factor's powers in z (degree 8, |z| ≤ 1/256, tail
    /// < 1e-17: no `exp`, no `powf`, no division); the second takes W = k·L^n·g(σ) from
    /// the table for the rollers on the loaded branch inside both ranges (s0 above the
    /// floor's deflection, so the film at the floor is positive and the gap above the
    /// floor), and [`Self::load`] for the others (separated, at the floor, a squeeze
    /// velocity outside the series, a σ outside the table). `None` where the reading
    /// has no lane kernel (the printed one).
    #[allow(clippy::too_many_arguments)] // the hot loop's scalars, each distinct
    #[inline]
    pub(crate) fn sums(
        &self,
        law: &ContactLaw,
        sp: &[f64],
        cp: &[f64],
        state: [f64; 4],
        omega_c: f64,
        s0: f64,
        c0: f64,
    ) -> Option<([f64; 3], usize)> {
        let lanes = self.lanes.as_ref()?;
        let [x, y, vx, vy] = state;
        let clearance = law.clearance_m;
        let floor = self.delta_floor_m;
        // θ_i = φ_i + ω_c t: x cos θ_i + y sin θ_i = A cos φ_i + B sin φ_i and
        // y cos θ_i − x sin θ_i = B cos φ_i − A sin φ_i with A = x c0 + y s0,
        // B = y c0 − x s0 (see `kernel::dry_sums_ten_ninths`); likewise the velocity's
        // part of ṗ with (ẋ, ẏ), and ω_c(y cos θ − x sin θ) from A and B: p_i and ṗ_i
        // are each two products per roller.
        let a = x * c0 + y * s0;
        let b = y * c0 - x * s0;
        let pd_c = (vx * c0 + vy * s0) + omega_c * b;
        let pd_s = (vy * c0 - vx * s0) - omega_c * a;
        let (ah, bh) = (0.5 * a, 0.5 * b);
        let (zc, zs) = (lanes.z_per_p_dot * pd_c, lanes.z_per_p_dot * pd_s);
        let (mut sum_c, mut sum_s) = (0.0, 0.0);
        let mut clamps = 0;
        for (sg, cg) in sp.chunks(BLOCK).zip(cp.chunks(BLOCK)) {
            let nb = sg.len().min(cg.len()).min(BLOCK);
            let (sg, cg) = (&sg[..nb], &cg[..nb]);
            let mut sigma = [0.0; BLOCK];
            let mut k_ln = [0.0; BLOCK];
            let mut lane_ok = [false; BLOCK];
            for l in 0..nb {
                // s0 = p/2 − C and z = 1.32·w/U with w = −ṗ/2.
                let s0l = ah * cg[l] + bh * sg[l] - clearance;
                let z = zc * cg[l] + zs * sg[l];
                sigma[l] = s0l * estrin8(&lanes.inv_l, z);
                k_ln[l] = estrin8(&lanes.k_ln, z);
                lane_ok[l] = (z.abs() <= Z_RADIUS) & (s0l > floor);
            }
            let mut wc = [0.0; BLOCK];
            let mut ws = [0.0; BLOCK];
            for l in 0..nb {
                let table = if lane_ok[l] {
                    self.table.g(sigma[l])
                } else {
                    None
                };
                let w = match table {
                    Some(g) => k_ln[l] * g,
                    None => {
                        let p = a * cg[l] + b * sg[l];
                        let p_dot = pd_c * cg[l] + pd_s * sg[l];
                        let (load, clamped) = self.load(law, p, p_dot);
                        clamps += usize::from(clamped);
                        load
                    }
                };
                wc[l] = w * cg[l];
                ws[l] = w * sg[l];
            }
            sum_c += wc[..nb].iter().sum::<f64>();
            sum_s += ws[..nb].iter().sum::<f64>();
        }
        let out = [
            c0 * sum_c - s0 * sum_s,
            s0 * sum_c + c0 * sum_s,
            b * sum_c - a * sum_s,
        ];
        Some((out, clamps))
    }

    /// The whole [`Contact`] of eqs. (2)–(4), as [`ContactLaw::contact`] gives it, from
    /// the table instead of the Newton solve (the sampled outputs: load, film, squeeze
    /// velocity of every roller at every sample). The same branches as [`Self::load`];
    /// on the loaded branch W = k·L^n·u(σ)^n and δ = L·u(σ) from the table, the film
    /// h = δ − s0 (eq. 3 at the root, as the Newton solve forms it) and dW/dp =
    /// W·n/δ · ½/(1 − dh/dδ) with dh/dδ = −e·h·n/δ. Outside the table: the Newton solve.
    #[inline]
    pub(crate) fn contact(&self, law: &ContactLaw, p_m: f64, p_dot_m_s: f64) -> Contact {
        let Some(film) = law.film else {
            return law.contact(p_m, p_dot_m_s);
        };
        let (k, n) = (law.stiffness, law.exponent);
        let s0 = 0.5 * p_m - law.clearance_m;
        let w = -0.5 * p_dot_m_s;
        let (factor, u) = self.squeeze(&film, p_dot_m_s);
        let h_floor_raw = film.scale * factor;
        let clamped = h_floor_raw < 0.0;
        let h_floor = h_floor_raw.max(0.0);
        let gap = s0 + h_floor;
        if gap <= 0.0 {
            return Contact {
                gap_m: gap,
                clamped,
                ..Contact::default()
            };
        }
        if h_floor == 0.0 || gap <= self.delta_floor_m {
            let pw = law.power(gap);
            return Contact {
                load_n: k * pw,
                film_m: h_floor,
                squeeze_m_s: w,
                gap_m: gap,
                stiffness_n_m: 0.5 * k * n * pw / gap,
                clamped,
            };
        }
        let (l, k_ln) = if factor == 1.0 {
            (self.l0_m, self.k_l0n)
        } else if let Some((root, power)) = self.near_one.filter(|_| u.abs() <= SERIES_RADIUS) {
            (self.l0_m * root.eval(u), self.k_l0n * power.eval(u))
        } else {
            let lf = factor.powf(self.inv_1pq);
            (self.l0_m * lf, self.k_l0n * law.power(lf))
        };
        let Some((g, root)) = self.table.g_and_root(s0 / l) else {
            return law.contact(p_m, p_dot_m_s);
        };
        let load = k_ln * g;
        let d = l * root;
        let h = (d - s0).max(0.0);
        let dh_dd = -LOAD_EXPONENT * h * n / d;
        Contact {
            load_n: load,
            film_m: h,
            squeeze_m_s: w,
            gap_m: gap,
            stiffness_n_m: load * n / d * (0.5 / (1.0 - dh_dd)),
            clamped: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The truck bearing's contact law (Tables A1/A2: η₀ 0.0499 Pa·s, α 1.39e-8 1/Pa,
    /// E′ from 210 GPa and ν 0.3, the roller/inner-race radius, 22 mm, the entrainment at
    /// 209 and 83.26 rad/s) with the slice-law stiffness 2e9 N/m^(10/9), in a film reading
    /// and at a clearance (negative: interference).
    fn truck_law(squeeze: Squeeze, clearance_m: f64) -> ContactLaw {
        ContactLaw {
            stiffness: 2.0e9,
            exponent: 10.0 / 9.0,
            clearance_m,
            film: super::super::film::FilmLaw {
                viscosity_pa_s: 0.0499,
                pressure_viscosity_pa_inv: 1.39e-8,
                reduced_modulus_pa: 210e9 / (1.0 - 0.09),
                reduced_radius_m: 6.35e-3 * 25e-3 / 31.35e-3,
                length_m: 0.022,
                entrainment_speed_m_s: (209.0 - 83.26) * 0.025,
                squeeze,
            }
            .coefficients(),
        }
    }

    #[test]
    fn the_table_matches_the_exact_root_to_1e_14() {
        // q = (10/9)·0.128; σ from the truck bearing's floor (≈ −2.4 with the
        // normalised squeeze at its largest factor) to 4 000 (W ≈ 2 MN). Sampled at
        // 20 001 points off the nodes: relative error of u^n below 1e-14 (a few ulp of
        // the series' ≈ 9 terms; the Chebyshev truncation is ≈ 1e-16 at 1/32 octave).
        let (n, q) = (10.0 / 9.0, 10.0 / 9.0 * 0.128);
        let table = FilmTable::new(q, n, -2.4, 4000.0).unwrap();
        assert!(table.segments() <= 13 * 32);
        let mut worst: f64 = 0.0;
        for j in 0..=20_000 {
            let s = -2.4 + (4000.0 + 2.4) * (f64::from(j) / 20_000.0).powi(3);
            let exact = exact_root(s, q).powf(n);
            let g = table.g(s).unwrap();
            worst = worst.max((g / exact - 1.0).abs());
            // The root itself (the sampled outputs' δ = L·u), and g_and_root's g is g.
            let (g2, u) = table.g_and_root(s).unwrap();
            assert_eq!(g2, g);
            worst = worst.max((u / exact_root(s, q) - 1.0).abs());
        }
        assert!(worst < 1e-14, "{worst:e}");
        // The root itself: u − u^(−q) = σ to rounding.
        for s in [-2.3, -1.0, 0.0, 0.5, 7.0, 3000.0] {
            let u = exact_root(s, q);
            assert!((u - u.powf(-q) - s).abs() <= 1e-14 * (1.0 + s.abs()), "{s}");
        }
        // Outside: none (the caller's Newton takes over).
        assert!(table.g(-2.5).is_none());
        assert!(table.g(1e6).is_none());
        assert!(table.g(f64::NAN).is_none());
    }

    #[test]
    fn the_power_series_is_powf_near_one() {
        // (1 + u)^e by the degree-11 series against `powf` (≤ 1 ulp) over |u| ≤ 1/32 for
        // the truck film's 1/(1+q) and n/(1+q), a negative and a large exponent: within
        // 1e-15 relative, 4.5 ulp (the tail is < 1e-17; the rest is the Estrin sum's
        // rounding and powf's own ulp: measured 4.4e-16).
        // Exponents whose tail the bound cannot hold get no series.
        let q = 10.0 / 9.0 * 0.128;
        for e in [1.0 / (1.0 + q), (10.0 / 9.0) / (1.0 + q), -0.5, 3.7] {
            let series = PowerSeries::new(e).unwrap_or_else(|| panic!("no series for {e}"));
            let mut worst: f64 = 0.0;
            for j in -2000..=2000 {
                let u = SERIES_RADIUS * f64::from(j) / 2000.0;
                let exact = (1.0 + u).powf(e);
                worst = worst.max((series.eval(u) / exact - 1.0).abs());
            }
            assert!(worst <= 1e-15, "{e}: {worst:e}");
        }
        assert!(PowerSeries::new(-1.5).is_none());
        assert!(PowerSeries::new(40.0).is_none());
    }

    #[test]
    fn the_squeeze_series_is_the_squeeze_factor() {
        // The normalised factor near w = 0 by the series of e^z − 1 against eq. (4)'s
        // `squeeze_factor` ((1 − 0.75e^z)/0.25 by `exp`: a few ulps itself): f within 8ε
        // of it over |z| ≤ 1/128 and beyond, u = f − 1 within 1e-15 relative of
        // −3·expm1(z) inside (the series is the more accurate near 0: f − 1 from `exp`
        // cancels).
        let law = truck_law(Squeeze::Normalised, -5e-6);
        let Some(film) = law.film else {
            panic!("no film")
        };
        let fast = FastFilm::new(&law, 2e6).unwrap_or_else(|| panic!("no table"));
        let u_ref = film.entrainment_speed_m_s;
        for j in -1100i32..=1100 {
            let z = EXP_SERIES_RADIUS * f64::from(j) / 1000.0;
            let w = z * u_ref / SQUEEZE_RATE;
            let p_dot = -2.0 * w;
            let (f, u) = fast.squeeze(&film, p_dot);
            let exact = film.squeeze_factor(-0.5 * p_dot);
            assert!(
                (f - exact).abs() <= 8.0 * f64::EPSILON * exact,
                "{z}: {f} {exact}"
            );
            if j.abs() < 1000 {
                let z_used = fast.z_per_w * (-0.5 * p_dot);
                let u_exact = -3.0 * z_used.exp_m1();
                assert!(
                    (u - u_exact).abs() <= 1e-15 * u_exact.abs(),
                    "{z}: {u} {u_exact}"
                );
            }
        }
    }

    #[test]
    fn the_squeeze_power_series_is_the_power_of_the_squeeze_factor() {
        // f(z)^a, f = 4 − 3e^z, by its degree-8 Taylor series against `exp` and `powf`
        // over |z| ≤ 1/256 for the truck film's −1/(1+q) and n/(1+q): within 2e-15
        // relative (the tail bound is 1e-17; the rest is rounding, of the Estrin sum and
        // of exp/powf themselves, whose f − 1 cancels). The steady film's series is 1.
        let q = 10.0 / 9.0 * LOAD_EXPONENT;
        for a in [-1.0 / (1.0 + q), (10.0 / 9.0) / (1.0 + q)] {
            let c = squeeze_power_series(a, 1.0).unwrap_or_else(|| panic!("no series for {a}"));
            let mut worst: f64 = 0.0;
            for j in -2000..=2000 {
                let z = Z_RADIUS * f64::from(j) / 2000.0;
                let exact = (4.0 - 3.0 * z.exp()).powf(a);
                worst = worst.max((estrin8(&c, z) / exact - 1.0).abs());
            }
            eprintln!("{a}: worst {worst:e}");
            assert!(worst <= 2e-15, "{a}: {worst:e}");
            let one = squeeze_power_series(a, 0.0).unwrap();
            assert_eq!(estrin8(&one, 0.0), 1.0);
        }
        // A power whose coefficients grow too fast for the bound: no series.
        assert!(squeeze_power_series(400.0, 1.0).is_none());
    }

    #[test]
    fn the_lane_kernel_is_the_roller_by_roller_sum() {
        // FastFilm::sums against Σ FastFilm::load (each within 1e-13 of the Newton
        // solve) over 12 and 13 rollers (a tail), the normalised and steady readings,
        // at states that load every roller, unload some (ρ = 5 µm and a 20 µm
        // clearance) and move fast enough to leave the series (|z| > 1/256: those rollers
        // take `load`): the sums to 1e-14·m of the largest roller term (|W|, |W|·|r| for
        // the third; the kernel regroups the sums), the same clamps.
        use std::f64::consts::TAU;
        for squeeze in [Squeeze::Normalised, Squeeze::None] {
            for clearance in [-5e-6, 20e-6] {
                let law = truck_law(squeeze, clearance);
                let fast = FastFilm::new(&law, 2e6).unwrap();
                for m in [12usize, 13] {
                    let (sp, cp): (Vec<f64>, Vec<f64>) = (0..m)
                        .map(|i| (TAU * i as f64 / m as f64).sin_cos())
                        .unzip();
                    for state in [
                        [-8e-6, 1e-7, 1e-4, -2e-4],
                        [-4e-5, 3e-6, 2e-3, 1e-3],
                        [-1.5e-5, 3e-6, 0.05, -0.03],
                        [0.0, 0.0, 0.0, 0.0],
                    ] {
                        for t in [0.0, 0.37] {
                            let (s0, c0) = (83.26f64 * t).sin_cos();
                            let (got, clamps) =
                                fast.sums(&law, &sp, &cp, state, 83.26, s0, c0).unwrap();
                            let [x, y, vx, vy] = state;
                            let mut want = [0.0; 3];
                            let (mut big, mut want_clamps): (f64, usize) = (0.0, 0);
                            for i in 0..m {
                                let (s, c) = (s0 * cp[i] + c0 * sp[i], c0 * cp[i] - s0 * sp[i]);
                                let p = x * c + y * s;
                                let pd = vx * c + vy * s + 83.26 * (y * c - x * s);
                                let (w, clamped) = fast.load(&law, p, pd);
                                want[0] += w * c;
                                want[1] += w * s;
                                want[2] += w * (y * c - x * s);
                                big = big.max(w.abs());
                                want_clamps += usize::from(clamped);
                            }
                            assert_eq!(clamps, want_clamps);
                            let r = x.hypot(y);
                            for j in 0..3 {
                                let scale = if j == 2 { big * r } else { big };
                                assert!(
                                    (got[j] - want[j]).abs() <= 1e-14 * scale.max(1e-300) * m as f64,
                                    "{squeeze:?} {clearance} {m} {state:?} {t} {j}: {got:?} vs {want:?}"
                                );
                            }
                        }
                    }
                }
            }
        }
        // The printed reading has no lane kernel.
        let printed = truck_law(Squeeze::Printed, -5e-6);
        let fast = FastFilm::new(&printed, 2e6).unwrap();
        assert!(fast
            .sums(&printed, &[0.0], &[1.0], [0.0; 4], 0.0, 0.0, 1.0)
            .is_none());
    }

    #[test]
    fn the_fast_contact_is_the_newton_solves_contact() {
        // The sampled outputs' contact from the table against ContactLaw::contact (Newton
        // to < 1e-18) for the truck bearing's film in the three readings, over the same
        // approaches and squeeze rates as the load test: the same branch, the load to
        // 1e-13 relative or 1e-12 N, the film h to 1e-12 relative or 1e-19 m (h = δ − s0
        // with δ ≈ 3–10 h: the table's 1e-14 on u times δ/h), the squeeze velocity
        // exactly, the gap to 4 ulp (the same formula; the squeeze factor within 8ε moves
        // it by < 1e-21 m, then s0 + h_floor rounds), the stiffness to 1e-6 relative (the Newton's dh/dδ is taken at
        // its last iterate, before the root: measured 1.3e-8 just above the load floor;
        // the sampled outputs do not use the stiffness).
        for squeeze in [Squeeze::None, Squeeze::Normalised, Squeeze::Printed] {
            let law = truck_law(squeeze, -5e-6);
            let fast = FastFilm::new(&law, 2e6).unwrap();
            let (mut worst_w, mut worst_h): (f64, f64) = (0.0, 0.0);
            for j in 0..2000 {
                let p = -12e-6 + 24e-6 * f64::from(j) / 2000.0;
                for p_dot in [-3.0, -0.3, -2e-3, 0.0, 1e-4, 2e-3, 0.3, 0.7, 3.0] {
                    let exact = law.contact(p, p_dot);
                    let got = fast.contact(&law, p, p_dot);
                    let at = format!("{squeeze:?} {p} {p_dot}: {got:?} vs {exact:?}");
                    assert_eq!(got.clamped, exact.clamped, "{at}");
                    assert_eq!(got.load_n > 0.0, exact.load_n > 0.0, "{at}");
                    assert_eq!(got.squeeze_m_s, exact.squeeze_m_s, "{at}");
                    let eg = (got.gap_m - exact.gap_m).abs();
                    assert!(eg <= 4.0 * f64::EPSILON * exact.gap_m.abs() + 1e-21, "{at}");
                    let ew = (got.load_n - exact.load_n).abs();
                    assert!(ew <= 1e-13 * exact.load_n + 1e-12, "{at}");
                    let eh = (got.film_m - exact.film_m).abs();
                    assert!(eh <= 1e-12 * exact.film_m + 1e-19, "{at}");
                    let es = (got.stiffness_n_m - exact.stiffness_n_m).abs();
                    assert!(es <= 1e-6 * exact.stiffness_n_m + 1e-6, "{at}");
                    if exact.load_n > 10.0 {
                        worst_w = worst_w.max(ew / exact.load_n);
                        worst_h = worst_h.max(eh / exact.film_m);
                    }
                }
            }
            eprintln!("{squeeze:?}: worst relative load {worst_w:e}, film {worst_h:e}");
        }
    }

    #[test]
    fn the_fast_load_is_the_newton_solves_load() {
        // Against ContactLaw::contact (Newton to < 1e-18) for the truck bearing's film
        // (Tables A1/A2) in the three readings, over approaches from separation through
        // the floor to 6 µm of interference beyond ρ and squeeze rates of both signs
        // (the normalised factor from 0 to ≈ 4): the same branch (separated, floor,
        // clamped) and the load to 1e-13 relative or 1e-12 N.
        for squeeze in [Squeeze::None, Squeeze::Normalised, Squeeze::Printed] {
            let law = truck_law(squeeze, -5e-6);
            let fast = FastFilm::new(&law, 2e6).unwrap();
            let mut worst: f64 = 0.0;
            for j in 0..2000 {
                let p = -12e-6 + 24e-6 * f64::from(j) / 2000.0;
                for p_dot in [-3.0, -0.3, -2e-3, 0.0, 1e-4, 2e-3, 0.3, 0.7, 3.0] {
                    let exact = law.contact(p, p_dot);
                    let (w, clamped) = fast.load(&law, p, p_dot);
                    assert_eq!(clamped, exact.clamped, "{squeeze:?} {p} {p_dot}");
                    assert_eq!(w > 0.0, exact.load_n > 0.0, "{squeeze:?} {p} {p_dot}");
                    let err = (w - exact.load_n).abs();
                    assert!(
                        err <= 1e-13 * exact.load_n + 1e-12,
                        "{squeeze:?} {p} {p_dot}: {w} vs {}",
                        exact.load_n
                    );
                    if exact.load_n > 10.0 {
                        worst = worst.max(err / exact.load_n);
                    }
                }
            }
            eprintln!("{squeeze:?}: worst relative load error {worst:e}");
        }
    }
}
