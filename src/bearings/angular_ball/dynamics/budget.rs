//! The bounds of the time simulation (issue 24 item 7): an estimate of its work and of
//! the samples it keeps, made from the deck before anything is integrated, a refusal of
//! a run whose estimate exceeds [`MAX_SLICE_EVALUATIONS`] (naming the keys to change),
//! the per-ball bound on step attempts that stops a stiff run early, and the decimation
//! of the recorded history to at most [`MAX_SERIES_ROWS`] rows.
//!
//! The work of one right-hand-side evaluation is the traction of every slice of both
//! contacts (2-16…2-18), so the work is counted in slice evaluations:
//! balls simulated × orbits × RHS evaluations per orbit × slices × 2. The RHS
//! evaluations per orbit are measured on the shipped decks (release build, rtol 1e-8,
//! `dynamics.orbits = 5`, 41 slices, free orbit):
//!
//! | deck, load            | steps / ball-orbit | RHS evaluations / ball-orbit |
//! |-----------------------|--------------------|------------------------------|
//! | chen_a, axial only    | 18                 | 132                          |
//! | chen_b, axial only    | 30                 | 188                          |
//! | chen_a, 500 N radial  | 236                | 1 582                        |
//! | chen_b, 500 N radial  | 133                | 841                          |
//!
//! (rtol 1e-11 with DOPRI5 took 3.0× the steps of 1e-8 on chen_a under 500 N radial,
//! against the (1e3)^(1/5) = 4.0 of a fifth-order error control: the estimate scales by
//! the latter, an upper bound.) One slice evaluation took 1.3e-8 to 2.9e-8 s on the 2
//! shared cores it was measured on (chen_b, 500 N radial, 2 001 slices: 5 orbits
//! 9.9 s, 50 orbits 45 s): [`SECONDS_PER_SLICE_EVALUATION`] is the round middle.

use super::super::error::BallError;
use super::super::input::BallInput;

/// RHS evaluations per ball and orbit under an axisymmetric load (the load track is
/// uniform: no kinks to integrate across): chen_b's 188, rounded up.
pub const RHS_PER_ORBIT_UNIFORM: f64 = 200.0;
/// RHS evaluations per ball and orbit under a radial load (a kink at every point of the
/// load track): chen_a's 1 582, rounded up.
pub const RHS_PER_ORBIT_TRACK: f64 = 1600.0;
/// Accepted steps per ball and orbit, uniform track (chen_b's 30, rounded up).
pub const STEPS_PER_ORBIT_UNIFORM: f64 = 30.0;
/// Accepted steps per ball and orbit under a radial load (chen_a's 236, rounded up).
pub const STEPS_PER_ORBIT_TRACK: f64 = 250.0;
/// Wall time of one slice evaluation, s (see the module doc).
pub const SECONDS_PER_SLICE_EVALUATION: f64 = 2e-8;
/// The bound on the estimated work, slice evaluations: about 40 s at
/// [`SECONDS_PER_SLICE_EVALUATION`]. The shipped decks' time simulations (5 orbits, 41
/// slices) estimate at most 1.3e7 (20 balls under radial load), 150× below; Chen's 30
/// orbits for a settled free orbit 7.9e7.
pub const MAX_SLICE_EVALUATIONS: f64 = 2e9;
/// The most rows of the recorded history over every ball (the `--series` CSV): beyond,
/// each ball's history before its last orbit is decimated (every k-th sample kept).
/// 100 000 rows are ≈ 15 MB of CSV; the shipped decks' 5 orbits of 20 balls are 9 020.
pub const MAX_SERIES_ROWS: usize = 100_000;
/// Samples recorded per orbit.
pub const SAMPLES_PER_ORBIT: usize = 90;
/// Bytes held per kept sample: the `Sample` (10 f64), the solver's state copy (5 f64 in
/// a Vec: 40 + 24) and its time.
const BYTES_PER_SAMPLE: f64 = 80.0 + 64.0 + 8.0;
/// Step attempts allowed per ball: this many times the steps expected (from the table
/// above, scaled for the tolerance), and at least [`MIN_STEP_ATTEMPTS`]. Rejected steps
/// ran at 15-20 % of the accepted ones on the shipped decks; a ball that needs 20× the
/// steps of the shipped decks' worst is not being simulated, it is stuck (constant
/// traction µ = 1 under 500 N radial on chen_b: ≈ 8 700 steps per orbit for the balls
/// that get through, 2 000 000 attempts in 0.06 orbit for the one that did not).
pub const STEP_ATTEMPT_FACTOR: f64 = 20.0;
/// The fewest step attempts allowed per ball (short runs: their start-up transient).
pub const MIN_STEP_ATTEMPTS: usize = 20_000;

