//! The study the workbench's Study pane runs on the deck under edit (issue 32 item 5): a
//! study file beside the decks that names this deck (`decks/studies/*.study.toml`,
//! `decks/*.study.toml`) when it has at most [`MAX_POINTS`] points, else a small
//! tolerance Monte Carlo built from the deck — each of the system's
//! [`BearingSystem::study_keys`] the deck gives a non-zero number (the first three)
//! uniform over ±1 % of its value, [`DEFAULT_SAMPLES`] samples, seed [`SEED`].
//!
//! The default study is written out as a study file's text ([`default_text`]) and read
//! back through the same parser, plan and solver as `rollbench study`, so the pane's
//! numbers are those of `rollbench study FILE --format json` on that text: the pane
//! never samples or summarises differently.
//!
//! [`BearingSystem::study_keys`]: crate::bearings::BearingSystem::study_keys

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use super::file::{Design, Distribution, Method, Shape, StudyFile};
use super::{Header, Prepared, Row, StudyResult};
use crate::bearings::Case;
use crate::numerics::cancel::Cancel;
use crate::units::Quantity;

/// The most points the pane runs (a bigger study file is left to `rollbench study`).
pub const MAX_POINTS: usize = 256;
/// Samples of the default study the pane starts with.
pub const DEFAULT_SAMPLES: usize = 64;
/// The sample counts the pane's `h`/`l` step through.
pub const SAMPLE_CHOICES: [usize; 4] = [32, 64, 128, 256];
/// Seed of the default study (fixed: the same deck always draws the same points).
pub const SEED: u64 = 1;
/// Half-width of the default tolerance band, as a fraction of the deck's value.
pub const BAND: f64 = 0.01;
/// Keys the default study varies at most.
pub const MAX_KEYS: usize = 3;

/// Where the pane's study comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// A study file that names the deck.
    File(PathBuf),
    /// The default tolerance Monte Carlo.
    Default,
}

/// A study ready for the pane.
pub struct PaneStudy {
    /// The study, prepared on the deck under edit.
    pub prepared: Prepared,
    /// Where it came from.
    pub source: Source,
    /// The study file's text (the default study's as generated).
    pub text: String,
    /// What is varied, one line each, in deck units.
    pub varied: Vec<String>,
    /// Why a study file beside the deck is not the one run (too many points, refused).
    pub notes: Vec<String>,
}

/// A TOML number that reads back to exactly `v` (`{:?}` keeps a decimal point or an
/// exponent, so the text is a TOML float).
fn toml_number(v: f64) -> String {
    format!("{v:?}")
}

/// The default study's text for `case` (deck file `deck_file`, relative to the study
/// file), `samples` points; an error saying so when the deck gives none of its system's
/// study keys a non-zero number.
pub fn default_text(case: &dyn Case, deck_file: &str, samples: usize) -> Result<String, String> {
    let system = case.system();
    let keys: Vec<(&str, f64)> = system
        .study_keys()
        .iter()
        .filter_map(|k| {
            let v = case.get(k)?.trim().parse::<f64>().ok()?;
            (v.is_finite() && v != 0.0).then_some((*k, v))
        })
        .take(MAX_KEYS)
        .collect();
    if keys.is_empty() {
        return Err(format!(
            "no default study: the deck gives none of the {} keys a tolerance study varies ({}) a non-zero number; put a study file naming this deck beside it (docs/studies.md)",
            system.id(),
            if system.study_keys().is_empty() {
                "none named".to_string()
            } else {
                system.study_keys().join(", ")
            }
        ));
    }
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# The workbench's default study: each key uniform over ±{} % of the deck's value.",
        BAND * 100.0
    );
    let _ = writeln!(s, "deck = {}", toml_edit::Value::from(deck_file));
    let _ = writeln!(s, "\n[sample]");
    let _ = writeln!(s, "method = \"monte-carlo\"");
    let _ = writeln!(s, "samples = {samples}");
    let _ = writeln!(s, "seed = {SEED}");
    for (k, v) in keys {
        let _ = writeln!(
            s,
            "\"{k}\" = {{ tolerance = [{}, {}] }}",
            toml_number(v),
            toml_number((v * BAND).abs())
        );
    }
    Ok(s)
}

