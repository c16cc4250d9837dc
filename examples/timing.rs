//! Quick timing of the full pipeline (no transient) on the shipped decks.
use rollbench::deck::Deck;
use rollbench::solve::pipeline::{run, Request};
fn main() {
    for name in ["aerospace", "radial_si", "thrust", "industrial"] {
        let d = Deck::load(format!("decks/{name}.toml")).unwrap();
        let mut t = vec![];
        let mut last = None;
        for _ in 0..100 {
            let s = std::time::Instant::now();
            last = Some(run(&d.bearing, &Request::default(), None).unwrap());
            t.push(s.elapsed().as_secs_f64());
        }
        t.sort_by(|a, b| a.total_cmp(b));
        let a = last.unwrap();
        println!(
            "{name}: median {:.2} ms, dyn its {}, ring its {}, roller its {}, lamina evals {}",
            t[50] * 1e3,
            a.speeds.iterations,
            a.load.stats.iterations,
            a.load.stats.roller_iterations,
            a.load.stats.lamina_evaluations
        );
    }
}
