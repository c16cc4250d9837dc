//! Shared numerics, independent of any bearing: cooperative cancellation, monotone
//! interpolation, Newton's method for small dense systems ([`newton`]), and (as systems
//! need them) ODE solvers, in the problem / solver / result style.
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod newton;
pub mod pchip;
