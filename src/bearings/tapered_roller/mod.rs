//! The tapered roller bearing with flange-guided rollers, centrifugal and gyroscopic
//! loads and the full 5×5 stiffness matrix (AFAPL-TR-78-6 Part III, seed 004): roller
//! geometry (eqs. 16–35), speeds (36–39), per-roller equilibrium of cup, cone and flange
//! by Lundberg line-contact slices (40–87, 121–130), bearing equilibrium (92–106) and
//! stiffness (88–91, 107–120).
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod bearing;
pub mod contact;
pub mod geometry;
pub mod input;
pub mod roller;
