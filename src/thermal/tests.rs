//! Thermal network tests: analytic references with stated tolerances.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use super::*;
use crate::deck::thermal::parse_thermal;
use crate::units::Units;

const RIG: &str = include_str!("../../decks/aerospace.toml");

fn rig() -> ThermalModel {
    let table: toml::Table = toml::from_str(RIG).expect("shipped deck is valid TOML");
    parse_thermal(&table, Units::Si).expect("shipped deck parses")
}

/// Heat of the shipped rig in normal operation, W (~2.1 kW).
fn rig_heat() -> HeatInput {
    HeatInput::new()
        .with(HeatSource::InnerContacts, 900.0)
        .with(HeatSource::OuterContacts, 700.0)
        .with(HeatSource::CageRails, 150.0)
        .with(HeatSource::ViscousDrag, 350.0)
}

/// Lost-lubrication heat: more contact friction, little drag.
fn rig_loss_heat() -> HeatInput {
    HeatInput::new()
        .with(HeatSource::InnerContacts, 1100.0)
        .with(HeatSource::OuterContacts, 900.0)
        .with(HeatSource::CageRails, 250.0)
        .with(HeatSource::ViscousDrag, 20.0)
}

/// Heat `q_w` delivered entirely to nodes bound to `InnerContacts` (roller fraction 0).
fn q(q_w: f64) -> HeatInput {
    HeatInput::new().with(HeatSource::InnerContacts, q_w)
}

fn continued(duration_s: f64, step_s: f64, integrator: Integrator) -> TransientSettings {
    TransientSettings {
        duration_s,
        step_s,
        integrator,
        scenario: Scenario::Continued,
        oil_node: None,
        stop_at_limits: false,
    }
}

/// One node, capacity C, conductance G to T∞, heat Q.
fn one_node(c: f64, g: f64, t_inf: f64) -> Network {
    let mut net = Network::new(
        vec![
            Node::free("body", c).with_heat(HeatMechanism::InnerContacts),
            Node::fixed("sink", t_inf),
        ],
        vec![Link::conductance("body", "sink", g)],
    );
    net.roller_heat_fraction = 0.0;
    net
}

fn analytic(t: f64, c: f64, g: f64, qw: f64, t_inf: f64, t0: f64) -> f64 {
    t_inf + qw / g + (t0 - t_inf - qw / g) * (-g * t / c).exp()
}

fn max_error(res: &TransientResult, c: f64, g: f64, qw: f64, t_inf: f64, t0: f64) -> f64 {
    let body = res.node("body").unwrap();
    res.time_s
        .iter()
        .zip(&body.temperature_c)
        .map(|(&t, &x)| (x - analytic(t, c, g, qw, t_inf, t0)).abs())
        .fold(0.0, f64::max)
}

// ---- one node against the analytic exponential ------------------------------------------

const C1: f64 = 1000.0; // J/K
const G1: f64 = 10.0; // W/K  -> τ = 100 s
const Q1: f64 = 500.0; // W   -> Q/G = 50 K
const TINF: f64 = 20.0;
const T0: f64 = 30.0;

#[test]
fn one_node_implicit_matches_exponential() {
    // Tolerance 0.01 K: backward Euler's global error is ≈ Δt/(2τ)·(t/τ)e^(−t/τ)·|ΔT|
    // ≤ 5e-4 · 0.37 · 40 K = 7.4e-3 K for Δt = 0.1 s, τ = 100 s.
    let net = one_node(C1, G1, TINF);
    let res = run_transient_from(
        &net,
        &[T0, TINF],
        &continued(500.0, 0.1, Integrator::Implicit),
        &q(Q1),
    )
    .unwrap();
    // 5000 steps, more than MAX_SAMPLES: every second step is stored (and the last).
    assert_eq!(res.sample_every_steps, 2);
    assert_eq!(res.stats.steps, 5000);
    assert_eq!(res.time_s.len(), 2501);
    assert!((res.time_s[2500] - 500.0).abs() < 1e-12);
    assert!((res.time_s[1] - 0.2).abs() < 1e-12);
    let err = max_error(&res, C1, G1, Q1, TINF, T0);
    assert!(err < 0.01, "max error {err} K");
    assert_eq!(res.stats.factorizations, 1);
}

#[test]
fn one_node_explicit_matches_exponential() {
    // Tolerance 0.01 K: forward Euler has the same leading error as backward Euler
    // (opposite sign), ≤ 7.4e-3 K here; Δt = 0.1 s is far below the bound C/G = 100 s,
    // so no sub-steps.
    let net = one_node(C1, G1, TINF);
    let res = run_transient_from(
        &net,
        &[T0, TINF],
        &continued(500.0, 0.1, Integrator::Explicit),
        &q(Q1),
    )
    .unwrap();
    let err = max_error(&res, C1, G1, Q1, TINF, T0);
    assert!(err < 0.01, "max error {err} K");
    assert_eq!(res.stats.substeps, res.stats.steps);
    assert!((res.stats.explicit_bound_s.unwrap() - 100.0).abs() < 1e-12);
}

