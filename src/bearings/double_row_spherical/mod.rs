//! The double-row spherical roller bearing (seed 002: Stirbu, Grigoras, Hanganu, *Combined
//! spherical roller bearings functioning analysis*; issue 27): two rows of crowned rollers
//! mirrored at ±α⁰, sharing the inner ring and one outer sphere, with a guide ring between
//! the rows. The rows' lamina statics are the spherical roller's
//! ([`crate::bearings::spherical_roller::load_distribution`] with a two-row
//! [`Layout`](crate::bearings::spherical_roller::load_distribution::Layout)); this folder
//! holds the deck, the assembly of the two rows and the wiring.

pub mod answer;
pub mod deck;
pub mod friction;
pub mod input;
pub mod jobs;
pub mod life;
pub mod load_sweep;
pub mod losses;
pub mod optimise;
pub mod report;
pub mod skew;
pub mod statics;
pub mod system;
pub mod view;

pub use input::*;

/// The deck `type` of this system.
pub const SYSTEM_ID: &str = "double-row-spherical-roller";

pub use system::SYSTEM;

#[cfg(test)]
mod losses_tests;
#[cfg(test)]
mod tests;