/// What a time simulation will cost, estimated from its inputs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Balls integrated (1 under an axisymmetric load: the others are copies).
    pub balls_simulated: usize,
    /// Balls reported.
    pub balls: usize,
    /// Slice evaluations.
    pub slice_evaluations: f64,
    /// Wall time, s.
    pub seconds: f64,
    /// Samples of the history kept over every ball (after decimation).
    pub samples_kept: f64,
    /// Bytes of the samples kept.
    pub bytes: f64,
    /// Step attempts allowed per ball simulated.
    pub max_step_attempts: usize,
    /// The most samples one ball keeps (its history's bound).
    pub samples_per_ball: usize,
}

/// The tolerance factor of the steps: (1e-8/rtol)^(1/5) below 1e-8, 1 above.
fn tolerance_factor(rtol: f64) -> f64 {
    (1e-8 / rtol).powf(0.2).max(1.0)
}

/// The estimate of a time simulation of `balls` balls (axisymmetric: one integrated).
pub fn estimate(input: &BallInput, balls: usize, axisymmetric: bool) -> Estimate {
    let d = &input.dynamics;
    let balls_simulated = if axisymmetric || balls < 2 { 1 } else { balls };
    let (rhs, steps) = if axisymmetric {
        (RHS_PER_ORBIT_UNIFORM, STEPS_PER_ORBIT_UNIFORM)
    } else {
        (RHS_PER_ORBIT_TRACK, STEPS_PER_ORBIT_TRACK)
    };
    let tf = tolerance_factor(d.tolerance);
    let slice_evaluations = balls_simulated as f64 * d.orbits * rhs * tf * d.slices as f64 * 2.0;
    let samples_per_ball = history_bound(d.orbits, balls);
    let total = sample_count(d.orbits);
    let kept = samples_per_ball.min(total) as f64 * balls as f64;
    let attempts = (STEP_ATTEMPT_FACTOR * steps * tf * d.orbits).min(1e15) as usize;
    Estimate {
        balls_simulated,
        balls,
        slice_evaluations,
        seconds: slice_evaluations * SECONDS_PER_SLICE_EVALUATION,
        samples_kept: kept,
        bytes: kept * BYTES_PER_SAMPLE,
        max_step_attempts: attempts.max(MIN_STEP_ATTEMPTS),
        samples_per_ball,
    }
}

/// Samples a ball records without decimation over `orbits` (both ends counted).
pub fn sample_count(orbits: f64) -> usize {
    ((orbits * SAMPLES_PER_ORBIT as f64).ceil().min(1e12) as usize).max(2) + 1
}

/// The samples one ball of `balls` keeps: its share of [`MAX_SERIES_ROWS`], and at least
/// its last orbit whole (the summary's mean heat and amplitude are over it) plus one.
pub fn history_bound(orbits: f64, balls: usize) -> usize {
    let last = ((orbits.min(1.0) * SAMPLES_PER_ORBIT as f64).round() as usize).max(1);
    (MAX_SERIES_ROWS / balls.max(1)).max(last + 1)
}

/// Refuses a time simulation whose estimate exceeds [`MAX_SLICE_EVALUATIONS`], naming the
/// keys to change with their values.
pub fn check(input: &BallInput, e: &Estimate) -> Result<(), BallError> {
    if e.slice_evaluations <= MAX_SLICE_EVALUATIONS {
        return Ok(());
    }
    let d = &input.dynamics;
    let balls = if e.balls_simulated > 1 {
        format!(
            ", or geometry.ball_count (now {}: under a radial load every ball is simulated)",
            e.balls
        )
    } else {
        String::new()
    };
    Err(BallError::InvalidInput(format!(
        "this time simulation would take about {:.1e} slice evaluations (≈ {:.0} s) and keep {} of samples; the bound is {:.0e} slice evaluations (≈ {:.0} s); lower dynamics.orbits (now {}) or dynamics.slices (now {}){balls}",
        e.slice_evaluations,
        e.seconds,
        human_bytes(e.bytes),
        MAX_SLICE_EVALUATIONS,
        MAX_SLICE_EVALUATIONS * SECONDS_PER_SLICE_EVALUATION,
        d.orbits,
        d.slices,
    )))
}

/// `bytes` as kB, MB or GB (decimal), two significant figures.
fn human_bytes(bytes: f64) -> String {
    let (v, unit) = if bytes >= 1e9 {
        (bytes / 1e9, "GB")
    } else if bytes >= 1e6 {
        (bytes / 1e6, "MB")
    } else {
        (bytes / 1e3, "kB")
    };
    if v >= 10.0 {
        format!("{v:.0} {unit}")
    } else {
        format!("{v:.1} {unit}")
    }
}

