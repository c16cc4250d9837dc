//! Verification: `rollbench validate`'s reference cases (`cases`, with each system's own
//! in `system_cases`), every model against an independent reference with its tolerance.

pub mod cases;
mod system_cases;
