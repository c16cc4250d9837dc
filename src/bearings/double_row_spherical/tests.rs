//! Validation of the double-row statics (issue 27 "Validation"): mirrored rows under pure
//! radial load, one row carrying a pure axial load, the force balance, and the reduction to
//! the spherical roller bearing with one row.

use super::input::{CageSpeedSource, DoubleRowInput};
use super::statics::analyse;
use crate::bearings::spherical_roller::load_distribution::RollerResult;
use crate::bearings::spherical_roller::pipeline::{self, Request};

fn solve(b: &DoubleRowInput) -> super::statics::DoubleRowAnalysis {
    analyse(b, "test", None).unwrap_or_else(|e| panic!("{e}"))
}

/// Σ of the contact forces the rollers of both rows put on the inner ring, and of the guide
/// ring reactions, in the bearing frame (radial along azimuth 0, axial + toward row 1), N.
/// Built from the lamina loads and normals of the report (independent of the solver's
/// gradient): the inner contact pushes the ring along the lamina's inner normal's opposite
/// (the normal is the force on the roller).
fn ring_force(a: &super::statics::DoubleRowAnalysis) -> [f64; 2] {
    let beta = a.input.geometry.contact_angle_rad;
    let axis = [beta.cos(), -beta.sin()];
    let mut f = [0.0, 0.0];
    for r in &a.combined.rollers {
        let sign = if r.row == 2 { -1.0 } else { 1.0 };
        let c = r.azimuth_deg.to_radians().cos();
        let (mut fx, mut fr) = (0.0, 0.0);
        for l in &r.laminae {
            // Force on the roller from the inner ring is Q·n_i; on the ring −Q·n_i.
            fx -= l.inner_load_n * l.inner_normal[0];
            fr -= l.inner_load_n * l.inner_normal[1];
        }
        // The guide ring (on the inner ring) pushes the roller along +a: the ring gets −F·a.
        fx -= r.guide_force_n * axis[0];
        fr -= r.guide_force_n * axis[1];
        f[0] += sign * fx;
        f[1] += fr * c;
    }
    // The inner ring's contact forces oppose the applied load: Σ = −(F_a, F_r).
    [-f[0], -f[1]]
}

fn assert_balance(a: &super::statics::DoubleRowAnalysis, what: &str) {
    let f = ring_force(a);
    let (fa, fr) = (
        a.input.operating.axial_load_n,
        a.input.operating.radial_load_n,
    );
    let scale = fa.abs().max(fr.abs());
    // 1e-7 of the load: the solver's 1e-9 force tolerance, summed over 26 rollers and the
    // lamina normals reconstructed from unit vectors.
    assert!(
        (f[0] - fa).abs() <= 1e-7 * scale,
        "{what}: axial {} vs {fa}",
        f[0]
    );
    assert!(
        (f[1] - fr).abs() <= 1e-7 * scale,
        "{what}: radial {} vs {fr}",
        f[1]
    );
}

fn loads(r: &RollerResult) -> (f64, f64) {
    (r.inner.normal_load_n, r.outer.normal_load_n)
}

