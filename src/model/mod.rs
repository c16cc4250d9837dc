//! Pure physics, SI units throughout.

pub mod bearing;
pub mod film;
pub mod hertz;
pub mod life;
pub mod pchip;
pub mod subsurface;

pub use bearing::*;
