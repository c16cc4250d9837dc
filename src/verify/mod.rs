//! Verification: `rollbench validate`'s reference cases (`cases`), `rollbench bench`'s
//! run-time-against-error study (`fidelity`) and `rollbench sweep`'s parameter sweep
//! (`sweep`).

pub mod cases;
pub mod fidelity;
pub mod sweep;
mod system_cases;
