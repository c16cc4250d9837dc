//! Shards of a study for a cluster scheduler, and their merge.
//!
//! Shard `I/N` computes the points whose index i ≡ I (mod N): round robin rather than
//! contiguous blocks, because a grid's cost varies smoothly along its keys (the last key
//! fastest: a block would give one shard all the high-speed, slow-to-solve points) and
//! round robin spreads any such trend evenly over the shards; a sample's points cost alike
//! either way. Points are independent (solved cold), so nothing is lost by not running
//! neighbours together.
//!
//! A part is JSONL: a header line ([`Header`], with the study's hash and `shard`), then
//! one row a line. While a shard runs, each finished row is appended to its part at once
//! (a journal), so a shard killed by a preemption keeps what it solved; re-running it
//! reads the part, discards a torn last line, skips the indices present, and computes the
//! rest. At the end the part is rewritten in index order through the one safe writer
//! (atomically), so a resumed shard's part is byte for byte the uninterrupted one's.

use std::collections::HashSet;
use std::io::Write as _;
use std::path::Path;
use std::sync::Mutex;

use super::output::{header_line, row_line};
use super::{Header, Prepared, Row, StudyResult, PART_FORMAT};

/// One shard: index I of N.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// I, 0 ≤ I < N.
    pub index: usize,
    /// N ≥ 1.
    pub count: usize,
}

impl Shard {
    /// `"I/N"`.
    pub fn label(&self) -> String {
        format!("{}/{}", self.index, self.count)
    }

    /// Parses `I/N`, or `auto`: Slurm's `SLURM_ARRAY_TASK_ID` (less
    /// `SLURM_ARRAY_TASK_MIN`) of `SLURM_ARRAY_TASK_COUNT`, or Kubernetes' Indexed Job's
    /// `JOB_COMPLETION_INDEX` of `shards` (`--shards N`) or `ROLLBENCH_SHARDS`. `env`
    /// reads an environment variable (a parameter, for tests).
    pub fn parse(
        spec: &str,
        shards: Option<usize>,
        env: &dyn Fn(&str) -> Option<String>,
    ) -> Result<Shard, String> {
        let num = |name: &str, v: &str| -> Result<usize, String> {
            v.trim()
                .parse::<usize>()
                .map_err(|_| format!("--shard {spec}: {name} = `{v}` is not a whole number ≥ 0"))
        };
        let (index, count) = if spec == "auto" {
            if let Some(id) = env("SLURM_ARRAY_TASK_ID") {
                let id = num("SLURM_ARRAY_TASK_ID", &id)?;
                let min = match env("SLURM_ARRAY_TASK_MIN") {
                    Some(m) => num("SLURM_ARRAY_TASK_MIN", &m)?,
                    None => 0,
                };
                let count = match (shards, env("SLURM_ARRAY_TASK_COUNT")) {
                    (Some(n), _) => n,
                    (None, Some(c)) => num("SLURM_ARRAY_TASK_COUNT", &c)?,
                    (None, None) => {
                        return Err("--shard auto: SLURM_ARRAY_TASK_ID is set but not SLURM_ARRAY_TASK_COUNT; give --shards N".to_string())
                    }
                };
                (id.checked_sub(min).ok_or_else(|| format!("--shard auto: SLURM_ARRAY_TASK_ID {id} is below SLURM_ARRAY_TASK_MIN {min}"))?, count)
            } else if let Some(id) = env("JOB_COMPLETION_INDEX") {
                let id = num("JOB_COMPLETION_INDEX", &id)?;
                let count = match (shards, env("ROLLBENCH_SHARDS")) {
                    (Some(n), _) => n,
                    (None, Some(c)) => num("ROLLBENCH_SHARDS", &c)?,
                    (None, None) => {
                        return Err("--shard auto: JOB_COMPLETION_INDEX is set but not the number of shards; give --shards N or ROLLBENCH_SHARDS (the Job's completions)".to_string())
                    }
                };
                (id, count)
            } else {
                return Err("--shard auto: neither SLURM_ARRAY_TASK_ID (a Slurm array job) nor JOB_COMPLETION_INDEX (a Kubernetes Indexed Job) is set; give --shard I/N".to_string());
            }
        } else {
            let Some((i, n)) = spec.split_once('/') else {
                return Err(format!("--shard {spec}: expected I/N (e.g. 0/4) or auto"));
            };
            (num("I", i)?, num("N", n)?)
        };
        if count == 0 || index >= count {
            return Err(format!(
                "--shard {spec}: shard {index} of {count}: need N ≥ 1 and 0 ≤ I < N"
            ));
        }
        Ok(Shard { index, count })
    }

