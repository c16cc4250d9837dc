//! Pure physics, SI units throughout.

pub mod bearing;
pub mod geometry;
pub mod heat;
pub mod kinematics;
pub mod lamina_law;
pub mod roller;
pub mod traction;

pub use bearing::*;
