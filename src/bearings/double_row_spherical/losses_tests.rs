//! Validation of the double-row loss breakdown on the solved statics (issue 27
//! "Validation": power identity, limits, the seed's findings as shapes, a plausibility
//! check against Palmgren's empirical friction moment).

use super::input::{CageSpeedSource, DoubleRowInput};
use super::losses::{
    loss_breakdown, loss_inputs, loss_kinematics, losses, losses_skewed, LossBreakdown,
    CAGE_TORQUE_TOLERANCE, SPIN_MOMENT_TOLERANCE,
};
use super::losses::{CAGE_TRACE, SPIN_COUNTS};
use super::statics::{analyse, DoubleRowAnalysis};
use crate::physics::lubrication::traction::TRACTION_CALLS;

fn solve(b: &DoubleRowInput) -> DoubleRowAnalysis {
    analyse(b, "test", None).unwrap_or_else(|e| panic!("{e}"))
}

fn breakdown(b: &DoubleRowInput) -> (DoubleRowAnalysis, LossBreakdown) {
    let a = solve(b);
    let l = losses(&a).unwrap_or_else(|e| panic!("{e}"));
    (a, l)
}

/// As [`breakdown`] with the loaded rollers' skew ([`losses_skewed`]).
fn breakdown_skewed(b: &DoubleRowInput) -> (DoubleRowAnalysis, LossBreakdown) {
    let a = solve(b);
    let l = losses_skewed(&a).unwrap_or_else(|e| panic!("{e}"));
    (a, l)
}

