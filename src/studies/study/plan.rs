//! A study's points: the values of point `i` are a pure function of the study file and
//! `i` (no state carried from point to point), so shards, re-runs and the local run agree
//! to the bit.

use super::file::{Design, Distribution, Method, Shape, StudyFile};
use super::random::{inverse_normal, normal_cdf, permutation, SplitMix64};
use crate::studies::sweep::value_text;

/// The points of a study file.
#[derive(Debug, Clone)]
pub struct Plan {
    design: Design,
    /// Latin hypercube: one permutation of the strata per key (empty otherwise).
    strata: Vec<Vec<u32>>,
    /// The deck keys a point sets, in column order.
    keys: Vec<String>,
}

impl Distribution {
    /// The value at probability `u` ∈ (0, 1) (the inverse distribution function).
    pub fn quantile(&self, u: f64) -> f64 {
        match *self {
            Distribution::Normal { mean, sigma } => mean + sigma * inverse_normal(u),
            Distribution::Uniform { lo, hi } => lo + (hi - lo) * u,
            Distribution::Tolerance {
                nominal,
                band,
                shape: Shape::Uniform,
            } => nominal + band * (2.0 * u - 1.0),
            Distribution::Tolerance {
                nominal,
                band,
                shape: Shape::TruncatedNormal { sigmas },
            } => {
                // Φ⁻¹ over [Φ(−k), Φ(k)]: the normal N(nominal, band/k) truncated at ±band.
                let lo = normal_cdf(-sigmas);
                let p = lo + u * (1.0 - 2.0 * lo);
                let x = nominal + band / sigmas * inverse_normal(p);
                x.clamp(nominal - band, nominal + band)
            }
        }
    }
}

impl Plan {
    /// The plan of a parsed study file.
    pub fn new(file: &StudyFile) -> Plan {
        let (keys, strata) = match &file.design {
            Design::Grid(axes) => (axes.iter().map(|a| a.key.clone()).collect(), Vec::new()),
            Design::Sample(s) => {
                let strata = match s.method {
                    Method::MonteCarlo => Vec::new(),
                    Method::LatinHypercube => (0..s.keys.len())
                        .map(|k| permutation(s.seed, k as u64, s.samples))
                        .collect(),
                };
                (s.keys.iter().map(|(k, _)| k.clone()).collect(), strata)
            }
            Design::Duty(d) => {
                let mut keys: Vec<String> = Vec::new();
                for c in &d.cases {
                    for (k, _) in &c.set {
                        if !keys.contains(k) {
                            keys.push(k.clone());
                        }
                    }
                }
                (keys, Vec::new())
            }
        };
        Plan {
            design: file.design.clone(),
            strata,
            keys,
        }
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        match &self.design {
            Design::Grid(axes) => axes.iter().map(|a| a.values.len()).product(),
            Design::Sample(s) => s.samples,
            Design::Duty(d) => d.cases.len(),
        }
    }

    /// No points (never, for a parsed study file).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The deck keys a point sets (the input columns).
    pub fn keys(&self) -> &[String] {
        &self.keys
    }

    /// The numbers behind a sampled point's values (deck units), one per key; for tests.
    pub fn sample_values(&self, index: usize) -> Vec<f64> {
        let Design::Sample(s) = &self.design else {
            return Vec::new();
        };
        let mut stream = SplitMix64::for_point(s.seed, index as u64);
        s.keys
            .iter()
            .enumerate()
            .map(|(k, (_, dist))| {
                let mut u = stream.next_open01();
                if let Some(p) = self.strata.get(k).and_then(|p| p.get(index)) {
                    u = (f64::from(*p) + u) / s.samples as f64;
                }
                dist.quantile(u)
            })
            .collect()
    }

    /// The values point `index` writes into the deck, one per key (`None`: the key keeps
    /// the deck's value, a duty case that does not set it).
    pub fn point(&self, index: usize) -> Vec<Option<String>> {
        match &self.design {
            Design::Grid(axes) => {
                // Mixed radix, the last key fastest.
                let mut rest = index;
                let mut out = vec![None; axes.len()];
                for (k, a) in axes.iter().enumerate().rev() {
                    let n = a.values.len().max(1);
                    out[k] = a.values.get(rest % n).cloned();
                    rest /= n;
                }
                out
            }
            Design::Sample(_) => self
                .sample_values(index)
                .into_iter()
                .map(|v| Some(value_text(v)))
                .collect(),
            Design::Duty(d) => {
                let Some(case) = d.cases.get(index) else {
                    return vec![None; self.keys.len()];
                };
                self.keys
                    .iter()
                    .map(|k| {
                        case.set
                            .iter()
                            .find(|(ck, _)| ck == k)
                            .map(|(_, v)| v.clone())
                    })
                    .collect()
            }
        }
    }
}
