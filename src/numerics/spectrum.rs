//! Amplitude spectra of uniformly sampled real signals (issue 25, "Spectra"): a
//! Hann-windowed one-sided amplitude spectrum over a real FFT (`realfft`), peak finding
//! with Hann-aware interpolation between bins, and the amplitude of one given frequency
//! by projection over whole periods (exact for a harmonic of the window, where the
//! windowed FFT would smear it over its main lobe).
//!
//! Amplitude convention: a pure sine `A·sin(2πft)` reads `A` at its peak, whatever its
//! position between bins (the Hann window's scalloping loss, up to 15 % half-way
//! between bins, is undone by the interpolation). The mean is removed before the
//! transform and reported as the bin-0 amplitude, so that the (often large) static
//! offset does not leak into the lowest bins.

use realfft::{RealFftPlanner, RealToComplex};
use std::sync::Arc;

/// A one-sided amplitude spectrum: `amplitude[k]` at `frequency_hz[k] = k/(N·dt)`,
/// k = 0..=N/2 (bin 0 holds |mean|).
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    /// Bin frequencies, Hz.
    pub frequency_hz: Vec<f64>,
    /// Amplitude in the signal's unit (a sine of amplitude A reads A at its peak).
    pub amplitude: Vec<f64>,
    /// Bin spacing 1/(N·dt), Hz.
    pub resolution_hz: f64,
}

/// One spectral peak, interpolated between bins.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    /// Interpolated frequency, Hz.
    pub frequency_hz: f64,
    /// Interpolated (scalloping-corrected) amplitude.
    pub amplitude: f64,
    /// The local-maximum bin the peak was found at.
    pub bin: usize,
}

/// Why a spectrum or a projection could not be formed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpectrumError {
    /// Fewer samples than a spectrum needs.
    #[error("a spectrum needs at least {needed} samples; {count} were given")]
    TooFewSamples {
        /// Samples given.
        count: usize,
        /// Samples needed.
        needed: usize,
    },
    /// The sampling step is not a finite positive number.
    #[error("the sampling step must be a finite number > 0 s; it is {dt_s}")]
    BadStep {
        /// The step, s.
        dt_s: f64,
    },
    /// A sample is NaN or infinite.
    #[error("sample {index} is not a finite number")]
    NonFinite {
        /// Its index.
        index: usize,
    },
    /// The frequency asked of a projection is not positive, or the record holds less
    /// than one of its periods.
    #[error(
        "the frequency {frequency_hz} Hz must be > 0 with at least one whole period in the \
         record ({duration_s} s)"
    )]
    BadFrequency {
        /// The frequency asked, Hz.
        frequency_hz: f64,
        /// The record length, s.
        duration_s: f64,
    },
}

/// Smallest record a spectrum is formed of: fewer points have no interior bin.
const MIN_SAMPLES: usize = 8;

fn check(samples: &[f64], dt_s: f64, needed: usize) -> Result<(), SpectrumError> {
    if samples.len() < needed {
        return Err(SpectrumError::TooFewSamples {
            count: samples.len(),
            needed,
        });
    }
    if !(dt_s.is_finite() && dt_s > 0.0) {
        return Err(SpectrumError::BadStep { dt_s });
    }
    if let Some(index) = samples.iter().position(|v| !v.is_finite()) {
        return Err(SpectrumError::NonFinite { index });
    }
    Ok(())
}

/// A planned real FFT of one length with its Hann window and scratch, reusable for many
/// records of that length (the bench and the workbench's live spectra reuse one).
pub struct SpectrumPlan {
    fft: Arc<dyn RealToComplex<f64>>,
    window: Vec<f64>,
    input: Vec<f64>,
    output: Vec<realfft::num_complex::Complex<f64>>,
    scratch: Vec<realfft::num_complex::Complex<f64>>,
}

impl std::fmt::Debug for SpectrumPlan {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SpectrumPlan")
            .field("len", &self.window.len())
            .finish()
    }
}

impl SpectrumPlan {
    /// Plan for records of `len` samples (at least 8).
    pub fn new(len: usize) -> Result<Self, SpectrumError> {
        if len < MIN_SAMPLES {
            return Err(SpectrumError::TooFewSamples {
                count: len,
                needed: MIN_SAMPLES,
            });
        }
        let fft = RealFftPlanner::<f64>::new().plan_fft_forward(len);
        // The periodic Hann window w_k = ½(1 − cos 2πk/N): its sum is exactly N/2 and its
        // spectrum has the closed form the peak interpolation below relies on.
        let window = (0..len)
            .map(|k| 0.5 * (1.0 - (std::f64::consts::TAU * k as f64 / len as f64).cos()))
            .collect();
        Ok(SpectrumPlan {
            input: fft.make_input_vec(),
            output: fft.make_output_vec(),
            scratch: fft.make_scratch_vec(),
            fft,
            window,
        })
    }

