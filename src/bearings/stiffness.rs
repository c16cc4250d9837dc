//! One bearing stiffness matrix, shared by every system (issue 29 item 3): the ring
//! degrees of freedom it couples, K_ij = ∂F_i/∂u_j in SI (forces and moments on the
//! inner ring, positive opposite to its displacements and rotations), how it was computed,
//! and its two renderings: the JSON report's `stiffness` object (the keys the tapered
//! system has always written: `matrix`, `rows`, `columns`, `units`, `method`,
//! `reference_point`, `asymmetry_max`, `finite_difference_matrix`,
//! `finite_difference_max_rel`; a system adds its own beside them) and the text block
//! titled "stiffness" in the deck's units (the round-off rule of
//! [`super::stiffness_text`]).

use std::fmt::Write;

use serde::{Deserialize, Serialize};
use serde_json::{json, Value};

use super::view::TextBlock;
use crate::units::{Quantity, Units};

/// A ring degree of freedom: three displacements and two tilts (rotation about the
/// bearing axis is the ring's speed, not a stiffness coordinate).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dof {
    /// Radial displacement along x (the radial load's direction), m.
    X,
    /// Radial displacement along y, m.
    Y,
    /// Axial displacement along the bearing axis z, m.
    Z,
    /// Tilt about x, rad.
    ThetaX,
    /// Tilt about y, rad.
    ThetaY,
}

impl Dof {
    /// Every degree of freedom, in the matrix order.
    pub const ALL: [Dof; 5] = [Dof::X, Dof::Y, Dof::Z, Dof::ThetaX, Dof::ThetaY];

    /// The column name (`x` … `theta_y`).
    pub fn column(self) -> &'static str {
        match self {
            Dof::X => "x",
            Dof::Y => "y",
            Dof::Z => "z",
            Dof::ThetaX => "theta_x",
            Dof::ThetaY => "theta_y",
        }
    }

    /// The symbol text and the screen use (`x` … `θy`; issue 30 item 10: one vocabulary,
    /// no ASCII `theta_x` in text). JSON and CSV keep [`Dof::column`].
    pub fn symbol(self) -> &'static str {
        match self {
            Dof::ThetaX => "θx",
            Dof::ThetaY => "θy",
            other => other.column(),
        }
    }

    /// The row name: the generalised force conjugate to it (`F_x` … `M_y`).
    pub fn row(self) -> &'static str {
        match self {
            Dof::X => "F_x",
            Dof::Y => "F_y",
            Dof::Z => "F_z",
            Dof::ThetaX => "M_x",
            Dof::ThetaY => "M_y",
        }
    }

    /// A rotation (its force is a moment).
    pub fn angular(self) -> bool {
        matches!(self, Dof::ThetaX | Dof::ThetaY)
    }
}

/// How the reported matrix was computed (the deck's `solver.stiffness` where a system
/// has that key).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// The Jacobian of the ring equilibrium.
    #[default]
    Analytic,
    /// Central differences of re-solved equilibria.
    FiniteDifference,
    /// Analytic, with the finite-difference check beside it.
    Both,
}

/// The deck spellings of [`Method`], in its order (a `solver.stiffness` choice field).
pub const METHODS: &[&str] = &["analytic", "finite-difference", "both"];

impl Method {
    /// The index of the deck choice ([`METHODS`]' order).
    pub fn index(self) -> f64 {
        match self {
            Method::Analytic => 0.0,
            Method::FiniteDifference => 1.0,
            Method::Both => 2.0,
        }
    }

    /// The method of deck choice `v` ([`METHODS`]' order).
    pub fn from_index(v: f64) -> Method {
        match v as usize {
            1 => Method::FiniteDifference,
            2 => Method::Both,
            _ => Method::Analytic,
        }
    }

    /// Whether the finite differences are computed.
    pub fn wants_fd(self) -> bool {
        self != Method::Analytic
    }

    /// The JSON name.
    pub fn name(self) -> &'static str {
        match self {
            Method::Analytic => "analytic",
            Method::FiniteDifference => "finite-difference",
            Method::Both => "both",
        }
    }
}

