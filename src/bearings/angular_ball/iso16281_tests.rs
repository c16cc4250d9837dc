//! The ball's degrees of freedom against ISO/TS 16281 worked cases (issue 29,
//! "Validation"): a deep-groove bearing, Z 7, D_w 11.5 mm, D_pw 43.5 mm, groove radii
//! 0.52·D_w (inner) and 0.53·D_w (outer), E 210 GPa, ν 0.3, at rest, as the public
//! ISO/TS 16281 implementation minzhun/ISO16281 sets it up (`Test_BallBearing.py`,
//! commit 1b0e9de, examples 1–6), with the reference displacements its comments give
//! (its "Err" lines compare against them): radial-only and axial-only with and without
//! play (P_d = 0.01 mm), radial + axial with the tilt free, and a moment alone.
//!
//! Displacements: the published references within 0.1 % (measured: ≤ 6e-5).
//!
//! Tilts: the published tilts (2.6872 mrad free, 3.6957 mrad under 1 N·m) are 1.0 %
//! and 1.1 % above what that implementation's own ISO/TS 16281 equations give (16–18:
//! c_p of the nominal geometry, the tilt moving each inner groove centre axially by
//! R_i·sin θ·cos ψ), evaluated for this test with scipy's `root` (tol 1e-14): 2.65981
//! mrad free, and 3.64742 mrad under 1 N·m with the moment arm R_i (the implementation
//! writes D_pw/2 in the moment balance, 1 % shorter: 3.65710 mrad; rollbench's balance,
//! like its geometry, uses R_i, the radius the tilt acts at). Rollbench is compared with
//! those evaluations within 0.1 % (measured: −2.9e-4, −1.8e-4); the published tilts'
//! 1 % is not explained by the implementation's equations and is not tested.
//! Its example 7 (radial, axial and a moment) is left out: neither sign of its moment
//! about the axis across the radial load reproduces its published numbers with its own
//! equations (17.59/147.42/2.27 or 21.40/145.41/3.02 against 19.71/146.31/2.72), so its
//! moment's axis is not the one rollbench's `operating.moment` takes.
//!
//! δ_a is measured from the centred ring as the implementation reports it
//! (`Delta_a_MASTA`: rollbench's δ_a + A·sin α₀, A the groove-centre distance); the tilt's
//! magnitude is compared (the sign conventions differ).

use super::analysis::analyse;
use super::input::{BallInput, PreloadMode};
use crate::numerics::cancel::Cancel;
use crate::physics::material::Material;

/// The example bearing under F_r, F_a (N) and M (N·m; `None`: tilt held at 0), play P_d
/// (m): (δ_r µm, δ_a µm from the centred ring, |θ| mrad).
fn iso_case(pd: f64, fr: f64, fa: f64, m: Option<f64>) -> [f64; 3] {
    let mut i = BallInput::chen_a();
    let g = &mut i.geometry;
    g.ball_count = 7;
    g.ball_diameter_m = 11.5e-3;
    g.pitch_diameter_m = 43.5e-3;
    g.inner_groove_curvature = 0.52;
    g.outer_groove_curvature = 0.53;
    g.free_contact_angle_rad = 0.0;
    g.clearance_m = Some(pd);
    let steel = Material {
        youngs_modulus_pa: 210e9,
        poisson_ratio: 0.3,
        ..i.materials.ball
    };
    i.materials.ball = steel;
    i.materials.rings = steel;
    i.operating.inner_speed_rad_s = 0.0;
    i.operating.outer_speed_rad_s = 0.0;
    i.operating.axial_load_n = fa;
    i.operating.preload_mode = PreloadMode::Force;
    i.operating.radial_load_n = fr;
    i.operating.moment_nm = m;
    let a = analyse(&i, Cancel::NONE).unwrap_or_else(|e| panic!("{e}"));
    let geo = &a.geometry;
    let centre = geo.centre_distance_m * geo.free_contact_angle_rad.sin();
    [
        a.load.radial_deflection_m * 1e6,
        (a.load.axial_deflection_m + centre) * 1e6,
        a.load.tilt_rad.abs() * 1e3,
    ]
}

/// (example, P_d m, F_r N, F_a N, M N·m or held, [δ_r µm, δ_a µm, |θ| mrad]).
type Case = (&'static str, f64, f64, f64, Option<f64>, [f64; 3]);

#[test]
fn iso_ts_16281_deep_groove_cases() {
    let nan = f64::NAN;
    // (example, P_d m, F_r N, F_a N, M N·m or held, [δ_r µm, δ_a µm, |θ| mrad]); NaN: not
    // compared (zero by symmetry or not given).
    let cases: [Case; 6] = [
        (
            "1 radial, no play",
            0.0,
            1000.0,
            0.0,
            None,
            [15.1101, nan, nan],
        ),
        (
            "2 axial, no play",
            0.0,
            0.0,
            1000.0,
            None,
            [nan, 133.5381, nan],
        ),
        (
            "3 radial, play",
            1e-5,
            1000.0,
            0.0,
            None,
            [21.223, nan, nan],
        ),
        (
            "4 axial, play",
            1e-5,
            0.0,
            1000.0,
            None,
            [nan, 149.1717, nan],
        ),
        (
            "5 radial + axial, tilt free",
            1e-5,
            1000.0,
            1000.0,
            Some(0.0),
            [19.5923, 146.4603, 2.65981],
        ),
        (
            "6 moment alone",
            0.0,
            0.0,
            0.0,
            Some(1.0),
            [nan, nan, 3.64742],
        ),
    ];
    for (name, pd, fr, fa, m, want) in cases {
        let got = iso_case(pd, fr, fa, m);
        for (k, (g, w)) in got.iter().zip(want).enumerate() {
            if w.is_nan() {
                continue;
            }
            let rel = (g - w) / w;
            assert!(
                rel.abs() < 1e-3,
                "example {name}, {}: rollbench {g:.5} vs {w:.5} ({rel:+.2e})",
                ["δ_r", "δ_a", "|θ|"][k]
            );
        }
    }
}