/// Pure radial load: the rows mirror each other to 1e-9 of the largest load, Δz = 0 and the
/// guide ring's net axial force is 0 (the problem is symmetric in the radial plane; the
/// numerics need not be, so this checks the mirrored frames and the ring Newton).
#[test]
fn pure_radial_mirrors_the_rows() {
    let mut b = DoubleRowInput::example_22308();
    b.operating.axial_load_n = 0.0;
    let a = solve(&b);
    let z = b.geometry.roller_count;
    let qmax = a.max_roller_load_n();
    assert!(qmax > 0.0);
    for j in 0..z {
        let (r1, r2) = (&a.combined.rollers[j], &a.combined.rollers[z + j]);
        let ((i1, o1), (i2, o2)) = (loads(r1), loads(r2));
        assert!((i1 - i2).abs() <= 1e-9 * qmax, "roller {j}: {i1} vs {i2}");
        assert!((o1 - o2).abs() <= 1e-9 * qmax, "roller {j}: {o1} vs {o2}");
        assert!((r1.guide_force_n - r2.guide_force_n).abs() <= 1e-9 * qmax);
    }
    let d = b.geometry.roller_diameter_m;
    assert!(
        a.axial_deflection_m().abs() <= 1e-12 * d,
        "{}",
        a.axial_deflection_m()
    );
    assert!(a.guide.net_axial_n.abs() <= 1e-9 * qmax, "{:?}", a.guide);
    // The floating guide ring is pressed equally by both rows' ends (the unloaded rollers
    // sliding down the outer sphere under the centrifugal force) and stays centred.
    assert!(a.guide.force_row1_n > 0.0, "{:?}", a.guide);
    assert!(a.guide.axial_offset_m.abs() <= 1e-12 * d, "{:?}", a.guide);
    assert_balance(&a, "pure radial");
}

/// Pure axial load with positive clearance: row 1 carries it all, row 2 is unloaded, the
/// floating guide ring passes no axial load to the inner ring (its net axial force is zero
/// to the ring tolerance, 1e-9 of F_a) and Σ_row 1 Q·sin α_op = F_a:
/// * with Q·(sin α_op) the resultant of each roller's inner lamina forces, to 1e-7 of F_a
///   (the ring balance's tolerance, as `assert_balance`);
/// * with the report's Q (§4.5: the lamina loads projected on the most loaded lamina's
///   normal) and its angle, to the spread of the lamina normals about that normal,
///   Σ_l Q_l·|sin(α_l − α_m)| + Σ_l Q_l·(1 − cos(α_l − α_m)) per roller (the projection's
///   only difference from the resultant; 7e-5 of F_a on the shipped deck).
///
/// Before the guide ring floated it carried 1.6 kN of the 5 kN into the inner ring.
#[test]
fn pure_axial_loads_one_row() {
    let mut b = DoubleRowInput::example_22308();
    b.operating.radial_load_n = 0.0;
    b.operating.axial_load_n = 5000.0;
    assert!(b.geometry.diametral_clearance_m > 0.0);
    let a = solve(&b);
    let z = b.geometry.roller_count;
    let row2: f64 = a.combined.rollers[z..]
        .iter()
        .map(|r| r.inner.normal_load_n)
        .sum();
    let row1: f64 = a.combined.rollers[..z]
        .iter()
        .map(|r| r.inner.normal_load_n)
        .sum();
    assert!(
        row2 == 0.0,
        "row 2 inner loads {row2} against row 1's {row1}"
    );
    let fa = b.operating.axial_load_n;
    // The guide ring floats: no net axial force (to the ring tolerance).
    assert!(
        a.guide.net_axial_n.abs() <= 1e-9 * fa,
        "guide ring net axial force {:?}",
        a.guide
    );
    // It is pressed by both rows (row 2's rollers slide down the outer sphere onto it), so it
    // sits where the two balance, moved off its centred place away from the loaded row.
    assert!(a.guide.force_row1_n > 0.0 && a.guide.force_row2_n > 0.0);
    assert!(a.guide.axial_offset_m < 0.0, "{:?}", a.guide);
    let mut exact = 0.0;
    let mut report = 0.0;
    let mut spread = 0.0;
    for r in &a.combined.rollers[..z] {
        exact -= r
            .laminae
            .iter()
            .map(|l| l.inner_load_n * l.inner_normal[0])
            .sum::<f64>();
        let am = r.inner.contact_angle_deg.to_radians();
        report += r.inner.normal_load_n * am.sin();
        spread += r
            .laminae
            .iter()
            .map(|l| {
                let d = l.inner_angle_deg().to_radians() - am;
                l.inner_load_n * (d.sin().abs() + 1.0 - d.cos())
            })
            .sum::<f64>();
    }
    // The inner normal points along the force on the roller; its axial component is +x for
    // the loaded row (the inner ring pushes the rollers toward row 1's outer raceway).
    assert!(
        (exact.abs() - fa).abs() <= 1e-7 * fa,
        "Σ Q sin α (resultant) {exact} vs {fa}"
    );
    assert!(
        (report.abs() - fa).abs() <= spread,
        "Σ Q sin α_op (report) {report} vs {fa}, lamina spread {spread}"
    );
    // Rigid rotation symmetry: every roller of row 1 carries the same load.
    let q0 = a.combined.rollers[0].inner.normal_load_n;
    for r in &a.combined.rollers[..z] {
        assert!((r.inner.normal_load_n / q0 - 1.0).abs() < 1e-9);
    }
    assert!(a.axial_deflection_m() > 0.0);
    assert_balance(&a, "pure axial");
}

