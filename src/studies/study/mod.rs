//! `rollbench study`: design studies over one deck (issue 32) — a full-factorial grid, a
//! Monte Carlo or Latin-hypercube sample of toleranced keys, or a duty cycle combined by
//! Palmgren–Miner — generic over every bearing system through [`Case`].
//!
//! A study is a pure function of its file, its deck and the point's index: point `i`'s
//! deck values come from [`plan::Plan::point`], each point is a new case built from the
//! validated deck with [`CaseDeck::with_values`] (the deck's own validation, no re-reading
//! of the deck file) and solved cold, without the transient, as `run --set` would. Cold
//! rather than warm-started along a worker's run: a warm start's answer depends (to the
//! solver tolerance) on which point came before, and a shard must give the same bits as
//! the local run. A point that cannot be built or solved is a row with its reason.
//!
//! Parts of a sharded run ([`part`]) and the local run's `jsonl` share one format: a
//! header line ([`Header`]: the study's hash, the columns) then one row a line.
//!
//! [`CaseDeck::with_values`]: crate::bearings::CaseDeck::with_values
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod file;
pub mod output;
pub mod part;
pub mod plan;
pub mod random;
pub mod summary;
pub mod workbench;

use std::path::Path;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::bearings::{Case, RunOptions};
use crate::numerics::cancel::Cancel;
use file::{Design, StudyFile};
use plan::Plan;

/// The first field of a part's header line: what the file is.
pub const PART_FORMAT: &str = "rollbench-study-part-1";

/// The duty cycle's combination, carried in the header so a merge can combine.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DutyMeta {
    /// Each case's time share, in index order.
    pub shares: Vec<f64>,
    /// The output column holding each case's life.
    pub life: String,
    /// The output column holding each case's power loss, if any.
    pub power: Option<String>,
}

/// What every part and every result of a study carries: where it came from and its
/// columns. Two parts merge only when their headers agree except for `shard`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Header {
    /// [`PART_FORMAT`].
    pub format: String,
    /// Hash of the study file's text, the deck's text and the rollbench version.
    pub study_hash: String,
    /// The study file as named.
    pub study: String,
    /// The deck's name.
    pub deck: String,
    /// The bearing system (`type`).
    pub system: String,
    /// `"grid"`, `"sample"` or `"duty"`.
    pub design: String,
    /// Number of points of the whole study.
    pub points: usize,
    /// `"I/N"` for a shard, absent for a whole run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shard: Option<String>,
    /// The deck keys set per point.
    pub inputs: Vec<String>,
    /// Their units in the deck (empty: dimensionless or not a scalar field).
    pub input_units: Vec<String>,
    /// The output columns (key-output names, SI with the unit in the name, or JSON
    /// pointers into the run's JSON report).
    pub outputs: Vec<String>,
    /// The duty cycle's shares and columns.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duty: Option<DutyMeta>,
    /// rollbench's version.
    pub version: String,
}

impl Header {
    /// The header with its shard field cleared: what must agree between parts.
    pub fn whole(&self) -> Header {
        Header {
            shard: None,
            ..self.clone()
        }
    }
}

/// One point's result.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// The point's index in the study (0-based).
    pub index: usize,
    /// The values written into the deck, one per input column (deck units).
    pub inputs: Vec<String>,
    /// One per output column (SI), `null` where absent, not finite or failed.
    pub outputs: Vec<Option<f64>>,
    /// Why the point has no outputs, if it has none.
    pub failure: Option<String>,
}

/// A whole study's result: its header and every row in index order.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyResult {
    /// Header (no shard).
    pub header: Header,
    /// Rows, in index order.
    pub rows: Vec<Row>,
}

impl StudyResult {
    /// Rows whose point failed.
    pub fn failures(&self) -> usize {
        self.rows.iter().filter(|r| r.failure.is_some()).count()
    }
}

