//! Pure physics, SI units throughout.

pub mod bearing;
pub mod film;
pub mod geometry;
pub mod heat;
pub mod hertz;
pub mod kinematics;
pub mod lamina_law;
pub mod life;
pub mod pchip;
pub mod roller;
pub mod subsurface;
mod subsurface_table;
pub mod traction;

pub use bearing::*;