/// The guide ring's gap at each roller of `a` recomputed from the report (independent of the
/// solver's code): g = g₀ + (q − s_g)·a − c·(cos t − 1), s_g = (sign·(u_a + s), u_r·cos φ),
/// in each row's frame.
fn guide_gaps(a: &super::statics::DoubleRowAnalysis) -> Vec<(usize, f64)> {
    let Some(gc) = a.input.guide_contact() else {
        return Vec::new();
    };
    let beta = a.input.geometry.contact_angle_rad;
    let axis = [beta.cos(), -beta.sin()];
    a.combined
        .rollers
        .iter()
        .map(|r| {
            let sign = if r.row == 2 { -1.0 } else { 1.0 };
            let cphi = r.azimuth_deg.to_radians().cos();
            let ga = sign * (a.axial_deflection_m() + a.guide.axial_offset_m);
            let gr = a.radial_deflection_m() * cphi;
            let g = gc.gap_m
                + (r.axial_displacement_m - ga) * axis[0]
                + (r.radial_displacement_m - gr) * axis[1]
                - gc.end_centre_offset_m * (r.tilt_rad.cos() - 1.0);
            (r.row, g)
        })
        .collect()
}

/// At rest (no centrifugal force) under pure axial load only the loaded row reaches the
/// guide ring: it slides away until that row's ends no longer press it (force within the
/// ring tolerance, so an overlap below (F/K)^(2/3) ≈ 1e-10 m) and stops there, the end of
/// its free travel nearest its centred place (the rule; row 2's ends stay clear). Under
/// loads that leave it untouched where it is centred, it stays centred (s = 0 exactly).
#[test]
fn guide_ring_floats_free_at_rest() {
    let mut b = DoubleRowInput::example_22308();
    b.operating.inner_speed_rad_s = 0.0;
    b.cage.measured_speed_rad_s = 0.0;
    b.operating.radial_load_n = 0.0;
    b.operating.axial_load_n = 5000.0;
    let a = solve(&b);
    let tol = 1e-9 * b.operating.axial_load_n;
    assert!(a.guide.force_row1_n <= tol, "{:?}", a.guide);
    assert_eq!(a.guide.force_row2_n, 0.0, "{:?}", a.guide);
    assert!(a.guide.axial_offset_m < 0.0, "{:?}", a.guide);
    let gaps = guide_gaps(&a);
    let min = |row| {
        gaps.iter()
            .filter(|g| g.0 == row)
            .map(|g| g.1)
            .fold(f64::INFINITY, f64::min)
    };
    assert!(min(1).abs() <= 1e-9, "row 1 end gap {} m", min(1));
    assert!(min(2) > 1e-6, "row 2 end gap {} m", min(2));
    // Touching neither row where it is centred: it stays centred.
    for (fr, fa) in [(20_000.0, 0.0), (20_000.0, 2_000.0)] {
        b.operating.radial_load_n = fr;
        b.operating.axial_load_n = fa;
        let a = solve(&b);
        assert_eq!(a.guide.force_row1_n + a.guide.force_row2_n, 0.0);
        assert_eq!(a.guide.axial_offset_m, 0.0);
        assert!(guide_gaps(&a).iter().all(|g| g.1 >= 0.0));
    }
}