/// The shipped deck `decks/srb_22308.toml` as the CLI reads it (cage speed computed).
fn shipped() -> DoubleRowInput {
    use crate::deck::form::Form;
    let mut f = Form::parse(
        super::system::EXAMPLE_DECK,
        "srb_22308.toml",
        &super::deck::SCHEMA,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    super::deck::optimise_table(&mut f).unwrap_or_else(|e| panic!("{e}"));
    f.value
}

/// The shipped deck with the seed's measured cage speed (1200 rpm), as
/// `--set cage.speed=measured` gives it: the example built in code.
fn measured() -> DoubleRowInput {
    let b = DoubleRowInput::example_22308();
    assert_eq!(b.cage.speed, CageSpeedSource::Measured);
    b
}

/// The shipped deck computes its cage speed (the measured 1200 rpm is incompatible with its
/// loads: the deck header), and is otherwise the example (`deck::tests`).
#[test]
fn shipped_deck_computes_the_cage_speed() {
    let b = shipped();
    assert_eq!(b.cage.speed, CageSpeedSource::Computed);
    let m = measured();
    assert_eq!(b.cage.measured_speed_rad_s, m.cage.measured_speed_rad_s);
    assert_eq!(b.operating.radial_load_n, m.operating.radial_load_n);
}

/// The shipped deck (computed cage speed) at the loads (N).
fn with_loads(fr: f64, fa: f64) -> DoubleRowInput {
    let mut b = shipped();
    b.operating.radial_load_n = fr;
    b.operating.axial_load_n = fa;
    b
}

fn show(what: &str, l: &LossBreakdown) -> String {
    let x = &l.losses;
    let s = &x.shares_pct;
    format!(
        "{what}: total {:.3} W; raceway in {:.1} % out {:.1} %, guide ring {:.1} %, pockets {:.2} %, land {:.2} %, skew {:.2} %; M_fi {:.4} M_fo {:.4} M {:.4} N·m; imbalance {:.4} N·m; cage {:.1} rpm (slip {:.2} %), spins {:.0}–{:.0} rad/s",
        x.total_w,
        s.raceway_inner,
        s.raceway_outer,
        s.guide_ring,
        s.cage_pockets,
        s.cage_land,
        s.skew,
        x.friction_torque_inner_nm,
        x.friction_torque_outer_nm,
        x.friction_torque_nm,
        x.cage_torque_imbalance_nm,
        x.cage_speed_rpm,
        x.cage_slip_pct,
        l.rollers.iter().map(|r| r.spin_rad_s).fold(f64::INFINITY, f64::min),
        l.rollers.iter().map(|r| r.spin_rad_s).fold(f64::NEG_INFINITY, f64::max),
    )
}

/// Power identity on the shipped deck, with the measured cage speed (so the cage is out of
/// balance and the imbalance is reported, not forced to 0) and with the computed one: the
/// seven mechanisms sum to the total and total = M·|ω_i − ω_o|, M_fi·|ω_i − ω_o| = Σ inner
/// raceway power, to 1e-9 relative (round-off of sums of ~4000 terms; the issue asks 1e-6).
#[test]
fn power_identity_on_the_shipped_deck() {
    for b in [measured(), shipped()] {
        power_identity_on(&b);
    }
}

fn power_identity_on(b: &DoubleRowInput) {
    let (a, l) = breakdown(b);
    let x = l.losses;
    eprintln!("{}", show("22308 deck", &l));
    let sum = x.raceway_inner_w
        + x.raceway_outer_w
        + x.guide_ring_w
        + x.cage_pockets_w
        + x.cage_land_w
        + x.skew_w
        + x.drag_w;
    assert!(x.total_w > 0.0);
    assert!(
        (sum - x.total_w).abs() <= 1e-9 * x.total_w,
        "{sum} {}",
        x.total_w
    );
    let dw = a.input.operating.inner_speed_rad_s.abs();
    assert!((x.friction_torque_nm * dw - x.total_w).abs() <= 1e-9 * x.total_w);
    let inner: f64 = l.rollers.iter().map(|r| r.inner_w).sum();
    let outer: f64 = l.rollers.iter().map(|r| r.outer_w).sum();
    assert!((x.friction_torque_inner_nm * dw - inner).abs() <= 1e-9 * inner);
    assert!((x.friction_torque_outer_nm * dw - outer).abs() <= 1e-9 * outer);
    // The raceway terms are exactly the laminae's power; the skew reaction is its own
    // mechanism, the rollers' sum.
    let lam = x.raceway_inner_w + x.raceway_outer_w;
    assert!((lam - inner - outer).abs() <= 1e-9 * lam);
    let skew: f64 = l.rollers.iter().map(|r| r.skew_w).sum();
    assert!((skew - x.skew_w).abs() <= 1e-9 * x.skew_w.max(1e-300));
    // The measured cage speed (1200 rpm) is not the balanced one: an imbalance remains;
    // the computed one is balanced.
    assert!(x.cage_torque_imbalance_nm.is_finite());
    assert_eq!(
        l.cage_speed_computed,
        b.cage.speed == CageSpeedSource::Computed
    );
    // Per roller: both rows, the guide ring's load and the pocket force.
    assert_eq!(l.rollers.len(), 26);
    assert!(l.rollers.iter().any(|r| r.row == 2));
    let g = l.guide_ring.as_ref().expect("the deck has a guide ring");
    // The ring runs between the cage and the inner ring (the bore drags it toward ω_i, the
    // roller ends toward ω_c).
    let wc = x.cage_speed_rpm * std::f64::consts::PI / 30.0;
    let wi = a.input.operating.inner_speed_rad_s;
    assert!(
        g.speed_rad_s >= wc.min(wi) - 1e-9 && g.speed_rad_s <= wc.max(wi) + 1e-9,
        "{} not in [{wc}, {wi}]",
        g.speed_rad_s
    );
}

/// 0 rpm (inner ring and cage at rest: measured 0, or computed) ⇒ 0 W and 0 torques.
#[test]
fn zero_speed_is_zero_loss() {
    for mut b in [measured(), shipped()] {
        b.operating.inner_speed_rad_s = 0.0;
        b.cage.measured_speed_rad_s = 0.0;
        let (_, l) = breakdown(&b);
        assert_eq!(l.losses.total_w, 0.0, "{}", show("0 rpm", &l));
        assert_eq!(l.losses.friction_torque_nm, 0.0);
    }
}

/// η = 0 ⇒ 0 W from every mechanism, and the loads the losses read are the statics'
/// (the viscosity does not enter the statics: the lamina loads in the inputs are the
/// solved ones, summed over each roller to round-off).
#[test]
fn inviscid_oil_is_zero_loss_with_the_same_loads() {
    let a = solve(&measured());
    let mut i = loss_inputs(&a).expect("inputs");
    i.lubricant.rheology.viscosity_pa_s = 0.0;
    let l = loss_breakdown(&i).expect("breakdown");
    assert_eq!(l.losses.total_w, 0.0);
    for (r, ri) in a.combined.rollers.iter().zip(&i.rollers) {
        let q: f64 = r.laminae.iter().map(|x| x.inner_load_n).sum();
        let qi: f64 = ri.inner.iter().map(|x| x.load_n).sum();
        assert!((q - qi).abs() <= 1e-12 * q.max(1.0), "{q} {qi}");
        assert_eq!(ri.guide_ring_load_n, r.guide_force_n);
    }
}

/// Palmgren's empirical friction moment (Harris & Kotzalas, *Essential Concepts of Bearing
/// Technology*, 5th ed., ch. 11 "friction"): M = f₀·(ν·n)^{2/3}·d_m³·10⁻⁷ + f₁·P₁·d_m
/// (N·mm; ν mm²/s, n rpm, d_m mm; νn ≥ 2000), for spherical roller bearings f₀ ≈ 4–6 and
/// f₁ ≈ 0.0004–0.0005 with P₁ = F_r + 1.35·Y₂·F_a, Y₂ = 0.45·cot α (ISO 281's Y for
/// F_a/F_r > e). The model's torque must lie within a factor 2 of that band (the issue's
/// plausibility check): below half its low end or above twice its high end fails. The
/// shipped deck (computed cage speed) and the seed's measured cage speed.
#[test]
fn total_torque_is_within_a_factor_two_of_palmgren() {
    for b in [shipped(), measured()] {
        palmgren_band(&b);
    }
}

fn palmgren_band(b: &DoubleRowInput) {
    let (_, l) = breakdown(b);
    let nu = b.viscosity_pa_s() / b.lubricant.density_kg_m3 * 1e6;
    let n = b.operating.inner_speed_rad_s * 30.0 / std::f64::consts::PI;
    let dm = b.geometry.pitch_diameter_m * 1e3;
    let y2 = 0.45 / b.geometry.contact_angle_rad.tan();
    let p1 = b.operating.radial_load_n + 1.35 * y2 * b.operating.axial_load_n;
    let m = |f0: f64, f1: f64| {
        (f0 * (nu * n).powf(2.0 / 3.0) * dm.powi(3) * 1e-7 + f1 * p1 * dm) * 1e-3
    };
    let (lo, hi) = (m(4.0, 0.0004), m(6.0, 0.0005));
    let got = l.losses.friction_torque_nm;
    eprintln!("Palmgren band {lo:.3}–{hi:.3} N·m, model {got:.3} N·m");
    assert!(got >= 0.5 * lo && got <= 2.0 * hi, "{got} vs [{lo}, {hi}]");
}

/// The three load directions of the shapes: radial 20 kN, axial 6 kN, combined 20 + 2 kN
/// (the deck's `[optimise]` load cases and the shipped deck).
fn directions() -> [(&'static str, LossBreakdown); 3] {
    directions_with(CageSpeedSource::Computed)
}

/// As [`directions`] with the cage speed measured (the deck's 1200 rpm) or computed.
fn directions_with(cage: CageSpeedSource) -> [(&'static str, LossBreakdown); 3] {
    let at = |fr: f64, fa: f64| {
        let mut b = with_loads(fr, fa);
        b.cage.speed = cage;
        breakdown(&b).1
    };
    [
        ("radial", at(20_000.0, 0.0)),
        ("axial", at(0.0, 6_000.0)),
        ("combined", at(20_000.0, 2_000.0)),
    ]
}

/// The seed's findings (§6) as shapes on the shipped deck: raceways 65–85 %, guide ring
/// 5–20 % and larger under radial than axial load, cage terms ≥ 2 %, skew 1–5 %,
/// M_fi > M_fo in every case, M_fo rises more (relative to M_fi) under axial load.
#[test]
fn seed_shapes_print() {
    for cage in [CageSpeedSource::Measured, CageSpeedSource::Computed] {
        for (what, l) in directions_with(cage) {
            eprintln!(
                "{cage:?} {}; statics' centrifugal at {:.1} rpm; land torque {:.4} N·m",
                show(what, &l),
                l.centrifugal_cage_speed_rpm,
                l.cage_land_torque_nm
            );
        }
    }
    // With the loaded rollers' skew (`losses_skewed`, not the default: module notes "Skew").
    for (what, fr, fa) in [
        ("radial", 20_000.0, 0.0),
        ("axial", 0.0, 6_000.0),
        ("combined", 20_000.0, 2_000.0),
    ] {
        let (_, l) = breakdown_skewed(&with_loads(fr, fa));
        eprintln!("Computed, skewed {}", show(what, &l));
    }
    // The neglected guide-ring end moment about each roller's axis: μ_fl·Q_end·arm, the arm
    // the end point's speed per unit spin, against the roller's traction moments.
    let a = solve(&measured());
    let i = loss_inputs(&a).expect("inputs");
    let mu = i.lubricant.rheology.limiting_traction_coefficient;
    let (mut arm, mut bound) = (0.0f64, 0.0f64);
    for r in &i.rollers {
        if r.spin_rad_s != 0.0 {
            let x = (r.roller_end_speed_m_s / r.spin_rad_s).abs();
            arm = arm.max(x);
            bound = bound.max(mu * r.guide_ring_load_n * x);
        }
    }
    eprintln!("guide-ring end: arm ≤ {arm:.3e} m, moment ≤ {bound:.3e} N·m");
    // The yaw (skew) moments and what the guide ring could react of them (module notes
    // "Skew"): its normal force's arm once the roller has skewed by ψ ≤ c_p/L is
    // |r_e − L/2|·c_p/L; its tangential traction's arm is L/2.
    let g = &a.input.geometry;
    let psi = a.input.cage.pocket_clearance_m / g.roller_length_m;
    let arm_n = (g.roller_end_radius_m - 0.5 * g.roller_length_m).abs() * psi;
    for (what, l) in directions_with(CageSpeedSource::Computed) {
        let ms = l
            .rollers
            .iter()
            .map(|r| r.skew_moment_nm.abs())
            .fold(0.0, f64::max);
        let qe = l
            .rollers
            .iter()
            .map(|r| r.guide_ring_load_n)
            .fold(0.0, f64::max);
        eprintln!(
            "{what}: |M_s| ≤ {ms:.4} N·m; guide ring could react ≤ {:.2e} N·m (normal, arm {arm_n:.2e} m) + {:.2e} N·m (traction, μ_fl·Q·L/2), Q_end ≤ {qe:.2} N",
            qe * arm_n,
            mu * qe * 0.5 * g.roller_length_m
        );
    }
}

/// The seed's shapes asserted on the shipped deck (cage speed computed: its torque
/// balance). Still fails (numbers of srb-loss, 3000 rpm, per-roller spins, the skew read as
/// the roller's yaw reacted at its pocket; `seed_shapes_print`):
/// * computed (balanced) cage, 1221.3 / 1221.6 / 1221.2 rpm, 20 kN radial / 6 kN axial /
///   20 + 2 kN: raceways 91.6 / 95.8 / 93.0 %, skew 2.00 / 1.10 / 1.32 %, guide ring
///   0.6 / 0.8 / 0.6 %, pockets + land 5.7 / 2.3 / 5.1 %, M_fi 0.455 / 0.550 / 0.462 >
///   M_fo 0.269 / 0.287 / 0.274 N·m. Skew, cage ≥ 2 % and M_fi > M_fo hold; the raceway
///   share (> 85 %), the guide ring (< 5 %, larger under axial load: only the unloaded
///   rollers' centrifugal push F_c·sin α⁰ ≈ 1.2 N presses it, at an end contact on the
///   roller axis — see `guide_ring_end_loads_are_the_unloaded_rollers_centrifugal_push`
///   for what a 22308 CC adds and why the model lacks it) and "M_fo rises more under axial
///   load" (M_fo/M_fi 0.52 axial against 0.59 radial) do not;
/// * measured 1200 rpm (`--set cage.speed=measured`; incompatible with the loads: cage
///   imbalance 48.6 / 67.7 / 51.2 N·m against M ≈ 1.2 N·m): raceways 74.5 / 71.1 / 75.1 %
///   (in the band), skew 6.3 / 6.6 / 5.9 % (above 5 %), guide ring 0.4–0.5 %, pockets + land
///   18.6–21.8 %;
/// * with the loaded rollers' skew (srb-skew, `losses_skewed`, not the default): nearly
///   every loaded roller runs to the pocket's stop ψ = c_p/L (24 / 26 / 23 of 26), raceways
///   62.0 / 45.7 / 62.1 %, skew 33.3 / 52.4 / 33.1 % (≫ 5 %), guide ring 1.3 / 0.5 / 1.4 %
///   (the two raceways' axial tractions nearly cancel; the net mostly points away from the
///   ring), spins off their balance by 12–15 %: further from the seed and not
///   self-consistent, so not adopted (`skew_couplings_print`; docs "Status against the
///   seed": the raceways' self-guidance needs a skew degree of freedom in the statics).
/// * with the self-guidance (srb-kellstrom, `losses::kellstrom::losses_self_guided`, not
///   the default; `kellstrom::tests::self_guided_print`): the walk holds the loaded rollers
///   at ψ = 0.1–0.25 mrad with the computed cage (4 / 0 / 2 of 26 at the pocket stop);
///   raceways 90.1 / 96.7 / 88.3 %, skew 2.97 / 0.09 / 5.20 %, guide ring 0.64 / 0.48 /
///   0.63 %: the skew's size moves toward the seed, the raceway and guide-ring shares do
///   not (the loaded rollers' net axial traction points away from the guide ring).
///
/// * srb10, the cage's land film reacting on the guide ring (Newton's third law; before,
///   only the cage felt it): computed cage 1221.3 / 1221.6 / 1221.2 rpm, total 247.8 /
///   274.3 / 248.2 W, raceways 91.8 / 95.9 / 93.0 %, guide ring 0.87 / 1.02 / 0.88 %
///   (ring 2107 / 1977 / 2103 rpm, was 2505 rpm), pockets + land 5.35 / 2.07 / 4.75 %,
///   skew 2.00 / 1.09 / 1.33 %, M_fi 0.455 / 0.550 / 0.462 > M_fo 0.269 / 0.287 / 0.274
///   N·m. **The guide-ring band cannot be met with this deck's ring**: whatever loads the
///   roller ends, the ring's torque balance caps its loss at k_b·(ω_i − ω_c)² = 5.8 W
///   (its bore's Petroff coefficient k_b = 1.67e-4 N·m·s), 2.1–2.3 % of the loss
///   (`guide_ring_loss_is_bounded_by_its_bore`); the loaded rollers' axial components
///   Q·sin(α − α⁰) that a roller unable to walk would put on it are ≤ 0.4 / 6.4 / 1.9 N
///   and a symmetric roller walks instead (SKF: "self-guiding rollers … a floating guide
///   ring guides unloaded rollers"); `guide_ring_physics_print`, docs "Why the guide
///   ring takes about 1 %". With the guide ring's 4–19 % missing from the other terms,
///   the raceways' 65–85 % band cannot be met either.
///
/// Nothing is tuned to pass.
#[test]
#[ignore = "seed shapes fail on the shipped deck (computed cage): raceways 92-96 % (> 85 %), guide ring 0.9-1.0 % (< 5 %: capped at 2.1-2.3 % by its bore, guide_ring_loss_is_bounded_by_its_bore), larger under axial, M_fo/M_fi lower under axial; skew 1.1-2.0 %, cage >= 2 %, M_fi > M_fo hold; see the doc comment"]
fn seed_shapes() {
    let d = directions();
    for (what, l) in &d {
        let s = &l.losses.shares_pct;
        let race = s.raceway_inner + s.raceway_outer;
        assert!((65.0..=85.0).contains(&race), "{what}: raceways {race} %");
        assert!(
            (5.0..=20.0).contains(&s.guide_ring),
            "{what}: guide ring {} %",
            s.guide_ring
        );
        assert!(s.cage_pockets + s.cage_land >= 2.0, "{what}");
        assert!((1.0..=5.0).contains(&s.skew), "{what}: skew {} %", s.skew);
        assert!(
            l.losses.friction_torque_inner_nm > l.losses.friction_torque_outer_nm,
            "{what}"
        );
    }
    let (r, a) = (&d[0].1.losses, &d[1].1.losses);
    assert!(r.shares_pct.guide_ring > a.shares_pct.guide_ring);
    assert!(
        a.friction_torque_outer_nm / a.friction_torque_inner_nm
            > r.friction_torque_outer_nm / r.friction_torque_inner_nm
    );
}

/// Each roller's spin closes its moment balance about its axis, checked by evaluating the
/// balance afresh (not by trusting the solver): the moment changes sign across the spin
/// (M(ω_s − δ) ≥ 0 ≥ M(ω_s + δ), δ = 1e-11·|ω_s|: a root of the decreasing M to 1e-11 of the
/// spin), and the residual is within [`SPIN_MOMENT_TOLERANCE`] of the traction moments'
/// scale unless M is near-vertical there: a lamina on eq. 3's Newtonian branch has
/// dF/dv = η·e^{αp}/h·A, ~1e8 N·s/m at 2 GPa (e^{αp} ≈ 1e17), so on the loaded rollers M
/// jumps by ~1 % of its scale within 1e-12 of the spin (measured on roller 0 of the 20 kN
/// case: +0.036 → −0.027 N·m of 3.2 N·m over 1e-9 rad/s); there the root is the jump.
#[test]
fn roller_spin_closes_its_moment_balance() {
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0)] {
        let a = solve(&with_loads(fr, fa));
        let k = loss_kinematics(&a).expect("kinematics");
        let wc = a.dynamic.cage_rad_s;
        let spins = k.spins_at(wc).expect("spins");
        let mut balanced = 0;
        for (i, s) in spins.iter().enumerate() {
            if !s.balanced {
                continue;
            }
            balanced += 1;
            let m = k.roller_moment_nm(i, wc, s.spin_rad_s).expect("moment");
            // The solver's residual, to round-off: each lamina's kink search starts from its
            // last root (srb12), which moves that root by ulps, not bit for bit.
            assert!(
                (m - s.residual_nm).abs() <= 1e-12 * s.scale_nm,
                "roller {i}: {m} vs {}",
                s.residual_nm
            );
            let d = 1e-11 * s.spin_rad_s.abs();
            let lo = k.roller_moment_nm(i, wc, s.spin_rad_s - d).expect("moment");
            let hi = k.roller_moment_nm(i, wc, s.spin_rad_s + d).expect("moment");
            let within = m.abs() <= SPIN_MOMENT_TOLERANCE * s.scale_nm;
            assert!(
                within || (lo >= 0.0 && hi <= 0.0),
                "roller {i}: {m} N·m at {} rad/s (scale {}), M(±δ) = {lo}, {hi}",
                s.spin_rad_s,
                s.scale_nm
            );
            // Away from the root by 1e-6 of the spin M has its sign (a root, not a flat
            // stretch the solver stopped in).
            let d = 1e-6 * s.spin_rad_s.abs();
            let lo = k.roller_moment_nm(i, wc, s.spin_rad_s - d).expect("moment");
            let hi = k.roller_moment_nm(i, wc, s.spin_rad_s + d).expect("moment");
            assert!(
                lo >= -SPIN_MOMENT_TOLERANCE * s.scale_nm,
                "roller {i}: {lo}"
            );
            assert!(hi <= SPIN_MOMENT_TOLERANCE * s.scale_nm, "roller {i}: {hi}");
        }
        assert!(balanced > 0);
    }
}

/// A roller loaded at both raceways spins between the spins at which its inner and its
/// outer contact would roll without sliding (at their load centroids): one ring drives it,
/// the other brakes it, so it cannot outrun both, and the pocket drag only brakes. So every
/// roller is at most as fast as the faster rolling spin (1e-9), and a roller in the load
/// zone (both contacts ≥ 10 % of the heaviest roller's load, where the raceway traction
/// outweighs the pocket drag) lies between the two. A lightly loaded roller may be slower
/// than both: the pocket drag brakes it (roller 15 of the 6 kN axial case: −716 rad/s
/// against −830 and −791). With the skew reaction's drag (the pocket's films brake harder)
/// a loaded roller may also fall a little below the slower rolling spin (roller 0 of the
/// 20 kN case: −794.6 rad/s against −800.3 and −806.0, 0.7 %): near their rolling points
/// the contacts' laminae slide slowly on the law's low-traction branch, so a small brake
/// moves the root. So a loaded roller must lie between the two, or below the slower by
/// at most 2 % of it, and then the moment at the slower rolling spin must be the brake's
/// sign (the root lies on the braked side; printed).
#[test]
fn spins_lie_between_the_rolling_spins() {
    for (fr, fa) in [(20_000.0, 0.0), (20_000.0, 2_000.0), (0.0, 6_000.0)] {
        let a = solve(&with_loads(fr, fa));
        let k = loss_kinematics(&a).expect("kinematics");
        let spins = k.spins_at(a.dynamic.cage_rad_s).expect("spins");
        let qmax = a.max_roller_load_n();
        let mut both = 0;
        for (i, s) in spins.iter().enumerate() {
            let (Some(si), Some(so)) = (s.rolling_spin_inner_rad_s, s.rolling_spin_outer_rad_s)
            else {
                continue;
            };
            let tol = 1e-9 * s.spin_rad_s.abs();
            assert!(
                s.spin_rad_s.abs() <= si.abs().max(so.abs()) + tol && s.spin_rad_s * si >= 0.0,
                "roller {i}: {} faster than [{si}, {so}]",
                s.spin_rad_s
            );
            let r = &a.combined.rollers[i];
            if r.inner.normal_load_n.min(r.outer.normal_load_n) < 0.1 * qmax {
                continue;
            }
            both += 1;
            let (fast, slow) = if si.abs() >= so.abs() {
                (si, so)
            } else {
                (so, si)
            };
            let between = s.spin_rad_s.abs() >= slow.abs() - tol;
            if !between {
                let m = k
                    .roller_moment_nm(i, a.dynamic.cage_rad_s, slow)
                    .expect("moment");
                eprintln!(
                    "({fr}, {fa}) roller {i}: {} below [{slow}, {fast}], moment {m} N·m at the slower",
                    s.spin_rad_s
                );
                assert!(
                    s.spin_rad_s.abs() >= 0.98 * slow.abs() && m * slow < 0.0,
                    "roller {i}: {} below [{si}, {so}] (moment {m} N·m at {slow})",
                    s.spin_rad_s
                );
            }
        }
        assert!(both > 0, "({fr}, {fa}): no roller loaded at both raceways");
    }
}

/// With `cage.speed = "computed"` the cage's torque is balanced at the reported speed to
/// [`CAGE_TORQUE_TOLERANCE`] of its scale (Σ|F_circ|·d_m/2 + |T_land| + M), the imbalance
/// changes sign across it (±0.1 % of the speed, evaluated afresh), and the speed lies
/// between the rings'.
#[test]
fn computed_cage_speed_balances_the_cage() {
    let mut b = with_loads(20_000.0, 0.0);
    b.cage.speed = CageSpeedSource::Computed;
    let (a, l) = breakdown(&b);
    let x = &l.losses;
    assert!(l.cage_speed_computed);
    let dm = a.input.geometry.pitch_diameter_m;
    let scale: f64 = l
        .rollers
        .iter()
        .map(|r| r.circumferential_force_n.abs())
        .sum::<f64>()
        * 0.5
        * dm
        + l.cage_land_torque_nm.abs()
        + x.friction_torque_nm;
    // The torque's resolution: the rollers' net tractions are fixed only to their spread
    // across each spin's final bracket (near-vertical balance), summed at d_m/2.
    let noise = l.cage_torque_noise_nm;
    let tol = (CAGE_TORQUE_TOLERANCE * scale).max(noise);
    eprintln!(
        "imbalance {} N·m, tolerance {} N·m (scale {scale}), noise {noise} N·m",
        x.cage_torque_imbalance_nm,
        CAGE_TORQUE_TOLERANCE * scale
    );
    assert!(
        x.cage_torque_imbalance_nm.abs() <= tol,
        "{} N·m vs tolerance {tol}",
        x.cage_torque_imbalance_nm
    );
    let wc = x.cage_speed_rpm * std::f64::consts::PI / 30.0;
    let wi = a.input.operating.inner_speed_rad_s;
    assert!(wc > 0.0 && wc < wi);
    let k = loss_kinematics(&a).expect("kinematics");
    let at = |w: f64| {
        loss_breakdown(&k.inputs_at(w).expect("inputs"))
            .expect("breakdown")
            .losses
            .cage_torque_imbalance_nm
    };
    let (lo, hi) = (at(wc * 0.999), at(wc * 1.001));
    assert!(lo > 0.0 && hi < 0.0, "{lo} {hi}");
    // The balance lies within 1e-6 of the reported speed: the imbalance, every spin solved
    // afresh, changes sign across ±1e-6 of it. (Where the torque steps across the balance,
    // ATZ laminae at their rolling points, the speed is bracketed to 1e-9 of the ring
    // speed and the step is the reported noise; 1e-6 leaves room for the cold spins'
    // own resolution.)
    let (lo6, hi6) = (at(wc * (1.0 - 1e-6)), at(wc * (1.0 + 1e-6)));
    assert!(lo6 > 0.0 && hi6 < 0.0, "{lo6} {hi6} (noise {noise} N·m)");
    // The warm-started spins of the balance are the cold-started ones: the imbalance at
    // the reported speed, every spin solved afresh, is within the tolerance too (2× for
    // the two spin solutions' own resolution).
    let cold = at(wc);
    assert!(cold.abs() <= 2.0 * tol, "{cold} N·m vs tolerance {tol}");
}

/// The losses stage's cost on the shipped deck's three cases, the cage speed measured and
/// computed (the cage's torque balance, every roller's spin re-solved per evaluation,
/// warm-started), mean of 3 runs each. Printed, not asserted: timings on a shared 2-core
/// machine in the test profile are not a pass/fail criterion.
#[test]
fn losses_stage_cost_print() {
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0), (20_000.0, 2_000.0)] {
        for cage in [CageSpeedSource::Measured, CageSpeedSource::Computed] {
            let mut b = with_loads(fr, fa);
            b.cage.speed = cage;
            let a = solve(&b);
            let t = std::time::Instant::now();
            let mut total = 0.0;
            SPIN_COUNTS.with(|c| c.set((0, 0, 0)));
            CAGE_TRACE.with(|c| c.borrow_mut().clear());
            TRACTION_CALLS.with(|c| c.set(0));
            for _ in 0..3 {
                total += losses(&a).unwrap_or_else(|e| panic!("{e}")).losses.total_w;
            }
            let ms = t.elapsed().as_secs_f64() / 3.0 * 1e3;
            let (solves, evals, laminae) = SPIN_COUNTS.with(std::cell::Cell::get);
            let cage_evals = CAGE_TRACE.with(|c| c.borrow().len()) / 3;
            let traction = TRACTION_CALLS.with(std::cell::Cell::get) / 3;
            let loaded: [usize; 2] = [0, 1].map(|side| {
                a.rows
                    .iter()
                    .flat_map(|r| r.contacts.iter())
                    .map(|rc| rc.iter().filter(|l| l[side].load_n > 0.0).count())
                    .sum()
            });
            let rollers = a.rows.iter().map(|r| r.load.rollers.len()).sum::<usize>();
            eprintln!(
                "  counts: {cage_evals} cage evaluations, {rollers} rollers, loaded laminae inner {} outer {} (of {} per raceway), {traction} traction integrations per losses() (spins {}, the rest breakdown + guide ring)",
                loaded[0],
                loaded[1],
                a.rows.iter().flat_map(|r| r.load.rollers.iter()).map(|r| r.laminae.len()).sum::<usize>(),
                laminae / 3,
            );
            let l = losses(&a).unwrap_or_else(|e| panic!("{e}"));
            eprintln!(
                "{fr} N radial, {fa} N axial, {cage:?}: {ms:.2} ms, per run {} spin solves, {:.2} moment evaluations per solve, {} lamina evaluations ({:.3} W, cage {:.3} rpm, imbalance {:.2e} N·m, noise {:.2e} N·m)",
                solves / 3,
                evals as f64 / solves.max(1) as f64,
                laminae / 3,
                total / 3.0,
                l.losses.cage_speed_rpm,
                l.losses.cage_torque_imbalance_nm,
                l.cage_torque_noise_nm
            );
        }
    }
}

