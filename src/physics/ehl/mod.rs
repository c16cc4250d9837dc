//! Elastohydrodynamic lubrication of one contact solved in detail (seed 003 §Contact
//! model, issue 26): the lubricated roller–raceway contact as a field p(x), h(x) rather
//! than a film formula.
//!
//! - `kernel`: the line-contact elastic deflection (seed 003 eq. 9 reduced to 1-D),
//!   integrated exactly over piecewise-constant pressure elements.
//! - `line`: the 1-D transient line-contact EHL solver (eqs. 5–9, 11, 13): Reynolds with
//!   the squeeze term, the film with elastic deflection, Houpert viscosity (10),
//!   Dowson–Higginson density (11), Swift–Stieber cavitation, the load balance (46); a
//!   coupled semismooth Newton on (p, h₀).
//! - `tipei`: Tipei's counter-flow inlet and outlet distances (eqs. 14–22).
//! - `thermal`: the energy equation across the film with the solids as moving half-spaces
//!   (eqs. 23–34), and the viscosity ↔ temperature iteration hook.
//! - `friction`: the contact friction, Greenwood–Tripp boundary plus limited viscous shear,
//!   node by node (eqs. 35–42).
//!
//! SI throughout; the solver works internally in Hertz-scaled variables (documented in
//! `line`).
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]
// `!(x > 0.0)` is used on purpose: it rejects NaN along with the out-of-range values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// The discretised Reynolds rows index several per-node arrays at i − 2 … i + 1; index
// loops say that more plainly than zipped iterators.
#![allow(clippy::needless_range_loop)]

pub mod friction;
pub mod kernel;
pub mod line;
pub mod thermal;
pub mod tipei;
