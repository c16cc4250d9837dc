//! The double-row spherical roller bearing's friction by mechanism (issue 28 item 4): the
//! loss breakdown's seven terms under their own names, nothing recomputed. Listed in the
//! order `losses` sums `total_w`, at the rings' speeds (outer ring fixed), so `power_w`
//! and `torque_nm` are `losses.total_w` and `losses.friction_torque_nm` to the bit.
//!
//! Heat binding for the thermal network: the raceways to the inner and outer contacts,
//! the guide ring to the guide ring, the cage pockets and land to the cage, the drag to
//! the oil. The skew loss is the pockets' reaction to the rollers' yaw plus the raceways'
//! axial sliding it causes (`RollerLoss::skew_raceway_w`, not split by ring in the loss
//! stage): it is released at the cage with the pockets, the larger part.

use super::losses::LossBreakdown;
use super::statics::DoubleRowAnalysis;
use crate::bearings::friction::{FrictionBreakdown, Mechanism};
use crate::thermal::HeatSource;

/// The friction breakdown of `l`, the losses of `a`.
pub fn friction(a: &DoubleRowAnalysis, l: &LossBreakdown) -> FrictionBreakdown {
    let x = &l.losses;
    let m = |name, power_w, heat| Mechanism {
        name,
        power_w,
        heat: Some(heat),
    };
    FrictionBreakdown::at_ring_speeds(
        a.input.operating.inner_speed_rad_s,
        0.0,
        vec![
            m(
                "raceway_inner",
                x.raceway_inner_w,
                HeatSource::InnerContacts,
            ),
            m(
                "raceway_outer",
                x.raceway_outer_w,
                HeatSource::OuterContacts,
            ),
            m("guide_ring", x.guide_ring_w, HeatSource::GuideRing),
            m("cage_pockets", x.cage_pockets_w, HeatSource::CageRails),
            m("cage_land", x.cage_land_w, HeatSource::CageRails),
            m("skew", x.skew_w, HeatSource::CageRails),
            m("drag", x.drag_w, HeatSource::ViscousDrag),
        ],
    )
}
