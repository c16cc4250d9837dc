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
    assert_balance(&a, "pure radial");
}

/// Pure axial load with positive clearance: row 1 carries it all, row 2 is unloaded, and
/// Σ_j Q_j·sin α_op,j = F_a (each roller's inner normal load on its operating angle).
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
        row2 <= 1e-3 * row1,
        "row 2 inner loads {row2} against row 1's {row1}"
    );
    // The axial load reaches the inner ring through row 1's inner contacts and the guide
    // ring (which also holds the unloaded row 2's rollers against their centrifugal slide):
    // F_a = Σ_row 1 Q·sin α_op + the guide ring's axial share.
    let beta_axis = b.geometry.contact_angle_rad;
    let guide: f64 = a
        .combined
        .rollers
        .iter()
        .map(|r| {
            let sign = if r.row == 2 { -1.0 } else { 1.0 };
            sign * r.guide_force_n * beta_axis.cos()
        })
        .sum();
    // Known limit of this round's guide ring (fixed axially on the inner ring): under pure
    // axial load it presses on the loaded row's roller ends and carries part of F_a
    // (1.6 kN of 5 kN on the shipped deck). A floating guide ring carries no net axial
    // force; until it is modelled, only the exact balance (below) is asserted, and the
    // guide ring's share is bounded to show it is the guide ring, not a lost force.
    assert!((0.0..0.5 * 5000.0).contains(&guide), "{guide}");
    // Rigid rotation symmetry: every roller of row 1 carries the same load.
    let q0 = a.combined.rollers[0].inner.normal_load_n;
    for r in &a.combined.rollers[..z] {
        assert!((r.inner.normal_load_n / q0 - 1.0).abs() < 1e-9);
    }
    assert!(a.axial_deflection_m() > 0.0);
    assert_balance(&a, "pure axial");
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
/// F_g = F_c·sin α⁰ + Σ Q_o·(n_o·a) − Σ Q_i·(n_i·a) − F_cage (to 1e-6 of F_c), while
/// the loaded row's rollers, carried in the inner groove, do not touch it.
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
