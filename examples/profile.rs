//! Run one deck's pipeline repeatedly (for `perf record`): `profile [DECK] [N] [load|contact|all]`.
use rollbench::bearings::spherical_roller::deck as sr_deck;
use rollbench::bearings::spherical_roller::pipeline::{run, Request};
fn main() {
    let mut args = std::env::args().skip(1);
    let path = args.next().unwrap_or("decks/aerospace.toml".into());
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(200);
    let what = args.next().unwrap_or("all".into());
    let d = sr_deck::load(&path).expect("deck");
    let r = Request {
        contact: what != "load",
        heat: what == "all",
        ..Request::default()
    };
    for _ in 0..n {
        std::hint::black_box(run(&d.value, &r, None).ok());
    }
}
