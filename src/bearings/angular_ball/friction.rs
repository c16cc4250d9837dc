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
//! - Every method: the EHL rolling resistance of each contact (Goksem–Hargreaves by
//!   strips over the ellipse, `physics::lubrication::rolling_resistance`, at race
//!   control's entrainment speed and loads): `inner_rolling_resistance`,
//!   `outer_rolling_resistance`. It is a loss computed from the solved contacts, not a
//!   force in the balls' equilibrium (F_R/Q ≈ 1e-3: it would move no load measurably).
//! - With the deck's `[cage]` section (`bearings::friction::CageLosses`): Palmgren's
//!   churning drag `viscous_drag` and a land-guided cage's `cage_rails` (seed 000
//!   §9.3–9.4, the spherical roller's laws and names).
//!
//! Not modelled, so absent (never zero-filled): elastic hysteresis (≈ 1e-4 of the
//! rolling resistance for bearing steel at these loads) and the ball–pocket sliding of
//! the cage (needs the cage's dynamic pocket forces). `heat.total_w` stays the seed's
//! sliding heat (spin or slice traction); `friction.power_w` is the whole.

use super::analysis::BallAnalysis;
use crate::bearings::friction::{FrictionBreakdown, Mechanism};
use crate::thermal::HeatSource;

/// The friction breakdown of a solved ball bearing at its rings' relative speed; its
/// sliding mechanisms add up to `heat.total_w` (the same heat, summed by race instead of
/// by ball), the rolling resistance and the `[cage]` losses come on top.
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
    let mut mechanisms = mechanisms;
    let rolling =
        |race: fn(&super::results::BallResult) -> f64| -> f64 { a.balls.iter().map(race).sum() };
    mechanisms.push(m(
        "inner_rolling_resistance",
        rolling(|b| b.inner.rolling_resistance_w),
        HeatSource::InnerContacts,
    ));
    mechanisms.push(m(
        "outer_rolling_resistance",
        rolling(|b| b.outer.rolling_resistance_w),
        HeatSource::OuterContacts,
    ));
    mechanisms.extend(a.cage_losses.iter().cloned());
    let op = &a.input.operating;
    FrictionBreakdown::at_ring_speeds(op.inner_speed_rad_s, op.outer_speed_rad_s, mechanisms)
}