#[test]
fn implicit_is_first_order() {
    // Halving Δt halves backward Euler's error at t = 100 s: ratio 2 within ±0.1
    // (the O(Δt²) remainder is ≈ Δt/τ = 2 % of the error at the coarsest step).
    let net = one_node(C1, G1, TINF);
    let err_at = |dt: f64| {
        let r = run_transient_from(
            &net,
            &[T0, TINF],
            &continued(100.0, dt, Integrator::Implicit),
            &q(Q1),
        )
        .unwrap();
        let x = *r.node("body").unwrap().temperature_c.last().unwrap();
        (x - analytic(100.0, C1, G1, Q1, TINF, T0)).abs()
    };
    let (e1, e2, e3) = (err_at(2.0), err_at(1.0), err_at(0.5));
    for ratio in [e1 / e2, e2 / e3] {
        assert!(
            (ratio - 2.0).abs() < 0.1,
            "error ratio {ratio} ({e1}, {e2}, {e3})"
        );
    }
}

#[test]
fn explicit_above_bound_is_substepped() {
    // C/G = 1 s; a 5 s step is split into ⌊5/1⌋ + 1 = 6 sub-steps of 5/6 s (< bound), so
    // forward Euler stays stable and monotone (amplification 1 − 5/6 > 0). At the output
    // times (every 5 τ) the transient has nearly died out, so the error against the
    // exponential is small (observed 0.27 K); tolerance 2 K = 5 % of |ΔT| = 40 K, loose
    // because a first-order step of 0.83 τ is coarse. After 100 τ it sits at Q/G to 1e-6 K.
    let (c, g) = (10.0, 10.0);
    let net = one_node(c, g, TINF);
    let res = run_transient_from(
        &net,
        &[T0, TINF],
        &continued(100.0, 5.0, Integrator::Explicit),
        &q(Q1),
    )
    .unwrap();
    assert_eq!(res.stats.steps, 20);
    assert_eq!(res.stats.substeps, 120);
    let err = max_error(&res, c, g, Q1, TINF, T0);
    assert!(err < 2.0, "max error {err} K");
    let last = *res.node("body").unwrap().temperature_c.last().unwrap();
    assert!((last - (TINF + Q1 / g)).abs() < 1e-6);
}

#[test]
fn explicit_substepped_matches_implicit_on_rig() {
    // Loss of oil on the shipped rig, 120 s. Reference: implicit with Δt = 0.01 s (within
    // 0.01 K of Δt = 0.001 s). Explicit with Δt = 5 s, above its bound (1.24 s, set by the
    // cavity air node: 5 J/K over 4.04 W/K), runs 5 sub-steps of 1 s; forward Euler's
    // first-order error at h = 1 s is ≈ 1 K on the fastest-heating node (cage, +380 K in
    // 120 s). Tolerance 2 K, i.e. ~0.5 % of the rise.
    let m = rig();
    let s = solve_steady(&m.network, &rig_heat()).unwrap();
    let bound = explicit_stable_step_s(&m.network.loss_of_oil())
        .unwrap()
        .unwrap();
    assert!(bound < 5.0);
    let mk = |step, integrator| TransientSettings {
        duration_s: 120.0,
        step_s: step,
        integrator,
        stop_at_limits: false,
        ..m.transient.clone()
    };
    let ex = run_transient(
        &m.network,
        &s,
        &mk(5.0, Integrator::Explicit),
        &rig_loss_heat(),
    )
    .unwrap();
    let im = run_transient(
        &m.network,
        &s,
        &mk(0.01, Integrator::Implicit),
        &rig_loss_heat(),
    )
    .unwrap();
    assert!(ex.stats.substeps > ex.stats.steps);
    let diff = ex
        .final_temperatures_c()
        .iter()
        .zip(im.final_temperatures_c())
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(diff < 2.0, "explicit vs implicit differ by {diff} K");
}

// ---- steady state against hand calculations --------------------------------------------

/// Relative closeness; 1e-12 is LU round-off on a well-conditioned 2×2 / 3×3 system.
fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs().max(1.0)
}

#[test]
fn two_nodes_in_series() {
    // fixed 20 °C —4 W/K— A —2 W/K— B(60 W): all 60 W flow through both links, so
    // T_A = 20 + 60/4 = 35 °C, T_B = 35 + 60/2 = 65 °C. Tolerance 1e-12 relative (round-off).
    let mut net = Network::new(
        vec![
            Node::fixed("wall", 20.0),
            Node::free("a", 1.0),
            Node::free("b", 1.0).with_heat(HeatMechanism::InnerContacts),
        ],
        vec![
            Link::conductance("wall", "a", 4.0),
            Link::conductance("a", "b", 2.0),
        ],
    );
    net.roller_heat_fraction = 0.0;
    let s = solve_steady(&net, &q(60.0)).unwrap();
    assert!(close(s.temperature_c("a").unwrap(), 35.0, 1e-12));
    assert!(close(s.temperature_c("b").unwrap(), 65.0, 1e-12));
    assert!(close(s.heat_out_w, 60.0, 1e-12));
    assert!(s.nodes[0].fixed && !s.nodes[1].fixed);
}

