use rollbench::model::Bearing;
use rollbench::solve::load_distribution::*;
fn main() {
    let mut b = Bearing::example_aerospace();
    b.operating.axial_load_n = 0.0;
    let s = DynamicSpeeds::app_c_estimate(&b);
    let r = solve(&b, &s, &SolveOptions::default(), None).unwrap();
    println!("ring {:.3e} {:.3e} its {} rit {} evals {} t {:.3} ms", r.axial_deflection_m, r.radial_deflection_m, r.stats.iterations, r.stats.roller_iterations, r.stats.lamina_evaluations, r.stats.wall_time_s*1e3);
    for x in r.rollers.iter().take(9) {
        println!("  {:2} Qi {:8.1} Qo {:8.1} ai {:6.2} ao {:6.2} ni {:2} no {:2} ex {:9.2e} er {:9.2e} tilt {:9.2e} cage {:8.3} {:8.4}", x.index, x.inner.normal_load_n, x.outer.normal_load_n, x.inner.contact_angle_deg, x.outer.contact_angle_deg, x.inner.loaded_laminae, x.outer.loaded_laminae, x.axial_displacement_m, x.radial_displacement_m, x.tilt_rad, x.cage_force_n, x.cage_moment_nm);
    }
}
