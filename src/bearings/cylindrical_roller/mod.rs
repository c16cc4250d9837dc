//! The cylindrical roller bearing (seed 003, Rahnejat et al., tribodynamics of cylindrical
//! roller bearings in a heavy-duty truck transmission): the quasi-static lamina load
//! distribution, the 2-DOF dynamics with variable compliance and film in the deflection,
//! spectra, and mixed-regime (Greenwood–Tripp + viscous) friction per roller.
//!
//! Layout: `input` (SI types), `deck` (the deck schema), `geometry` (derived geometry
//! and kinematics), `quasi_static` (lamina load distribution and ring stiffness),
//! `analysis` (a solved case), `view`, `report` (JSON and text), `system` (the registry
//! entry). More files join as the system is built (issue 25).
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
// `!(x > 0.0)` is used on purpose: it rejects NaN along with the out-of-range values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod analysis;
pub mod answer;
pub mod contact;
pub mod contact_job;
pub mod deck;
pub mod dynamics;
pub mod friction;
pub mod geometry;
pub mod input;
pub mod life;
pub mod quasi_static;
pub mod quasi_static_ribs;
pub mod report;
pub mod report_tribo;
pub mod system;
pub mod tribodynamics;
pub mod view;
pub mod view_tribo;

/// The deck `type` of this system (its schema's `system`, the JSON's `type`).
pub const SYSTEM_ID: &str = "cylindrical-roller";

pub use system::SYSTEM;
