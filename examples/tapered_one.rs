//! One tapered roller bearing case for the SciPy side by side of issue 17
//! (`benches/tapered_side_by_side.sh`): "a SciPy script of the same model takes 5–7 s
//! per case: be ≥ 1 000× faster, measured side by side in one run".
//!
//! `cargo run --release --example tapered_one -- [deck] [model.json] [repeats] [--set key=value …]`
//!
//! Solves the deck (default `decks/trb_afapl.toml`, Load Condition 1: 3 000 lbf thrust at
//! 20 000 rpm; Load Condition 2 with `--set operating.radial_load=700`) the way
//! `rollbench run` does (`analyse`: bearing equilibrium with the analytic 5×5 stiffness,
//! plus the stiffness by central differences of re-solved roller equilibria when the deck
//! asks for it, as the shipped deck does), `repeats` times (default 21), and prints one
//! line `key=value …`: the median wall time of the whole case and of the equilibrium
//! alone, δz, P₁..P₃ of roller 1, K_xx, K_zz. With a file name, writes every input the
//! SciPy model needs as JSON (the roller geometry as rollbench derived it, the slice law's
//! constants, loads, solver settings) and rollbench's answers (displacements, every
//! roller's P₁, P₂, P₃, M₁, M₂, the analytic and difference 5×5 stiffness), so that
//! `benches/tapered_scipy.py` solves the same model and compares.
use rollbench::bearings::tapered_roller::analysis::analyse;
use rollbench::bearings::tapered_roller::bearing::{Bearing, Matrix5};
use rollbench::bearings::tapered_roller::deck::SCHEMA;
use rollbench::bearings::tapered_roller::input::Crown;
use rollbench::deck::form::Form;
use rollbench::physics::contact::lundberg::{compliance, LUNDBERG_CONSTANT};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn rows(k: &Matrix5) -> Vec<Vec<f64>> {
    (0..5)
        .map(|i| (0..5).map(|j| k[(i, j)]).collect())
        .collect()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut positional = Vec::new();
    let mut sets = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--set" {
            sets.push(args.next().ok_or("--set needs key=value")?);
        } else {
            positional.push(a);
        }
    }
    let deck = positional
        .first()
        .cloned()
        .unwrap_or_else(|| "decks/trb_afapl.toml".into());
    let out = positional.get(1).cloned();
    let repeats: usize = match positional.get(2) {
        Some(s) => s.parse()?,
        None => 21,
    };
    let text = std::fs::read_to_string(&deck)?;
    let mut form = Form::parse(&text, &deck, &SCHEMA).map_err(|e| e.to_string())?;
    form.apply_assignments(&sets).map_err(|e| e.to_string())?;
    let input = form.value;

    // The whole case as `rollbench run` solves it, and the equilibrium (with its analytic
    // stiffness) alone; medians over `repeats` runs, each from a cold start.
    let mut whole = Vec::with_capacity(repeats);
    let mut equilibrium = Vec::with_capacity(repeats);
    let mut last = None;
    for _ in 0..repeats.max(1) {
        let t = std::time::Instant::now();
        let a = analyse(std::hint::black_box(&input), &form.name)?;
        whole.push(t.elapsed().as_secs_f64());
        let t = std::time::Instant::now();
        let b = Bearing::new(std::hint::black_box(&input))?;
        let s = b.solve()?;
        equilibrium.push(t.elapsed().as_secs_f64());
        std::hint::black_box(s);
        last = Some(a);
    }
    let a = last.ok_or("no run")?;
    let (t_whole, t_eq) = (median(whole), median(equilibrium));
    let sol = &a.solution;
    let r1 = &sol.rollers[0].0;
    println!(
        "time_s={t_whole:.6e} time_equilibrium_s={t_eq:.6e} dz_m={:.15e} p1_n={:.15e} p2_n={:.15e} p3_n={:.15e} kxx={:.15e} kzz={:.15e}",
        sol.displacement_m[2],
        r1.cup.load_n,
        r1.cone.load_n,
        r1.flange_n,
        sol.stiffness[(0, 0)],
        sol.stiffness[(2, 2)]
    );

    if let Some(path) = out {
        let g = &input.geometry;
        let rg = &a.bearing.geometry;
        let dy = &a.bearing.dynamics;
        let op = &input.operating;
        let m = &input.materials;
        let crown = match g.crown {
            Crown::Radius(r) => serde_json::json!({"radius_m": r}),
            Crown::Drop(v) => serde_json::json!({"drop_m": v}),
        };
        let rollers: Vec<serde_json::Value> = sol
            .rollers
            .iter()
            .map(|(r, delta, theta)| {
                serde_json::json!({
                    "state": r.state.as_str(),
                    "ring_approach_m": delta,
                    "ring_misalignment_rad": theta,
                    "delta1_m": r.delta1_m,
                    "theta1_rad": r.theta1_rad,
                    "delta2_m": r.delta2_m,
                    "theta2_rad": r.theta2_rad,
                    "p1_n": r.cup.load_n,
                    "p2_n": r.cone.load_n,
                    "p3_n": r.flange_n,
                    "m1_nm": r.cup.moment_nm,
                    "m2_nm": r.cone.moment_nm,
                })
            })
            .collect();
        let j = serde_json::json!({
            "deck": deck,
            "set": sets,
            "name": form.name,
            "geometry": {
                "roller_count": g.roller_count,
                "roller_diameter_m": g.roller_diameter_m,
                "pitch_diameter_m": g.pitch_diameter_m,
                "cup_angle_rad": g.cup_angle_rad,
                "effective_length_m": g.effective_length_m,
                "flat_length_m": g.flat_length_m,
                "crown": crown,
                "diametral_clearance_m": g.diametral_clearance_m(),
            },
            "roller": {
                "half_cone_rad": rg.half_cone_rad,
                "axis_angle_rad": rg.axis_angle_rad,
                "h0_m": rg.h0_m,
                "h1_m": rg.h1_m,
                "h2_m": rg.h2_m,
                "crown_radius_m": rg.crown_radius_m,
                "crown_offset_m": rg.crown_offset_m,
                "crown_drop_m": rg.crown_drop_m,
                "r1_m": rg.r1_m,
                "r2_m": rg.r2_m,
                "mass_kg": rg.mass_kg,
                "cg_offset_m": rg.cg_offset_m,
                "polar_inertia_kg_m2": rg.polar_inertia_kg_m2,
                "big_end_radius_m": rg.big_end_radius_m,
                "flange_contact_radius_m": rg.flange_contact_radius_m,
                "flange_angle_rad": rg.flange_angle_rad,
                "flange_lever_arm_m": rg.flange_lever_arm_m,
                "moment_radius_m": rg.moment_radius_m,
                "approach_ratio": rg.approach_ratio,
            },
            "dynamics": {
                "cage_rad_s": dy.cage_rad_s,
                "roller_spin_rad_s": dy.roller_spin_rad_s,
                "centrifugal_force_n": dy.centrifugal_force_n,
                "gyroscopic_moment_nm": dy.gyroscopic_moment_nm,
            },
            "materials": {
                "lundberg_constant": LUNDBERG_CONSTANT,
                "cup_compliance_1_pa": compliance(&m.roller, &m.cup),
                "cone_compliance_1_pa": compliance(&m.roller, &m.cone),
            },
            "operating": {
                "inner_speed_rad_s": op.inner_speed_rad_s,
                "outer_speed_rad_s": op.outer_speed_rad_s,
                "axial_load_n": op.axial_load_n,
                "radial_load_n": op.radial_load_n,
                "initial_displacement_m": op.initial_displacement_m,
                "misalignment_rad": op.misalignment_rad,
            },
            "solver": {
                "slices": input.solver.slices,
                "force_tolerance": input.solver.force_tolerance,
            },
            "rollbench": {
                "time_s": t_whole,
                "time_equilibrium_s": t_eq,
                "repeats": repeats,
                "displacement_m": sol.displacement_m,
                "rotation_rad": sol.rotation_rad,
                "reaction": sol.reaction,
                "iterations": sol.iterations,
                "unique_rollers": sol.unique_rollers,
                "rollers": rollers,
                "stiffness": rows(&sol.stiffness),
                "stiffness_fd": a.stiffness_fd.as_ref().map(rows),
            },
        });
        std::fs::write(path, serde_json::to_string_pretty(&j)?)?;
    }
    Ok(())
}