/// 0 rpm: no centrifugal force or gyroscopic moment, and each roller is the static Hertz
/// balance: the inner and outer lamina forces, the guide ring and the cage spring sum to zero
/// (1e-7 of the largest roller load: the roller tolerance over 81 laminae), so a roller off
/// the guide ring is a two-force member with equal inner and outer resultants. The cage
/// speed's source cannot matter at rest (identical loads, to 1e-9 of the largest).
#[test]
fn zero_speed_is_the_static_balance() {
    let mut b = DoubleRowInput::example_22308();
    b.operating.inner_speed_rad_s = 0.0;
    b.cage.measured_speed_rad_s = 0.0;
    let a = solve(&b);
    let qmax = a.max_roller_load_n();
    let beta = b.geometry.contact_angle_rad;
    let axis = [beta.cos(), -beta.sin()];
    for r in &a.combined.rollers {
        assert_eq!(r.centrifugal_force_n, 0.0);
        assert_eq!(r.gyroscopic_moment_nm, 0.0);
        let (mut fi, mut fo) = ([0.0; 2], [0.0; 2]);
        for l in &r.laminae {
            for k in 0..2 {
                fi[k] += l.inner_load_n * l.inner_normal[k];
                fo[k] -= l.outer_load_n * l.outer_normal[k];
            }
        }
        let extra = r.guide_force_n + r.cage_force_n;
        for k in 0..2 {
            let sum = fi[k] + fo[k] + extra * axis[k];
            assert!(
                sum.abs() <= 1e-7 * qmax,
                "roller {} row {}: {sum}",
                r.index,
                r.row
            );
        }
        if r.guide_force_n == 0.0 {
            let (ni, no) = (fi[0].hypot(fi[1]), fo[0].hypot(fo[1]));
            assert!((ni - no).abs() <= 1e-7 * qmax, "{ni} vs {no}");
        }
    }
    let mut bc = b.clone();
    bc.cage.speed = CageSpeedSource::Computed;
    let c = solve(&bc);
    for (r, t) in a.combined.rollers.iter().zip(&c.combined.rollers) {
        assert!((r.inner.normal_load_n - t.inner.normal_load_n).abs() <= 1e-9 * qmax);
        assert!((r.outer.normal_load_n - t.outer.normal_load_n).abs() <= 1e-9 * qmax);
    }
    assert_balance(&a, "0 rpm");
}

/// `cage.speed = "computed"`: one cage speed for both rows, the §7 speed of the final loads
/// (the mean over the rollers of both rows loaded at both raceways): recomputed from the
/// reported loads it is the speed the centrifugal forces used, to the dynamic iteration's
/// tolerance (10× the force tolerance, relative); both rows' rollers count, and it lies
/// within 5 % of App. C's rolling-without-slip estimate (small slip under 20 kN).
#[test]
fn computed_cage_speed_is_one_fixed_point() {
    use crate::bearings::spherical_roller::stages;
    let mut b = DoubleRowInput::example_22308();
    b.cage.speed = CageSpeedSource::Computed;
    let a = solve(&b);
    let contacts: Vec<_> = a.rows.iter().flat_map(|r| r.contacts.clone()).collect();
    let sp = stages::internal_speeds(&a.row_bearing, &a.combined, &contacts);
    let wc = a.dynamic.cage_rad_s;
    assert!(
        (sp.cage_speed_rad_s / wc - 1.0).abs() <= 1e-8,
        "{} vs {wc}",
        sp.cage_speed_rad_s
    );
    let controlling = |row: usize| {
        a.combined
            .rollers
            .iter()
            .filter(|r| r.row == row && r.inner.normal_load_n > 0.0 && r.outer.normal_load_n > 0.0)
            .count()
    };
    assert!(controlling(1) > 0 && controlling(2) > 0);
    assert_eq!(sp.controlling_rollers, controlling(1) + controlling(2));
    for r in &a.combined.rollers {
        assert_eq!(
            r.centrifugal_force_n,
            a.combined.rollers[0].centrifugal_force_n
        );
    }
    let est = crate::bearings::spherical_roller::load_distribution::DynamicSpeeds::app_c_estimate(
        &a.row_bearing,
    );
    assert!(
        (wc / est.cage_rad_s - 1.0).abs() < 0.05,
        "{wc} vs {}",
        est.cage_rad_s
    );
}