    /// The record length this plan takes.
    pub fn len(&self) -> usize {
        self.window.len()
    }

    /// Always false (a plan has at least 8 samples); for clippy's `len_without_is_empty`.
    pub fn is_empty(&self) -> bool {
        self.window.is_empty()
    }

    /// The amplitude spectrum of `samples` (exactly [`SpectrumPlan::len`] of them)
    /// sampled every `dt_s` seconds.
    pub fn amplitude(&mut self, samples: &[f64], dt_s: f64) -> Result<Spectrum, SpectrumError> {
        let mut out = Spectrum {
            frequency_hz: Vec::new(),
            amplitude: Vec::new(),
            resolution_hz: 0.0,
        };
        self.amplitude_into(samples, dt_s, &mut out)?;
        Ok(out)
    }

    /// [`SpectrumPlan::amplitude`] into `out`, reusing its storage (no allocation once
    /// `out` has held a spectrum of this length): the window, the transform and the
    /// magnitudes, nothing planned or allocated per call.
    pub fn amplitude_into(
        &mut self,
        samples: &[f64],
        dt_s: f64,
        out: &mut Spectrum,
    ) -> Result<(), SpectrumError> {
        let n = self.window.len();
        check(samples, dt_s, n)?;
        if samples.len() != n {
            return Err(SpectrumError::TooFewSamples {
                count: samples.len(),
                needed: n,
            });
        }
        // The mean over eight interleaved partial sums (one sequential chain of 2^16
        // additions waits on each add's latency; eight independent ones vectorise), and
        // the largest |sample| for the overflow test of the magnitudes below.
        let (sum, peak) = sum_and_peak(samples);
        let mean = sum / n as f64;
        for ((i, &s), &w) in self.input.iter_mut().zip(samples).zip(&self.window) {
            *i = (s - mean) * w;
        }
        // The lengths were made by the plan itself, so the transform cannot refuse them;
        // the error is still mapped rather than unwrapped.
        self.fft
            .process_with_scratch(&mut self.input, &mut self.output, &mut self.scratch)
            .map_err(|_| SpectrumError::TooFewSamples {
                count: samples.len(),
                needed: n,
            })?;
        // One-sided amplitude of a windowed sine: 2|X_k|/Σw = 4|X_k|/N (Σw = N/2).
        // |X_k| as √(re² + im²) in one branch-free pass that vectorises (a few ns a bin;
        // `hypot` costs several times that and was most of a 2^16 spectrum's time).
        // |X_k| ≤ Σ|x_k − mean|·w_k ≤ 2N·max|x|, so the squares stay finite while
        // 2N·max|x| < 1e150 (every physical record); past that, `hypot` for every bin.
        let scale = 4.0 / n as f64;
        let resolution_hz = 1.0 / (n as f64 * dt_s);
        let bins = self.output.len();
        out.amplitude.clear();
        if 2.0 * n as f64 * peak < 1e150 {
            out.amplitude.extend(
                self.output
                    .iter()
                    .map(|c| (c.re * c.re + c.im * c.im).sqrt() * scale),
            );
        } else {
            out.amplitude
                .extend(self.output.iter().map(|c| c.re.hypot(c.im) * scale));
        }
        if let Some(a0) = out.amplitude.first_mut() {
            *a0 = mean.abs();
        }
        // The Nyquist bin of an even record is real and not doubled.
        if n.is_multiple_of(2) {
            if let Some(last) = out.amplitude.last_mut() {
                *last *= 0.5;
            }
        }
        if out.resolution_hz != resolution_hz || out.frequency_hz.len() != bins {
            out.frequency_hz.clear();
            out.frequency_hz
                .extend((0..bins).map(|k| k as f64 * resolution_hz));
        }
        out.resolution_hz = resolution_hz;
        Ok(())
    }
}

