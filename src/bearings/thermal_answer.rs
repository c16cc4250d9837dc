//! The `[thermal]` network of a system whose friction is a [`FrictionBreakdown`] (issue 28
//! item 5: ball, cylindrical, double-row spherical): steady state under the friction's
//! heat ([`FrictionBreakdown::heat_input`]) and, when asked, the deck's transient from that
//! steady state, with the JSON `thermal` of the spherical roller's field names and the
//! Thermal pane's [`ThermalResults`].
//!
//! The transient's heat: these systems have no lost-lubrication traction (the spherical
//! roller switches to a constant dry coefficient, seed 000 §9.5), so the transient keeps
//! the lubricated friction's heat; `transient_heat_w` says which heat it used. The
//! loss-of-oil scenario still removes the oil's mass transport and switches the oil nodes
//! to air (seed 000 §10.3), which is what heats the bearing.
//!
//! Temperatures do not feed back into the friction of these systems: none of them
//! iterates its lubricant's viscosity on a temperature (the ball's bulk temperature, eq.
//! 4-1, is reported, not iterated; the cylindrical and double-row friction are isothermal
//! at the deck's inlet temperature), so the network is the last stage, one-way.

use serde::Serialize;
use serde_json::{json, Value};

use super::friction::FrictionBreakdown;
use super::view::{NodeSeries, SteadyNode, ThermalResults, Transient};
use crate::thermal::{self, SteadyResult, ThermalModel, TransientResult};
use crate::units::{Quantity, Units, FAHRENHEIT_PER_KELVIN};

/// A thermal network's results.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BearingThermal {
    /// Steady state under the friction's heat.
    pub steady: SteadyResult,
    /// The deck's transient, when run.
    pub transient: Option<TransientResult>,
    /// Heat fed to the transient, W (the friction's: see the module notes).
    pub transient_heat_w: Option<f64>,
}

/// Solves `model` under `friction`'s heat: the steady state, then the transient when
/// `transient` (checking `cancelled` between steps).
///
/// # Errors
/// The network's own error (an unbound heat source, an ungrounded node, a bad setting),
/// as a sentence naming the stage.
pub fn solve(
    model: &ThermalModel,
    friction: &FrictionBreakdown,
    transient: bool,
    cancelled: &dyn Fn() -> bool,
) -> Result<BearingThermal, String> {
    let heat = friction.heat_input();
    let err = |e: thermal::ThermalError| format!("thermal network (seed 000 §10): {e}");
    let steady = thermal::solve_steady(&model.network, &heat).map_err(err)?;
    let (transient, transient_heat_w) = if transient {
        let tr = thermal::run_transient_cancellable(
            &model.network,
            &steady.temperatures_c(),
            &model.transient,
            &heat,
            cancelled,
        )
        .map_err(err)?;
        (Some(tr), Some(heat.total_w()))
    } else {
        (None, None)
    };
    Ok(BearingThermal {
        steady,
        transient,
        transient_heat_w,
    })
}

impl BearingThermal {
    /// JSON `thermal`: {`steady`, `transient`, `transient_heat_w`}, as the spherical
    /// roller's.
    pub fn json(&self) -> Value {
        json!({
            "steady": serde_json::to_value(&self.steady).unwrap_or(Value::Null),
            "transient": self.transient.as_ref().map(|t| serde_json::to_value(t).unwrap_or(Value::Null)),
            "transient_heat_w": self.transient_heat_w,
        })
    }

    /// The Thermal pane's results.
    pub fn view(&self) -> ThermalResults {
        ThermalResults {
            steady: self
                .steady
                .nodes
                .iter()
                .map(|n| SteadyNode {
                    name: n.name.clone(),
                    temperature_c: n.temperature_c,
                    fixed: n.fixed,
                })
                .collect(),
            transient: self.transient.as_ref().map(|tr| Transient {
                time_s: tr.time_s.clone(),
                nodes: tr
                    .nodes
                    .iter()
                    .map(|n| NodeSeries {
                        name: n.name.clone(),
                        temperature_c: n.temperature_c.clone(),
                        limit_c: n.limit_c,
                        time_to_limit_s: n.time_to_limit_s,
                    })
                    .collect(),
            }),
        }
    }

    /// The hottest free node's steady temperature, °C.
    pub fn hottest_c(&self) -> Option<f64> {
        self.steady
            .nodes
            .iter()
            .filter(|n| !n.fixed)
            .map(|n| n.temperature_c)
            .reduce(f64::max)
    }
}