/// A study ready to run: its plan, the validated deck and the header.
pub struct Prepared {
    /// The parsed file.
    pub file: StudyFile,
    /// Its points.
    pub plan: Plan,
    /// The deck as read (no point's values set).
    pub base: Box<dyn Case>,
    /// Header of every part and result.
    pub header: Header,
    /// Each input key's value in the unmodified deck (shown where a duty case keeps it).
    base_inputs: Vec<String>,
    /// Each output column's quantity (a key output's, for display units; `None`: a JSON
    /// pointer, or the deck did not solve to say).
    pub output_quantities: Vec<Option<crate::units::Quantity>>,
}

/// 64-bit FNV-1a (Fowler–Noll–Vo): a stable hash of bytes, the same on every machine and
/// build (std's hashers are not promised to be). Identifies a study, guards nothing.
fn fnv1a(parts: &[&[u8]]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for p in parts {
        // The length first, so ("ab", "c") and ("a", "bc") differ.
        for b in (p.len() as u64).to_le_bytes().iter().chain(p.iter()) {
            h ^= u64::from(*b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
    }
    h
}

/// The study's identity: hash of the study file's text, the deck's text and the version.
pub fn study_hash(study_text: &str, deck_text: &str) -> String {
    format!(
        "{:016x}",
        fnv1a(&[
            env!("CARGO_PKG_VERSION").as_bytes(),
            study_text.as_bytes(),
            deck_text.as_bytes()
        ])
    )
}

/// Reads the study file at `path` and its deck, checks every key and output against the
/// deck (one solve of the unmodified deck, which also fixes the output columns when the
/// file lists none), and returns the study ready to run. Errors name the file, line and key.
pub fn prepare(path: &Path) -> Result<Prepared, String> {
    let text = crate::deck::read_deck_text(path).map_err(|e| e.to_string())?;
    prepare_text(&text, path)
}

/// [`prepare`] from the study file's text (`path` names it and anchors the deck path).
pub fn prepare_text(text: &str, path: &Path) -> Result<Prepared, String> {
    let file = file::parse(text, path).map_err(|errs| {
        errs.iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n")
    })?;
    let deck_text = crate::deck::read_deck_text(&file.deck)
        .map_err(|e| format!("{}: deck = {}: {e}", file.source, file.deck.display()))?;
    let base = crate::bearings::load_case(&deck_text, &file.deck.display().to_string(), &[])
        .map_err(|e| e.to_string())?;
    prepare_parsed(file, text, base, &deck_text)
}

/// [`prepare_text`] over a deck already loaded (`base`, whose text is `deck_text`): the
/// workbench's Study pane runs a study on the deck under edit, not on the file's.
pub fn prepare_on(text: &str, path: &Path, base: Box<dyn Case>) -> Result<Prepared, String> {
    let file = file::parse(text, path).map_err(|errs| {
        errs.iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n")
    })?;
    let deck_text = base.text();
    prepare_parsed(file, text, base, &deck_text)
}

/// The study of a parsed file over its loaded deck (see [`prepare`]).
fn prepare_parsed(
    file: StudyFile,
    text: &str,
    base: Box<dyn Case>,
    deck_text: &str,
) -> Result<Prepared, String> {
    let plan = Plan::new(&file);
    // A key the deck does not know is wrong for every point: say so once, with the deck's
    // own message (close matches), before anything is solved.
    for (k, key) in plan.keys().iter().enumerate() {
        if base.get(key).is_none() {
            let v = (0..plan.len())
                .find_map(|i| plan.point(i).get(k).cloned().flatten())
                .unwrap_or_default();
            if let Err(e) = base.with_value(key, &v) {
                return Err(format!("{}: {key}: {e}", file.source));
            }
        }
    }
    let units = base.units();
    let fields = base.fields();
    let input_units = plan
        .keys()
        .iter()
        .map(|k| {
            fields
                .iter()
                .find(|f| f.key == k)
                .map_or(String::new(), |f| f.unit(units).to_string())
        })
        .collect();
    let base_inputs = plan
        .keys()
        .iter()
        .map(|k| base.get(k).unwrap_or_default())
        .collect();
    let (outputs, output_quantities) = output_columns(&file, base.as_ref())?;
    let duty = match &file.design {
        Design::Duty(d) => {
            for name in std::iter::once(&d.life).chain(d.power.iter()) {
                if !outputs.contains(name) {
                    return Err(format!(
                        "{}: duty names `{name}`, which is not among the study's outputs ({}); add it to outputs",
                        file.source,
                        outputs.join(", ")
                    ));
                }
            }
            Some(DutyMeta {
                shares: d.cases.iter().map(|c| c.share).collect(),
                life: d.life.clone(),
                power: d.power.clone(),
            })
        }
        _ => None,
    };
    let header = Header {
        format: PART_FORMAT.to_string(),
        study_hash: study_hash(text, deck_text),
        study: file.source.clone(),
        deck: base.name().to_string(),
        system: base.system().id().to_string(),
        design: file.design.kind().to_string(),
        points: plan.len(),
        shard: None,
        inputs: plan.keys().to_vec(),
        input_units,
        outputs,
        duty,
        version: env!("CARGO_PKG_VERSION").to_string(),
    };
    Ok(Prepared {
        file,
        plan,
        base,
        header,
        base_inputs,
        output_quantities,
    })
}

/// The output columns: the file's list, each checked against one solve of the unmodified
/// deck (a key output it has, or a JSON pointer to a number), or that solve's key outputs
/// when the file lists none.
fn output_columns(file: &StudyFile, base: &dyn Case) -> Result<Columns, String> {
    let solved = base.solve(
        RunOptions {
            skip_transient: true,
        },
        Cancel::NONE,
    );
    let solution = match solved {
        Ok(s) => s,
        Err(e) if file.outputs.is_empty() => {
            return Err(format!(
                "{}: the deck itself does not solve, so the output columns cannot be known (name them in outputs = [...]): {e}",
                file.source
            ))
        }
        // The deck as written fails but its points may not: the names cannot be checked.
        Err(_) => return Ok((file.outputs.clone(), vec![None; file.outputs.len()])),
    };
    let view = solution.view();
    let names: Vec<&str> = view.key_outputs.iter().map(|o| o.name).collect();
    let quantity = |name: &str| {
        view.key_outputs
            .iter()
            .find(|o| o.name == name)
            .map(|o| o.quantity)
    };
    if file.outputs.is_empty() {
        return Ok((
            names.iter().map(|s| s.to_string()).collect(),
            names.iter().map(|n| quantity(n)).collect(),
        ));
    }
    let json = file
        .outputs
        .iter()
        .any(|o| o.starts_with('/'))
        .then(|| solution.json());
    for o in &file.outputs {
        if let Some(j) = json.as_ref().filter(|_| o.starts_with('/')) {
            if !j.pointer(o).is_some_and(serde_json::Value::is_number) {
                return Err(format!(
                    "{}: outputs: `{o}` is not a number in the deck's JSON report (`rollbench run {} --format json` shows its paths)",
                    file.source,
                    file.deck.display()
                ));
            }
        } else if !o.starts_with('/') && !names.contains(&o.as_str()) {
            return Err(format!(
                "{}: outputs: `{o}` is not a key output of this {} deck (it has: {}; or give a JSON pointer such as /life/…)",
                file.source,
                base.system().id(),
                names.join(", ")
            ));
        }
    }
    let quantities = file.outputs.iter().map(|o| quantity(o)).collect();
    Ok((file.outputs.clone(), quantities))
}

/// Output column names and their quantities.
type Columns = (Vec<String>, Vec<Option<crate::units::Quantity>>);

/// A panic's message.
fn panic_text(p: &(dyn std::any::Any + Send)) -> String {
    p.downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| p.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".to_string())
}

impl Prepared {
    /// Solves point `index`: the deck with the point's values, solved cold without the
    /// transient, reduced to the output columns. Never fails: a refused value, a solver
    /// failure or a panic inside a solver is the row's `failure`.
    pub fn solve(&self, index: usize) -> Row {
        self.solve_with(index, Cancel::NONE)
    }

    /// [`Prepared::solve`] with a cancel flag checked inside the point's solve (the
    /// workbench's Study pane: the next edit stops it; a cancelled point's row says so
    /// and is dropped by the caller).
    pub fn solve_with(&self, index: usize, cancel: Cancel) -> Row {
        let texts = self.plan.point(index);
        let keys = self.plan.keys();
        let assignments: Vec<String> = keys
            .iter()
            .zip(&texts)
            .filter_map(|(k, t)| t.as_ref().map(|t| format!("{k}={t}")))
            .collect();
        let inputs: Vec<String> = texts
            .into_iter()
            .zip(&self.base_inputs)
            .map(|(t, b)| t.unwrap_or_else(|| b.clone()))
            .collect();
        let n = self.header.outputs.len();
        let failed = |failure: String| Row {
            index,
            inputs: inputs.clone(),
            outputs: vec![None; n],
            failure: Some(failure),
        };
        let case = match self.base.with_values(&assignments) {
            Ok(c) => c,
            Err(e) => return failed(format!("the deck refuses this point: {e}")),
        };
        let need_json = self.header.outputs.iter().any(|o| o.starts_with('/'));
        let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            case.solve(
                RunOptions {
                    skip_transient: true,
                },
                cancel,
            )
            .map(|s| (s.view().key_outputs, need_json.then(|| s.json())))
        }));
        match run {
            Ok(Ok((keys, json))) => Row {
                index,
                inputs,
                outputs: self
                    .header
                    .outputs
                    .iter()
                    .map(|o| {
                        let v = if o.starts_with('/') {
                            json.as_ref()
                                .and_then(|j| j.pointer(o))
                                .and_then(serde_json::Value::as_f64)
                        } else {
                            keys.iter().find(|k| k.name == o).and_then(|k| k.value)
                        };
                        // Not finite: absent (JSON has no NaN; every writer says the same).
                        v.filter(|x| x.is_finite())
                    })
                    .collect(),
                failure: None,
            },
            Ok(Err(e)) => failed(e),
            Err(p) => failed(format!("solver panicked: {}", panic_text(p.as_ref()))),
        }
    }

    /// Solves `indices` in parallel over the cores (rayon), calling `on_row` as each
    /// finishes (from any worker thread; the journal of a shard, a progress bar), and
    /// returns the rows in the order of `indices`.
    pub fn solve_all(&self, indices: &[usize], on_row: &(dyn Fn(&Row) + Sync)) -> Vec<Row> {
        indices
            .par_iter()
            .map(|&i| {
                let r = self.solve(i);
                on_row(&r);
                r
            })
            .collect()
    }

    /// The whole study, locally: every point in parallel; a progress bar on standard
    /// error when `progress`.
    pub fn run(&self, progress: bool) -> StudyResult {
        let bar = progress_bar(progress, self.plan.len(), &self.file.source);
        let indices: Vec<usize> = (0..self.plan.len()).collect();
        let rows = self.solve_all(&indices, &|_| {
            if let Some(b) = &bar {
                b.inc(1);
            }
        });
        if let Some(b) = bar {
            b.finish_and_clear();
        }
        StudyResult {
            header: self.header.clone(),
            rows,
        }
    }
}

/// A progress bar on standard error (none when `show` is false).
pub fn progress_bar(show: bool, len: usize, what: &str) -> Option<indicatif::ProgressBar> {
    if !show {
        return None;
    }
    let bar = indicatif::ProgressBar::new(len as u64);
    if let Ok(style) = indicatif::ProgressStyle::with_template(
        "study {msg} {wide_bar} {pos}/{len} points, {elapsed} (eta {eta})",
    ) {
        bar.set_style(style);
    }
    bar.set_message(what.to_string());
    Some(bar)
}

#[cfg(test)]
mod tests;