    /// The indices of this shard among `points`: I, I + N, I + 2N, …
    pub fn indices(&self, points: usize) -> Vec<usize> {
        (self.index..points).step_by(self.count.max(1)).collect()
    }
}

/// A part as read.
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// Its header.
    pub header: Header,
    /// Its complete rows, in file order.
    pub rows: Vec<Row>,
    /// The 1-based line of a torn last line (no newline, or not a whole row), if any.
    pub torn: Option<usize>,
}

/// Reads a part's text (`name` for messages). A last line without its newline, or that
/// is not a whole row, is reported in [`Part::torn`] and left out; any other bad line is
/// an error naming it.
pub fn read_part(text: &str, name: &str) -> Result<Part, String> {
    let not_part = || {
        format!(
            "{name} is not a rollbench study part (its first line is not a `{PART_FORMAT}` header)"
        )
    };
    let mut lines = text.split_inclusive('\n');
    let first = lines.next().ok_or_else(not_part)?;
    let header: Header = serde_json::from_str(first.trim_end()).map_err(|_| not_part())?;
    if header.format != PART_FORMAT || !first.ends_with('\n') {
        return Err(not_part());
    }
    let mut rows = Vec::new();
    let mut torn = None;
    let all: Vec<&str> = lines.collect();
    for (k, line) in all.iter().enumerate() {
        let number = k + 2;
        let last = k + 1 == all.len();
        let parsed: Option<Row> = serde_json::from_str(line.trim_end()).ok();
        match parsed {
            Some(row) if line.ends_with('\n') => {
                if row.index >= header.points
                    || row.inputs.len() != header.inputs.len()
                    || row.outputs.len() != header.outputs.len()
                {
                    return Err(format!(
                        "{name}:{number}: the row does not fit its header (index {} of {} points, {} inputs, {} outputs)",
                        row.index,
                        header.points,
                        row.inputs.len(),
                        row.outputs.len()
                    ));
                }
                rows.push(row);
            }
            _ if last => torn = Some(number),
            _ => return Err(format!("{name}:{number}: not a row of a study part")),
        }
    }
    Ok(Part { header, rows, torn })
}

/// What a shard run did.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ShardRun {
    /// Points of the shard.
    pub points: usize,
    /// Found already in the part (resumed).
    pub kept: usize,
    /// Computed now.
    pub computed: usize,
    /// Failed points among all of the shard's.
    pub failures: usize,
    /// Whether a torn last line was discarded.
    pub discarded_torn_line: bool,
}

