//! Angular-contact ball bearings (seed 001: S.-H. Chen, *Investigation on Ball Skidding
//! and Traction within Elastohydrodynamic Films*, 1989): quasi-static load distribution
//! with centrifugal force and gyroscopic moment, Jones's race-control kinematics, spin
//! heat, the skidding threshold, and the EHD film of each contact.
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod analysis;
mod contacts;
pub mod deck;
pub mod dynamics;
pub mod error;
pub mod geometry;
pub mod input;
mod load_conditions;
pub mod load_distribution;
pub mod load_track;
pub mod race_control;
pub mod report;
pub mod results;
mod skid;
pub mod system;
pub mod view;
pub mod warnings;

pub use error::BallError;
pub use input::BallInput;
