//! Random numbers of a sampled study, each a pure function of the study's seed and the
//! point's index, so that any shard computes any point alone and gets the same number.
//!
//! - Streams: SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number
//!   generators", OOPSLA 2014), seeded by its own finaliser applied to (seed, index): one
//!   stream per point, the k-th draw for the k-th key. SplitMix64 passes BigCrush and its
//!   seeding by a hash is what it was designed for (splitting).
//! - Normal deviates: Φ⁻¹ by Acklam's rational approximation (relative error < 1.15e-9)
//!   refined by one Halley step on Φ(x) − p with `libm::erfc` (musl's, about 1 ulp), which
//!   brings it to a few ulp (Acklam's own recommendation; std has no erfc).
//! - Latin hypercube: per key a permutation of the strata 0…n−1 (Fisher–Yates driven by a
//!   stream seeded by (seed, key number)), so every shard builds the same permutation.

/// One SplitMix64 stream.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

/// The golden-ratio increment of SplitMix64.
const GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;

/// SplitMix64's output function (Stafford's Mix13): a bijective 64-bit hash.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Tags keeping the point streams apart from the permutation streams.
const POINT_TAG: u64 = 0x5054; // "PT"
const LHS_TAG: u64 = 0x4C48_5300; // "LHS"

impl SplitMix64 {
    /// A stream seeded with `state` directly.
    pub fn new(state: u64) -> SplitMix64 {
        SplitMix64(state)
    }

    /// The stream of point `index` of a study seeded `seed`.
    pub fn for_point(seed: u64, index: u64) -> SplitMix64 {
        SplitMix64(mix(
            mix(seed ^ POINT_TAG).wrapping_add(mix(index.wrapping_add(GAMMA)))
        ))
    }

    /// The stream of the Latin-hypercube permutation of key number `key`.
    pub fn for_permutation(seed: u64, key: u64) -> SplitMix64 {
        SplitMix64(mix(
            mix(seed ^ LHS_TAG).wrapping_add(mix(key.wrapping_add(GAMMA)))
        ))
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(GAMMA);
        mix(self.0)
    }

    /// A uniform number strictly inside (0, 1): the top 53 bits, offset by half a step,
    /// so Φ⁻¹ never sees 0 or 1.
    pub fn next_open01(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64)
    }

    /// A uniform whole number in 0..n (n ≥ 1), by Lemire's multiply-shift with rejection
    /// (no modulo bias).
    pub fn below(&mut self, n: u64) -> u64 {
        let n = n.max(1);
        let threshold = n.wrapping_neg() % n;
        loop {
            let m = u128::from(self.next_u64()) * u128::from(n);
            if (m as u64) >= threshold {
                return (m >> 64) as u64;
            }
        }
    }
}

/// The standard normal distribution function Φ(x) = erfc(−x/√2)/2.
pub fn normal_cdf(x: f64) -> f64 {
    0.5 * libm::erfc(-x / std::f64::consts::SQRT_2)
}

/// Φ⁻¹(p) for 0 < p ≤ 1/2 (the lower half, where Φ(x) − p is computed without
/// cancellation): Acklam's approximation and one Halley step.
fn inverse_normal_lower(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969_683_028_665_376e1,
        2.209_460_984_245_205e2,
        -2.759_285_104_469_687e2,
        1.383_577_518_672_69e2,
        -3.066_479_806_614_716e1,
        2.506_628_277_459_239,
    ];
    const B: [f64; 5] = [
        -5.447_609_879_822_406e1,
        1.615_858_368_580_409e2,
        -1.556_989_798_598_866e2,
        6.680_131_188_771_972e1,
        -1.328_068_155_288_572e1,
    ];
    const C: [f64; 6] = [
        -7.784_894_002_430_293e-3,
        -3.223_964_580_411_365e-1,
        -2.400_758_277_161_838,
        -2.549_732_539_343_734,
        4.374_664_141_464_968,
        2.938_163_982_698_783,
    ];
    const D: [f64; 4] = [
        7.784_695_709_041_462e-3,
        3.224_671_290_700_398e-1,
        2.445_134_137_142_996,
        3.754_408_661_907_416,
    ];
    const P_LOW: f64 = 0.02425;
    let x = if p < P_LOW {
        let q = (-2.0 * p.ln()).sqrt();
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    };
    // Halley's step on f(x) = Φ(x) − p: f' = φ(x), f''/f' = −x.
    let e = normal_cdf(x) - p;
    let u = e * (2.0 * std::f64::consts::PI).sqrt() * (0.5 * x * x).exp();
    x - u / (1.0 + 0.5 * x * u)
}

/// Φ⁻¹(p), the standard normal quantile, for 0 < p < 1 (±∞ at the ends). The upper half
/// by symmetry, Φ⁻¹(p) = −Φ⁻¹(1 − p), where 1 − p is exact (Sterbenz) for p ≥ 1/2.
pub fn inverse_normal(p: f64) -> f64 {
    if p <= 0.0 {
        f64::NEG_INFINITY
    } else if p >= 1.0 {
        f64::INFINITY
    } else if p <= 0.5 {
        inverse_normal_lower(p)
    } else {
        -inverse_normal_lower(1.0 - p)
    }
}

/// A permutation of 0..n that is a pure function of (seed, key): Fisher–Yates.
pub fn permutation(seed: u64, key: u64, n: usize) -> Vec<u32> {
    let mut s = SplitMix64::for_permutation(seed, key);
    let mut p: Vec<u32> = (0..n as u32).collect();
    for i in (1..n).rev() {
        let j = s.below(i as u64 + 1) as usize;
        p.swap(i, j);
    }
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix_matches_the_reference_sequence() {
        // The reference C implementation (Vigna, splitmix64.c) seeded with 0 starts
        // 0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4.
        let mut s = SplitMix64::new(0);
        assert_eq!(s.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(s.next_u64(), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn inverse_normal_inverts_the_cdf() {
        // Reference quantiles from Wichura's AS 241 (Python's statistics.NormalDist,
        // R's qnorm), independent of Acklam's approximation.
        for (p, z) in [
            (0.975, 1.959_963_984_540_053_6),
            (0.5, 0.0),
            (0.841_344_746_068_542_9, 1.0),
            (1e-10, -6.361_340_902_404_056),
            (0.05, -1.644_853_626_951_472_6),
        ] {
            let x = inverse_normal(p);
            assert!(
                (x - z).abs() <= 1e-13 * z.abs().max(1.0),
                "p {p}: {x} vs {z}"
            );
        }
        // Round trip on a fine grid: Φ(Φ⁻¹(p)) = p to a few ulp of p (relative 1e-14).
        for k in 1..1000 {
            let p = k as f64 / 1000.0;
            let back = normal_cdf(inverse_normal(p));
            assert!((back - p).abs() <= 1e-14 * p, "p {p}: {back}");
        }
    }

    #[test]
    fn permutations_are_permutations_and_repeat() {
        let p = permutation(42, 3, 1000);
        let mut seen = vec![false; 1000];
        for &k in &p {
            assert!(!seen[k as usize]);
            seen[k as usize] = true;
        }
        assert_eq!(p, permutation(42, 3, 1000));
        assert_ne!(p, permutation(42, 4, 1000));
        assert_ne!(p, permutation(43, 3, 1000));
    }
}
