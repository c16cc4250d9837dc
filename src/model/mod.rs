//! Pure physics, SI units throughout.

pub mod bearing;
pub mod heat;
pub mod kinematics;
pub mod traction;

pub use bearing::*;
