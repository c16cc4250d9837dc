//! A study's summary: per output the distribution over the solved points (mean, standard
//! deviation, percentiles, extremes, a histogram), the failures, the sensitivities
//! (Spearman rank correlation of each varied input with each output), and for a duty
//! cycle the combined life (Palmgren–Miner) and the mean power.

use std::fmt::Write as _;

use serde_json::{json, Map, Value};

use super::{Header, Row, StudyResult};

/// Bins of each histogram.
pub const BINS: usize = 10;

/// The distribution of one output over the solved points.
#[derive(Debug, Clone, PartialEq)]
pub struct Stats {
    /// Points with a value.
    pub n: usize,
    /// Points without one (failed, or the output absent there).
    pub missing: usize,
    /// Mean.
    pub mean: f64,
    /// Sample standard deviation (n − 1; 0 for one point).
    pub sigma: f64,
    /// 5th, 50th and 95th percentiles (linear between order statistics, Hyndman–Fan
    /// type 7, numpy's default).
    pub p5: f64,
    /// Median.
    pub p50: f64,
    /// 95th percentile.
    pub p95: f64,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
    /// Counts in [`BINS`] equal bins from min to max (the last bin closed).
    pub histogram: Vec<usize>,
}

/// The percentile `q` ∈ [0, 1] of sorted values (type 7).
pub fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let h = (sorted.len() - 1) as f64 * q;
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(sorted.len() - 1);
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}

