//! Contact mechanics: Hertz line contact of a lamina (`line`), Hertz point contact of a
//! ball with exact elliptic integrals or the Brewe–Hamrock fits (`point`, `elliptic`), the
//! lamina load–deflection law (`lamina_law`) and the subsurface stresses under a Hertz
//! ellipse (`subsurface`).

pub mod elliptic;
pub mod lamina_law;
pub mod line;
pub mod lundberg;
pub mod point;
pub mod subsurface;
mod subsurface_table;