/// The guide ring's share (issue 27: 5–20 %; the seed: 10–15 % "especially under radial
/// load") traced to what drives it. In the model the ring is pressed only by the rollers the
/// raceways do not hold axially: an unloaded roller rests on the outer sphere, whose normal
/// is normal to the roller axis, so the axis component of its centrifugal force,
/// F_c·sin α⁰, goes to the ring: checked here to 15 % per roller (measured 1.07 N against
/// 1.21 N at 20 kN radial, 12 % less: the outer contact sits off the roller's centre on
/// its crown, where the normal leans toward the axis by y/R_W — 1 mm of offset takes 2.5 %
/// of F_c·cos α⁰ — and the statics' soft pocket spring and the roller's tilt take part). Hand estimate of the model at 20 kN radial,
/// 3000 rpm: F_c = m·ω_c²·d_m/2 ≈ 0.0116 kg·(128 rad/s)²·0.0325 m ≈ 6.2 N, so
/// Q_end ≈ 1.3 N on ~6 unloaded rollers per row; the end contact lies on the roller axis,
/// so it slides at the ring's speed relative to the cage, (ω_g − ω_c)·r_g ≲ 6 m/s, at
/// μ ≤ μ_fl = 0.06: ≲ 0.5 W per roller, ≲ 6 W in all, and the bore's Petroff film
/// (2π·η·R_b³·L_b/c ≈ 1.6e-4 N·m·s at 25 mPa·s, R_b 28 mm, L_b 1.45 mm, c 30 µm) a few W
/// more: ~1–2 % of ~250 W at most; the model gives 0.6 %.
///
/// A 22308 CC in service (order of magnitude, not published): the ring is pressed mainly
/// by the *loaded* rollers, through the axial tractions of their skew (a roller skewed by
/// ψ slides axially by ψ·u at its raceway contacts; at ψ ~ 1e-3 rad and the limiting
/// traction that is ~ μ_fl·Q·ψ·u/(|v_sl|+ψ·u) ~ 0.01–0.03·Q, 30–100 N at Q ≈ 3.5 kN) and by
/// end faces that touch the ring off the roller axis (~1 mm: sliding ω_s·1 mm ≈ 0.8 m/s
/// from the spin alone): 10 loaded rollers × μ 0.05 × 50 N × 1–3 m/s ≈ 25–75 W, 10–25 %
/// of the loss — the seed's range. (srb10: not so for a floating ring. Its torque balance
/// caps the ends' circumferential sliding loss with the bore's, at k_b·(ω_i − ω_c)² ≈ 6 W
/// on this deck, `guide_ring_loss_is_bounded_by_its_bore`; only end points off the roller
/// axis, swept by the spin, escape the cap.) Neither is in the model: the statics' rollers have no
/// skew degree of freedom (the loaded rollers' axial balance closes on the raceways with
/// 0 N at the ring) and the derived end contact lies on the axis (the 22308's end and
/// ring geometry is not published). So the share stays < 1 % and `seed_shapes` keeps that
/// shape failing; no constant is tuned.
#[test]
fn guide_ring_end_loads_are_the_unloaded_rollers_centrifugal_push() {
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0)] {
        let b = with_loads(fr, fa);
        let (a, l) = breakdown(&b);
        let alpha = b.geometry.contact_angle_rad;
        let g = l.guide_ring.as_ref().expect("the deck has a guide ring");
        let (mut unloaded, mut loaded_on_ring) = (0, 0.0f64);
        for (k, r) in a.combined.rollers.iter().enumerate() {
            let c = &g.contacts[k];
            if r.inner.normal_load_n == 0.0 && r.guide_force_n > 0.0 {
                unloaded += 1;
                let push = r.centrifugal_force_n * alpha.sin();
                assert!(
                    (r.guide_force_n - push).abs() <= 0.15 * push,
                    "({fr}, {fa}) roller {k}: {} N on the ring, F_c·sin α⁰ = {push} N",
                    r.guide_force_n
                );
            } else {
                loaded_on_ring = loaded_on_ring.max(r.guide_force_n);
            }
            if k < 2 || r.guide_force_n > 0.0 && unloaded == 1 {
                eprintln!(
                    "({fr}, {fa}) roller {k}: Q_in {:.1} N, Q_end {:.3} N, F_c {:.3} N, end sliding {:.3} m/s, end power {:.4} W",
                    r.inner.normal_load_n,
                    r.guide_force_n,
                    r.centrifugal_force_n,
                    c.sliding_speed_m_s,
                    c.power_w
                );
            }
        }
        eprintln!(
            "({fr}, {fa}): ring {:.1} rpm (cage {:.1} rpm), ends {:.3} W, bore {:.3} W, share {:.2} %, {unloaded} rollers on the ring by F_c, largest end load of the others {loaded_on_ring:.3} N",
            g.speed_rad_s * 30.0 / std::f64::consts::PI,
            l.losses.cage_speed_rpm,
            g.ends_power_w,
            g.bore_power_w,
            l.losses.shares_pct.guide_ring
        );
        assert!(unloaded > 0, "({fr}, {fa}): no roller rests on the ring");
    }
}