#[test]
fn three_nodes_in_series_with_conduction() {
    // fixed 20 °C —10 W/K— A(30 W) —5 W/K— B(20 W) —G_BC— C(10 W), with G_BC a conduction
    // link k·A/L = 40·0.01/0.2 = 2 W/K. Heat through each link: 60, 30, 10 W, so
    // T_A = 20 + 60/10 = 26, T_B = 26 + 30/5 = 32, T_C = 32 + 10/2 = 37 °C.
    // The three heats are placed via three mechanisms (inner, outer, cage) with f = 0.
    // Tolerance 1e-12 relative (round-off).
    let mut net = Network::new(
        vec![
            Node::fixed("wall", 20.0),
            Node::free("a", 1.0).with_heat(HeatMechanism::InnerContacts),
            Node::free("b", 1.0).with_heat(HeatMechanism::OuterContacts),
            Node::free("c", 1.0).with_heat(HeatMechanism::CageRails),
        ],
        vec![
            Link::conductance("wall", "a", 10.0),
            Link::conductance("a", "b", 5.0),
            Link::new(
                "b",
                "c",
                LinkKind::Conduction {
                    conductivity_w_m_k: 40.0,
                    area_m2: 0.01,
                    length_m: 0.2,
                },
            ),
        ],
    );
    net.roller_heat_fraction = 0.0;
    let heat = HeatInput::new()
        .with(HeatSource::InnerContacts, 30.0)
        .with(HeatSource::OuterContacts, 20.0)
        .with(HeatSource::CageRails, 10.0)
        .with(HeatSource::ViscousDrag, 0.0);
    let s = solve_steady(&net, &heat).unwrap();
    for (name, t) in [("a", 26.0), ("b", 32.0), ("c", 37.0)] {
        let got = s.temperature_c(name).unwrap();
        assert!(close(got, t, 1e-12), "{name}: {got} vs {t}");
    }
    assert!(close(s.heat_in_w, 60.0, 1e-12) && s.balance_w.abs() < 1e-10);
}

#[test]
fn contact_heat_split_between_raceway_and_rollers() {
    // f = 0.3: inner raceway gets 0.7·100 = 70 W, rollers 0.3·(100 + 50) = 45 W; each node
    // has 1 W/K to ground, so its rise equals its heat. Tolerance 1e-12 relative.
    let mut net = Network::new(
        vec![
            Node::fixed("g", 0.0),
            Node::free("ir", 1.0).with_heat(HeatMechanism::InnerContacts),
            Node::free("or", 1.0).with_heat(HeatMechanism::OuterContacts),
            Node::free("ro", 1.0).with_heat(HeatMechanism::Rollers),
        ],
        vec![
            Link::conductance("ir", "g", 1.0),
            Link::conductance("or", "g", 1.0),
            Link::conductance("ro", "g", 1.0),
        ],
    );
    net.roller_heat_fraction = 0.3;
    let heat = HeatInput::new()
        .with(HeatSource::InnerContacts, 100.0)
        .with(HeatSource::OuterContacts, 50.0);
    let s = solve_steady(&net, &heat).unwrap();
    for (name, t) in [("ir", 70.0), ("or", 35.0), ("ro", 45.0)] {
        assert!(close(s.temperature_c(name).unwrap(), t, 1e-12), "{name}");
    }
}

// ---- mass transport ------------------------------------------------------------------