/// The statistics of `values` (`None`: no value).
pub fn stats(values: &[Option<f64>]) -> Option<Stats> {
    let mut v: Vec<f64> = values.iter().flatten().copied().collect();
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    let mean = v.iter().sum::<f64>() / n as f64;
    let sigma = if n > 1 {
        (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt()
    } else {
        0.0
    };
    let (min, max) = (v[0], v[n - 1]);
    let mut histogram = vec![0; BINS];
    for x in &v {
        let b = if max > min {
            (((x - min) / (max - min)) * BINS as f64).floor() as usize
        } else {
            0
        };
        histogram[b.min(BINS - 1)] += 1;
    }
    Some(Stats {
        n,
        missing: values.len() - n,
        mean,
        sigma,
        p5: percentile(&v, 0.05),
        p50: percentile(&v, 0.5),
        p95: percentile(&v, 0.95),
        min,
        max,
        histogram,
    })
}

/// Ranks (1-based, ties averaged).
fn ranks(x: &[f64]) -> Vec<f64> {
    let mut idx: Vec<usize> = (0..x.len()).collect();
    idx.sort_by(|&a, &b| x[a].total_cmp(&x[b]));
    let mut r = vec![0.0; x.len()];
    let mut i = 0;
    while i < idx.len() {
        let mut j = i;
        while j + 1 < idx.len() && x[idx[j + 1]] == x[idx[i]] {
            j += 1;
        }
        let avg = (i + j) as f64 / 2.0 + 1.0;
        for k in &idx[i..=j] {
            r[*k] = avg;
        }
        i = j + 1;
    }
    r
}

/// Pearson's correlation; `None` when either side is constant or there are < 3 pairs.
fn pearson(x: &[f64], y: &[f64]) -> Option<f64> {
    let n = x.len();
    if n < 3 {
        return None;
    }
    let mx = x.iter().sum::<f64>() / n as f64;
    let my = y.iter().sum::<f64>() / n as f64;
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (a, b) in x.iter().zip(y) {
        sxy += (a - mx) * (b - my);
        sxx += (a - mx).powi(2);
        syy += (b - my).powi(2);
    }
    (sxx > 0.0 && syy > 0.0).then(|| sxy / (sxx * syy).sqrt())
}

/// Spearman's rank correlation of input column `i` with output column `o` over the rows
/// where both are numbers; `None` when undefined (constant, too few points).
pub fn spearman(rows: &[Row], i: usize, o: usize) -> Option<f64> {
    let (x, y): (Vec<f64>, Vec<f64>) = rows
        .iter()
        .filter_map(|r| {
            let x = r.inputs.get(i)?.parse::<f64>().ok()?;
            let y = (*r.outputs.get(o)?)?;
            Some((x, y))
        })
        .unzip();
    pearson(&ranks(&x), &ranks(&y))
}

/// A duty cycle's combination.
#[derive(Debug, Clone, PartialEq)]
pub struct DutyResult {
    /// Palmgren–Miner life 1/Σ(share_i/L_i), in the life column's unit; `Err`: why not.
    pub life: Result<f64, String>,
    /// Σ share_i·P_i, in the power column's unit, when a power column is named.
    pub power: Option<Result<f64, String>>,
}

/// Combines the cases of a duty cycle (rows in index order = case order). Palmgren–Miner:
/// each case uses up share_i/L_i of the bearing's life, so 1/L = Σ share_i/L_i
/// (Palmgren 1924; Miner 1945; ISO 281:2007 §A). The shares are those of the life
/// column's measure: time shares for a life in hours; for a life in revolutions, the same
/// as time shares only when the cases run at one speed (docs/studies.md).
pub fn duty(header: &Header, rows: &[Row]) -> Option<DutyResult> {
    let d = header.duty.as_ref()?;
    let column = |name: &str| header.outputs.iter().position(|o| o == name);
    let combine = |name: &str, miner: bool| -> Result<f64, String> {
        let c = column(name).ok_or_else(|| format!("no column {name}"))?;
        let mut acc = 0.0;
        for (r, share) in rows.iter().zip(&d.shares) {
            let v = r.outputs.get(c).copied().flatten().ok_or_else(|| {
                format!(
                    "case {} has no {name}{}",
                    r.index,
                    r.failure
                        .as_deref()
                        .map_or(String::new(), |f| format!(" ({f})"))
                )
            })?;
            if miner {
                if v <= 0.0 {
                    return Err(format!("case {} has {name} = {v} (not > 0)", r.index));
                }
                acc += share / v;
            } else {
                acc += share * v;
            }
        }
        Ok(if miner { 1.0 / acc } else { acc })
    };
    Some(DutyResult {
        life: combine(&d.life, true),
        power: d.power.as_deref().map(|p| combine(p, false)),
    })
}

/// A number for the text summary: six significant digits.
pub fn num(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 {
        "0".to_string()
    } else if (1e-3..1e7).contains(&a) {
        let d = (5 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.d$}")
    } else {
        format!("{v:.5e}")
    }
}

/// Inputs that vary over the rows (sensitivities are about them only).
pub fn varied_inputs(r: &StudyResult) -> Vec<usize> {
    (0..r.header.inputs.len())
        .filter(|&i| {
            let mut vals = r.rows.iter().filter_map(|row| row.inputs.get(i));
            let first = vals.next();
            vals.any(|v| Some(v) != first)
        })
        .collect()
}

/// The summary as text: one line per output (n, mean, σ, P5, P50, P95, min, max), a
/// histogram per output, the failures, the sensitivities, the duty cycle's combination.
pub fn text(r: &StudyResult) -> String {
    let h = &r.header;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "study {} ({}, {} points, {} failed): {} ({}), hash {}",
        h.study,
        h.design,
        r.rows.len(),
        r.failures(),
        h.deck,
        h.system,
        h.study_hash
    );
    let inputs: Vec<String> = h
        .inputs
        .iter()
        .zip(&h.input_units)
        .map(|(k, u)| {
            if u.is_empty() {
                k.clone()
            } else {
                format!("{k} [{u}]")
            }
        })
        .collect();
    let _ = writeln!(out, "inputs: {}", inputs.join(", "));
    let all: Vec<(String, Option<Stats>)> = h
        .outputs
        .iter()
        .enumerate()
        .map(|(o, name)| {
            let col: Vec<Option<f64>> = r.rows.iter().map(|row| row.outputs[o]).collect();
            (name.clone(), stats(&col))
        })
        .collect();
    let w = h
        .outputs
        .iter()
        .map(|s| s.chars().count())
        .max()
        .unwrap_or(6)
        .max(6);
    let _ = writeln!(
        out,
        "\n{:<w$}  {:>6}  {:>12}  {:>12}  {:>12}  {:>12}  {:>12}  {:>12}  {:>12}",
        "output", "n", "mean", "sigma", "P5", "P50", "P95", "min", "max"
    );
    for (name, s) in &all {
        match s {
            Some(s) => {
                let _ = writeln!(
                    out,
                    "{name:<w$}  {:>6}  {:>12}  {:>12}  {:>12}  {:>12}  {:>12}  {:>12}  {:>12}",
                    s.n,
                    num(s.mean),
                    num(s.sigma),
                    num(s.p5),
                    num(s.p50),
                    num(s.p95),
                    num(s.min),
                    num(s.max)
                );
            }
            None => {
                let _ = writeln!(out, "{name:<w$}  {:>6}  (no point has a value)", 0);
            }
        }
    }
    // Histograms say something from a few tens of points on; a duty cycle's few cases
    // are read from the table.
    if r.rows.len() >= 10 && h.design != "duty" {
        for (name, s) in &all {
            let Some(s) = s else { continue };
            if s.max <= s.min {
                continue;
            }
            let _ = writeln!(out, "\n{name}: histogram of {} points", s.n);
            let top = s.histogram.iter().copied().max().unwrap_or(1).max(1);
            let step = (s.max - s.min) / BINS as f64;
            for (b, c) in s.histogram.iter().enumerate() {
                let lo = s.min + step * b as f64;
                let bar = "#".repeat((c * 40).div_ceil(top));
                let _ = writeln!(
                    out,
                    "  {:>12} … {:<12} {c:>6} {bar}",
                    num(lo),
                    num(lo + step)
                );
            }
        }
    }
    let failed: Vec<&Row> = r.rows.iter().filter(|r| r.failure.is_some()).collect();
    if !failed.is_empty() {
        let _ = writeln!(out, "\n{} failed points (first 5):", failed.len());
        for row in failed.iter().take(5) {
            let f = row.failure.as_deref().unwrap_or("");
            let _ = writeln!(out, "  {}: {}", row.index, f.lines().next().unwrap_or(f));
        }
    }
    let varied = varied_inputs(r);
    if !varied.is_empty() && r.rows.len() >= 3 && h.design != "duty" {
        let _ = writeln!(
            out,
            "\nsensitivities (Spearman rank correlation of each input with each output, −1 … 1):"
        );
        let cols: Vec<&str> = varied.iter().map(|&i| h.inputs[i].as_str()).collect();
        let cw: Vec<usize> = cols.iter().map(|c| c.chars().count().max(6)).collect();
        let mut line = format!("{:<w$}", "output");
        for (c, cw) in cols.iter().zip(&cw) {
            let _ = write!(line, "  {c:>cw$}");
        }
        let _ = writeln!(out, "{}", line.trim_end());
        for (o, name) in h.outputs.iter().enumerate() {
            let mut line = format!("{name:<w$}");
            for (&i, cw) in varied.iter().zip(&cw) {
                let cell = spearman(&r.rows, i, o).map_or("-".to_string(), |s| format!("{s:+.2}"));
                let _ = write!(line, "  {cell:>cw$}");
            }
            let _ = writeln!(out, "{}", line.trim_end());
        }
    }
    if let Some(d) = duty(h, &r.rows) {
        let meta = h.duty.as_ref();
        let life = meta.map_or("", |m| m.life.as_str());
        let _ = writeln!(
            out,
            "\nduty cycle (shares {}):",
            meta.map_or(String::new(), |m| m
                .shares
                .iter()
                .map(|s| num(*s))
                .collect::<Vec<_>>()
                .join(", "))
        );
        match &d.life {
            Ok(l) => {
                let _ = writeln!(
                    out,
                    "  {life} (Palmgren–Miner, 1/L = Σ share_i/L_i): {}",
                    num(*l)
                );
            }
            Err(e) => {
                let _ = writeln!(out, "  {life}: not combined: {e}");
            }
        }
        if let (Some(p), Some(name)) = (&d.power, meta.and_then(|m| m.power.as_deref())) {
            match p {
                Ok(v) => {
                    let _ = writeln!(out, "  {name} (mean, Σ share_i·P_i): {}", num(*v));
                }
                Err(e) => {
                    let _ = writeln!(out, "  {name}: not combined: {e}");
                }
            }
        }
    }
    out
}