/// Seed Fig. 3a's numbers (pure axial 6 kN, R′_Ci = 1.002·R_Ci) with the measured and the
/// computed cage speed: M_fi, M_fo and C = (L10/L10,0)^(1/4) changes (the optimiser's
/// `raising_r_ci_*` tests assert them on the measured cage). Run with --ignored.
#[test]
#[ignore = "diagnostic print"]
fn raising_r_ci_print() {
    for cage in [CageSpeedSource::Measured, CageSpeedSource::Computed] {
        let run = |k: f64| {
            let mut b = with_loads(0.0, 6_000.0);
            b.cage.speed = cage;
            b.geometry.inner_raceway_radius_m *= k;
            breakdown(&b)
        };
        let ((a0, l0), (a1, l1)) = (run(1.0), run(1.002));
        let rel = |x: f64, y: f64| 100.0 * (y / x - 1.0);
        let c = 100.0
            * ((a1.l10_mrev.unwrap_or(f64::NAN) / a0.l10_mrev.unwrap_or(f64::NAN)).powf(0.25)
                - 1.0);
        eprintln!(
            "{cage:?}: M_fi {:.5} -> {:.5} N·m ({:+.2} %), M_fo {:.5} -> {:.5} N·m ({:+.2} %), C {c:+.2} %",
            l0.losses.friction_torque_inner_nm,
            l1.losses.friction_torque_inner_nm,
            rel(l0.losses.friction_torque_inner_nm, l1.losses.friction_torque_inner_nm),
            l0.losses.friction_torque_outer_nm,
            l1.losses.friction_torque_outer_nm,
            rel(l0.losses.friction_torque_outer_nm, l1.losses.friction_torque_outer_nm),
        );
    }
}