/// Radius perturbations for the optimiser (which varies R_Ci, R_W, R_CE by ±0.5 %): the
/// crown geometry is computed without cancellation, so the largest roller load's central
/// finite difference at a relative step of 1e-4 agrees with the one at 1e-5 to 1 % (each
/// solve's 1e-9 force tolerance leaves ~1e-4 N of noise against a 0.08 N change at 1e-5;
/// the step's truncation error is far smaller), and ±0.1 %, ±0.2 % move it smoothly: the
/// change across ±0.2 % is the local derivative's to 10 % (the curvature over that span
/// accounts for 1.4–3.3 % on the shipped deck; cancellation noise would make it random) and
/// monotone in 0.1 % steps. R_CE is varied alone in the
/// library input (the deck check on d_m would refuse it in a deck; see
/// [`super::input::DrGeometry::outer_sphere_radius_m`]).
#[test]
fn radius_perturbations_are_smooth() {
    type Set = fn(&mut DoubleRowInput, f64);
    let radii: [(&str, Set); 3] = [
        ("R_Ci", |b, k| b.geometry.inner_raceway_radius_m *= k),
        ("R_W", |b, k| b.geometry.roller_crown_radius_m *= k),
        ("R_CE", |b, k| b.geometry.outer_sphere_radius_m *= k),
    ];
    let base = DoubleRowInput::example_22308();
    let f0 = solve(&base).max_roller_load_n();
    for (name, set) in radii {
        let at = |k: f64| {
            let mut b = base.clone();
            set(&mut b, k);
            solve(&b).max_roller_load_n()
        };
        let fd = |h: f64| (at(1.0 + h) - at(1.0 - h)) / (2.0 * h);
        let (d4, d5) = (fd(1e-4), fd(1e-5));
        assert!(
            d4.abs() > 0.0 && (d4 / d5 - 1.0).abs() < 0.01,
            "{name}: {d4} vs {d5}"
        );
        let (fm, fp) = (at(1.0 - 1e-3), at(1.0 + 1e-3));
        let (fmm, fpp) = (at(1.0 - 2e-3), at(1.0 + 2e-3));
        let span = (fpp - fmm) / 4e-3;
        assert!((span / d4 - 1.0).abs() < 0.1, "{name}: {span} vs {d4}");
        // Monotone across ±0.2 % (each step moves the same way).
        let steps = [fm - fmm, f0 - fm, fp - f0, fpp - fp];
        assert!(
            steps.iter().all(|d| d * steps[0] > 0.0),
            "{name}: {steps:?}"
        );
    }
}

/// Combined loads at both cage-speed sources: the ring balance holds.
#[test]
fn force_balance_combined() {
    for speed in [CageSpeedSource::Measured, CageSpeedSource::Computed] {
        let mut b = DoubleRowInput::example_22308();
        b.cage.speed = speed;
        let a = solve(&b);
        assert_balance(&a, &format!("{speed:?}"));
        // Under F_a > 0 row 1 carries more.
        let z = b.geometry.roller_count;
        let s1: f64 = a.combined.rollers[..z]
            .iter()
            .map(|r| r.inner.normal_load_n)
            .sum();
        let s2: f64 = a.combined.rollers[z..]
            .iter()
            .map(|r| r.inner.normal_load_n)
            .sum();
        assert!(s1 > s2, "{s1} vs {s2}");
    }
}

