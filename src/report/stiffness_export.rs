//! `rollbench stiffness DECK --export ross|csv|json` (issue 29 item 4): the bearing's
//! stiffness matrix in a file a rotordynamics user loads directly. This module only reads
//! a [`StiffnessMatrix`] (rebuilt from the JSON report's `stiffness` object, the one
//! place every system writes it) and writes it out; it computes nothing.
//!
//! - `ross`: a TOML file in the layout of ROSS's own `BearingElement.save` (petrobras/ross,
//!   read at commit 631a249adbae414d5f5f986479b58f1a4c47935e, version 2.3.0:
//!   `ross/bearing_seal_element.py` `BearingElement.__init__`, `save`, `read_toml_data`;
//!   `ross/element.py` `Element.load`; `ross/utils.py` `load_data`): one table named
//!   `BearingElement_<tag>` holding the constructor's arguments, each coefficient a list
//!   (one value: no speed dependence), SI (N/m, N·s/m, kg). `rs.BearingElement.load(file)`
//!   reads it back. ROSS's bearing has three translations per node (x, y, z; its
//!   `dof_mapping`), stiffness K = [[kxx, kxy, 0], [kyx, kyy, 0], [0, 0, kzz]] with the
//!   force on the rotor −K·u: the same sign as rollbench's K_ij = ∂F_i/∂u_j (forces
//!   positive opposite to the displacements). The tilt rows and columns have no place in
//!   it: the file says so and gives their values in its comments.
//! - `csv`: one line per entry `row,column,value,unit`, in the deck's units.
//! - `json`: the matrix in the deck's units with each entry's unit.
//!
//! No system computes damping (or a bearing mass): ROSS's c and m coefficients are
//! written as 0 and every export says so.

use std::fmt::Write;

use serde_json::{json, Value};

use crate::bearings::stiffness::{Dof, Method, StiffnessMatrix};
use crate::units::{Quantity, Units};

/// The export formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Export {
    /// ROSS's `BearingElement` TOML (SI).
    Ross,
    /// One entry a line, deck units.
    Csv,
    /// The matrix and its units, deck units.
    Json,
}

/// The sentence every export carries about damping.
pub const NO_DAMPING: &str = "no damping: no rollbench system computes a damping (or bearing mass) coefficient yet, so ROSS's c and m terms are 0";

/// The ROSS commit whose source the `ross` format was checked against.
pub const ROSS_COMMIT: &str = "631a249adbae414d5f5f986479b58f1a4c47935e";

/// The matrix in the JSON report's `stiffness` object (`columns`, `matrix`, `method`,
/// and what else it holds), or `None` when `v` is not one.
pub fn matrix_from_json(v: &Value) -> Option<StiffnessMatrix> {
    let dofs: Vec<Dof> = v
        .get("columns")?
        .as_array()?
        .iter()
        .map(|c| {
            let c = c.as_str()?;
            Dof::ALL.into_iter().find(|d| d.column() == c)
        })
        .collect::<Option<_>>()?;
    let n = dofs.len();
    let rows = v.get("matrix")?.as_array()?;
    if rows.len() != n {
        return None;
    }
    let mut k = Vec::with_capacity(n * n);
    for row in rows {
        let row = row.as_array()?;
        if row.len() != n {
            return None;
        }
        for x in row {
            k.push(x.as_f64()?);
        }
    }
    let method = match v.get("method").and_then(Value::as_str) {
        Some("finite-difference") => Method::FiniteDifference,
        Some("both") => Method::Both,
        _ => Method::Analytic,
    };
    let mut m = StiffnessMatrix::new(dofs, k, method);
    m.reference_point = v
        .get("reference_point")
        .and_then(Value::as_str)
        .map(str::to_string);
    if let Some(notes) = v.get("notes").and_then(Value::as_array) {
        m.notes = notes
            .iter()
            .filter_map(Value::as_str)
            .map(str::to_string)
            .collect();
    }
    Some(m)
}

/// Entry (i, j)'s factor from `units` to SI (value_SI = value · factor) and its unit.
fn entry_unit(k: &StiffnessMatrix, i: usize, j: usize, units: Units) -> (f64, String) {
    let (f, l, m) = (Quantity::Force, Quantity::Length, Quantity::Moment);
    let (num, nu) = if k.dofs[i].angular() {
        (m.factor(units), m.unit(units))
    } else {
        (f.factor(units), f.unit(units))
    };
    if k.dofs[j].angular() {
        (num, format!("{nu}/rad"))
    } else {
        (num / l.factor(units), format!("{nu}/{}", l.unit(units)))
    }
}