/// The safeguarded Newton finds the same spins as the Illinois false position it replaced
/// (kept as a test reference), on every roller of the shipped deck's three cases at the
/// statics' cage speed and 5 % off it: to 1e-10 relative; or both residuals within
/// [`SPIN_MOMENT_TOLERANCE`] of the scale and 1e-8 apart (the root is unique, M falls
/// strictly with ω_s, so two closings of the same tolerance differ by the tolerance's
/// width in ω_s, 1e-9·scale/|M'|, wider on a lightly loaded roller); or the new spin is
/// inside a vertical stretch of M (sign change at ±1e-10 relative).
#[test]
fn newton_spins_match_illinois() {
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0), (20_000.0, 2_000.0)] {
        let a = solve(&with_loads(fr, fa));
        let k = loss_kinematics(&a).expect("kinematics");
        for wc in [a.dynamic.cage_rad_s, 0.95 * a.dynamic.cage_rad_s] {
            let new = k.spins_at(wc).expect("spins");
            let old = k.spins_illinois(wc).expect("spins");
            assert_eq!(new.len(), old.len());
            for (i, (n, o)) in new.iter().zip(&old).enumerate() {
                assert_eq!(n.balanced, o.balanced, "roller {i}");
                let (x, y) = (n.spin_rad_s, o.spin_rad_s);
                let rel = (x - y).abs() / y.abs().max(1.0);
                if rel <= 1e-10 {
                    continue;
                }
                // Both close the same balance to the tolerance (a roller with a shallow
                // M, lightly loaded, has a wider ω_s band inside it: measured 1.8e-10 on
                // roller 13 of the combined case), or M changes sign across ±1e-10.
                let tol = |r: &super::losses::RollerSpin| {
                    r.residual_nm.abs() <= SPIN_MOMENT_TOLERANCE * r.scale_nm
                };
                if tol(n) && tol(o) && rel <= 1e-8 {
                    continue;
                }
                let d = 1e-10 * x.abs().max(1.0);
                let lo = k.roller_moment_nm(i, wc, x - d).expect("moment");
                let hi = k.roller_moment_nm(i, wc, x + d).expect("moment");
                assert!(
                    lo >= 0.0 && hi <= 0.0,
                    "{fr} N/{fa} N, roller {i}: Newton {x} vs Illinois {y} rad/s ({rel:.2e}), M(±δ) = {lo}, {hi}"
                );
            }
        }
    }
}

