//! Shared numerics, independent of any bearing, in the problem / solver / result style:
//! cooperative cancellation ([`cancel`]), Newton's method for small dense systems
//! ([`newton`]), blocked dense LU ([`dense_lu`]), preconditioned GMRES ([`gmres`]), ODE integrators with dense output and events ([`ode`]), monotone
//! interpolation ([`pchip`]) and amplitude spectra ([`spectrum`]).
#![cfg_attr(
    not(test),
    deny(clippy::unwrap_used, clippy::expect_used, clippy::panic)
)]

pub mod cancel;
pub mod dense_lu;
pub mod gmres;
pub mod newton;
pub mod ode;
pub mod pchip;
pub mod spectrum;
