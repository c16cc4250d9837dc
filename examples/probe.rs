use rollbench::deck::Deck;
use rollbench::solve::load_distribution::*;
fn main() {
    let d = Deck::load("decks/radial_si.toml").unwrap();
    let mut b = d.bearing;
    b.geometry.roller_crown_radius_m = 100.0;
    b.geometry.inner_crown_radius_m = 100.0;
    b.geometry.outer_crown_radius_m = 100.0;
    b.geometry.diametral_clearance_m = 0.0;
    b.operating.radial_load_n = 100.0;
    let s = DynamicSpeeds::app_c_estimate(&b);
    let opts = SolveOptions { warm_start: None, trace_roller: Some(3) };
    match solve(&b, &s, &opts, None) {
        Ok(r) => println!("ok {:?}", r.stats),
        Err(e) => println!("err {e}"),
    }
    let mut o2 = opts.clone(); o2.trace_roller = Some(3);
    // re-run with huge iteration limit to see the trace
    b.solver.force_tolerance = 1e-9;
    let rr = solve(&b, &s, &o2, None); println!("{:?}", rr.as_ref().err()); if let Ok(r) = rr {
        for t in r.trace.iter().filter(|t| t.roller_iteration < 1000).take(400) {
            if true { println!("{} {} q {:?} res {:?} nload {}", t.ring_iteration, t.roller_iteration, t.roller, t.residual, t.inner_load_n.iter().filter(|x| **x>0.0).count()); }
        }
    }
}
