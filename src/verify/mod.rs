//! Verification: `rollbench validate`'s reference cases (`cases`) and `rollbench bench`'s
//! run-time-against-error study (`fidelity`).

pub mod cases;
pub mod fidelity;
