//! rollbench: high-speed rolling-bearing analysis (SASHBEAN lamina method, NASA CR-191182).
//!
//! Layers: `model` (pure physics), `solve` (equilibrium solvers, staged pipeline),
//! `deck` (TOML input), `report` (text/JSON/CSV), `thermal` (lumped network). None of
//! these depend on the terminal UI; `cli` and `tui` are thin layers on top.
#![forbid(unsafe_code)]

pub mod cli;
pub mod deck;
pub mod fidelity;
pub mod model;
pub mod report;
pub mod solve;
pub mod thermal;
pub mod tui;
pub mod units;
pub mod validate;
