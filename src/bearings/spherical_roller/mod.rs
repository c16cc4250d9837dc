//! The angular-contact spherical roller bearing by the SASHBEAN lamina method
//! (A. K. Aggarwal, NASA CR-191182, 1993; seed 000): lamina load distribution with
//! centrifugal and gyroscopic loads, stresses, EHD film, life, speeds, heat.

pub mod answer;
pub mod contacts;
pub mod converged;
pub mod deck;
pub mod deck_schema;
pub mod geometry;
pub mod input;
pub mod iso_life;
pub mod load_distribution;
pub mod pipeline;
pub mod report;
pub mod roller;
pub mod stages;
pub mod stiffness;
pub mod system;
pub mod view;
pub mod warnings;

pub use input::*;
/// The deck `type` of this system (its schema's `system`, the JSON's `type`), here at the
/// folder's root so that every file below reads it downward.
pub const SYSTEM_ID: &str = "spherical-roller";

pub use system::SYSTEM;