/// The decimation of a ball's history of `n + 1` samples (indices 0..=n, `per_last` of
/// them the last orbit's) to at most `bound`: every `every`-th sample before the last
/// orbit, the last orbit whole. `every` = 1 keeps everything.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Decimation {
    /// The last sample index (the samples are 0..=n, [`SAMPLES_PER_ORBIT`] an orbit).
    pub n: usize,
    /// Every how many samples one is kept before the last orbit.
    pub every: usize,
    /// The first index of the last orbit (kept whole from there).
    pub last_from: usize,
}

impl Decimation {
    /// The decimation of a history over `orbits` kept to at most `bound` samples.
    pub fn of_orbits(orbits: f64, bound: usize) -> Self {
        let n = ((orbits * SAMPLES_PER_ORBIT as f64).ceil() as usize).max(2);
        // The last orbit's samples, chosen by index (see `simulate`'s summary).
        let per_last = ((orbits.min(1.0) / orbits) * n as f64).round() as usize;
        Decimation::new(n, per_last.clamp(1, n), bound)
    }

    /// The samples of the last orbit.
    pub fn per_last(&self) -> usize {
        self.n + 1 - self.last_from
    }

    /// The decimation of samples 0..=`n` with the last `per_last` forming the last orbit.
    pub fn new(n: usize, per_last: usize, bound: usize) -> Self {
        let last_from = (n + 1).saturating_sub(per_last);
        if n < bound {
            return Decimation {
                n,
                every: 1,
                last_from,
            };
        }
        // Room for the samples before the last orbit: ⌈last_from / every⌉ of them.
        let room = bound.saturating_sub(per_last).max(1);
        Decimation {
            n,
            every: last_from.div_ceil(room).max(1),
            last_from,
        }
    }

    /// Whether sample `k` is kept.
    pub fn keeps(&self, k: usize) -> bool {
        k >= self.last_from || k.is_multiple_of(self.every)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::angular_ball::input::BallInput;

    fn input(orbits: f64, slices: usize) -> BallInput {
        let mut i = BallInput::chen_a();
        i.dynamics.orbits = orbits;
        i.dynamics.slices = slices;
        i
    }

    /// The shipped decks' time simulations (5 orbits, 41 slices, 20 balls under radial
    /// load) and Chen's 30 orbits sit well inside the bound; the 45-s and 43-s
    /// runs (50 orbits × 2 001 slices, 1 000 orbits) do not, and their refusal names the
    /// keys with their values.
    #[test]
    fn shipped_runs_pass_and_long_ones_are_refused_naming_the_keys() {
        for (o, s, axi) in [(5.0, 41, false), (30.0, 41, false), (1000.0, 41, true)] {
            let i = input(o, s);
            let e = estimate(&i, 20, axi);
            assert!(
                e.slice_evaluations < MAX_SLICE_EVALUATIONS / 10.0,
                "{o} orbits, {s} slices: {e:?}"
            );
            assert!(check(&i, &e).is_ok());
        }
        for (o, s) in [(50.0, 2001), (1000.0, 41)] {
            let i = input(o, s);
            let e = estimate(&i, 20, false);
            let msg = check(&i, &e).unwrap_err().to_string();
            for want in [
                "slice evaluations",
                "dynamics.orbits (now",
                "dynamics.slices (now",
                "geometry.ball_count (now 20",
                "the bound is 2e9",
            ] {
                assert!(msg.contains(want), "{want:?} not in {msg}");
            }
        }
    }

    /// The history is bounded: 1 000 orbits of one ball keep ≤ the bound, the last
    /// orbit whole; a short run keeps everything.
    #[test]
    fn decimation_bounds_the_history_and_keeps_the_last_orbit() {
        let n = 90_000;
        let d = Decimation::new(n, 90, 5_000);
        let kept = (0..=n).filter(|&k| d.keeps(k)).count();
        assert!(kept <= 5_000, "{kept}");
        // ⌈·⌉ of the step leaves it a little under the bound (4 823 here).
        assert!(kept > 4_500, "{kept}");
        assert!((n + 1 - 90..=n).all(|k| d.keeps(k)));
        assert!(d.keeps(0));
        let d = Decimation::new(450, 90, 5_000);
        assert_eq!(d.every, 1);
        assert!((0..=450).all(|k| d.keeps(k)));
        // 20 balls share MAX_SERIES_ROWS; 2 000 balls still keep their last orbit.
        assert_eq!(history_bound(1000.0, 20), 5_000);
        assert_eq!(history_bound(1000.0, 2_000), 91);
    }
}
