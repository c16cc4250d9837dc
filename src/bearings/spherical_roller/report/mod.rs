//! The spherical roller bearing's reports: JSON (SI, units in key names; a contract with
//! scripts: fields are added, never renamed) and text (SASHBEAN-like tables in the deck's
//! unit system). Both read the per-roller rows of [`super::view::rollers`].

pub mod json;
pub mod text;
