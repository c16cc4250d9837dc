//! Pure physics, SI units throughout.

pub mod bearing;

pub use bearing::*;
