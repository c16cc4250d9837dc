//! What a solved bearing shows, independent of the system: tables of SI values with
//! their columns' units, and the key outputs the fidelity bench compares. Reports and
//! panes draw from a [`View`]; none of them re-joins a system's per-element arrays.

use crate::units::Quantity;

/// How a column's values are written to CSV (kept per column so the CSV of an existing
/// system never changes: counts and angles plain, physical values in `{:e}`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CsvStyle {
    /// A whole number.
    Integer,
    /// Shortest round-trip decimal (`{}`).
    Plain,
    /// Shortest round-trip scientific (`{:e}`).
    Scientific,
}

/// One column of a table.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    /// Machine name with its SI unit, as in JSON and CSV (`inner_normal_load_n`).
    pub key: &'static str,
    /// What the values are (decides the display unit).
    pub quantity: Quantity,
    /// CSV formatting.
    pub csv: CsvStyle,
}

impl Column {
    /// A column of `quantity` values.
    pub const fn new(key: &'static str, quantity: Quantity, csv: CsvStyle) -> Column {
        Column { key, quantity, csv }
    }
}

/// A table: one row per rolling element (or per point of a sweep), SI values; `None`
/// where a stage was not run.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Machine name (`rollers`, `balls`).
    pub id: &'static str,
    /// Columns, in order.
    pub columns: Vec<Column>,
    /// Rows, each as long as `columns`.
    pub rows: Vec<Vec<Option<f64>>>,
}

/// Whether a key output decides the recommended fidelity or only guards it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KeyRole {
    /// Must meet the accuracy target (e.g. max contact stress, life).
    Target,
    /// Must stay within the looser guard band (e.g. heat, cage speed).
    Guard,
}

/// One scalar a user judges a design by.
#[derive(Debug, Clone, PartialEq)]
pub struct KeyOutput {
    /// Machine name with unit (`max_stress_pa`).
    pub name: &'static str,
    /// SI value; `None` when it does not exist (an unloaded bearing's life).
    pub value: Option<f64>,
    /// What it is (display unit).
    pub quantity: Quantity,
    /// Its role in the fidelity bench.
    pub role: KeyRole,
}

/// Everything a solved bearing shows.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// The system's deck `type`.
    pub system: &'static str,
    /// Per-element tables; the first is the one CSV reports.
    pub tables: Vec<Table>,
    /// Key outputs.
    pub key_outputs: Vec<KeyOutput>,
}

impl View {
    /// The key output called `name`.
    pub fn key(&self, name: &str) -> Option<&KeyOutput> {
        self.key_outputs.iter().find(|k| k.name == name)
    }

    /// The table called `id`.
    pub fn table(&self, id: &str) -> Option<&Table> {
        self.tables.iter().find(|t| t.id == id)
    }
}