/// The guide ring holds the unloaded rollers against the centrifugal slide along the outer
/// sphere: under pure axial load the unloaded row's rollers rest on it, and
/// each one's balance along its axis a holds with the reported forces,
/// F_g = F_c·sin α⁰ + Σ Q_o·(n_o·a) − Σ Q_i·(n_i·a) − F_cage (to 1e-6 of F_c); the floating
/// guide ring, pushed by them, rests against the loaded row's ends with the same axial force
/// (`pure_axial_loads_one_row`).
#[test]
fn guide_ring_holds_the_unloaded_row() {
    let mut b = DoubleRowInput::example_22308();
    b.operating.radial_load_n = 0.0;
    b.operating.axial_load_n = 5000.0;
    let a = solve(&b);
    let z = b.geometry.roller_count;
    let beta = b.geometry.contact_angle_rad;
    let axis = [beta.cos(), -beta.sin()];
    for r in &a.combined.rollers[z..] {
        assert!(
            r.guide_force_n > 0.0,
            "row 2 roller {} off the guide ring",
            r.index
        );
        let along = |n: [f64; 2]| n[0] * axis[0] + n[1] * axis[1];
        let outer: f64 = r
            .laminae
            .iter()
            .map(|l| l.outer_load_n * along(l.outer_normal))
            .sum();
        let inner: f64 = r
            .laminae
            .iter()
            .map(|l| l.inner_load_n * along(l.inner_normal))
            .sum();
        // On the roller: −Q_o·n_o (n_o points outward), +Q_i·n_i, F_c·e_r, +F_g·a, the cage.
        let expect = r.centrifugal_force_n * beta.sin() + outer - inner - r.cage_force_n;
        assert!(
            (r.guide_force_n - expect).abs() <= 1e-6 * r.centrifugal_force_n,
            "{} vs {expect}",
            r.guide_force_n
        );
    }
}

