//! The Summary pane's lines every system builds alike (issue 28): the lives of
//! [`IsoLife`] beside the load-distribution life, the largest friction mechanism, the
//! element where a maximum or minimum occurs. Each system's `answer` module picks its own
//! numbers; this module keeps their wording and JSON paths the same across systems.

use super::view::{AnswerLine, Display, ThermalResults};
use crate::physics::rating::IsoLife;

/// Section names, in the order the pane shows them.
pub const LIFE: &str = "Life";
/// Stresses, films and Λ.
pub const CONTACT: &str = "Contact";
/// Cage and element speeds, vibration.
pub const SPEEDS: &str = "Speeds";
/// Friction torque and power.
pub const FRICTION: &str = "Friction";
/// Temperatures.
pub const TEMPERATURE: &str = "Temperature";
/// Loaded elements, skidding.
pub const ELEMENTS: &str = "Elements";

/// Significant figures of lives (they span decades).
const LIFE_DIGITS: usize = 4;

/// ISO 281's lines of the Summary pane (basic L10, modified L10m, a_ISO), each absent
/// number with its reason from `iso.reasons`; shared by every system's life lines.
pub fn iso_lines(iso: &IsoLife) -> Vec<AnswerLine> {
    let why = |prefix: &str| -> String {
        iso.reasons
            .iter()
            .find(|r| r.starts_with(prefix))
            .or(iso.reasons.first())
            .cloned()
            .unwrap_or_else(|| "not computed".into())
    };
    vec![
        AnswerLine::number(
            LIFE,
            "L10 basic ISO 281",
            iso.basic_l10_mrev,
            Display::Mrev,
            LIFE_DIGITS,
            "/life/basic_l10_mrev",
            &why("ISO 281 P"),
        ),
        AnswerLine::number(
            LIFE,
            "L10m modified",
            iso.modified_l10_mrev,
            Display::Mrev,
            LIFE_DIGITS,
            "/life/modified_l10_mrev",
            &why("a_ISO"),
        ),
        AnswerLine::number(
            LIFE,
            "a_ISO",
            iso.a_iso,
            Display::Plain,
            3,
            "/life/a_iso",
            &why("a_ISO"),
        ),
    ]
}

/// The reference (load-distribution) life in Mrev and hours, ISO 281's basic and modified
/// lives and the static safety, from the `life` object every system writes
/// ([`crate::physics::rating::life_json`]).
pub fn life_lines(
    l10_bearing_mrev: Option<f64>,
    l10_bearing_h: Option<f64>,
    reference_why: &str,
    iso: &IsoLife,
) -> Vec<AnswerLine> {
    let mut out = vec![
        AnswerLine::number(
            LIFE,
            "L10 reference",
            l10_bearing_mrev,
            Display::Mrev,
            LIFE_DIGITS,
            "/life/l10_bearing_mrev",
            reference_why,
        ),
        AnswerLine::number(
            LIFE,
            "L10 reference",
            l10_bearing_h,
            Display::Hours,
            LIFE_DIGITS,
            "/life/l10_bearing_h",
            reference_why,
        ),
    ];
    out.extend(iso_lines(iso));
    out.push(AnswerLine::number(
        LIFE,
        "static safety s0",
        iso.static_safety,
        Display::Plain,
        2,
        "/life/static_safety",
        "no contact stress",
    ));
    out
}

/// The thermal network's hottest node at steady state, and, when the loss-of-oil transient
/// ran (the Thermal pane on screen, or `run`), the first node to reach its limit.
pub fn thermal_lines(th: &ThermalResults) -> Vec<AnswerLine> {
    let hottest = arg_max(th.steady.iter().map(|n| n.temperature_c));
    let mut out = vec![AnswerLine::number(
        TEMPERATURE,
        "hottest, steady",
        hottest.map(|h| h.1),
        Display::Temperature,
        1,
        "max /thermal/steady/nodes/*/temperature_c",
        "no node",
    )
    .at(hottest.and_then(|(i, _)| th.steady.get(i).map(|n| n.name.clone())))];
    if let Some(tr) = &th.transient {
        let first = arg_min(
            tr.nodes
                .iter()
                .map(|n| n.time_to_limit_s.unwrap_or(f64::NAN)),
        );
        out.push(
            AnswerLine::number(
                TEMPERATURE,
                "time to limit, no oil",
                first.map(|f| f.1),
                Display::Seconds,
                1,
                "min /thermal/transient/nodes/*/time_to_limit_s",
                "no node reaches its limit within the transient",
            )
            .at(first.and_then(|(i, _)| tr.nodes.get(i).map(|n| n.name.clone()))),
        );
    }
    out
}

/// The largest of named powers (W) as `name (P W, s %)` in SI; `None` when all are 0.
pub fn largest_mechanism(mechanisms: &[(&str, f64)]) -> Option<String> {
    let total: f64 = mechanisms.iter().map(|(_, w)| w).sum();
    let (name, w) = mechanisms
        .iter()
        .copied()
        .filter(|(_, w)| w.is_finite())
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    (total > 0.0 && w > 0.0).then(|| format!("{name}, {:.0} % of the loss", 100.0 * w / total))
}

/// The index and value of the largest of `values`, the first of equals (a symmetric load
/// zone names its first element); `None`: empty or all non-finite.
pub fn arg_max(values: impl IntoIterator<Item = f64>) -> Option<(usize, f64)> {
    values
        .into_iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite())
        .reduce(|a, b| if b.1 > a.1 { b } else { a })
}

/// The index and value of the smallest of `values`.
pub fn arg_min(values: impl IntoIterator<Item = f64>) -> Option<(usize, f64)> {
    values
        .into_iter()
        .enumerate()
        .filter(|(_, v)| v.is_finite())
        .min_by(|a, b| a.1.total_cmp(&b.1))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest mechanism is named with its share; ties keep one; nothing loaded
    /// names none.
    #[test]
    fn largest_mechanism_names_the_largest_share() {
        let m = [("inner", 1.0), ("outer", 3.0)];
        assert_eq!(
            largest_mechanism(&m).as_deref(),
            Some("outer, 75 % of the loss")
        );
        assert_eq!(largest_mechanism(&[("inner", 0.0)]), None);
        assert_eq!(arg_max([1.0, f64::NAN, 3.0, 2.0]), Some((2, 3.0)));
        assert_eq!(arg_max([3.0, 1.0, 3.0]), Some((0, 3.0)));
        assert_eq!(arg_min([1.0, 3.0, 1.0]), Some((0, 1.0)));
        assert_eq!(arg_min([1.0, f64::NAN, 3.0, 0.5]), Some((3, 0.5)));
        assert_eq!(arg_max(Vec::<f64>::new()), None);
    }
}
