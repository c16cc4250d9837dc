//! Time per stage group on the aerospace deck.
use rollbench::deck::Deck;
use rollbench::solve::pipeline::{run, Request};
fn med(b: &rollbench::model::Bearing, r: &Request) -> f64 {
    let mut t: Vec<f64> = (0..60)
        .map(|_| {
            let s = std::time::Instant::now();
            let _ = run(b, r, None);
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(|a, b| a.total_cmp(b));
    t[30] * 1e3
}
fn main() {
    let d = Deck::load("decks/aerospace.toml").expect("deck");
    let b = d.bearing;
    let ld = Request {
        contact: false,
        heat: false,
        ..Request::default()
    };
    let ct = Request {
        heat: false,
        ..Request::default()
    };
    println!(
        "load+speeds {:.2} ms, +contact {:.2} ms, +heat {:.2} ms",
        med(&b, &ld),
        med(&b, &ct),
        med(&b, &Request::default())
    );
}