/// Reduction: one row, no guide ring, the cage speed computed, the same inputs as a
/// `spherical-roller` bearing ⇒ that system's loads, stresses, film and life to 1e-9
/// relative (the generalisation of the single-row solver changed nothing).
#[test]
fn one_row_is_the_spherical_roller() {
    let mut b = DoubleRowInput::example_22308();
    // Loads one angular-contact row can hold (F_a/F_r above tan α⁰).
    b.operating.radial_load_n = 5000.0;
    b.operating.axial_load_n = 3000.0;
    b.geometry.rows = 1;
    b.guide_ring.present = false;
    b.cage.speed = CageSpeedSource::Computed;
    let a = solve(&b);
    // The single-row bearing built independently of the double-row code path.
    let single = b.row_bearing("test");
    let s = pipeline::run(
        &single,
        &Request {
            heat: false,
            ..Request::default()
        },
        None,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let row = &a.rows[0];
    assert_eq!(row.load.rollers.len(), s.load.rollers.len());
    let close = |x: f64, y: f64, scale: f64| (x - y).abs() <= 1e-9 * scale.max(1e-30);
    let qmax = a.max_roller_load_n();
    assert!(close(
        a.radial_deflection_m(),
        s.load.radial_deflection_m,
        s.load.radial_deflection_m.abs()
    ));
    assert!(close(
        a.axial_deflection_m(),
        s.load.axial_deflection_m,
        s.load.axial_deflection_m.abs()
    ));
    let (sa, sb) = (row.stresses.as_ref(), s.stresses.as_ref());
    for (j, (r, t)) in row.load.rollers.iter().zip(&s.load.rollers).enumerate() {
        assert!(
            close(r.inner.normal_load_n, t.inner.normal_load_n, qmax),
            "roller {j}"
        );
        assert!(
            close(r.outer.normal_load_n, t.outer.normal_load_n, qmax),
            "roller {j}"
        );
        for (l, m) in r.laminae.iter().zip(&t.laminae) {
            assert!(close(l.inner_load_n, m.inner_load_n, qmax));
            assert!(close(l.outer_load_n, m.outer_load_n, qmax));
        }
        if let (Some(x), Some(y)) = (sa, sb) {
            for k in 0..2 {
                let (p, q) = (x.rollers[j][k].max_stress_pa, y.rollers[j][k].max_stress_pa);
                assert!(
                    close(p, q, q.abs().max(1.0)),
                    "roller {j} stress {p} vs {q}"
                );
            }
        }
    }
    let (la, lb) = (row.life.as_ref(), s.life.as_ref());
    if let (Some(x), Some(y)) = (la, lb) {
        let (p, q) = (
            x.result.l10_bearing_mrev.unwrap_or(0.0),
            y.result.l10_bearing_mrev.unwrap_or(0.0),
        );
        assert!(close(p, q, q), "life {p} vs {q}");
        // One row: the bearing's L-10 is the row's.
        assert!(close(a.l10_mrev.unwrap_or(0.0), q, q));
    } else {
        panic!("no life");
    }
}

/// The ring stiffness is the Jacobian of the ring balance: a 1e-3 relative step of the
/// radial load moves the ring by K⁻¹·ΔF to first order (central difference, 1e-4 relative:
/// the step's second-order term and the solver's 1e-9 tolerance over a 20 N step).
#[test]
fn stiffness_is_the_ring_jacobian() {
    let b = DoubleRowInput::example_22308();
    let a = solve(&b);
    let k = a.stiffness_n_m; // (axial, radial)
    let h = 1e-3 * b.operating.radial_load_n;
    let mut bp = b.clone();
    bp.operating.radial_load_n += h;
    let mut bm = b.clone();
    bm.operating.radial_load_n -= h;
    let (ap, am) = (solve(&bp), solve(&bm));
    let du = [
        (ap.axial_deflection_m() - am.axial_deflection_m()) / (2.0 * h),
        (ap.radial_deflection_m() - am.radial_deflection_m()) / (2.0 * h),
    ];
    // K·du/dF_r = (0, 1).
    let r0 = k[0][0] * du[0] + k[0][1] * du[1];
    let r1 = k[1][0] * du[0] + k[1][1] * du[1];
    assert!(r0.abs() < 1e-4 && (r1 - 1.0).abs() < 1e-4, "{r0} {r1}");
}

/// Issue 29 item 3: the double row on the shared 5×5. Its x–z block is the 2×2 it always
/// reported (`stiffness_xz`, bit for bit: the same numbers, now inside the 5×5); K_yy is
/// positive and between the rows' K_xx-like sums (0 < K_yy); the tilts are exact zeros
/// (self-aligning, one outer sphere); with `solver.stiffness = "both"` the analytic sum
/// (guide ring held) equals the central differences of every roller of both rows re-solved
/// at its own azimuth to 1e-6 of each row's scale.
#[test]
fn shared_five_by_five_keeps_the_two_by_two() {
    use crate::bearings::stiffness::{Dof, Method};
    let mut b = DoubleRowInput::example_22308();
    b.solver.stiffness = Method::Both;
    let a = solve(&b);
    let k2 = super::report::stiffness_xz(&a);
    let k = a.stiffness.as_ref().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(k.get(0, 0), k2[0][0]);
    assert_eq!(k.get(0, 2), k2[0][1]);
    assert_eq!(k.get(2, 0), k2[1][0]);
    assert_eq!(k.get(2, 2), k2[1][1]);
    assert!(k.diagonal(Dof::Y).unwrap() > 0.0);
    for i in 0..5 {
        for j in 3..5 {
            assert_eq!(k.get(i, j), 0.0);
            assert_eq!(k.get(j, i), 0.0);
        }
    }
    let gap = k.fd_max_rel.unwrap();
    assert!(gap < 1e-6, "finite_difference_max_rel {gap:.3e}");
    let j = super::report::json(&a);
    assert_eq!(j["stiffness"]["unit"], "N/m");
    assert_eq!(j["stiffness"]["rows"][1], "F_y");
    // The pre-issue-29 2×2 layout stays readable by name.
    assert_eq!(j["stiffness"]["matrix_xz"][1][1].as_f64(), Some(k2[1][1]));
    assert_eq!(j["stiffness"]["matrix_xz"][0][1].as_f64(), Some(k2[0][1]));
}
