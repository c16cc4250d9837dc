//! Quick timing of the pipeline on the shipped decks: the load stage alone (with its
//! nanoseconds per lamina evaluation) and the full pipeline without the transient.
use rollbench::bearings::spherical_roller::deck as sr_deck;
use rollbench::bearings::spherical_roller::pipeline::{run, Analysis, Request};

/// Median and minimum wall time of `n` runs (the minimum is the steadier figure on a busy
/// machine; the median is what the README quotes).
fn median(
    b: &rollbench::bearings::spherical_roller::Bearing,
    r: &Request,
    n: usize,
) -> (f64, f64, Analysis) {
    let mut t = vec![];
    let mut last = None;
    for _ in 0..n {
        let s = std::time::Instant::now();
        last = Some(run(b, r, None).expect("solve"));
        t.push(s.elapsed().as_secs_f64());
    }
    t.sort_by(|a, b| a.total_cmp(b));
    (t[n / 2], t[0], last.expect("ran"))
}

fn main() {
    let load_only = Request {
        contact: false,
        heat: false,
        ..Request::default()
    };
    for name in ["aerospace", "radial_si", "thrust", "industrial"] {
        let d = sr_deck::load(format!("decks/{name}.toml")).expect("deck");
        let (tl, ml, a) = median(&d.value, &load_only, 200);
        let (tf, mf, _) = median(&d.value, &Request::default(), 200);
        let evals = a.load.stats.lamina_evaluations;
        println!(
            "{name}: load {:.3} ms (min {:.3}, {:.0} ns/lamina eval), full {:.3} ms (min {:.3}); dyn its {}, ring its {}, roller its {}, lamina evals {evals}",
            tl * 1e3,
            ml * 1e3,
            ml * 1e9 / evals as f64,
            tf * 1e3,
            mf * 1e3,
            a.speeds.iterations,
            a.load.stats.iterations,
            a.load.stats.roller_iterations,
        );
    }
}
