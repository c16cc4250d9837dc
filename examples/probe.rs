use rollbench::deck::Deck;
use rollbench::model::Slicing;
use rollbench::solve::pipeline::{run, Request};
fn key(b: &rollbench::model::Bearing) -> (f64, f64, f64, f64) {
    let a = run(b, &Request::default(), None).unwrap();
    let st = a.stresses.as_ref().unwrap();
    let smax = st
        .rollers
        .iter()
        .flat_map(|r| r.iter().map(|x| x.max_stress_pa))
        .fold(0.0, f64::max);
    let l10 = a.life.as_ref().unwrap().result.l10_bearing_mrev.unwrap();
    let q = a
        .load
        .rollers
        .iter()
        .map(|r| r.outer.normal_load_n)
        .fold(0.0, f64::max);
    (smax, l10, q, a.friction.as_ref().unwrap().heat.total_w)
}
fn main() {
    for name in ["aerospace", "radial_si", "thrust", "industrial"] {
        let mut b = Deck::load(format!("decks/{name}.toml")).unwrap().bearing;
        b.solver.laminae = 400;
        b.solver.slicing = Slicing::Cosine;
        b.solver.force_tolerance = 1e-10;
        let r = key(&b);
        println!("{name}: ref smax {:.4e} l10 {:.4e}", r.0, r.1);
        for sl in [Slicing::Uniform, Slicing::Cosine] {
            for g in [11, 15, 21, 31, 41, 61] {
                b.solver.laminae = g;
                b.solver.slicing = sl;
                b.solver.force_tolerance = 1e-9;
                let t = std::time::Instant::now();
                let k = key(&b);
                println!(
                    "  {sl:?} Γ {g:3}: smax {:+.3}%  l10 {:+.3}%  q {:+.4}% heat {:+.3}%  {:.2} ms",
                    100.0 * (k.0 / r.0 - 1.0),
                    100.0 * (k.1 / r.1 - 1.0),
                    100.0 * (k.2 / r.2 - 1.0),
                    100.0 * (k.3 / r.3 - 1.0),
                    t.elapsed().as_secs_f64() * 1e3
                );
            }
        }
    }
}