/// K_ij of `a` on `b`, SI, when the matrix has both.
fn term(k: &StiffnessMatrix, a: Dof, b: Dof) -> Option<f64> {
    let i = k.dofs.iter().position(|d| *d == a)?;
    let j = k.dofs.iter().position(|d| *d == b)?;
    Some(k.get(i, j))
}

/// A TOML float that reads back to exactly `x` (Rust's shortest round-trip form, which
/// TOML and Python both parse to the same double), or why not.
fn toml_float(x: f64) -> Result<String, String> {
    if !x.is_finite() {
        return Err(format!(
            "a stiffness term is {x}: ROSS's file cannot hold it"
        ));
    }
    let s = format!("{x:?}");
    Ok(if s.contains(['.', 'e']) { s } else { s + ".0" })
}

/// What the export is written from: the deck's name (ROSS's `tag`), its system's title
/// and its unit system.
#[derive(Debug, Clone, Copy)]
pub struct Source<'a> {
    /// The deck's file stem.
    pub tag: &'a str,
    /// The bearing system's title.
    pub system: &'a str,
    /// The deck's unit system (csv and json).
    pub units: Units,
}

/// `k` in `format`, or a sentence saying why it cannot be written.
pub fn export(k: &StiffnessMatrix, format: Export, src: Source) -> Result<String, String> {
    match format {
        Export::Ross => ross_toml(k, src),
        Export::Csv => Ok(csv(k, src.units)),
        Export::Json => json_deck_units(k, src),
    }
}

/// A TOML basic string.
fn toml_string(s: &str) -> String {
    serde_json::to_string(s).unwrap_or_else(|_| "\"\"".into())
}

/// ROSS's `BearingElement` TOML: kxx, kyy, kxy, kyx, kzz from the matrix (kzz 0 where the
/// system has no axial row, said), every c and m 0 (no damping model, said).
fn ross_toml(k: &StiffnessMatrix, src: Source) -> Result<String, String> {
    let need = |d: Dof| {
        k.dofs.contains(&d).then_some(()).ok_or_else(|| {
            format!(
                "the {} stiffness matrix has no {} row (its degrees of freedom: {}): ROSS's bearing element needs kxx, kyy, kxy and kyx",
                src.system,
                d.column(),
                k.dofs.iter().map(|d| d.column()).collect::<Vec<_>>().join(", ")
            )
        })
    };
    need(Dof::X)?;
    need(Dof::Y)?;
    let get = |a, b| term(k, a, b).unwrap_or(0.0);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# ROSS (petrobras/ross) bearing element, written by rollbench {} from {} ({}).",
        env!("CARGO_PKG_VERSION"),
        src.tag,
        src.system
    );
    let _ = writeln!(
        s,
        "# Load it with:  import ross as rs; bearing = rs.BearingElement.load(\"THIS_FILE.toml\")"
    );
    let _ = writeln!(
        s,
        "# Layout of ROSS's BearingElement.save (ross/bearing_seal_element.py at {ROSS_COMMIT}):"
    );
    let _ = writeln!(
        s,
        "# one table of the constructor's arguments, coefficients as lists, SI (N/m, N*s/m, kg)."
    );
    let _ = writeln!(
        s,
        "# n = 0 is the rotor node: set it (or bearing.n) to where the bearing sits."
    );
    let _ = writeln!(
        s,
        "# x is rollbench's x (the radial load's direction), y across it, z the bearing axis;"
    );
    let _ = writeln!(
        s,
        "# ROSS's x is horizontal and y vertical: rotate if the radial load is not horizontal."
    );
    let _ = writeln!(s, "# {NO_DAMPING}.");
    if !k.dofs.contains(&Dof::Z) {
        let _ = writeln!(s, "# kzz = 0: the {} matrix has no axial row.", src.system);
    }
    let dropped: Vec<String> = (0..k.n())
        .flat_map(|i| (0..k.n()).map(move |j| (i, j)))
        .filter(|&(i, j)| {
            k.dofs[i].angular() || k.dofs[j].angular() || {
                let (a, b) = (k.dofs[i], k.dofs[j]);
                (a == Dof::Z) != (b == Dof::Z)
            }
        })
        .map(|(i, j)| {
            let (_, unit) = entry_unit(k, i, j, Units::Si);
            format!(
                "{}/{} = {:.6e} {unit}",
                k.dofs[i].row(),
                k.dofs[j].column(),
                k.get(i, j)
            )
        })
        .collect();
    if !dropped.is_empty() {
        let _ = writeln!(
            s,
            "# Not in ROSS's bearing element (translations only, no x-z coupling): the terms"
        );
        for chunk in dropped.chunks(3) {
            let _ = writeln!(s, "#   {}", chunk.join("; "));
        }
        let _ = writeln!(
            s,
            "# (rollbench stiffness DECK --export csv|json writes the whole matrix)."
        );
    }
    let tag = src.tag;
    let _ = writeln!(s, "\n[{}]", toml_string(&format!("BearingElement_{tag}")));
    let _ = writeln!(s, "n = 0");
    let _ = writeln!(s, "tag = {}", toml_string(tag));
    let _ = writeln!(s, "scale_factor = 1");
    let _ = writeln!(s, "color = \"#355d7a\"");
    for (name, a, b) in [
        ("kxx", Dof::X, Dof::X),
        ("kyy", Dof::Y, Dof::Y),
        ("kxy", Dof::X, Dof::Y),
        ("kyx", Dof::Y, Dof::X),
        ("kzz", Dof::Z, Dof::Z),
    ] {
        let _ = writeln!(s, "{name} = [{}]", toml_float(get(a, b))?);
    }
    for name in [
        "cxx", "cyy", "cxy", "cyx", "czz", "mxx", "myy", "mxy", "myx", "mzz",
    ] {
        let _ = writeln!(s, "{name} = [0.0]");
    }
    Ok(s)
}

