//! Spectra of the sampled dynamics with labelled peaks (issue 25 Model item 3): f_c and
//! its multiples k·f_c, the roller pass m·f_c, the base natural frequency f_bn (the
//! x spectrum's strongest line away from the cage harmonics), 2f_bn and the modulation
//! sidebands f_bn ± k·f_c (seed 003, discussion of Figs. 3 and 5).

use super::Series;
use crate::numerics::spectrum::{amplitude_spectrum, Peak, Spectrum, SpectrumError};

/// A spectral line with its name.
#[derive(Debug, Clone, PartialEq)]
pub struct LabelledPeak {
    /// Interpolated frequency, Hz.
    pub frequency_hz: f64,
    /// Amplitude (the signal's unit).
    pub amplitude: f64,
    /// "f_c", "3f_c", "m·f_c", "f_bn", "2f_bn", "f_bn+2f_c", … or "" when none fits.
    pub label: String,
}

/// A one-sided amplitude spectrum and its labelled peaks (strongest first).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LabelledSpectrum {
    /// Bin frequencies, Hz.
    pub frequency_hz: Vec<f64>,
    /// Amplitudes.
    pub amplitude: Vec<f64>,
    /// The strongest peaks, labelled.
    pub peaks: Vec<LabelledPeak>,
}

pub(crate) struct Spectra {
    pub x: LabelledSpectrum,
    pub roller_load: LabelledSpectrum,
    pub base_natural_frequency_hz: Option<f64>,
}

/// Peaks kept per spectrum, and the smallest kept relative to the strongest.
const PEAKS_KEPT: usize = 16;
const PEAK_FLOOR_REL: f64 = 1e-4;
/// A peak takes a line's label within this many bins of it.
const LABEL_BINS: f64 = 2.0;

/// The cage-harmonic orders 1..=2m with their labels.
fn cage_lines(fc: f64, m: usize) -> Vec<(f64, String)> {
    if fc <= 0.0 {
        return Vec::new();
    }
    (1..=2 * m)
        .map(|k| {
            let label = match k {
                1 => "f_c".to_string(),
                _ if k == m => "m·f_c".to_string(),
                _ => format!("{k}f_c"),
            };
            (k as f64 * fc, label)
        })
        .collect()
}

/// f_bn: the strongest x peak above half the cage frequency (and 2 bins) that is not a
/// cage harmonic.
fn base_natural(spec: &Spectrum, fc: f64, m: usize) -> Option<f64> {
    let near_cage = |p: &Peak| {
        cage_lines(fc, m)
            .iter()
            .any(|(f, _)| (p.frequency_hz - f).abs() <= LABEL_BINS * spec.resolution_hz)
    };
    spec.peaks(0.0, usize::MAX)
        .into_iter()
        .filter(|p| p.frequency_hz >= (0.5 * fc).max(2.0 * spec.resolution_hz))
        .find(|p| !near_cage(p))
        .map(|p| p.frequency_hz)
}

fn labelled(spec: Spectrum, fc: f64, m: usize, fbn: Option<f64>) -> LabelledSpectrum {
    let mut lines = cage_lines(fc, m);
    if let Some(fb) = fbn {
        lines.push((fb, "f_bn".into()));
        lines.push((2.0 * fb, "2f_bn".into()));
        if fc > 0.0 {
            for k in 1..=4 {
                let kf = k as f64 * fc;
                let tag = if k == 1 { String::new() } else { k.to_string() };
                lines.push((fb + kf, format!("f_bn+{tag}f_c")));
                if fb > kf {
                    lines.push((fb - kf, format!("f_bn-{tag}f_c")));
                }
            }
        }
    }
    let strongest = spec.peaks(0.0, 1).first().map_or(0.0, |p| p.amplitude);
    let tol = LABEL_BINS * spec.resolution_hz;
    let peaks = spec
        .peaks(PEAK_FLOOR_REL * strongest, PEAKS_KEPT)
        .into_iter()
        .map(|p| {
            let label = lines
                .iter()
                .map(|(f, l)| ((p.frequency_hz - f).abs(), l))
                .filter(|(d, _)| *d <= tol)
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .map_or_else(String::new, |(_, l)| l.clone());
            LabelledPeak {
                frequency_hz: p.frequency_hz,
                amplitude: p.amplitude,
                label,
            }
        })
        .collect();
    LabelledSpectrum {
        frequency_hz: spec.frequency_hz,
        amplitude: spec.amplitude,
        peaks,
    }
}

pub(crate) fn spectra(series: &Series, fc: f64, m: usize) -> Result<Spectra, SpectrumError> {
    let sx = amplitude_spectrum(&series.x_m, series.dt_s)?;
    let fbn = base_natural(&sx, fc, m);
    let load = series.roller_load_n.first().map_or(&[][..], |v| &v[..]);
    let sw = amplitude_spectrum(load, series.dt_s)?;
    Ok(Spectra {
        x: labelled(sx, fc, m, fbn),
        roller_load: labelled(sw, fc, m, fbn),
        base_natural_frequency_hz: fbn,
    })
}
