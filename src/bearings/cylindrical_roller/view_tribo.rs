//! The tribodynamics' charts (issue 25 "Workbench panes"): the Orbit (x–ẋ phase plane
//! after settling), the two Spectra (the shaft's x and roller 1's load, log amplitude
//! with the strongest labelled peaks in the title), and roller 1's Cycle (load, film,
//! friction and power over a cage cycle, each divided by its cycle maximum so that one
//! axis holds one unit). Without a dynamics run each says why.

use super::dynamics::LabelledSpectrum;
use super::tribodynamics::Tribodynamics;
use crate::bearings::view::{Chart, ChartAxis, Display, Series};
use crate::units::{Quantity, Units};

/// Points drawn per series at most: a braille chart is at most a few hundred cells
/// wide, and the orbit repeats itself.
const MAX_POINTS: usize = 2_000;

fn thin<T: Copy>(v: &[T]) -> Vec<T> {
    let stride = v.len().div_ceil(MAX_POINTS).max(1);
    v.iter().step_by(stride).copied().collect()
}

fn empty(title: &str) -> Chart {
    Chart {
        title: title.to_string(),
        title_us: None,
        x: ChartAxis {
            label: "",
            display: Display::Plain,
            bounds: Some([0.0, 1.0]),
        },
        y: ChartAxis {
            label: "",
            display: Display::Plain,
            bounds: Some([0.0, 1.0]),
        },
        series: Vec::new(),
        per_element: false,
        operating: None,
    }
}

/// The four charts, in pane order (Orbit, Spectrum, Load spectrum, Cycle).
pub fn charts(t: Option<&Tribodynamics>) -> Vec<Chart> {
    let Some(t) = t else {
        let why = "no dynamics: dynamics.revolutions = 0 (or run --no-transient)";
        return vec![empty(why), empty(why), empty(why), empty(why)];
    };
    vec![orbit(t), spectrum(t, false), spectrum(t, true), cycle(t)]
}

/// The x–ẋ phase plane after settling: the first cage cycle apart from the later ones
/// (issue 25: "the first cycle dim"), drawn first so that the later cycles lie over it.
fn orbit(t: &Tribodynamics) -> Chart {
    let s = &t.dynamics.series;
    let all: Vec<(f64, f64)> = s.x_m.iter().zip(&s.vx_m_s).map(|(&x, &v)| (x, v)).collect();
    // Samples per cage cycle: the recorded cycle's length (whole cycles are sampled);
    // with the cage frozen there is no cycle and the orbit is one series.
    let per_cycle = t.dynamics.cycle.cage_angle_deg.len();
    let split = if per_cycle > 0 && per_cycle < all.len() {
        per_cycle + 1
    } else {
        0
    };
    let (lo, hi) = all
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.0), hi.max(p.0))
        });
    let pad = 0.05 * (hi - lo).abs().max(1e-12);
    let fbn = t
        .dynamics
        .base_natural_frequency_hz
        .map_or_else(|| "-".to_string(), |f| format!("{f:.1}"));
    let mut series = Vec::new();
    if split > 0 {
        series.push(Series {
            name: "first cage cycle",
            points: thin(&all[..split]),
            display: None,
        });
        series.push(Series {
            name: "later cycles",
            points: thin(&all[split - 1..]),
            display: None,
        });
    } else {
        series.push(Series {
            name: "orbit",
            points: thin(&all),
            display: None,
        });
    }
    Chart {
        title: format!(
            "x–ẋ after settling, f_bn {fbn} Hz, static x {:.4} µm",
            t.dynamics.static_offset_m[0] * 1e6
        ),
        title_us: Some(format!(
            "x–ẋ after settling, f_bn {fbn} Hz, static x {:.3} µin",
            Quantity::Length.from_si(t.dynamics.static_offset_m[0], Units::Us) * 1e6
        )),
        x: ChartAxis {
            label: "x",
            display: Display::Film,
            bounds: all.first().map(|_| [lo - pad, hi + pad]),
        },
        y: ChartAxis {
            label: "ẋ",
            // mm/s: the vibration velocity is of order 1 mm/s, which m/s labels round
            // to 0.001.
            display: Display::SmallSpeed,
            bounds: None,
        },
        series,
        per_element: false,
        operating: None,
    }
}

