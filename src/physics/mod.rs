//! Shared physics: knows no bearing system. SI units throughout.
//!
//! Contact mechanics (`contact`: line and point Hertz, the lamina load law, subsurface
//! stresses), lubrication (`lubrication`: film thickness and traction), fatigue life
//! (`life` for line contact, `life_point` for ball bearings; capacity geometry passed in),
//! heat sources (`heat`), rolling-element kinematics (`kinematics`) and materials. Bearing systems (`crate::bearings`) compose
//! these; nothing here imports a bearing system, the deck, a report or the UI.
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod contact;
pub mod ehl;
pub mod heat;
pub mod kinematics;
pub mod life;
pub mod life_point;
pub mod lubrication;
pub mod material;
pub mod rating;
pub mod thrust_ball_rating;
