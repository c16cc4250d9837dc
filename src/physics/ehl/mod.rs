//! Lubricated line contact in detail (issue 26, seed 003 §Contact model), SI.
//!
//! - `tipei`: Tipei's counter-flow inlet and outlet distances (eqs. 14–22).
//! - `thermal`: the energy equation across the film with the solids as moving half-spaces
//!   (eqs. 23–34), and the viscosity ↔ temperature iteration hook.
//! - `friction`: the contact friction, Greenwood–Tripp boundary plus limited viscous shear,
//!   node by node (eqs. 35–42).

pub mod friction;
pub mod thermal;
pub mod tipei;
