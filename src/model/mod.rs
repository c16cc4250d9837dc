//! Pure physics, SI units throughout.

pub mod bearing;
pub mod geometry;
pub mod lamina_law;
pub mod roller;

pub use bearing::*;
