use rollbench::deck::Deck;
use rollbench::solve::pipeline::{run, Request};
fn main() {
    for name in ["aerospace", "radial_si", "thrust", "industrial"] {
        let d = Deck::load(format!("decks/{name}.toml")).unwrap();
        let req = Request::default();
        let n = 200;
        let mut times = vec![];
        let mut a = None;
        for _ in 0..n {
            let t = std::time::Instant::now();
            a = Some(run(&d.bearing, &req, None).unwrap());
            times.push(t.elapsed().as_secs_f64());
        }
        times.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let a = a.unwrap();
        let mut t2 = vec![];
        let req2 = Request {
            contact: false,
            heat: false,
            ..Request::default()
        };
        for _ in 0..n {
            let t = std::time::Instant::now();
            let _ = run(&d.bearing, &req2, None).unwrap();
            t2.push(t.elapsed().as_secs_f64());
        }
        t2.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let mut t3 = vec![];
        let req3 = Request {
            contact: true,
            heat: false,
            ..Request::default()
        };
        for _ in 0..n {
            let t = std::time::Instant::now();
            let _ = run(&d.bearing, &req3, None).unwrap();
            t3.push(t.elapsed().as_secs_f64());
        }
        t3.sort_by(|a, b| a.partial_cmp(b).unwrap());
        println!(
            "  LD+speeds only {:.3} ms, +contact {:.3} ms",
            t2[n / 2] * 1e3,
            t3[n / 2] * 1e3
        );
        println!(
            "{name}: median {:.3} ms, dyn its {}, ring its {}, roller its {}, evals {}",
            times[n / 2] * 1e3,
            a.speeds.iterations,
            a.load.stats.iterations,
            a.load.stats.roller_iterations,
            a.load.stats.lamina_evaluations
        );
    }
}
#[allow(dead_code)]
fn stage_times() {}