#[test]
fn mass_transport_chain() {
    // oil_in (fixed 80 °C) → cavity (1000 W) → drain (no heat): ṁc = 0.05 kg/s · 2000
    // J/(kg·K) = 100 W/K, so T_cavity = 80 + 1000/100 = 90 °C and the insulated drain
    // carries the same oil, 90 °C. The upstream node is unaffected by the link (the fixed
    // inlet stays 80). Heat out is the oil enthalpy rise ṁc(T_drain − T_in) = 1000 W.
    // Tolerance 1e-12 relative (round-off).
    let mut net = Network::new(
        vec![
            Node::fixed("oil_in", 80.0).with_role(NodeRole::Oil),
            Node::free("cavity", 100.0)
                .with_role(NodeRole::Oil)
                .with_heat(HeatMechanism::ViscousDrag),
            Node::free("drain", 50.0).with_role(NodeRole::Oil),
        ],
        vec![
            Link::mass_transport("oil_in", "cavity", 100.0),
            Link::mass_transport("cavity", "drain", 100.0),
        ],
    );
    net.roller_heat_fraction = 0.0;
    let heat = HeatInput::new().with(HeatSource::ViscousDrag, 1000.0);
    let s = solve_steady(&net, &heat).unwrap();
    assert!(close(s.temperature_c("cavity").unwrap(), 90.0, 1e-12));
    assert!(close(s.temperature_c("drain").unwrap(), 90.0, 1e-12));
    assert!(close(s.heat_out_w, 1000.0, 1e-12));
    // The upstream node of a mass-transport link is not grounded through it.
    let bad = Network::new(
        vec![
            Node::fixed("sink", 80.0),
            Node::free("up", 1.0).with_heat(HeatMechanism::ViscousDrag),
        ],
        vec![Link::mass_transport("up", "sink", 100.0)],
    );
    assert_eq!(
        solve_steady(&bad, &heat).unwrap_err(),
        ThermalError::Ungrounded { node: "up".into() }
    );
}

// ---- shipped network -----------------------------------------------------------------

#[test]
fn shipped_rig_steady_balance() {
    // Energy balance to 1e-9 relative (the brief's contract; LU round-off is ~1e-13).
    // Plausibility: ~2.1 kW into 100 W/K of oil gives a ~20 K oil rise; rings and rollers
    // run 10–40 K above the oil, all below their limits.
    let root: toml::Table = toml::from_str(RIG).unwrap();
    assert!(
        root.contains_key("thermal"),
        "the aerospace deck carries the rig network"
    );
    let m = rig();
    let n = m.network.nodes.len();
    assert!((15..=20).contains(&n), "{n} nodes");
    let s = solve_steady(&m.network, &rig_heat()).unwrap();
    assert!(close(s.heat_in_w, 2100.0, 1e-12));
    assert!(
        s.balance_w.abs() <= 1e-9 * s.heat_in_w,
        "balance {} W",
        s.balance_w
    );
    let t = |name: &str| s.temperature_c(name).unwrap();
    assert!(t("oil_out") > 90.0 && t("oil_out") < 110.0);
    for name in ["inner_ring", "outer_ring", "rollers"] {
        assert!(
            t(name) > t("oil_cavity") && t(name) < 150.0,
            "{name} {}",
            t(name)
        );
    }
    assert_eq!(m.transient.oil_node.as_deref(), Some("oil_cavity"));
}

#[test]
fn continued_transient_stays_at_steady_state() {
    // Started from the steady state with nothing changed, both integrators must stay put:
    // tolerance 1e-9 K (round-off of the residual A·T − Q − b, ~1e-12 of 100 °C, over
    // 600 steps).
    let m = rig();
    let s = solve_steady(&m.network, &rig_heat()).unwrap();
    for integrator in [Integrator::Implicit, Integrator::Explicit] {
        let r = run_transient(
            &m.network,
            &s,
            &continued(600.0, 1.0, integrator),
            &rig_heat(),
        )
        .unwrap();
        assert_eq!(r.scenario, Scenario::Continued);
        for (node, t0) in r.nodes.iter().zip(s.temperatures_c()) {
            for &x in &node.temperature_c {
                assert!(
                    (x - t0).abs() < 1e-9,
                    "{integrator:?} {}: {x} vs {t0}",
                    node.name
                );
            }
        }
    }
}

#[test]
fn implicit_loss_of_oil_tends_to_new_steady_state() {
    // After the loss of oil every free node is still grounded (air convection, housing and
    // shaft to ambient), so the modified network has a steady state. Backward Euler with
    // Δt = 100 s over 2e5 s damps the slowest mode (τ ≲ 2000 s) by (1 + Δt/τ)^−2000 ≈ 0;
    // tolerance 1e-6 K (round-off on ~600 °C).
    let m = rig();
    let s = solve_steady(&m.network, &rig_heat()).unwrap();
    let lost = m.network.loss_of_oil();
    assert!(lost.links.iter().all(|l| !l.is_mass_transport()));
    assert!(lost.nodes.iter().all(|n| n.role != NodeRole::Oil));
    let target = solve_steady(&lost, &rig_loss_heat()).unwrap();
    let settings = TransientSettings {
        duration_s: 2.0e5,
        step_s: 100.0,
        stop_at_limits: false,
        ..m.transient.clone()
    };
    let r = run_transient(&m.network, &s, &settings, &rig_loss_heat()).unwrap();
    for (x, t) in r.final_temperatures_c().iter().zip(target.temperatures_c()) {
        assert!((x - t).abs() < 1e-6, "{x} vs {t}");
    }
    // Loss of oil with more friction heat: rollers reach their 230 °C limit first.
    let t_roll = r.node("rollers").unwrap().time_to_limit_s.unwrap();
    let t_ir = r.node("inner_ring").unwrap().time_to_limit_s.unwrap();
    assert!(t_roll < t_ir);
}