/// The study files beside `deck` (in `studies/` next to it, or next to it) whose `deck`
/// is this file, sorted by path.
pub fn study_files_for(deck: &Path) -> Vec<PathBuf> {
    let Ok(me) = std::fs::canonicalize(deck) else {
        return Vec::new();
    };
    let dir = deck.parent().unwrap_or_else(|| Path::new("."));
    let mut found = Vec::new();
    for d in [dir.join("studies"), dir.to_path_buf()] {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries.flatten() {
            let p = e.path();
            if !p.to_string_lossy().ends_with(".study.toml") {
                continue;
            }
            let Ok(text) = crate::deck::read_deck_text(&p) else {
                continue;
            };
            let Ok(f) = super::file::parse(&text, &p) else {
                continue;
            };
            if std::fs::canonicalize(&f.deck).is_ok_and(|d| d == me) {
                found.push(p);
            }
        }
    }
    found.sort();
    found
}

/// Points of a parsed study file.
fn points(f: &StudyFile) -> usize {
    super::plan::Plan::new(f).len()
}

/// The pane's study of `case` (read from `deck_path`, if any): the first study file
/// naming the deck with at most [`MAX_POINTS`] points, else the default study of
/// `samples` points. The study runs on `case` as edited, not on the file.
pub fn for_deck(
    case: &dyn Case,
    deck_path: Option<&Path>,
    samples: usize,
) -> Result<PaneStudy, String> {
    let mut notes = Vec::new();
    if let Some(deck) = deck_path {
        for path in study_files_for(deck) {
            let Ok(text) = crate::deck::read_deck_text(&path) else {
                continue;
            };
            let Ok(file) = super::file::parse(&text, &path) else {
                continue;
            };
            let n = points(&file);
            if n > MAX_POINTS {
                notes.push(format!(
                    "{} has {n} points, more than the pane's {MAX_POINTS}: `rollbench study` runs it",
                    path.display()
                ));
                continue;
            }
            let base = case.with_values(&[]).map_err(|e| e.to_string())?;
            match super::prepare_on(&text, &path, base) {
                Ok(prepared) => {
                    let varied = describe(&prepared.file, &prepared.header);
                    return Ok(PaneStudy {
                        prepared,
                        source: Source::File(path),
                        text,
                        varied,
                        notes,
                    });
                }
                Err(e) => notes.push(format!(
                    "{} is refused on this deck: {}",
                    path.display(),
                    e.lines().next().unwrap_or("")
                )),
            }
        }
    }
    let deck_file = deck_path.and_then(Path::file_name).map_or_else(
        || "deck.toml".to_string(),
        |f| f.to_string_lossy().into_owned(),
    );
    let text = default_text(case, &deck_file, samples.clamp(1, MAX_POINTS))?;
    let study_path = deck_path
        .and_then(Path::parent)
        .unwrap_or_else(|| Path::new(""))
        .join("workbench.study.toml");
    let base = case.with_values(&[]).map_err(|e| e.to_string())?;
    let prepared = super::prepare_on(&text, &study_path, base)?;
    let varied = describe(&prepared.file, &prepared.header);
    Ok(PaneStudy {
        prepared,
        source: Source::Default,
        text,
        varied,
        notes,
    })
}

/// A number as the study draws from it, to 12 significant figures (shortest form of
/// that): the ±1 % band of 0.0008 in reads `0.000008`, not the `0.000008000000000000001`
/// its product is in binary. The study's own text keeps the exact value.
fn short(v: f64) -> String {
    let rounded: f64 = format!("{v:.11e}").parse().unwrap_or(v);
    format!("{rounded}")
}

