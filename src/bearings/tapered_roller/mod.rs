//! The tapered roller bearing with flange-guided rollers, centrifugal and gyroscopic
//! loads and the full 5×5 stiffness matrix (AFAPL-TR-78-6 Part III, seed 004): roller
//! geometry (eqs. 16–35), speeds (36–39), per-roller equilibrium of cup, cone and flange
//! by Lundberg line-contact slices (40–87, 121–130), bearing equilibrium (92–106) and
//! stiffness (88–91, 107–120).
//!
//! Layout: `input` (SI types), `deck` (the deck schema), `geometry`, `contact` (one race
//! by slices), `roller` (one roller's equilibrium), `bearing` (equilibrium and
//! stiffness), `analysis` (a solved case), `view`, `report` (JSON and text), `system`
//! (the registry entry).
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
// `!(x > 0.0)` is used on purpose: it rejects NaN along with the out-of-range values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod analysis;
pub mod answer;
pub mod bearing;
pub mod contact;
pub mod deck;
pub mod geometry;
pub mod input;
pub mod life;
#[cfg(test)]
mod moment_tests;
pub mod report;
pub mod roller;
pub mod system;
pub mod thermal;
pub mod tribology;
pub mod view;

/// The deck `type` of this system (its schema's `system`, the JSON's `type`), here at the
/// folder's root so that every file below reads it downward.
pub const SYSTEM_ID: &str = "tapered-roller";

pub use system::SYSTEM;