/// Computes shard `shard` of `study` into the part `path` (a regular file; created, or
/// resumed when it holds a part of this very shard), in parallel; `on_row` after each
/// point (progress). Errors name the part and why (another study's part, another shard's,
/// a write that failed).
pub fn run_shard(
    study: &Prepared,
    shard: Shard,
    path: &Path,
    on_row: &(dyn Fn() + Sync),
) -> Result<ShardRun, String> {
    let name = path.display().to_string();
    let header = Header {
        shard: Some(shard.label()),
        ..study.header.clone()
    };
    let mine: Vec<usize> = shard.indices(study.plan.len());
    let mut kept: Vec<Row> = Vec::new();
    let mut discarded_torn_line = false;
    match std::fs::metadata(path) {
        Ok(m) if !m.is_file() => {
            return Err(format!("--output {name}: a shard's part must be a regular file (it is appended to as points finish)"));
        }
        Ok(m) if m.len() > 0 => {
            let text = std::fs::read_to_string(path)
                .map_err(|e| format!("{name}: cannot read the part to resume it: {e}"))?;
            let part = read_part(&text, &name)?;
            if part.header.study_hash != header.study_hash {
                return Err(format!(
                    "{name} is a part of another study (hash {}, from {}); this study's hash is {}: remove the file or choose another --output",
                    part.header.study_hash, part.header.study, header.study_hash
                ));
            }
            if part.header != header {
                return Err(format!(
                    "{name} is shard {} of this study, not {}: choose another --output",
                    part.header.shard.as_deref().unwrap_or("(whole)"),
                    shard.label()
                ));
            }
            let allowed: HashSet<usize> = mine.iter().copied().collect();
            let mut seen = HashSet::new();
            for row in part.rows {
                if !allowed.contains(&row.index) {
                    return Err(format!(
                        "{name}: index {} is not in shard {}",
                        row.index,
                        shard.label()
                    ));
                }
                if seen.insert(row.index) {
                    kept.push(row);
                }
            }
            discarded_torn_line = part.torn.is_some();
        }
        _ => {}
    }
    kept.sort_by_key(|r| r.index);
    let write_all = |rows: &[Row]| -> Result<(), String> {
        let mut text = header_line(&header);
        for r in rows {
            text.push_str(&row_line(r));
        }
        crate::files::write_atomic(path, text.as_bytes())
            .map(|_| ())
            .map_err(|e| format!("cannot write {name}: {e}"))
    };
    // The part as it stands (torn line dropped), then the journal appended to it.
    write_all(&kept)?;
    let done: HashSet<usize> = kept.iter().map(|r| r.index).collect();
    let todo: Vec<usize> = mine.iter().copied().filter(|i| !done.contains(i)).collect();
    let journal = std::fs::OpenOptions::new()
        .append(true)
        .open(path)
        .map_err(|e| format!("cannot append to {name}: {e}"))?;
    let journal = Mutex::new(journal);
    let write_error: Mutex<Option<String>> = Mutex::new(None);
    let rows = study.solve_all(&todo, &|row| {
        let line = row_line(row);
        if let Ok(mut f) = journal.lock() {
            if let Err(e) = f.write_all(line.as_bytes()) {
                if let Ok(mut w) = write_error.lock() {
                    w.get_or_insert_with(|| format!("cannot append to {name}: {e}"));
                }
            }
        }
        on_row();
    });
    if let Some(e) = write_error.into_inner().ok().flatten() {
        return Err(e);
    }
    let computed = rows.len();
    let kept_n = kept.len();
    let mut all = kept;
    all.extend(rows);
    all.sort_by_key(|r| r.index);
    write_all(&all)?;
    Ok(ShardRun {
        points: mine.len(),
        kept: kept_n,
        computed,
        failures: all.iter().filter(|r| r.failure.is_some()).count(),
        discarded_torn_line,
    })
}

/// Merges parts `(name, text)` into the whole result, in index order. Refuses, naming
/// them: a file that is not a part, an incomplete part, parts of different studies, an
/// index present twice, indices missing.
pub fn merge(parts: &[(String, String)]) -> Result<StudyResult, String> {
    let mut reference: Option<(String, Header)> = None;
    let mut slots: Vec<Option<(Row, usize)>> = Vec::new();
    for (k, (name, text)) in parts.iter().enumerate() {
        let part = read_part(text, name)?;
        if let Some(line) = part.torn {
            return Err(format!(
                "{name}:{line}: the part is incomplete (its shard is still running or was killed): re-run the shard with the same --shard and --output to finish it"
            ));
        }
        match &reference {
            None => {
                slots = vec![None; part.header.points];
                reference = Some((name.clone(), part.header.whole()));
            }
            Some((first, h)) => {
                if part.header.study_hash != h.study_hash {
                    return Err(format!(
                        "{name} is a part of another study: hash {} ({}), but {first} has {} ({})",
                        part.header.study_hash, part.header.study, h.study_hash, h.study
                    ));
                }
                if part.header.whole() != *h {
                    return Err(format!(
                        "{name} and {first} carry the same study hash but different headers (columns or points): were they written by different rollbench builds?"
                    ));
                }
            }
        }
        for row in part.rows {
            let i = row.index;
            match slots.get_mut(i) {
                Some(Some((_, other))) => {
                    return Err(format!(
                        "index {i} is present twice: in {} and in {name}",
                        parts[*other].0
                    ));
                }
                Some(slot) => *slot = Some((row, k)),
                None => return Err(format!("{name}: index {i} is beyond the study's points")),
            }
        }
    }
    let Some((_, header)) = reference else {
        return Err("study merge: no part given".to_string());
    };
    let missing: Vec<usize> = slots
        .iter()
        .enumerate()
        .filter(|(_, s)| s.is_none())
        .map(|(i, _)| i)
        .collect();
    if !missing.is_empty() {
        let shown: Vec<String> = missing.iter().take(10).map(ToString::to_string).collect();
        return Err(format!(
            "{} of {} indices are missing: {}{} (a shard not given or not finished)",
            missing.len(),
            header.points,
            shown.join(", "),
            if missing.len() > 10 { ", …" } else { "" }
        ));
    }
    Ok(StudyResult {
        header,
        rows: slots.into_iter().flatten().map(|(r, _)| r).collect(),
    })
}
