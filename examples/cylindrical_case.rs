//! The cylindrical roller's lamina solve on the cases of `benches/tribology_compare.py
//! --cylindrical` (issue 25 validation 1: side by side with the Python `tribology`
//! package's `load_distr_cyl_rol_bear`, the DIN/ISO 26281 slicing).
//!
//! `cargo run --release --example cylindrical_case -- LAMINAE CLEARANCE_MM DUB_OFF_MM`
//! Z = 12 rollers of 12.7 × 22 mm on 50/75.4 mm races (seed 003's truck bearing), F_r =
//! 5 kN along +x onto roller 1, no centrifugal force. CLEARANCE_MM is the package's
//! `radial_clearance` c: its roller approach is δ_r·cos ψ − c/2 (both contacts together),
//! ours x·cos ψ + 2ρ, so ρ = −c/4. The package's stiffness is ISO's c_L = 35 948·L^(8/9)
//! N/mm^(10/9) on the total approach; the lamina law here is Palmgren's, so the rollers'
//! Young's modulus is chosen to make the two constants equal (k_n·2^(−10/9) = c_L), which
//! makes the models identical with clearance and a dub-off too. Prints one JSON line:
//! the median wall time of a cold solve, iterations, and the roller loads.
use rollbench::bearings::cylindrical_roller::quasi_static::{
    effective_contact_stiffness, solve, Profile, QuasiStaticModel,
};
use rollbench::numerics::cancel::Cancel;
use rollbench::physics::material::Material;

fn median<F: FnMut()>(n: usize, mut f: F) -> f64 {
    let mut t: Vec<f64> = (0..n)
        .map(|_| {
            let s = std::time::Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(|a, b| a.total_cmp(b));
    t[n / 2]
}

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .filter_map(|s| s.parse().ok())
        .collect();
    let laminae = args.first().copied().unwrap_or(21.0) as usize;
    let clearance_m = args.get(1).copied().unwrap_or(0.0) * 1e-3;
    let dub_off_m = args.get(2).copied().unwrap_or(0.0) * 1e-3;
    let length = 0.022;
    let profile = Profile::DubOff {
        radius_m: 0.05,
        length_m: dub_off_m,
    };
    let mut model = QuasiStaticModel {
        roller_count: 12,
        first_azimuth_rad: 0.0,
        roller_radius_m: 6.35e-3,
        inner_raceway_radius_m: 0.025,
        outer_raceway_radius_m: 0.0377,
        roller_length_m: length,
        profile,
        slices: laminae,
        radial_interference_m: -clearance_m / 4.0,
        centrifugal_n: 0.0,
        roller: Material::STEEL,
        inner: Material::STEEL,
        outer: Material::STEEL,
        load_n: [5000.0, 0.0],
        tolerance: 1e-10,
    };
    // Match ISO's c_L: k_n ∝ E*^0.9·(10/9) = E*; scale all three moduli (equal materials).
    let l_eff = model.effective_length_m();
    let s = Material::STEEL;
    let k_n = effective_contact_stiffness(l_eff, &s, &s, &s).expect("k_n");
    let iso = 35_948.0 * (l_eff * 1e3).powf(8.0 / 9.0) * 1e3f64.powf(10.0 / 9.0);
    let target = iso * 2f64.powf(10.0 / 9.0);
    let e = s.youngs_modulus_pa * target / k_n;
    let m = Material {
        youngs_modulus_pa: e,
        ..s
    };
    model.roller = m;
    model.inner = m;
    model.outer = m;
    let check = effective_contact_stiffness(l_eff, &m, &m, &m).expect("k_n");
    assert!((check / target - 1.0).abs() < 1e-9, "{check} {target}");
    let q = solve(&model, None, &Cancel::NONE).expect("solve");
    let t = median(400, || {
        std::hint::black_box(solve(&model, None, &Cancel::NONE).ok());
    });
    let mut moved = model.clone();
    moved.load_n[0] *= 1.05;
    let warm = solve(&moved, Some(&q), &Cancel::NONE).expect("warm");
    let t_warm = median(400, || {
        std::hint::black_box(solve(&moved, Some(&q), &Cancel::NONE).ok());
    });
    let loads: Vec<String> = q
        .rollers
        .iter()
        .map(|r| format!("{:.6}", r.inner_load_n))
        .collect();
    println!(
        "{{\"laminae\": {laminae}, \"solver_median_s\": {t:.4e}, \"warm_median_s\": {t_warm:.4e}, \"iterations\": {}, \"warm_iterations\": {}, \"youngs_modulus_pa\": {e:.6e}, \"loads_n\": [{}]}}",
        q.iterations,
        warm.iterations,
        loads.join(", ")
    );
}