/// The skew on the shipped deck (computed cage; `skew.rs`): every roller's yaw balance
/// closes — either the ring holds it inside the pocket play (|h| ≤ 1e-8 of |M_s(0)|, the
/// search's tolerance with margin) or the pocket stops it at ψ = ±c_p/L with the reaction of
/// M_s(0)'s sign —, ψ has the sign of M_s(0), a roller without a yaw moment does not skew,
/// and the floating guide ring passes no axial load: the two rows' skew end loads are equal
/// (1e-9 of their sum). Under pure radial load the rows mirror each other (1e-9).
#[test]
fn skew_balances_each_roller_and_the_floating_ring() {
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0), (20_000.0, 2_000.0)] {
        let b = with_loads(fr, fa);
        let (_, l) = breakdown_skewed(&b);
        let psi_max = b.cage.pocket_clearance_m / b.geometry.roller_length_m;
        let (mut s1, mut s2) = (0.0, 0.0);
        for (k, r) in l.rollers.iter().enumerate() {
            let m0 = r.unskewed_skew_moment_nm;
            if m0 == 0.0 {
                assert_eq!(r.skew_angle_rad, 0.0, "({fr}, {fa}) roller {k}");
            } else {
                assert!(r.skew_angle_rad * m0 > 0.0, "({fr}, {fa}) roller {k}");
                let limited = (r.skew_angle_rad.abs() - psi_max).abs() <= 1e-15;
                if limited {
                    assert!(r.skew_pocket_moment_nm * m0 >= 0.0, "roller {k}");
                } else {
                    assert!(r.skew_angle_rad.abs() < psi_max);
                    assert!(
                        r.skew_pocket_moment_nm.abs() <= 1e-8 * m0.abs(),
                        "({fr}, {fa}) roller {k}: {} of {m0}",
                        r.skew_pocket_moment_nm
                    );
                }
            }
            if r.row == 1 {
                s1 += r.skew_guide_ring_load_n;
            } else {
                s2 += r.skew_guide_ring_load_n;
            }
        }
        assert!(
            (s1 - s2).abs() <= 1e-9 * (s1 + s2).max(1e-300),
            "({fr}, {fa}): {s1} vs {s2}"
        );
        if fa == 0.0 {
            let (r1, r2) = l.rollers.split_at(13);
            for (x, y) in r1.iter().zip(r2) {
                let tol = 1e-9 * x.skew_guide_ring_load_n.abs().max(1.0);
                assert!((x.skew_guide_ring_load_n - y.skew_guide_ring_load_n).abs() <= tol);
                assert!((x.skew_angle_rad.abs() - y.skew_angle_rad.abs()).abs() <= 1e-9 * psi_max);
            }
        }
    }
}