/// A bearing's stiffness matrix at its operating point, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct StiffnessMatrix {
    /// The degrees of freedom, rows and columns alike, in [`Dof::ALL`]'s order.
    pub dofs: Vec<Dof>,
    /// K, row-major n×n: N/m, N/rad, N·m/m, N·m/rad by block.
    pub k: Vec<f64>,
    /// How `k` was computed.
    pub method: Method,
    /// The matrix by central differences, when computed beside the analytic one
    /// (`finite_difference_matrix`).
    pub fd: Option<Vec<f64>>,
    /// Largest analytic–difference gap over each row's scale
    /// (`finite_difference_max_rel`).
    pub fd_max_rel: Option<f64>,
    /// Largest scaled |K_ij − K_ji| (`asymmetry_max`), when the system reports it.
    pub asymmetry_max: Option<f64>,
    /// Where the displacements and moments are referred to (`reference_point`).
    pub reference_point: Option<String>,
    /// Sentences for a person (which DOFs are free and why, how the steps were
    /// chosen): the JSON `notes` (absent when empty) and the text's last lines.
    pub notes: Vec<String>,
}

impl StiffnessMatrix {
    /// A matrix over `dofs` from `k` (row-major), with nothing else said.
    pub fn new(dofs: Vec<Dof>, k: Vec<f64>, method: Method) -> StiffnessMatrix {
        StiffnessMatrix {
            dofs,
            k,
            method,
            fd: None,
            fd_max_rel: None,
            asymmetry_max: None,
            reference_point: None,
            notes: Vec::new(),
        }
    }

    /// The number of degrees of freedom.
    pub fn n(&self) -> usize {
        self.dofs.len()
    }