/// One line per entry, `row,column,value,unit`, in `units`.
fn csv(k: &StiffnessMatrix, units: Units) -> String {
    let mut s = String::from("row,column,value,unit\n");
    for i in 0..k.n() {
        for j in 0..k.n() {
            let (f, unit) = entry_unit(k, i, j, units);
            let _ = writeln!(
                s,
                "{},{},{},{unit}",
                k.dofs[i].row(),
                k.dofs[j].column(),
                super::csv::csv_number(k.get(i, j) / f)
            );
        }
    }
    s
}

/// The matrix in `units` with each entry's unit, the damping said absent.
fn json_deck_units(k: &StiffnessMatrix, src: Source) -> Result<String, String> {
    let n = k.n();
    let matrix: Vec<Vec<f64>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| k.get(i, j) / entry_unit(k, i, j, src.units).0)
                .collect()
        })
        .collect();
    let units: Vec<Vec<String>> = (0..n)
        .map(|i| (0..n).map(|j| entry_unit(k, i, j, src.units).1).collect())
        .collect();
    let mut v = json!({
        "deck": src.tag,
        "system": src.system,
        "unit_system": match src.units { Units::Si => "SI", Units::Us => "US" },
        "rows": k.dofs.iter().map(|d| d.row()).collect::<Vec<_>>(),
        "columns": k.dofs.iter().map(|d| d.column()).collect::<Vec<_>>(),
        "stiffness": matrix,
        "units": units,
        "method": k.method.name(),
        "damping": Value::Null,
        "damping_note": NO_DAMPING,
    });
    if let (Some(o), Some(r)) = (v.as_object_mut(), &k.reference_point) {
        o.insert("reference_point".into(), json!(r));
    }
    serde_json::to_string_pretty(&v)
        .map(|s| s + "\n")
        .map_err(|e| format!("cannot write the JSON: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> StiffnessMatrix {
        // A made-up 5×5 with distinct entries (i+1)·10^(j+5)·(−1)^(i+j) and a value
        // whose shortest form has no '.' (2e8).
        let k: Vec<f64> = (0..25)
            .map(|n| {
                let (i, j) = (n / 5, n % 5);
                let s = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
                s * (i as f64 + 1.0) * 10f64.powi(j + 5) / 3.0
            })
            .collect();
        let mut m = StiffnessMatrix::new(Dof::ALL.to_vec(), k, Method::Analytic);
        m.k[0] = 2e8;
        m
    }

    fn src(units: Units) -> Source<'static> {
        Source {
            tag: "t",
            system: "angular-contact ball bearing",
            units,
        }
    }

    /// The ROSS table parses as TOML and holds K's x–y block and K_zz exactly (the
    /// shortest round-trip float form), every damping and mass term 0, and the tilt
    /// terms in its comments; ROSS's required arguments (n, kxx, cxx) are there.
    #[test]
    fn ross_table_holds_the_translations_exactly() {
        let k = sample();
        let text = export(&k, Export::Ross, src(Units::Si)).unwrap();
        let t: toml::Table = toml::from_str(&text).unwrap();
        let b = t["BearingElement_t"].as_table().unwrap();
        let one = |name: &str| {
            let a = b[name].as_array().unwrap();
            assert_eq!(a.len(), 1, "{name}");
            a[0].as_float().unwrap()
        };
        assert_eq!(one("kxx"), k.get(0, 0));
        assert_eq!(one("kyy"), k.get(1, 1));
        assert_eq!(one("kxy"), k.get(0, 1));
        assert_eq!(one("kyx"), k.get(1, 0));
        assert_eq!(one("kzz"), k.get(2, 2));
        for c in [
            "cxx", "cyy", "cxy", "cyx", "czz", "mxx", "myy", "mxy", "myx", "mzz",
        ] {
            assert_eq!(one(c), 0.0);
        }
        assert_eq!(b["n"].as_integer(), Some(0));
        assert!(text.contains("M_y/theta_y = "), "{text}");
        assert!(text.contains("F_x/z = "), "{text}");
        assert!(text.contains("no damping"), "{text}");
    }

    /// A matrix without a y row cannot be a ROSS element: refused with a sentence.
    #[test]
    fn ross_needs_y() {
        let k = StiffnessMatrix::new(
            vec![Dof::X, Dof::Z],
            vec![1.0, 0.0, 0.0, 2.0],
            Method::Analytic,
        );
        let e = export(&k, Export::Ross, src(Units::Si)).unwrap_err();
        assert!(e.contains("no y row") && e.contains("x, z"), "{e}");
    }

    /// CSV and JSON in US units divide by the independent factors lbf/in =
    /// 4.4482216152605/0.0254 N/m, lbf/rad, in·lbf/in = lbf, in·lbf/rad =
    /// 4.4482216152605·0.0254 N·m/rad, to 1e-12.
    #[test]
    fn csv_and_json_in_deck_units() {
        let k = sample();
        let lbf = 4.448_221_615_260_5;
        let inch = 0.0254;
        let factor = |i: usize, j: usize| match (i >= 3, j >= 3) {
            (false, false) => lbf / inch,
            (false, true) => lbf,
            (true, false) => lbf,
            (true, true) => lbf * inch,
        };
        let j: Value =
            serde_json::from_str(&export(&k, Export::Json, src(Units::Us)).unwrap()).unwrap();
        let csv = export(&k, Export::Csv, src(Units::Us)).unwrap();
        let lines: Vec<&str> = csv.lines().skip(1).collect();
        assert_eq!(lines.len(), 25);
        for i in 0..5 {
            for jj in 0..5 {
                let want = k.get(i, jj) / factor(i, jj);
                let got = j["stiffness"][i][jj].as_f64().unwrap();
                assert!(
                    (got - want).abs() <= 1e-12 * want.abs(),
                    "{i}{jj}: {got} {want}"
                );
                let cells: Vec<&str> = lines[i * 5 + jj].split(',').collect();
                assert_eq!(cells[0], Dof::ALL[i].row());
                assert_eq!(cells[1], Dof::ALL[jj].column());
                let c: f64 = cells[2].parse().unwrap();
                assert!((c - want).abs() <= 1e-12 * want.abs(), "{cells:?} {want}");
            }
        }
        assert_eq!(j["units"][0][0], "lbf/in");
        assert_eq!(j["units"][4][4], "in·lbf/rad");
        assert_eq!(j["damping"], Value::Null);
        assert_eq!(
            lines[0],
            format!(
                "F_x,x,{},lbf/in",
                super::super::csv::csv_number(2e8 / (lbf / inch))
            )
        );
    }

    /// The JSON `stiffness` object reads back to the matrix it came from, exactly.
    #[test]
    fn json_object_round_trip() {
        let k = sample();
        let back = matrix_from_json(&k.json()).unwrap();
        assert_eq!(back.dofs, k.dofs);
        assert_eq!(back.k, k.k);
    }
}