/// What the skew's one-way coupling leaves out (module notes "Skew", neglected couplings),
/// measured on the shipped deck: the spin balance's residual at ψ (the circumferential
/// tractions F_θ(ψ) against the spin's F(v_θ), over the traction moments' scale), the end
/// load against the roller's load (the statics' axial balance), the axial tractions' pitch
/// couple ρ·|F_a| against Q·L (the lamina loads' moment scale), the ring's yaw share
/// Σ|M_g·a_r| against its bore torque. Printed, not asserted.
#[test]
fn skew_couplings_print() {
    use super::skew::skewed_lamina;
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0), (20_000.0, 2_000.0)] {
        let b = with_loads(fr, fa);
        let (a, l) = breakdown_skewed(&b);
        let k = loss_kinematics(&a).expect("kinematics").skewed();
        let wc = l.losses.cage_speed_rpm * std::f64::consts::PI / 30.0;
        let i = k.inputs_at(wc).expect("inputs");
        let lub = &i.lubricant;
        let (mut spin_res, mut q_ratio, mut pitch, mut ring_yaw) = (0.0f64, 0.0f64, 0.0f64, 0.0);
        let (mut limited, mut skewed, mut psi_max) = (0, 0, 0.0f64);
        for (ri, rl) in i.rollers.iter().zip(&l.rollers) {
            let Some(sp) = &ri.skew else { continue };
            if rl.skew_angle_rad == 0.0 {
                continue;
            }
            skewed += 1;
            psi_max = psi_max.max(rl.skew_angle_rad.abs());
            if rl.skew_pocket_moment_nm.abs() > 1e-8 * rl.unskewed_skew_moment_nm.abs() {
                limited += 1;
            }
            let (mut d, mut scale, mut fa_sum) = (0.0, 0.0, 0.0f64);
            for (sl, us) in [(&ri.inner, &sp.inner_m_s), (&ri.outer, &sp.outer_m_s)] {
                let mut fa_side = 0.0;
                for (s, &u) in sl.iter().zip(us.iter()) {
                    let m = u / ri.spin_rad_s;
                    let t0 = skewed_lamina(lub.law, &lub.rheology, s, 0.0).expect("lamina");
                    let t = skewed_lamina(lub.law, &lub.rheology, s, rl.skew_angle_rad * u)
                        .expect("lamina");
                    d += (t.circumferential_n - t0.circumferential_n) * m;
                    scale += (t0.circumferential_n * m).abs();
                    fa_side += t.axial_n;
                }
                fa_sum = fa_sum.max(fa_side.abs());
            }
            spin_res = spin_res.max(d.abs() / scale.max(1e-300));
            let q: f64 = ri.inner.iter().map(|x| x.load_n).sum();
            if q > 0.0 {
                q_ratio = q_ratio.max(rl.skew_guide_ring_load_n / q);
                let rho = 0.5 * b.geometry.roller_diameter_m;
                pitch = pitch.max(rho * fa_sum / (q * b.geometry.effective_length_m));
            }
            ring_yaw += (rl.skew_ring_moment_nm * ri.skew_axis_axial_component).abs();
        }
        let g = l.guide_ring.as_ref().expect("guide ring");
        let s = &l.losses.shares_pct;
        eprintln!(
            "({fr}, {fa}): {skewed} rollers skewed (ψ ≤ {psi_max:.3e} rad, {limited} stopped by the pocket); spin residual at ψ ≤ {:.2} % of the traction moments; skew end load ≤ {:.2} % of the inner load; pitch couple ρ·|ΣF_a| ≤ {:.2} % of Q·L_eff; ring yaw share Σ|M_g·a_r| {ring_yaw:.3e} N·m against its bore torque {:.3e} N·m; ring {:.1} rpm; shares: raceways {:.1} %, skew {:.2} %, ring {:.2} %, cage {:.2} %",
            100.0 * spin_res,
            100.0 * q_ratio,
            100.0 * pitch,
            g.bore_torque_nm.abs(),
            g.speed_rad_s * 30.0 / std::f64::consts::PI,
            s.raceway_inner + s.raceway_outer,
            s.skew,
            s.guide_ring,
            s.cage_pockets + s.cage_land,
        );
    }
}

/// The guide ring's own Petroff coefficient k_b = 2π·η·R_b³·L_b/c_b, N·m·s (the bore on the
/// inner ring, `losses::derived_geometry`), computed here from the deck.
fn bore_petroff_coefficient(b: &DoubleRowInput) -> f64 {
    let rb = super::losses::derived_geometry(b).guide_bore_radius_m;
    2.0 * std::f64::consts::PI * b.viscosity_pa_s() * rb.powi(3) * b.guide_ring.width_m
        / (0.5 * b.guide_ring.bore_clearance_m)
}

/// The ceiling on the guide ring's loss (srb10), a consequence of its torque balance alone:
/// the ring turns between the cage and the inner ring, driven by its bore film (torque
/// T_b ≥ 0 toward ω_i) and braked by the roller ends (and the cage's land, when the cage
/// is piloted on it). Its loss is the bore's T_b·(ω_i − ω_g) plus the ends' Σ|F_k|·|v_k|
/// with v_k = (ω_g − ω_c)·r_g − u_k (u_k the end point's own speed); the ends' torque
/// Σ F_k·r_g is at most T_b (the land brakes too), so
/// P_ring ≤ T_b·(ω_i − ω_c) + Σ|F_k|·|u_k| ≤ k_b·(ω_i − ω_c)² + Σ|F_k|·|u_k|,
/// k_b = 2π·η·R_b³·L_b/c_b the bore's Petroff coefficient. Checked on the shipped deck's
/// three cases to 1e-9 (the balance's residual), **whatever loads the ends**: so with the
/// deck's ring (bore 1.45 mm wide, 30 µm radial clearance, R_b 28.4 mm, 60 °C) the ring
/// cannot take more than k_b·(ω_i − ω_c)² ≈ 6 W, 2.1–2.4 % of the loss, unless its end
/// contacts lie off the roller axis (u_k ≠ 0: the spin sweeps them) — the derived end
/// geometry puts them on the axis (|u_k| ≤ 4e-5 m·|ω_s|). The seed's 10–15 % (issue band
/// 5–20 %) is therefore out of reach of this deck's guide ring; asserted below 5 %.
#[test]
fn guide_ring_loss_is_bounded_by_its_bore() {
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0), (20_000.0, 2_000.0)] {
        let b = with_loads(fr, fa);
        let (_, l) = breakdown(&b);
        let g = l.guide_ring.as_ref().expect("the deck has a guide ring");
        let wi = b.operating.inner_speed_rad_s;
        let wc = l.losses.cage_speed_rpm * std::f64::consts::PI / 30.0;
        let rg = super::losses::derived_geometry(&b).guide_contact_radius_m;
        let kb = bore_petroff_coefficient(&b);
        let own: f64 = g
            .contacts
            .iter()
            .map(|c| {
                let u = (g.speed_rad_s - wc) * rg - c.sliding_speed_m_s;
                c.force_on_roller_n.abs() * u.abs()
            })
            .sum();
        let bound = kb * (wi - wc).powi(2) + own;
        let p = l.losses.guide_ring_w;
        eprintln!(
            "({fr}, {fa}): guide ring {p:.3} W ({:.2} %), ceiling {bound:.3} W ({:.2} % of {:.1} W; ends' own sliding {own:.2e} W), ring {:.1} rpm, cage {:.1} rpm",
            l.losses.shares_pct.guide_ring,
            100.0 * bound / l.losses.total_w,
            l.losses.total_w,
            g.speed_rad_s * 30.0 / std::f64::consts::PI,
            l.losses.cage_speed_rpm
        );
        assert!(p <= bound * (1.0 + 1e-9), "({fr}, {fa}): {p} W > {bound} W");
        assert!(
            bound < 0.05 * l.losses.total_w,
            "({fr}, {fa}): the ceiling {bound} W is 5 % of {} W or more",
            l.losses.total_w
        );
    }
}

