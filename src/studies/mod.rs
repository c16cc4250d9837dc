//! Studies a user runs over many solves of one deck: `rollbench sweep`'s parameter sweep
//! (`sweep`, also the workbench's Sweep pane) and `rollbench bench`'s
//! run-time-against-error study (`fidelity`). Multi-key grids, Monte Carlo samples,
//! shards and the optimiser belong here too. Generic over the bearing system: a study
//! reaches a system only through `crate::bearings` (its cases, sessions and key outputs).

pub mod fidelity;
pub mod study;
pub mod sweep;