#[test]
fn loss_of_oil_stops_when_limits_reached() {
    // The shipped settings stop once every limited node has crossed its limit; each
    // crossing time lies inside the run and the recorded history ends at the last one.
    let m = rig();
    let s = solve_steady(&m.network, &rig_heat()).unwrap();
    let r = run_transient(&m.network, &s, &m.transient, &rig_loss_heat()).unwrap();
    let end = *r.time_s.last().unwrap();
    assert!(end < m.transient.duration_s);
    let latest = r
        .nodes
        .iter()
        .filter(|n| n.limit_c.is_some())
        .map(|n| n.time_to_limit_s.unwrap())
        .fold(0.0, f64::max);
    assert!(latest <= end && latest > end - m.transient.step_s);
    assert!(r.node("shaft_end").unwrap().time_to_limit_s.is_none());
}

#[test]
fn time_to_limit_is_interpolated() {
    // An insulated node (no links) heated at Q = 50 W with C = 100 J/K rises at exactly
    // 0.5 K/s; backward Euler is exact for a constant rate, and linear interpolation is
    // exact for a linear history: 20 → 33.3 °C at t = 26.6 s. Tolerance 1e-9 s.
    let mut net = Network::new(
        vec![Node::free("body", 100.0)
            .with_heat(HeatMechanism::InnerContacts)
            .with_limit(33.3)],
        vec![],
    );
    net.roller_heat_fraction = 0.0;
    let settings = TransientSettings {
        stop_at_limits: true,
        ..continued(100.0, 1.0, Integrator::Implicit)
    };
    let r = run_transient_from(&net, &[20.0], &settings, &q(50.0)).unwrap();
    let t = r.nodes[0].time_to_limit_s.unwrap();
    assert!((t - 26.6).abs() < 1e-9, "{t}");
    assert_eq!(*r.time_s.last().unwrap(), 27.0);
    // Already at the limit at t = 0 → 0; no limit → None.
    let r0 = run_transient_from(&net, &[40.0], &settings, &q(50.0)).unwrap();
    assert_eq!(r0.nodes[0].time_to_limit_s, Some(0.0));
}

#[test]
fn oil_coupled_heat_reaches_fixed_point() {
    // Viscosity coupling: Q(T_oil) = 600 − 2·(T_oil − 20) W on one oil node with 10 W/K to
    // 20 °C. Steady: 10·(T − 20) = 600 − 2·(T − 20) → T = 20 + 600/12 = 70 °C. The lagged
    // coupling converges (the loop gain 2/10 < 1); after 40 time constants the implicit run
    // is at the fixed point to 1e-6 K.
    let mut net = Network::new(
        vec![
            Node::free("oil", 100.0)
                .with_role(NodeRole::Oil)
                .with_heat(HeatMechanism::ViscousDrag),
            Node::fixed("sink", 20.0),
        ],
        vec![Link::conductance("oil", "sink", 10.0)],
    );
    net.roller_heat_fraction = 0.0;
    let heat = OilCoupled(|t_oil: f64| {
        HeatInput::new().with(HeatSource::ViscousDrag, 600.0 - 2.0 * (t_oil - 20.0))
    });
    for integrator in [Integrator::Implicit, Integrator::Explicit] {
        let r = run_transient_from(
            &net,
            &[20.0, 20.0],
            &continued(400.0, 0.5, integrator),
            &heat,
        )
        .unwrap();
        let last = *r.node("oil").unwrap().temperature_c.last().unwrap();
        assert!((last - 70.0).abs() < 1e-6, "{integrator:?}: {last}");
    }
}

// ---- bad networks --------------------------------------------------------------------

fn base() -> Network {
    Network::new(
        vec![Node::fixed("sink", 20.0), Node::free("a", 10.0)],
        vec![Link::conductance("a", "sink", 1.0)],
    )
}