/// Issue 27 / srb10 item 1: what could load the guide ring of a 22308 CC, measured on the
/// shipped deck (three cases, computed cage). Printed, not asserted (the assertions are
/// `guide_ring_loss_is_bounded_by_its_bore` and
/// `guide_ring_end_loads_are_the_unloaded_rollers_centrifugal_push`):
/// (a) the loaded rollers' contact angles α_i ≠ α_o and the axial components
///     Q·sin(α − α⁰) of each raceway's resultant along the roller axis — what a roller that
///     could not walk along its crown would press on the ring —, the roller's actual walk
///     against the end gap, and the ring force the statics finds;
/// (b) the ring's bore and the cage's land films at the balanced ring speed, and the
///     ceiling k_b·(ω_i − ω_c)²;
/// (c) the ends: Σ Q_end, their loss, and what an end contact 1 mm off the roller axis
///     (spin sweeping it at ω_s·1 mm) would dissipate at μ_fl.
#[test]
#[ignore = "diagnostic print"]
fn guide_ring_physics_print() {
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0), (20_000.0, 2_000.0)] {
        let b = with_loads(fr, fa);
        let (a, l) = breakdown(&b);
        let a0 = b.geometry.contact_angle_rad;
        let (mut worst_da, mut worst_fi, mut worst_fo, mut worst_walk) =
            (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        let (mut loaded, mut loaded_ring) = (0, 0.0f64);
        for r in &a.combined.rollers {
            if r.inner.normal_load_n <= 0.0 || r.outer.normal_load_n <= 0.0 {
                continue;
            }
            loaded += 1;
            let (ai, ao) = (
                r.inner.contact_angle_deg.to_radians(),
                r.outer.contact_angle_deg.to_radians(),
            );
            worst_da = worst_da.max((ai - ao).abs().to_degrees());
            worst_fi = worst_fi.max((r.inner.normal_load_n * (ai - a0).sin()).abs());
            worst_fo = worst_fo.max((r.outer.normal_load_n * (ao - a0).sin()).abs());
            worst_walk = worst_walk.max(r.axial_displacement_m.abs());
            loaded_ring = loaded_ring.max(r.guide_force_n);
        }
        let g = l.guide_ring.as_ref().expect("guide ring");
        let wi = b.operating.inner_speed_rad_s;
        let wc = l.losses.cage_speed_rpm * std::f64::consts::PI / 30.0;
        let kb = bore_petroff_coefficient(&b);
        let rh = loss_inputs(&a)
            .expect("inputs")
            .lubricant
            .rheology
            .limiting_traction_coefficient;
        let q_end: f64 = l.rollers.iter().map(|r| r.guide_ring_load_n).sum();
        let spin = l
            .rollers
            .iter()
            .map(|r| r.spin_rad_s.abs())
            .fold(0.0, f64::max);
        eprintln!(
            "({fr}, {fa}) (a) {loaded} loaded rollers: |α_i − α_o| ≤ {worst_da:.3}°, |Q_i·sin(α_i − α⁰)| ≤ {worst_fi:.1} N, |Q_o·sin(α_o − α⁰)| ≤ {worst_fo:.1} N, walk ≤ {:.2} µm (end gap at rest {:.1} µm), ring force on a loaded roller ≤ {loaded_ring:.3} N",
            worst_walk * 1e6,
            b.guide_gap_m() * 1e6
        );
        eprintln!(
            "({fr}, {fa}) (b) ring {:.1} rpm, cage {:.1} rpm, inner {:.1} rpm; bore {:.3} W (T_b {:.4} N·m, k_b {kb:.3e} N·m·s), land torque on the ring {:.4} N·m; ceiling k_b(ω_i − ω_c)² = {:.3} W; guide ring {:.3} W = {:.2} % of {:.1} W",
            g.speed_rad_s * 30.0 / std::f64::consts::PI,
            l.losses.cage_speed_rpm,
            wi * 30.0 / std::f64::consts::PI,
            g.bore_power_w,
            g.bore_torque_nm,
            g.land_torque_nm,
            kb * (wi - wc).powi(2),
            l.losses.guide_ring_w,
            l.losses.shares_pct.guide_ring,
            l.losses.total_w
        );
        eprintln!(
            "({fr}, {fa}) (c) Σ Q_end {q_end:.2} N on {} rollers, ends {:.3} W (sliding ≤ {:.3} m/s); at 1 mm off the axis: μ_fl·ΣQ·ω_s·1 mm ≤ {:.3} W (ω_s ≤ {spin:.0} rad/s); the seed's 10–15 % would need {:.0}–{:.0} W",
            l.rollers.iter().filter(|r| r.guide_ring_load_n > 0.0).count(),
            g.ends_power_w,
            g.contacts.iter().map(|c| c.sliding_speed_m_s.abs()).fold(0.0, f64::max),
            rh * q_end * spin * 1e-3,
            0.10 / 0.90 * (l.losses.total_w - l.losses.guide_ring_w),
            0.15 / 0.85 * (l.losses.total_w - l.losses.guide_ring_w),
        );
    }
}

/// srb12: the cage balance's breakdown reads each unskewed roller's raceway sums from its
/// spin solve (`LossKinematics::breakdown_at`) instead of integrating every lamina once
/// more per cage speed. Those sums are the breakdown's own (the same laminae, forces and
/// order of addition; the spin solves' kink search is hinted, so to round-off): every loss
/// term, the friction torques, the cage imbalance and each roller's net traction agree
/// with `loss_breakdown` re-integrating the same spins to 1e-12 of their scale, on the
/// three load cases at the balanced cage speed. (A sum missing a lamina or a term would
/// move a raceway's loss by ≳1e-4.)
#[test]
fn cage_point_sums_are_the_breakdown() {
    for (fr, fa) in [(20_000.0, 0.0), (0.0, 6_000.0), (20_000.0, 2_000.0)] {
        let (a, l) = breakdown(&with_loads(fr, fa));
        let wc = l.losses.cage_speed_rpm * std::f64::consts::PI / 30.0;
        let k = loss_kinematics(&a).expect("kinematics");
        let spins = k.spins_at(wc).expect("spins");
        let fast = k.breakdown_at(wc, &spins, None).expect("from the spins");
        let full = loss_breakdown(&k.inputs_with(wc, &spins)).expect("re-integrated");
        let (x, y) = (&fast.losses, &full.losses);
        for (name, p, q) in [
            ("raceway_inner_w", x.raceway_inner_w, y.raceway_inner_w),
            ("raceway_outer_w", x.raceway_outer_w, y.raceway_outer_w),
            ("guide_ring_w", x.guide_ring_w, y.guide_ring_w),
            ("cage_pockets_w", x.cage_pockets_w, y.cage_pockets_w),
            ("cage_land_w", x.cage_land_w, y.cage_land_w),
            ("skew_w", x.skew_w, y.skew_w),
            ("total_w", x.total_w, y.total_w),
        ] {
            assert!(
                (p - q).abs() <= 1e-12 * y.total_w,
                "{fr} N, {fa} N: {name} {p} vs {q}"
            );
        }
        let m = y.friction_torque_nm;
        assert!((x.friction_torque_inner_nm - y.friction_torque_inner_nm).abs() <= 1e-12 * m);
        assert!((x.cage_torque_imbalance_nm - y.cage_torque_imbalance_nm).abs() <= 1e-12 * m);
        let scale = full
            .rollers
            .iter()
            .map(|r| r.circumferential_force_n.abs())
            .fold(0.0, f64::max);
        for (r, s) in fast.rollers.iter().zip(&full.rollers) {
            let d = r.circumferential_force_n - s.circumferential_force_n;
            assert!(
                d.abs() <= 1e-12 * scale,
                "{fr} N, {fa} N: {d} N of {scale} N"
            );
            assert_eq!(r.eq3_flagged_laminae, s.eq3_flagged_laminae);
        }
    }
}
