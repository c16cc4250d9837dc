//! Contact mechanics: Hertz line contact of a lamina (`line`), the lamina load–deflection
//! law (`lamina_law`) and the subsurface stresses under a Hertz ellipse (`subsurface`).

pub mod lamina_law;
pub mod line;
pub mod subsurface;
mod subsurface_table;