fn peaks_title(sp: &LabelledSpectrum) -> String {
    let p: Vec<String> = sp
        .peaks
        .iter()
        .filter(|p| !p.label.is_empty())
        .take(4)
        .map(|p| format!("{} {:.1} Hz", p.label, p.frequency_hz))
        .collect();
    if p.is_empty() {
        "no labelled peak".to_string()
    } else {
        p.join(", ")
    }
}

fn spectrum(t: &Tribodynamics, roller: bool) -> Chart {
    let d = &t.dynamics;
    let sp = if roller {
        &d.spectrum_roller_load
    } else {
        &d.spectrum_x
    };
    // Up to past the highest line of interest: 2 f_bn or the roller pass, whichever is
    // higher, with a margin.
    let fbn = d.base_natural_frequency_hz.unwrap_or(0.0);
    let top = (2.2 * fbn).max(1.2 * d.roller_pass_frequency_hz).max(1.0);
    // The reference of the log: 1 µm for x, 1 N for a load (the axis says which).
    let (scale, label) = if roller {
        (1.0, "log₁₀ W/N")
    } else {
        (1e6, "log₁₀ x/µm")
    };
    let floor = sp.amplitude.iter().copied().fold(0.0, f64::max) * 1e-9;
    let pts: Vec<(f64, f64)> = sp
        .frequency_hz
        .iter()
        .zip(&sp.amplitude)
        .skip(1)
        .filter(|(f, _)| **f <= top)
        .map(|(&f, &a)| (f, (a.max(floor) * scale).max(f64::MIN_POSITIVE).log10()))
        .collect();
    let (lo, hi) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p.1), hi.max(p.1))
        });
    let what = if roller { "roller 1 load" } else { "shaft x" };
    Chart {
        title: format!("{what} spectrum: {}", peaks_title(sp)),
        title_us: None,
        x: ChartAxis {
            label: "f Hz",
            display: Display::Plain,
            bounds: Some([0.0, top]),
        },
        y: ChartAxis {
            label,
            display: Display::Plain,
            bounds: pts.first().map(|_| [lo.floor(), hi.ceil()]),
        },
        series: vec![Series {
            name: what,
            points: thin(&pts),
            display: None,
        }],
        per_element: false,
        operating: None,
    }
}

fn cycle(t: &Tribodynamics) -> Chart {
    let c = &t.cycle;
    let norm = |v: &[f64]| -> (Vec<(f64, f64)>, f64) {
        let max = v.iter().copied().fold(0.0, f64::max);
        let pts = c
            .cage_angle_deg
            .iter()
            .zip(v)
            .map(|(&a, &y)| (a, if max > 0.0 { y / max } else { 0.0 }))
            .collect();
        (pts, max)
    };
    let total: Vec<f64> = c
        .boundary_friction_n
        .iter()
        .zip(&c.viscous_friction_n)
        .map(|(b, v)| b + v)
        .collect();
    let (load, wmax) = norm(&c.roller_load_n);
    let (film, hmax) = norm(&c.film_m);
    let (fric, fmax) = norm(&total);
    let (power, pmax) = norm(&c.power_w);
    let title = |u: Units| {
        format!(
            "roller 1 ÷ cycle max: W {:.0} {}, h {:.3} {}, f {:.1} {}, P {:.1} {}",
            Quantity::Force.from_si(wmax, u),
            Quantity::Force.unit(u),
            Display::Film.convert(hmax, u),
            Display::Film.unit(u),
            Quantity::Force.from_si(fmax, u),
            Quantity::Force.unit(u),
            Quantity::Power.from_si(pmax, u),
            Quantity::Power.unit(u),
        )
    };
    Chart {
        title: title(Units::Si),
        title_us: Some(title(Units::Us)),
        x: ChartAxis {
            label: "cage angle deg",
            display: Display::Plain,
            bounds: Some([0.0, 360.0]),
        },
        y: ChartAxis {
            label: "÷ max",
            display: Display::Plain,
            bounds: Some([0.0, 1.05]),
        },
        series: vec![
            Series {
                name: "load W",
                points: sort(load),
                display: None,
            },
            Series {
                name: "film h",
                points: sort(film),
                display: None,
            },
            Series {
                name: "friction f",
                points: sort(fric),
                display: None,
            },
            Series {
                name: "power P",
                points: sort(power),
                display: None,
            },
        ],
        per_element: false,
        operating: None,
    }
}

/// Points in cage-angle order (the cycle starts anywhere in [0, 360)).
fn sort(mut v: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    v.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal));
    v
}
