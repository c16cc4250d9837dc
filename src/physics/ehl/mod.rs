//! Lubricated line contact in detail (issue 26, seed 003 §Contact model), SI.
//!
//! - `tipei`: Tipei's counter-flow inlet and outlet distances (eqs. 14–22).

pub mod tipei;