#[test]
fn bad_networks_name_the_culprit() {
    let mut n = base();
    n.links.push(Link::conductance("a", "ghost", 1.0));
    let e = n.validate().unwrap_err();
    assert_eq!(
        e,
        ThermalError::UnknownNode {
            link: "a-ghost".into(),
            node: "ghost".into()
        }
    );
    assert!(e.to_string().contains("'ghost'"));

    let mut n = base();
    n.nodes.push(Node::free("a", 1.0));
    assert_eq!(
        n.validate().unwrap_err(),
        ThermalError::DuplicateNode { name: "a".into() }
    );

    let mut n = base();
    n.nodes[1].capacity_j_k = -1.0;
    let e = n.validate().unwrap_err();
    assert!(matches!(&e, ThermalError::InvalidNodeValue { node, .. } if node == "a"));

    let mut n = base();
    n.links[0] = Link::conductance("a", "sink", -2.0);
    let e = n.validate().unwrap_err();
    assert!(matches!(&e, ThermalError::InvalidLinkValue { link, .. } if link == "a-sink"));

    // A floating pair b–c (connected to each other only): steady state singular.
    let mut n = base();
    n.nodes.push(Node::free("b", 1.0));
    n.nodes.push(Node::free("c", 1.0));
    n.links.push(Link::conductance("b", "c", 1.0));
    let e = solve_steady(&n, &HeatInput::default()).unwrap_err();
    assert_eq!(e, ThermalError::Ungrounded { node: "b".into() });
    assert!(e.to_string().contains("'b'"));

    // Zero capacity is fine in steady state, an error in a transient.
    let mut n = base();
    n.nodes[1].capacity_j_k = 0.0;
    assert!(solve_steady(&n, &HeatInput::default()).is_ok());
    let e = run_transient_from(
        &n,
        &[20.0, 20.0],
        &continued(1.0, 0.1, Integrator::Implicit),
        &HeatInput::default(),
    )
    .unwrap_err();
    assert_eq!(e, ThermalError::ZeroCapacity { node: "a".into() });

    // Heat on a fixed node, and heat with nowhere to go.
    let mut n = base();
    n.nodes[0].heat.push(HeatMechanism::CageRails);
    assert!(matches!(
        n.validate().unwrap_err(),
        ThermalError::HeatOnFixedNode { node, .. } if node == "sink"
    ));
    let e = solve_steady(&base(), &q(1.0)).unwrap_err();
    assert!(matches!(
        e,
        ThermalError::UnboundHeat {
            mechanism: "inner_contacts",
            ..
        }
    ));

    // Self link.
    let mut n = base();
    n.links.push(Link::conductance("a", "a", 1.0));
    assert!(matches!(
        n.validate().unwrap_err(),
        ThermalError::SelfLink { .. }
    ));
}

// ---- deck ----------------------------------------------------------------------------

fn parse(text: &str, units: Units) -> Result<ThermalModel, ThermalError> {
    let table: toml::Table = toml::from_str(text).unwrap();
    parse_thermal(&table, units)
}

#[test]
fn deck_errors_name_node_link_and_field() {
    let e = parse(
        r#"
        [[thermal.nodes]]
        name = "cage"
        capacty = 3.0
        "#,
        Units::Si,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("node 'cage'") && e.contains("capacty"), "{e}");

    let e = parse(
        r#"
        [[thermal.nodes]]
        name = "a"
        capacity = 1.0
        [[thermal.nodes]]
        name = "sink"
        fixed_temperature = 20.0
        [[thermal.links]]
        from = "a"
        to = "sink"
        kind = "conduction"
        conductivity = 40.0
        area = 0.01
        "#,
        Units::Si,
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("link #1 (a-sink)") && e.contains("'length'"),
        "{e}"
    );

    let e = parse(
        r#"
        [[thermal.nodes]]
        name = "a"
        density = 7800.0
        volume = 1e-5
        "#,
        Units::Si,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("node 'a'") && e.contains("specific_heat"), "{e}");

    let e = parse(
        r#"
        [[thermal.nodes]]
        name = "a"
        capacity = 1.0
        [[thermal.nodes]]
        name = "sink"
        fixed_temperature = 20.0
        [[thermal.links]]
        name = "fit"
        from = "a"
        to = "sink"
        kind = "conductance"
        conductance = 1.0
        h = 5.0
        "#,
        Units::Si,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("link 'fit'") && e.contains("'h'"), "{e}");

    let e = parse("[bearing]\nz = 1\n", Units::Si)
        .unwrap_err()
        .to_string();
    assert!(e.contains("[thermal]") && e.contains("missing"), "{e}");

    let e = parse("[thermal]\nnodez = []\n", Units::Si)
        .unwrap_err()
        .to_string();
    assert!(e.contains("nodez"), "{e}");
}

