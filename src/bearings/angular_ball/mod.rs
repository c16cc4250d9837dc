//! Angular-contact ball bearings (seed 001: S.-H. Chen, *Investigation on Ball Skidding
//! and Traction within Elastohydrodynamic Films*, 1989): quasi-static load distribution
//! with centrifugal force and gyroscopic moment, Jones's race-control kinematics, spin
//! heat, the skidding threshold, and the EHD film of each contact.
//!
//! Imports run one way, top down: `system` → `analysis` (the driver) → `contacts` and
//! `skid` (→ `load_conditions` → `load_distribution`) and `dynamics` (→ `load_track`) →
//! `results` → `race_control`, `geometry`, `input`, `error`. The result types that the
//! stages below the driver read (`BallResult`, `ContactResult`) live in `results`, not in
//! `analysis`, so that no stage imports its driver.
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod analysis;
pub mod answer;
mod contacts;
pub mod deck;
pub mod dynamics;
pub mod error;
pub mod friction;
pub mod geometry;
pub mod input;
pub mod life;
mod load_conditions;
pub mod load_distribution;
pub mod load_track;
pub mod race_control;
pub mod report;
pub mod results;
mod skid;
pub mod stiffness;
pub mod system;
pub mod view;
pub mod warnings;

#[cfg(test)]
mod dof_tests;
#[cfg(test)]
mod iso16281_tests;
#[cfg(test)]
mod le7_tests;

/// The deck `type` of this system (its schema's `system`, the JSON's `type`), here at the
/// folder's root so that every file below reads it downward.
pub const SYSTEM_ID: &str = "angular-contact-ball";

pub use error::BallError;
pub use input::BallInput;
