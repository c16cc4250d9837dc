//! The cylindrical roller bearing's friction by mechanism (issue 28 item 4), from the
//! tribodynamics' cage-cycle friction (seed 003 eqs. 35–42: Greenwood–Tripp boundary
//! friction plus limited viscous shear at every roller's inner and outer contact).
//!
//! Every contact slides at the same speed, the deck's `contact.sliding_speed` (the seed's
//! prescribed slide; `tribodynamics::ContactFriction` passes it to each contact), so each
//! contact's power is its friction force times that one speed and the cycle-mean power
//! splits over the mechanisms exactly as the cycle-mean forces do:
//! P_k = P · F_k / F_total, with F_k the boundary and viscous force at each race.
//! Not modelled, so absent: the rib (flange) contacts' friction, the cage and the
//! churning drag.

use super::analysis::CylindricalAnalysis;
use crate::bearings::friction::{FrictionBreakdown, Mechanism};
use crate::thermal::HeatSource;

/// The friction breakdown when the tribodynamics ran (`None` otherwise: the deck asked for
/// no friction). The outer ring is fixed: the relative speed is ω_i.
pub fn friction(a: &CylindricalAnalysis) -> Option<FrictionBreakdown> {
    let f = &a.tribo.as_ref()?.friction;
    let share = |force_n: f64| {
        if f.total_n != 0.0 {
            f.power_w * force_n / f.total_n
        } else {
            0.0
        }
    };
    let outer_boundary_n = f.boundary_n - f.inner_boundary_n;
    let m = |name, force_n: f64, heat| Mechanism {
        name,
        power_w: share(force_n),
        heat: Some(heat),
    };
    Some(FrictionBreakdown::at_ring_speeds(
        a.input.operating.inner_speed_rad_s,
        0.0,
        vec![
            m(
                "inner_boundary",
                f.inner_boundary_n,
                HeatSource::InnerContacts,
            ),
            m(
                "inner_viscous",
                f.inner_n - f.inner_boundary_n,
                HeatSource::InnerContacts,
            ),
            m(
                "outer_boundary",
                outer_boundary_n,
                HeatSource::OuterContacts,
            ),
            m(
                "outer_viscous",
                f.outer_n - outer_boundary_n,
                HeatSource::OuterContacts,
            ),
        ],
    ))
}
