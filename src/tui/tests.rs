use super::*;
#[test]
fn tui_timing_probe() {
    let b = crate::model::Bearing::example_aerospace();
    let t = std::time::Instant::now();
    let a = crate::solve::pipeline::run(
        &b,
        &crate::solve::pipeline::Request {
            trace_roller: Some(0),
            thermal_transient: false,
        },
        None,
    )
    .unwrap();
    eprintln!(
        "solve {:?} trace {} rollers {}",
        t.elapsed(),
        a.trace.len(),
        a.load.rollers.len()
    );
    for r in &a.load.rollers {
        eprintln!(
            "{} {} {} {}",
            r.index,
            r.azimuth_deg,
            r.inner.normal_load_n,
            r.laminae.len()
        );
    }
    let _ = App::new(DeckDoc::parse(&deck_io::default_text(), "x").unwrap(), None);
}
