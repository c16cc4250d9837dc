//! The load-distribution conditions of a case from its input: how the inner ring is held
//! axially (the preload as a force, or as the displacement that holds it at rest) and
//! the ring speeds. Shared by the driver (`analysis`), the rheology curve's first solve
//! (`contacts`) and the skid search (`skid`), so it sits below all three.

use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{BallInput, PreloadMode};
use super::load_distribution::{self, Axial, Conditions, Tilt};
use crate::numerics::cancel::Cancel;

pub(super) fn axial_condition(
    input: &BallInput,
    geom: &BallGeometry,
    cancel: Cancel,
) -> Result<(Axial, Option<f64>), BallError> {
    let op = &input.operating;
    // No axial load (issue 29). Held as a displacement, the rest displacement of a
    // vanishing preload is δ_a = 0 (the balls just touch both grooves at α₀: the limit of
    // δ_a(F_a) as F_a → 0, where the rest solve itself has no load to find it from).
    // Held as a force with a radial load, F_a = 0 is solved as it is: the ring finds its
    // axial place from the radial load through the contact angles. With neither load
    // nothing fixes the ring's axial place within the play: it is held at δ_a = 0 and
    // the warnings say so (`warnings::undetermined`): where depends on how the load is
    // held (below).
    if op.axial_load_n == 0.0 {
        match op.preload_mode {
            PreloadMode::Displacement => return Ok((Axial::Displacement(0.0), Some(0.0))),
            // Centred in its play, δ_a = −A sin α₀: the grooves face each other and no
            // ball is pressed by the inner ring at any speed (at speed the balls move
            // out), so the held force is indeed zero there.
            PreloadMode::Force if op.radial_load_n == 0.0 => {
                let a0 = geom.free_contact_angle_rad;
                return Ok((
                    Axial::Displacement(-geom.centre_distance_m * a0.sin()),
                    None,
                ));
            }
            PreloadMode::Force => {}
        }
    }
    match op.preload_mode {
        PreloadMode::Force => Ok((Axial::Force(op.axial_load_n), None)),
        PreloadMode::Displacement => {
            let rest = Conditions {
                inner_speed_rad_s: 0.0,
                outer_speed_rad_s: 0.0,
                axial: Axial::Force(op.axial_load_n),
                radial_load_n: 0.0,
                tilt: Tilt::Held(0.0),
                race_control: input.kinematics.race_control,
                gyroscopic_friction: input.kinematics.gyroscopic_friction,
                friction_split: input.kinematics.friction_split,
                max_friction: input.traction.curve().max_mu(),
            };
            let d = load_distribution::solve(geom, &rest, cancel)?.axial_deflection_m;
            Ok((Axial::Displacement(d), Some(d)))
        }
    }
}

pub(super) fn conditions(input: &BallInput, axial: Axial, scale: f64) -> Conditions {
    let op = &input.operating;
    Conditions {
        inner_speed_rad_s: op.inner_speed_rad_s * scale,
        outer_speed_rad_s: op.outer_speed_rad_s * scale,
        axial,
        radial_load_n: op.radial_load_n,
        tilt: match op.moment_nm {
            Some(m) => Tilt::Moment(m),
            None => Tilt::Held(op.misalignment_rad),
        },
        race_control: input.kinematics.race_control,
        gyroscopic_friction: input.kinematics.gyroscopic_friction,
        friction_split: input.kinematics.friction_split,
        max_friction: input.traction.curve().max_mu(),
    }
}
