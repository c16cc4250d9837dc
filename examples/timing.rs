//! Quick timing of the pipeline on the shipped decks: the load stage alone (with its
//! nanoseconds per lamina evaluation) and the full pipeline without the transient.
use rollbench::deck::Deck;
use rollbench::solve::pipeline::{run, Analysis, Request};

fn median(b: &rollbench::model::Bearing, r: &Request, n: usize) -> (f64, Analysis) {
    let mut t = vec![];
    let mut last = None;
    for _ in 0..n {
        let s = std::time::Instant::now();
        last = Some(run(b, r, None).expect("solve"));
        t.push(s.elapsed().as_secs_f64());
    }
    t.sort_by(|a, b| a.total_cmp(b));
    (t[n / 2], last.expect("ran"))
}

fn main() {
    let load_only = Request {
        contact: false,
        heat: false,
        ..Request::default()
    };
    for name in ["aerospace", "radial_si", "thrust", "industrial"] {
        let d = Deck::load(format!("decks/{name}.toml")).expect("deck");
        let (tl, a) = median(&d.bearing, &load_only, 200);
        let (tf, _) = median(&d.bearing, &Request::default(), 200);
        let evals = a.load.stats.lamina_evaluations;
        println!(
            "{name}: load {:.3} ms ({:.0} ns/lamina eval), full {:.3} ms; dyn its {}, ring its {}, roller its {}, lamina evals {evals}",
            tl * 1e3,
            tl * 1e9 / evals as f64,
            tf * 1e3,
            a.speeds.iterations,
            a.load.stats.iterations,
            a.load.stats.roller_iterations,
        );
    }
}
