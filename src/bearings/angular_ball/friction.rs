//! The ball bearing's friction by mechanism (issue 28 item 4), from the heat the analysis
//! already computes; nothing is recomputed here.
//!
//! - Race control (`dynamics.method = "race_control"`): the spin heat M_s·|ω_s| of each
//!   contact (seed 001 eqs. 2-13a/b), summed over the balls at each race: mechanisms
//!   `inner_spin`, `outer_spin`.
//! - Ball dynamics (`quasi_static`, `time_simulation`): the slices' traction heat
//!   (2-16…2-18) split at each race into its lateral part (spin and transverse sliding)
//!   and its rolling-direction part (micro-slip and gross sliding of the traction curve):
//!   `inner_lateral_sliding`, `inner_rolling_direction_sliding`,
//!   `outer_lateral_sliding`, `outer_rolling_direction_sliding`.
//!
//! Not modelled, so absent (never zero-filled): the elastic-hysteresis and EHD rolling
//! resistance of the contacts (the seed's traction acts on sliding only), the cage
//! (pocket and land) friction and the churning drag of the oil. The heat is therefore the
//! contacts' sliding heat alone, and the torque its share of the bearing's friction
//! moment; the Palmgren band test says how much of an empirical moment that is.

use super::analysis::BallAnalysis;
use crate::bearings::friction::{FrictionBreakdown, Mechanism};
use crate::thermal::HeatSource;

/// The friction breakdown of a solved ball bearing at its rings' relative speed; its
/// power is `heat.total_w` (the same heat, summed by race instead of by ball).
pub fn friction(a: &BallAnalysis) -> FrictionBreakdown {
    let m = |name, power_w, heat| Mechanism {
        name,
        power_w,
        heat: Some(heat),
    };
    let mechanisms = match &a.dynamics {
        None => {
            let inner: f64 = a.balls.iter().map(|b| b.inner.spin_heat_w).sum();
            let outer: f64 = a.balls.iter().map(|b| b.outer.spin_heat_w).sum();
            vec![
                m("inner_spin", inner, HeatSource::InnerContacts),
                m("outer_spin", outer, HeatSource::OuterContacts),
            ]
        }
        Some(d) => {
            let [il, ir] = d.inner_w();
            vec![
                m("inner_lateral_sliding", il, HeatSource::InnerContacts),
                m(
                    "inner_rolling_direction_sliding",
                    ir,
                    HeatSource::InnerContacts,
                ),
                m(
                    "outer_lateral_sliding",
                    d.lateral_w() - il,
                    HeatSource::OuterContacts,
                ),
                m(
                    "outer_rolling_direction_sliding",
                    d.rolling_w() - ir,
                    HeatSource::OuterContacts,
                ),
            ]
        }
    };
    let op = &a.input.operating;
    FrictionBreakdown::at_ring_speeds(op.inner_speed_rad_s, op.outer_speed_rad_s, mechanisms)
}