/// A template's `[thermal]` section: a small working network, commented out, whose nodes
/// take `$heat` (the system's heat mechanisms, a TOML array's items) and the viscous drag
/// in the oil. Used by each system's `TemplateNotes`; a test uncomments it and solves it.
#[macro_export]
#[doc(hidden)]
macro_rules! __thermal_template_note {
    ($heat:literal) => {
        concat!(
            "[thermal]  # optional: a lumped thermal network (seed 000 §10) under the friction's heat,
# steady state and loss-of-oil transient. A small working example follows; uncomment it.
# [thermal]
#
# [[thermal.nodes]]
# name = \"rings_and_elements\"
# capacity = 900.0            # J/K
# limit = 230.0               # °C: the transient reports when it is reached
# heat = [",
            $heat,
            "]
#
# [[thermal.nodes]]
# name = \"oil_in\"
# role = \"oil\"
# fixed_temperature = 80.0    # °C
#
# [[thermal.nodes]]
# name = \"oil_cavity\"
# role = \"oil\"
# capacity = 100.0
# air_capacity = 5.0          # J/K once the oil is lost
# heat = [\"viscous_drag\"]
#
# [[thermal.links]]
# from = \"oil_in\"
# to = \"oil_cavity\"
# kind = \"mass_transport\"
# mass_flow = 0.05            # kg/s
# specific_heat = 2000.0      # J/(kg·K)
#
# [[thermal.links]]
# from = \"oil_cavity\"
# to = \"rings_and_elements\"
# kind = \"convection\"
# h = 2500.0                  # W/(m²·K)
# area = 0.02                 # m²
# h_loss_of_oil = 60.0
#
# [thermal.transient]
# duration = 600.0            # s
# step = 1.0
# integrator = \"implicit\"
# scenario = \"loss_of_oil\"
# oil_node = \"oil_cavity\""
        )
    };
}
pub use crate::__thermal_template_note as thermal_template_note;

/// `thermal` into a system's JSON object (nothing without a network).
pub fn add_to_json(v: &mut Value, th: Option<&BearingThermal>) {
    if let (Some(th), Some(o)) = (th, v.as_object_mut()) {
        o.insert("thermal".into(), th.json());
    }
}

/// The Thermal pane's results and the Summary's temperature lines into a system's view.
pub fn add_to_view(v: &mut super::view::View, th: Option<&BearingThermal>) {
    if let Some(th) = th {
        let r = th.view();
        v.answer.extend(super::answer::thermal_lines(&r));
        v.thermal = Some(r);
    }
}