#[test]
fn deck_us_units_convert() {
    use crate::units::{BTU_J, FAHRENHEIT_PER_KELVIN, HOUR_S};
    // Each US link below is exactly 1 Btu/(hr·°F) = 0.527 527 926 W/K:
    // conduction 1 Btu/(hr·ft·°F)·144 in²/12 in; convection 1 Btu/(hr·ft²·°F)·144 in²;
    // plain conductance 1. Mass transport 1/3600 lbm/s · 1 Btu/(lbm·°F) = 1 Btu/(hr·°F).
    // 68 °F = 20 °C; capacity 1 Btu/°F = 1899.10 J/K; density·c·V: 0.283 lbm/in³ ·
    // 0.11 Btu/(lbm·°F) · 10 in³. Tolerance 1e-12 relative (exact factors, round-off).
    let m = parse(
        r#"
        [[thermal.nodes]]
        name = "sink"
        fixed_temperature = 68.0
        [[thermal.nodes]]
        name = "a"
        capacity = 1.0
        limit = 212.0
        [[thermal.nodes]]
        name = "b"
        density = 0.283
        specific_heat = 0.11
        volume = 10.0
        [[thermal.links]]
        from = "a"
        to = "sink"
        kind = "conduction"
        conductivity = 1.0
        area = 144.0
        length = 12.0
        [[thermal.links]]
        from = "b"
        to = "sink"
        kind = "convection"
        h = 1.0
        area = 144.0
        [[thermal.links]]
        from = "a"
        to = "b"
        kind = "conductance"
        conductance = 1.0
        [[thermal.links]]
        from = "sink"
        to = "b"
        kind = "mass_transport"
        mass_flow = 2.777777777777778e-4
        specific_heat = 1.0
        "#,
        Units::Us,
    )
    .unwrap();
    let w_per_k = BTU_J * FAHRENHEIT_PER_KELVIN / HOUR_S;
    // The hand values quoted above, to the digits given.
    assert!(close(w_per_k, 0.527_527_926, 1e-9));
    assert!(close(BTU_J * FAHRENHEIT_PER_KELVIN, 1_899.10, 1e-6));
    for l in &m.network.links {
        assert!(close(l.coefficient_w_k(), w_per_k, 1e-12), "{}", l.name);
    }
    let nodes = &m.network.nodes;
    assert!(close(nodes[0].fixed_c.unwrap(), 20.0, 1e-12));
    assert!(close(nodes[1].limit_c.unwrap(), 100.0, 1e-12));
    assert!(close(
        nodes[1].capacity_j_k,
        BTU_J * FAHRENHEIT_PER_KELVIN,
        1e-12
    ));
    let rho_c_v = 0.283 * 0.11 * 10.0 * BTU_J * FAHRENHEIT_PER_KELVIN; // Btu/°F → J/K
    assert!(close(nodes[2].capacity_j_k, rho_c_v, 1e-12));
    assert_eq!(m.transient, TransientSettings::default());
}