    /// K_ij, SI.
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.k[i * self.n() + j]
    }

    /// The diagonal term of `dof`, SI, when the matrix has that DOF.
    pub fn diagonal(&self, dof: Dof) -> Option<f64> {
        let i = self.dofs.iter().position(|d| *d == dof)?;
        Some(self.get(i, i))
    }

    /// `m` (row-major, this matrix's size) as rows.
    pub fn nested(&self, m: &[f64]) -> Vec<Vec<f64>> {
        m.chunks(self.n().max(1)).map(<[f64]>::to_vec).collect()
    }

    /// The SI unit of entry (i, j).
    fn unit_si(&self, i: usize, j: usize) -> &'static str {
        match (self.dofs[i].angular(), self.dofs[j].angular()) {
            (false, false) => "N/m",
            (false, true) => "N/rad",
            (true, false) => "N·m/m",
            (true, true) => "N·m/rad",
        }
    }

    /// The JSON report's `stiffness` object (SI).
    pub fn json(&self) -> Value {
        let n = self.n();
        let units: Vec<Vec<&str>> = (0..n)
            .map(|i| (0..n).map(|j| self.unit_si(i, j)).collect())
            .collect();
        let mut v = json!({
            "matrix": self.nested(&self.k),
            "rows": self.dofs.iter().map(|d| d.row()).collect::<Vec<_>>(),
            "columns": self.dofs.iter().map(|d| d.column()).collect::<Vec<_>>(),
            "units": units,
            "method": self.method.name(),
        });
        if let Some(o) = v.as_object_mut() {
            if let Some(r) = &self.reference_point {
                o.insert("reference_point".into(), json!(r));
            }
            if let Some(a) = self.asymmetry_max {
                o.insert("asymmetry_max".into(), json!(a));
            }
            if let Some(fd) = &self.fd {
                o.insert("finite_difference_matrix".into(), json!(self.nested(fd)));
            }
            if let Some(d) = self.fd_max_rel {
                o.insert("finite_difference_max_rel".into(), json!(d));
            }
            if !self.notes.is_empty() {
                o.insert("notes".into(), json!(self.notes));
            }
        }
        v
    }

    /// Entry (i, j)'s factor from SI to `units` and its unit's name.
    fn unit(&self, i: usize, j: usize, units: Units) -> (f64, String) {
        let (lu, fu, mu) = (
            Quantity::Length.unit(units),
            Quantity::Force.unit(units),
            Quantity::Moment.unit(units),
        );
        let (f, l, m) = (
            Quantity::Force.factor(units),
            Quantity::Length.factor(units),
            Quantity::Moment.factor(units),
        );
        match (self.dofs[i].angular(), self.dofs[j].angular()) {
            (false, false) => (f / l, format!("{fu}/{lu}")),
            (false, true) => (f, format!("{fu}/rad")),
            (true, false) => (m / l, format!("{mu}/{lu}")),
            (true, true) => (m, format!("{mu}/rad")),
        }
    }

    /// The text block in `units`: the matrix (round-off shown as 0), the round-off
    /// note, the units, the asymmetry and the finite-difference check when known, and
    /// the notes.
    pub fn lines(&self, units: Units) -> Vec<String> {
        let n = self.n();
        let mut s = String::new();
        let _ = writeln!(
            s,
            "Stiffness matrix (rows {}; columns {})",
            self.dofs
                .iter()
                .map(|d| d.row())
                .collect::<Vec<_>>()
                .join(" "),
            self.dofs
                .iter()
                .map(|d| d.symbol())
                .collect::<Vec<_>>()
                .join(" ")
        );
        for i in 0..n {
            let mut line = format!("  {:<4}", self.dofs[i].row());
            for j in 0..n {
                let (f, _) = self.unit(i, j, units);
                let shown = super::stiffness_text::shown(|r, c| self.get(r, c), i, j);
                let _ = write!(line, " {:>12.4e}", shown / f);
            }
            let _ = writeln!(s, "{line}");
        }
        let _ = writeln!(s, "{}", super::stiffness_text::round_off_note());
        let lineal = self.dofs.iter().position(|d| !d.angular());
        let angular = self.dofs.iter().position(|d| d.angular());
        match (lineal, angular) {
            (Some(l), Some(a)) => {
                let _ = writeln!(
                    s,
                    "  units: lineal {}, lineal-angular {} and {}, angular {}",
                    self.unit(l, l, units).1,
                    self.unit(l, a, units).1,
                    self.unit(a, l, units).1,
                    self.unit(a, a, units).1
                );
            }
            (Some(l), None) => {
                let _ = writeln!(s, "  units: lineal {}", self.unit(l, l, units).1);
            }
            (None, Some(a)) => {
                let _ = writeln!(s, "  units: angular {}", self.unit(a, a, units).1);
            }
            (None, None) => {}
        }
        if let Some(a) = self.asymmetry_max {
            let _ = writeln!(s, "  largest asymmetry |K_ij - K_ji| (scaled): {a:.3e}");
        }
        if let Some(d) = self.fd_max_rel {
            let _ = writeln!(
                s,
                "  analytic vs finite differences: largest gap {d:.3e} of the row scale"
            );
        }
        for note in &self.notes {
            let _ = writeln!(s, "  {note}");
        }
        s.lines().map(str::to_string).collect()
    }

    /// The view's text block titled "stiffness" (the workbench's Stiffness pane and
    /// `rollbench stiffness`), with `extra` lines in each unit system appended.
    pub fn text_block(&self, extra: impl Fn(Units) -> Vec<String>) -> TextBlock {
        let block = |units| {
            let mut v = self.lines(units);
            v.extend(extra(units));
            v
        };
        TextBlock {
            title: "stiffness",
            si: block(Units::Si),
            us: block(Units::Us),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2×2 lineal matrix names its rows and columns, writes SI units for every entry
    /// and omits what it does not know; US text divides by lbf/in = 175.127 N/m.
    #[test]
    fn json_and_text_of_a_lineal_matrix() {
        let mut k = StiffnessMatrix::new(
            vec![Dof::X, Dof::Z],
            vec![2.0e8, 1.0e-3, 1.0e-3, 5.0e7],
            Method::FiniteDifference,
        );
        k.notes.push("tilt is free".into());
        let j = k.json();
        assert_eq!(j["rows"], json!(["F_x", "F_z"]));
        assert_eq!(j["columns"], json!(["x", "z"]));
        assert_eq!(j["units"][0][1], json!("N/m"));
        assert_eq!(j["method"], json!("finite-difference"));
        assert_eq!(j["matrix"][1][1], json!(5.0e7));
        assert!(j.get("finite_difference_max_rel").is_none());
        assert!(j.get("asymmetry_max").is_none());
        assert_eq!(j["notes"], json!(["tilt is free"]));
        assert_eq!(k.diagonal(Dof::Z), Some(5.0e7));
        assert_eq!(k.diagonal(Dof::Y), None);
        let us = k.lines(Units::Us);
        assert_eq!(us[0], "Stiffness matrix (rows F_x F_z; columns x z)");
        // 2e8 N/m in lbf/in: 2e8·0.0254/4.448222 = 1.1420e6; the 1e-3 coupling is
        // round-off of √(2e8·5e7) = 1e8 and shown as 0.
        assert_eq!(us[1], "  F_x      1.1420e6     0.0000e0");
        assert_eq!(us[4], "  units: lineal lbf/in");
        assert_eq!(us[5], "  tilt is free");
    }

    /// Mixed blocks: N/rad above the diagonal, N·m/m below, N·m/rad in the corner.
    #[test]
    fn mixed_units_by_block() {
        let k = StiffnessMatrix::new(
            vec![Dof::X, Dof::ThetaY],
            vec![1.0, 2.0, 3.0, 4.0],
            Method::Analytic,
        );
        let j = k.json();
        assert_eq!(j["units"], json!([["N/m", "N/rad"], ["N·m/m", "N·m/rad"]]));
        assert_eq!(
            k.lines(Units::Si)[4],
            "  units: lineal N/m, lineal-angular N/rad and N·m/m, angular N·m/rad"
        );
    }
}