/// A percentage to three decimals, trailing zeros dropped (`1`, `0.5`).
fn percent(v: f64) -> String {
    let t = format!("{v:.3}");
    t.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// One line per varied key (deck units), led by the design.
pub fn describe(f: &StudyFile, h: &Header) -> Vec<String> {
    let unit = |k: &str| {
        h.inputs
            .iter()
            .position(|i| i == k)
            .and_then(|i| h.input_units.get(i))
            .filter(|u| !u.is_empty())
            .map_or(String::new(), |u| format!(" {u}"))
    };
    let mut out = Vec::new();
    match &f.design {
        Design::Grid(axes) => {
            out.push(format!("grid, {} points: every combination of", points(f)));
            for a in axes {
                let vals = if a.values.len() <= 4 {
                    a.values.join(", ")
                } else {
                    format!(
                        "{}, {}, …, {} ({} values)",
                        a.values[0],
                        a.values[1],
                        a.values[a.values.len() - 1],
                        a.values.len()
                    )
                };
                out.push(format!("{}: {vals}{}", a.key, unit(&a.key)));
            }
        }
        Design::Sample(s) => {
            out.push(format!(
                "{}, {} samples, seed {}",
                match s.method {
                    Method::MonteCarlo => "Monte Carlo",
                    Method::LatinHypercube => "Latin hypercube",
                },
                s.samples,
                s.seed
            ));
            for (k, d) in &s.keys {
                let u = unit(k);
                let what = match *d {
                    Distribution::Normal { mean, sigma } => {
                        format!("normal, mean {}{u}, σ {}{u}", short(mean), short(sigma))
                    }
                    Distribution::Uniform { lo, hi } => {
                        format!("uniform {} … {}{u}", short(lo), short(hi))
                    }
                    Distribution::Tolerance {
                        nominal,
                        band,
                        shape,
                    } => {
                        let pct = if nominal != 0.0 {
                            format!(" (±{} %)", percent((band / nominal).abs() * 100.0))
                        } else {
                            String::new()
                        };
                        let shape = match shape {
                            Shape::Uniform => "uniform".to_string(),
                            Shape::TruncatedNormal { sigmas } => {
                                format!("normal, band = {}σ", short(sigmas))
                            }
                        };
                        format!("{} ± {}{u}{pct}, {shape}", short(nominal), short(band))
                    }
                };
                out.push(format!("{k}: {what}"));
            }
        }
        Design::Duty(d) => {
            out.push(format!("duty cycle of {} cases", d.cases.len()));
            for (i, c) in d.cases.iter().enumerate() {
                let set: Vec<String> = c
                    .set
                    .iter()
                    .map(|(k, v)| format!("{k} = {v}{}", unit(k)))
                    .collect();
                out.push(format!(
                    "case {}: share {}, {}",
                    i + 1,
                    short(c.share),
                    set.join(", ")
                ));
            }
        }
    }
    out
}

/// What the pane draws: the study as described and its rows so far.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyProgress {
    /// Where the study comes from.
    pub source: Source,
    /// What is varied ([`describe`]).
    pub varied: Vec<String>,
    /// Why a study file beside the deck is not the one run.
    pub notes: Vec<String>,
    /// The study's header (columns).
    pub header: Header,
    /// Each output column's quantity (display units).
    pub quantities: Vec<Option<Quantity>>,
    /// The rows solved so far, in index order.
    pub rows: Vec<Row>,
    /// Points of the whole study.
    pub total: usize,
    /// All points solved.
    pub finished: bool,
    /// Why there is no study (no default keys, a refused file).
    pub error: Option<String>,
}

impl StudyProgress {
    /// No study: why.
    pub fn failed(error: String) -> StudyProgress {
        StudyProgress {
            source: Source::Default,
            varied: Vec::new(),
            notes: Vec::new(),
            header: Header {
                format: super::PART_FORMAT.to_string(),
                study_hash: String::new(),
                study: String::new(),
                deck: String::new(),
                system: String::new(),
                design: String::new(),
                points: 0,
                shard: None,
                inputs: Vec::new(),
                input_units: Vec::new(),
                outputs: Vec::new(),
                duty: None,
                version: String::new(),
            },
            quantities: Vec::new(),
            rows: Vec::new(),
            total: 0,
            finished: true,
            error: Some(error),
        }
    }

    /// The rows so far as a study result (what the summary reads).
    pub fn result(&self) -> StudyResult {
        StudyResult {
            header: self.header.clone(),
            rows: self.rows.clone(),
        }
    }
}