#[test]
fn json_field_names_are_the_contract() {
    let m = rig();
    let s = solve_steady(&m.network, &rig_heat()).unwrap();
    let v = serde_json::to_value(&s).unwrap();
    for key in ["nodes", "heat_in_w", "heat_out_w", "balance_w"] {
        assert!(v.get(key).is_some(), "steady.{key}");
    }
    for key in ["name", "temperature_c", "fixed"] {
        assert!(v["nodes"][0].get(key).is_some(), "steady.nodes[].{key}");
    }
    let r = run_transient(&m.network, &s, &m.transient, &rig_loss_heat()).unwrap();
    let v = serde_json::to_value(&r).unwrap();
    assert_eq!(v["scenario"], "loss_of_oil");
    assert!(v["time_s"].is_array());
    for key in ["name", "temperature_c", "limit_c", "time_to_limit_s"] {
        assert!(v["nodes"][0].get(key).is_some(), "transient.nodes[].{key}");
    }
    let shaft_end = v["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|n| n["name"] == "shaft_end")
        .unwrap();
    assert!(shaft_end["time_to_limit_s"].is_null() && shaft_end["limit_c"].is_null());
}

#[test]
fn transient_can_be_cancelled() {
    // The cancel flag is checked before each step: flipping it after 3 steps stops the
    // run at t = 3 s with a typed error.
    let net = one_node(C1, G1, TINF);
    let calls = std::cell::Cell::new(0);
    let cancel = || {
        calls.set(calls.get() + 1);
        calls.get() > 3
    };
    let e = run_transient_cancellable(
        &net,
        &[T0, TINF],
        &continued(100.0, 1.0, Integrator::Implicit),
        &q(Q1),
        &cancel,
    )
    .unwrap_err();
    assert_eq!(e, ThermalError::Cancelled { time_s: 3.0 });
}

#[test]
fn cancellation_is_seen_inside_the_explicit_substeps() {
    // One output step of 1000 s with the explicit scheme needs C/ΣG-bounded substeps
    // (10 000 here: C/ΣG = 0.1 s): a flag raised after the first check stops the run
    // inside that step, before the output step completes (it used to run every substep
    // first).
    let net = one_node(1.0, G1, TINF);
    let bound = explicit_stable_step_s(&net).unwrap().unwrap();
    assert!(
        1000.0 / bound > 1000.0,
        "needs many substeps, bound {bound}"
    );
    let calls = std::cell::Cell::new(0);
    let cancel = || {
        calls.set(calls.get() + 1);
        calls.get() > 1
    };
    let e = run_transient_cancellable(
        &net,
        &[T0, TINF],
        &continued(1000.0, 1000.0, Integrator::Explicit),
        &q(Q1),
        &cancel,
    )
    .unwrap_err();
    match e {
        ThermalError::Cancelled { time_s } => assert!(time_s > 0.0 && time_s < 1000.0, "{time_s}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn fixed_nodes_keep_their_temperature_in_transients() {
    // A wrong initial value for the fixed sink is ignored: the sink is reported at its
    // given 20 °C throughout (exact).
    let net = one_node(C1, G1, TINF);
    let r = run_transient_from(
        &net,
        &[T0, 999.0],
        &continued(10.0, 1.0, Integrator::Implicit),
        &q(Q1),
    )
    .unwrap();
    assert!(r
        .node("sink")
        .unwrap()
        .temperature_c
        .iter()
        .all(|&t| t == TINF));
}

mod props {
    use super::*;
    use proptest::prelude::*;

    /// A random tree of free nodes hanging from one fixed node at 20 °C, each free node
    /// with a random conductance to its parent, non-negative heat (via the cage-rail
    /// mechanism, shared equally) and optionally an oil stream from the fixed node.
    fn network(parents: &[usize], g: &[f64], heated: &[bool], oil: &[Option<f64>]) -> Network {
        let mut nodes = vec![Node::fixed("n0", 20.0)];
        let mut links = Vec::new();
        for (k, ((&p, &gk), (&h, o))) in parents
            .iter()
            .zip(g)
            .zip(heated.iter().zip(oil))
            .enumerate()
        {
            let i = k + 1;
            let mut node = Node::free(format!("n{i}"), 1.0);
            if h {
                node = node.with_heat(HeatMechanism::CageRails);
            }
            nodes.push(node);
            links.push(Link::conductance(
                format!("n{i}"),
                format!("n{}", p % i),
                gk,
            ));
            if let Some(mc) = o {
                links.push(Link::mass_transport("n0", format!("n{i}"), *mc));
            }
        }
        let mut net = Network::new(nodes, links);
        net.roller_heat_fraction = 0.0;
        net
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Energy balance to 1e-9 relative, and the maximum principle: with heat ≥ 0 no
        /// free node is colder than the coldest fixed node (20 °C, to 1e-9 K round-off).
        #[test]
        fn balance_and_maximum_principle(
            parents in prop::collection::vec(0usize..100, 1..25),
            g in prop::collection::vec(0.01f64..100.0, 25),
            heated in prop::collection::vec(any::<bool>(), 25),
            oil in prop::collection::vec(prop::option::of(1.0f64..200.0), 25),
            q_w in 0.0f64..5000.0,
        ) {
            let n = parents.len();
            let mut heated = heated[..n].to_vec();
            heated[n - 1] = true;
            let net = network(&parents, &g[..n], &heated, &oil[..n]);
            let heat = HeatInput::new().with(HeatSource::CageRails, q_w);
            let s = solve_steady(&net, &heat).unwrap();
            prop_assert!(s.balance_w.abs() <= 1e-9 * s.heat_in_w.max(1.0));
            for node in &s.nodes {
                prop_assert!(node.temperature_c >= 20.0 - 1e-9);
            }
        }
    }
}

#[test]
fn heat_sources_are_conserved_across_mechanisms() {
    // Conservation: whatever the roller fraction, the heat released into the mechanisms
    // (raceway shares, rollers, cage, drag) sums to the heat generated, to round-off; a
    // source listed twice adds up (a system may report e.g. two flange contacts).
    let heat = rig_heat().with(HeatSource::CageRails, 25.0);
    assert_eq!(heat.watts(HeatSource::CageRails), 175.0);
    for f in [0.0, 0.3, 0.5, 1.0] {
        let released: f64 = HeatMechanism::ALL
            .iter()
            .map(|&m| heat.mechanism_w(m, f))
            .sum();
        assert!(
            (released - heat.total_w()).abs() <= 1e-12 * heat.total_w(),
            "f = {f}"
        );
        assert_eq!(
            heat.mechanism_w(HeatMechanism::Rollers, f),
            f * (900.0 + 700.0)
        );
    }
    assert_eq!(heat.total_w(), 900.0 + 700.0 + 150.0 + 350.0 + 25.0);
}

/// Absurd counts are refused, never wrapped: `duration = step = 1e20` with the explicit
/// integrator used to overflow `(dt / b).floor() as usize + 1` to 0 substeps and report
/// "limit not reached"; a run needing more than MAX_SUBSTEPS explicit substeps or more
/// than MAX_STEPS steps is an InvalidSetting error.
#[test]
fn transient_counts_are_checked() {
    let net = one_node(C1, G1, TINF);
    for (d, s, i) in [
        (1e20, 1e20, Integrator::Explicit),
        (1e11, 1e11, Integrator::Explicit),
        (1e308, 1e-308, Integrator::Implicit),
        (1e7, 1.0, Integrator::Implicit),
    ] {
        let r = run_transient_from(&net, &[T0, TINF], &continued(d, s, i), &q(Q1));
        assert!(
            matches!(r, Err(ThermalError::InvalidSetting { .. })),
            "{d} {s} {i:?}: {r:?}"
        );
    }
}