fn opt(v: f64) -> Value {
    serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number)
}

/// The summary as JSON: `{"outputs": {name: {n, missing, mean, sigma, p5, p50, p95, min,
/// max, histogram: {min, max, counts}}}, "failures", "sensitivities": {output: {input:
/// rho}}, "duty": {life, power}}`.
pub fn json(r: &StudyResult) -> Value {
    let h = &r.header;
    let mut outputs = Map::new();
    for (o, name) in h.outputs.iter().enumerate() {
        let col: Vec<Option<f64>> = r.rows.iter().map(|row| row.outputs[o]).collect();
        let v = stats(&col).map_or(Value::Null, |s| {
            json!({
                "n": s.n, "missing": s.missing, "mean": opt(s.mean), "sigma": opt(s.sigma),
                "p5": opt(s.p5), "p50": opt(s.p50), "p95": opt(s.p95),
                "min": opt(s.min), "max": opt(s.max),
                "histogram": {"min": opt(s.min), "max": opt(s.max), "counts": s.histogram},
            })
        });
        outputs.insert(name.clone(), v);
    }
    let mut sens = Map::new();
    if h.design != "duty" {
        let varied = varied_inputs(r);
        for (o, name) in h.outputs.iter().enumerate() {
            let mut m = Map::new();
            for &i in &varied {
                m.insert(
                    h.inputs[i].clone(),
                    spearman(&r.rows, i, o).map_or(Value::Null, opt),
                );
            }
            sens.insert(name.clone(), Value::Object(m));
        }
    }
    let mut m = Map::new();
    m.insert("outputs".into(), Value::Object(outputs));
    m.insert("failures".into(), json!(r.failures()));
    m.insert("sensitivities".into(), Value::Object(sens));
    if let Some(d) = duty(h, &r.rows) {
        let res = |x: &Result<f64, String>| match x {
            Ok(v) => opt(*v),
            Err(_) => Value::Null,
        };
        m.insert(
            "duty".into(),
            json!({
                "life": res(&d.life),
                "life_column": h.duty.as_ref().map(|d| d.life.clone()),
                "power": d.power.as_ref().map_or(Value::Null, res),
                "power_column": h.duty.as_ref().and_then(|d| d.power.clone()),
            }),
        );
    }
    Value::Object(m)
}