/// Runs `study`, its points in batches over the cores (rayon), reporting the rows so far
/// after each batch; `None` when `cancel` was raised (the next edit), else the finished
/// progress.
pub fn run(
    study: &PaneStudy,
    cancel: &AtomicBool,
    report: &mut dyn FnMut(&StudyProgress),
) -> Option<StudyProgress> {
    let p = &study.prepared;
    let total = p.plan.len();
    let mut progress = StudyProgress {
        source: study.source.clone(),
        varied: study.varied.clone(),
        notes: study.notes.clone(),
        header: p.header.clone(),
        quantities: p.output_quantities.clone(),
        rows: Vec::with_capacity(total),
        total,
        finished: false,
        error: None,
    };
    report(&progress);
    let batch = rayon::current_num_threads().max(1) * 2;
    let indices: Vec<usize> = (0..total).collect();
    for chunk in indices.chunks(batch) {
        if cancel.load(Ordering::Acquire) {
            return None;
        }
        let rows: Vec<Row> = chunk
            .par_iter()
            .map(|&i| p.solve_with(i, Cancel::new(cancel)))
            .collect();
        if cancel.load(Ordering::Acquire) {
            return None; // a point cut short is not an answer
        }
        progress.rows.extend(rows);
        progress.finished = progress.rows.len() == total;
        report(&progress);
    }
    progress.finished = true;
    Some(progress)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pane's description shows 12 significant figures: binary round-off of a band
    /// (0.0008 × 0.01) is not shown as data; a value with fewer figures is unchanged.
    #[test]
    fn description_numbers_drop_binary_round_off() {
        assert_eq!(short(0.0008 * 0.01), "0.000008");
        assert_eq!(format!("{}", 0.0008 * 0.01), "0.000008000000000000001");
        assert_eq!(short(0.1 + 0.2), "0.3");
        assert_eq!(short(12345.678), "12345.678");
        assert_eq!(short(1.0 / 3.0), "0.333333333333");
        assert_eq!(short(-2.5e7), "-25000000");
    }

    fn case(name: &str) -> Box<dyn Case> {
        let path = format!("{}/decks/{name}.toml", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).expect("deck");
        crate::bearings::load_case(&text, &path, &[]).expect("loads")
    }

    /// The default study varies the system's first keys the deck gives a non-zero value,
    /// ±1 % uniform about the deck's value, and its text parses back to exactly that.
    #[test]
    fn default_study_tolerances_the_decks_own_values() {
        let c = case("radial_si");
        let text = default_text(c.as_ref(), "radial_si.toml", 64).expect("text");
        let f = super::super::file::parse(&text, Path::new("decks/w.study.toml")).expect("parses");
        let Design::Sample(s) = &f.design else {
            panic!("a sample")
        };
        assert_eq!(
            (s.samples, s.seed, s.method),
            (64, SEED, Method::MonteCarlo)
        );
        // radial_si: roller diameter 0.016 m, clearance 3e-5 m, radial load 20000 N
        // (the axial load is 0: not varied; three keys at most).
        let keys: Vec<&str> = s.keys.iter().map(|(k, _)| k.as_str()).collect();
        assert_eq!(
            keys,
            [
                "geometry.roller_diameter",
                "geometry.diametral_clearance",
                "operating.radial_load"
            ]
        );
        for (k, d) in &s.keys {
            let v: f64 = c.get(k).expect("key").parse().expect("number");
            assert_eq!(
                *d,
                Distribution::Tolerance {
                    nominal: v,
                    band: v * BAND,
                    shape: Shape::Uniform
                },
                "{k}"
            );
        }
    }

    /// A study file naming the deck is found (and only by the deck it names).
    #[test]
    fn the_decks_study_file_is_found() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/decks");
        let found = study_files_for(&Path::new(dir).join("trb_32007.toml"));
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0].ends_with("studies/trb_32007_clearance_tolerance.study.toml"));
        assert!(study_files_for(&Path::new(dir).join("thrust.toml")).is_empty());
    }
}
