//! Lubricated line contact in detail (issue 26, seed 003 §Contact model), SI.
//!
//! - `tipei`: Tipei's counter-flow inlet and outlet distances (eqs. 14–22).
//! - `friction`: the contact friction, Greenwood–Tripp boundary plus limited viscous shear,
//!   node by node (eqs. 35–42).

pub mod friction;
pub mod tipei;