/// Σx and max|x| over eight interleaved lanes (vectorisable; the sum's rounding
/// differs from a sequential sum's by a few ulps of the largest partial sum).
fn sum_and_peak(samples: &[f64]) -> (f64, f64) {
    const LANES: usize = 8;
    let mut sum = [0.0; LANES];
    let mut peak = [0.0f64; LANES];
    let chunks = samples.chunks_exact(LANES);
    let tail = chunks.remainder();
    for c in chunks {
        for l in 0..LANES {
            sum[l] += c[l];
            peak[l] = peak[l].max(c[l].abs());
        }
    }
    for (l, &v) in tail.iter().enumerate() {
        sum[l] += v;
        peak[l] = peak[l].max(v.abs());
    }
    (sum.iter().sum(), peak.iter().copied().fold(0.0, f64::max))
}

/// Plans kept per thread by [`amplitude_spectrum`] (the dynamics takes two spectra of
/// one length per run, the workbench re-runs it on every edit).
const CACHED_PLANS: usize = 4;

thread_local! {
    /// The last few plans by length, most recent last.
    static PLANS: std::cell::RefCell<Vec<SpectrumPlan>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// The Hann-windowed one-sided amplitude spectrum of `samples` taken every `dt_s`
/// seconds. The plan (transform, window, scratch) of each length is made once per
/// thread and kept (the last few lengths); see [`SpectrumPlan`] to hold one yourself.
pub fn amplitude_spectrum(samples: &[f64], dt_s: f64) -> Result<Spectrum, SpectrumError> {
    check(samples, dt_s, MIN_SAMPLES)?;
    let n = samples.len();
    PLANS.with(|cell| {
        // Not re-entrant, so never borrowed here; should it be, plan afresh.
        let Ok(mut plans) = cell.try_borrow_mut() else {
            return SpectrumPlan::new(n)?.amplitude(samples, dt_s);
        };
        let mut plan = match plans.iter().position(|p| p.len() == n) {
            Some(i) => plans.remove(i),
            None => SpectrumPlan::new(n)?,
        };
        let result = plan.amplitude(samples, dt_s);
        if plans.len() >= CACHED_PLANS {
            plans.remove(0);
        }
        plans.push(plan);
        result
    })
}

/// `sin(πd)/(πd)`, 1 at d = 0.
fn sinc(d: f64) -> f64 {
    if d.abs() < 1e-12 {
        1.0
    } else {
        let x = std::f64::consts::PI * d;
        x.sin() / x
    }
}

impl Spectrum {
    /// The local maxima (a bin above both neighbours, bin 0 excluded) with amplitude at
    /// least `min_amplitude`, strongest first, at most `max_count` of them.
    ///
    /// Interpolation (Hann-aware): for a tone at `k + d` bins the periodic Hann
    /// spectrum gives |X(k+1)|/|X(k)| = (1+d)/(2−d) for d ∈ [0, ½] (Grandke 1983), so
    /// d = (2α − 1)/(α + 1) from the larger neighbour's ratio α; the amplitude is
    /// corrected by the window's response at d, (1 − d²)/sinc(d). Exact for one tone
    /// far (≳ 3 bins) from any other.
    pub fn peaks(&self, min_amplitude: f64, max_count: usize) -> Vec<Peak> {
        let a = &self.amplitude;
        let mut peaks: Vec<Peak> = Vec::new();
        for k in 1..a.len().saturating_sub(1) {
            let (l, c, r) = (a[k - 1], a[k], a[k + 1]);
            if !(c > l && c >= r && c >= min_amplitude && c > 0.0) {
                continue;
            }
            let (alpha, sign) = if r >= l { (r / c, 1.0) } else { (l / c, -1.0) };
            let d = ((2.0 * alpha - 1.0) / (alpha + 1.0)).clamp(0.0, 0.5);
            let amplitude = c * (1.0 - d * d) / sinc(d);
            peaks.push(Peak {
                frequency_hz: (k as f64 + sign * d) * self.resolution_hz,
                amplitude,
                bin: k,
            });
        }
        peaks.sort_by(|p, q| q.amplitude.total_cmp(&p.amplitude));
        peaks.truncate(max_count);
        peaks
    }

    /// The strongest peak at or above `min_frequency_hz`, if any.
    pub fn dominant_peak(&self, min_frequency_hz: f64) -> Option<Peak> {
        self.peaks(0.0, usize::MAX)
            .into_iter()
            .find(|p| p.frequency_hz >= min_frequency_hz)
    }
}

/// Amplitude of the component at `frequency_hz` of `samples` (taken every `dt_s`
/// seconds), by projection onto cos and sin over the largest whole number of its
/// periods from the record's start, after removing that window's mean:
/// A = √(a² + b²), a = (2/N)Σ x_k cos 2πf t_k, b likewise with sin. Exact (to rounding)
/// for a harmonic when the window holds a whole number of sampling steps per period
/// count, as it does over whole cage cycles sampled an integer number of times each.
pub fn amplitude_at(samples: &[f64], dt_s: f64, frequency_hz: f64) -> Result<f64, SpectrumError> {
    check(samples, dt_s, 2)?;
    let duration_s = samples.len() as f64 * dt_s;
    let periods = (duration_s * frequency_hz + 1e-9).floor();
    if !(frequency_hz.is_finite() && frequency_hz > 0.0 && periods >= 1.0) {
        return Err(SpectrumError::BadFrequency {
            frequency_hz,
            duration_s,
        });
    }
    let n = ((periods / (frequency_hz * dt_s)).round() as usize).clamp(2, samples.len());
    let window = &samples[..n];
    let mean = window.iter().sum::<f64>() / n as f64;
    let w = std::f64::consts::TAU * frequency_hz * dt_s;
    // cos/sin of w·k: exact at the start of every block of `BLOCK` samples, rotated by
    // w within it (≤ BLOCK roundings, ~1e-14, instead of a `sin_cos` per sample).
    const BLOCK: usize = 32;
    let (sw, cw) = w.sin_cos();
    let (mut a, mut b) = (0.0, 0.0);
    for (block, xs) in window.chunks(BLOCK).enumerate() {
        let (mut s, mut c) = (w * (block * BLOCK) as f64).sin_cos();
        for &x in xs {
            a += (x - mean) * c;
            b += (x - mean) * s;
            (s, c) = (s * cw + c * sw, c * cw - s * sw);
        }
    }
    Ok(2.0 / n as f64 * a.hypot(b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    fn tone(n: usize, dt: f64, parts: &[(f64, f64, f64)], offset: f64) -> Vec<f64> {
        (0..n)
            .map(|k| {
                let t = k as f64 * dt;
                offset
                    + parts
                        .iter()
                        .map(|&(a, f, ph)| a * (TAU * f * t + ph).sin())
                        .sum::<f64>()
            })
            .collect()
    }

    #[test]
    fn a_sine_reads_its_amplitude_and_frequency_between_bins() {
        // 4096 samples at 1 kHz: bins of 0.244 Hz. Tones placed on a bin, a quarter and
        // half-way between bins: the Hann-aware interpolation recovers the amplitude to
        // 1e-3 (its model is exact for an infinite record; the neighbour's own
        // sidelobe and the negative-frequency image cost < 1e-3 at ≥ 100 bins) and the
        // frequency to 1e-3 of a bin.
        let (n, dt) = (4096, 1e-3);
        let df = 1.0 / (n as f64 * dt);
        for offset_bins in [0.0, 0.25, 0.5, 0.8] {
            let f = (300.0 + offset_bins) * df;
            let x = tone(n, dt, &[(2.5, f, 0.3)], 7.0);
            let s = amplitude_spectrum(&x, dt).unwrap();
            let p = s.peaks(0.0, 1)[0];
            assert!(
                (p.amplitude - 2.5).abs() < 2.5e-3,
                "offset {offset_bins}: amplitude {}",
                p.amplitude
            );
            assert!(
                (p.frequency_hz - f).abs() < 1e-3 * df,
                "offset {offset_bins}: {} vs {f}",
                p.frequency_hz
            );
            // The mean in bin 0: exact over whole periods; otherwise the sine's own
            // mean over the record, ≤ A/(π·300) ≈ 2.7e-3, is part of it.
            let mean_tol = if offset_bins == 0.0 { 1e-9 } else { 3e-3 };
            assert!((s.amplitude[0] - 7.0).abs() < mean_tol, "mean in bin 0");
        }
    }

    #[test]
    fn two_tones_are_both_found_in_order() {
        let (n, dt) = (8192, 5e-4);
        let x = tone(n, dt, &[(1.0, 50.3, 0.0), (0.1, 173.7, 1.0)], 0.0);
        let s = amplitude_spectrum(&x, dt).unwrap();
        let p = s.peaks(1e-3, 2);
        assert_eq!(p.len(), 2);
        assert!((p[0].frequency_hz - 50.3).abs() < 1e-3, "{p:?}");
        assert!((p[1].frequency_hz - 173.7).abs() < 1e-3, "{p:?}");
        assert!((p[0].amplitude - 1.0).abs() < 2e-3, "{p:?}");
        assert!((p[1].amplitude - 0.1).abs() < 2e-4, "{p:?}");
        // Beyond the main lobes the Hann sidelobes fall fast: nothing else above 1e-3.
        assert_eq!(s.peaks(1e-3, 10).len(), 2);
    }

    #[test]
    fn a_fft_of_two_to_the_sixteen_points() {
        let n = 1 << 16;
        let dt = 1.0 / 65536.0;
        let x = tone(n, dt, &[(0.5, 1000.0, 0.7)], 0.0);
        let mut plan = SpectrumPlan::new(n).unwrap();
        let s = plan.amplitude(&x, dt).unwrap();
        assert_eq!(s.amplitude.len(), n / 2 + 1);
        // On-bin tone: the Hann main lobe is bins 999..=1001 at ½, 1, ½ of the peak.
        assert!((s.amplitude[1000] - 0.5).abs() < 1e-12);
        assert!((s.amplitude[999] - 0.25).abs() < 1e-12);
        assert!(s.amplitude[1003] < 1e-12);
    }

    #[test]
    fn projection_over_whole_periods_is_exact_for_harmonics() {
        // Cage-cycle-like: 40 cycles of 13.25 Hz, 256 samples each; harmonics 1..4 with
        // amplitudes 1, 0.02, 0.005, 0 (the last must read ~0, not leakage).
        let fc = 13.25;
        let dt = 1.0 / (256.0 * fc);
        let n = 256 * 40;
        let x = tone(
            n,
            dt,
            &[
                (1.0, fc, 0.2),
                (0.02, 2.0 * fc, 1.0),
                (0.005, 3.0 * fc, 2.0),
            ],
            3.0,
        );
        for (k, want) in [(1.0, 1.0), (2.0, 0.02), (3.0, 0.005), (4.0, 0.0)] {
            let a = amplitude_at(&x, dt, k * fc).unwrap();
            assert!((a - want).abs() < 1e-12, "{k}·fc: {a} vs {want}");
        }
        assert!(matches!(
            amplitude_at(&x, dt, 0.01),
            Err(SpectrumError::BadFrequency { .. })
        ));
    }

    #[test]
    fn bad_records_are_refused_by_name() {
        assert!(matches!(
            amplitude_spectrum(&[1.0; 4], 1e-3),
            Err(SpectrumError::TooFewSamples { count: 4, .. })
        ));
        assert!(matches!(
            amplitude_spectrum(&[1.0; 16], 0.0),
            Err(SpectrumError::BadStep { .. })
        ));
        let mut x = vec![0.0; 16];
        x[3] = f64::NAN;
        assert_eq!(
            amplitude_spectrum(&x, 1e-3),
            Err(SpectrumError::NonFinite { index: 3 })
        );
    }
    #[test]
    fn the_fast_spectrum_is_the_direct_dft() {
        // The vectorised mean and magnitudes against the definition: a direct DFT of
        // (x − mean)·w in `hypot`, 4|X_k|/N, on 1 000 samples (a length that is not a
        // power of two, a tail for the eight-lane sum) of two tones on a large offset:
        // every bin within 1e-12 of the largest (the FFT's and the direct sum's
        // roundings over 1 000 terms). Records near f64::MAX take the `hypot` pass and
        // read the same spectrum scaled.
        let (n, dt) = (1000, 1e-3);
        let x = tone(n, dt, &[(1.0, 50.0, 0.3), (1e-3, 173.0, 1.0)], 40.0);
        let s = amplitude_spectrum(&x, dt).unwrap();
        let mean = x.iter().sum::<f64>() / n as f64;
        let w: Vec<f64> = (0..n)
            .map(|j| 0.5 * (1.0 - (TAU * j as f64 / n as f64).cos()))
            .collect();
        for k in 1..n / 2 {
            let (mut re, mut im) = (0.0, 0.0);
            for j in 0..n {
                let ph = TAU * (k * j % n) as f64 / n as f64;
                re += (x[j] - mean) * w[j] * ph.cos();
                im -= (x[j] - mean) * w[j] * ph.sin();
            }
            let want = re.hypot(im) * 4.0 / n as f64;
            assert!(
                (s.amplitude[k] - want).abs() < 1e-12,
                "bin {k}: {} vs {want}",
                s.amplitude[k]
            );
        }
        assert!((s.amplitude[0] - mean).abs() < 1e-12);
        let big: Vec<f64> = x.iter().map(|v| v * 1e300).collect();
        let sb = amplitude_spectrum(&big, dt).unwrap();
        for k in 0..=n / 2 {
            assert!(sb.amplitude[k].is_finite(), "bin {k}");
            let want = s.amplitude[k] * 1e300;
            assert!((sb.amplitude[k] - want).abs() <= 1e-12 * 1e300, "bin {k}");
        }
    }
}
