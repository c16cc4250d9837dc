//! rollbench: high-speed rolling-bearing analysis.
//!
//! Layers, bottom up: `units`, `numerics` and `files` (the one atomic file writer);
//! `physics` (shared by every bearing system); `bearings` (one folder per bearing system,
//! behind one trait); `thermal` (the lumped network); `deck` (all input), `report` (text,
//! JSON, CSV), `verify` (`validate`), `studies` (`sweep`, `bench`). None of these depend on the terminal UI;
//! `cli` and `tui` are thin layers on top. See `docs/architecture.md`.
#![forbid(unsafe_code)]

pub mod bearings;
pub mod cli;
pub mod deck;
pub mod files;
pub mod numerics;
pub mod physics;
pub mod pipeline;
pub mod report;
pub mod studies;
pub mod thermal;
pub mod tui;
pub mod units;
pub mod verify;
