//! The load-distribution conditions of a case from its input: how the inner ring is held
//! axially (the preload as a force, or as the displacement that holds it at rest) and
//! the ring speeds. Shared by the driver (`analysis`), the rheology curve's first solve
//! (`contacts`) and the skid search (`skid`), so it sits below all three.

use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{BallInput, PreloadMode};
use super::load_distribution::{self, Axial, Conditions};
use crate::numerics::cancel::Cancel;

pub(super) fn axial_condition(
    input: &BallInput,
    geom: &BallGeometry,
    cancel: Cancel,
) -> Result<(Axial, Option<f64>), BallError> {
    let op = &input.operating;
    match op.preload_mode {
        PreloadMode::Force => Ok((Axial::Force(op.axial_load_n), None)),
        PreloadMode::Displacement => {
            let rest = Conditions {
                inner_speed_rad_s: 0.0,
                outer_speed_rad_s: 0.0,
                axial: Axial::Force(op.axial_load_n),
                radial_load_n: 0.0,
                race_control: input.kinematics.race_control,
                gyroscopic_friction: input.kinematics.gyroscopic_friction,
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
        race_control: input.kinematics.race_control,
        gyroscopic_friction: input.kinematics.gyroscopic_friction,
        max_friction: input.traction.curve().max_mu(),
    }
}