/// The text report's thermal section, in `units` (temperatures °C | °F, heat W | the
/// deck's power unit).
pub fn add_to_text(s: &mut String, th: Option<&BearingThermal>, units: Units) {
    use std::fmt::Write;
    let Some(th) = th else {
        return;
    };
    let temp = |c: f64| match units {
        Units::Si => format!("{c:.1} °C"),
        Units::Us => format!("{:.1} °F", c * FAHRENHEIT_PER_KELVIN + 32.0),
    };
    let p = |w: f64| Quantity::Power.from_si(w, units);
    let pu = Quantity::Power.unit(units);
    let _ = writeln!(s);
    let _ = writeln!(
        s,
        "THERMAL NETWORK, STEADY STATE (seed 000 §10.2): heat in {:.1} {pu}, out {:.1} {pu}, balance {:.2e} {pu}",
        p(th.steady.heat_in_w),
        p(th.steady.heat_out_w),
        p(th.steady.balance_w),
    );
    for n in &th.steady.nodes {
        let _ = writeln!(
            s,
            "  {:<18} {:>10}{}",
            n.name,
            temp(n.temperature_c),
            if n.fixed { "  (fixed)" } else { "" }
        );
    }
    if let Some(tr) = &th.transient {
        let _ = writeln!(
            s,
            "TRANSIENT (seed 000 §10.3): {:.1} {pu} friction heat held, {:.0} s simulated",
            p(th.transient_heat_w.unwrap_or(0.0)),
            tr.time_s.last().copied().unwrap_or(0.0)
        );
        for n in tr.nodes.iter().filter(|n| n.limit_c.is_some()) {
            let t = n
                .time_to_limit_s
                .map_or("not reached".to_string(), |t| format!("{t:.1} s"));
            let _ = writeln!(
                s,
                "  {:<18} limit {:>10}: {}",
                n.name,
                temp(n.limit_c.unwrap_or(0.0)),
                t
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use serde_json::Value;

    use crate::bearings::{BearingSystem, RunOptions};
    use crate::numerics::cancel::Cancel;
    use crate::units::Units;

    /// The systems that gained a network here.
    fn systems() -> [&'static dyn BearingSystem; 3] {
        [
            &crate::bearings::angular_ball::system::SYSTEM,
            &crate::bearings::cylindrical_roller::SYSTEM,
            &crate::bearings::double_row_spherical::SYSTEM,
        ]
    }

    /// The template's commented `[thermal]` example, uncommented into the template.
    fn with_network(template: &str) -> String {
        let start = template
            .find("# [thermal]\n")
            .unwrap_or_else(|| panic!("no example"));
        let (head, tail) = template.split_at(start);
        let mut out = head.to_string();
        let mut rest = Vec::new();
        let mut in_example = true;
        for line in tail.lines() {
            if in_example && (line.starts_with("# ") || line == "#") {
                out.push_str(line.trim_start_matches('#').trim_start_matches(' '));
                out.push('\n');
            } else {
                in_example = false;
                rest.push(line);
            }
        }
        // The example is the deck's last table: anything after it goes before it.
        format!("{}\n{out}", rest.join("\n"))
    }

    fn solve(system: &dyn BearingSystem, text: &str) -> Value {
        system
            .load(text, "t.toml", &[])
            .unwrap_or_else(|e| panic!("{}: {e}", system.id()))
            .solve(
                RunOptions {
                    skip_transient: false,
                },
                Cancel::NONE,
            )
            .unwrap_or_else(|e| panic!("{}: {e}", system.id()))
            .json()
    }

    /// Each system's template carries a working network: uncommented, the deck solves;
    /// every watt of the friction enters the network (`heat_in_w` = `friction.power_w`
    /// to 1e-12: the same terms summed) and leaves it (energy balance to round-off,
    /// 1e-9 of the heat: an LU solve of a 2-unknown system); the transient ran.
    #[test]
    fn every_template_carries_a_working_network() {
        for system in systems() {
            let text = with_network(&system.template(Units::Si));
            let v = solve(system, &text);
            let th = &v["thermal"];
            let heat_in = th["steady"]["heat_in_w"].as_f64().unwrap_or(f64::NAN);
            let p = v["friction"]["power_w"].as_f64().unwrap_or(f64::NAN);
            assert!(p > 0.0, "{}: {p}", system.id());
            assert!(
                (heat_in - p).abs() <= 1e-12 * p,
                "{}: {heat_in} vs {p}",
                system.id()
            );
            let balance = th["steady"]["balance_w"].as_f64().unwrap_or(f64::NAN);
            assert!(
                balance.abs() <= 1e-9 * p,
                "{}: balance {balance}",
                system.id()
            );
            assert!(th["transient"].is_object(), "{}: {th}", system.id());
            // The same heat, summed by source instead of by mechanism: 1e-12.
            let held = th["transient_heat_w"].as_f64().unwrap_or(f64::NAN);
            assert!(
                (held - p).abs() <= 1e-12 * p,
                "{}: {held} vs {p}",
                system.id()
            );
            // The steady hottest node is warmer than the oil supply (80 °C): heat flows
            // out of the bearing, never in.
            let t = th["steady"]["nodes"][0]["temperature_c"]
                .as_f64()
                .unwrap_or(0.0);
            assert!(t > 80.0, "{}: {t}", system.id());
        }
    }

    /// A deck without `[thermal]` answers exactly as before the network existed: no
    /// `thermal` key, and with the network every other number is the same (the network
    /// is the last stage, nothing feeds back).
    #[test]
    fn the_network_moves_no_other_number() {
        for system in systems() {
            let plain = system.template(Units::Si);
            let a = solve(system, &plain);
            assert!(a.get("thermal").is_none(), "{}", system.id());
            let mut b = solve(system, &with_network(&plain));
            if let Some(o) = b.as_object_mut() {
                o.remove("thermal");
            }
            assert_eq!(strip_times(a), strip_times(b), "{}", system.id());
        }
    }

    /// Wall times differ run to run: zeroed before comparing.
    fn strip_times(mut v: Value) -> Value {
        fn walk(v: &mut Value) {
            match v {
                Value::Object(m) => {
                    for (k, x) in m.iter_mut() {
                        if k.contains("wall_time") {
                            *x = Value::Null;
                        } else {
                            walk(x);
                        }
                    }
                }
                Value::Array(a) => a.iter_mut().for_each(walk),
                _ => {}
            }
        }
        walk(&mut v);
        v
    }

    /// An unknown key of `[thermal]` is refused at its node's line, naming the key and
    /// the allowed keys.
    #[test]
    fn an_unknown_thermal_key_is_refused_at_its_line() {
        for system in systems() {
            let text = with_network(&system.template(Units::Si))
                .replace("name = \"oil_in\"\n", "name = \"oil_in\"\nbogus = 1.0\n");
            // The node's `[[thermal.nodes]]` header, two lines above the key.
            let line = text
                .lines()
                .position(|l| l.starts_with("bogus"))
                .map(|i| i - 1)
                .unwrap_or(0);
            let e = system
                .load(&text, "t.toml", &[])
                .err()
                .map(|e| e.to_string())
                .unwrap_or_default();
            assert!(
                e.contains("bogus") && e.contains("expected one of `name`"),
                "{}: {e}",
                system.id()
            );
            assert!(
                e.contains(&format!("t.toml:{line}")),
                "{}: line {line}: {e}",
                system.id()
            );
        }
    }
}
