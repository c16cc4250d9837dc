//! Unit systems of the deck and the one table of exact conversion factors.
//!
//! Physics works in SI throughout; deck values are converted here, at the boundary, and
//! nowhere else. Every factor is exact by definition (international inch, pound, BTU_IT).
#![warn(missing_docs)]

use std::fmt;
use std::str::FromStr;

/// 1 in in m (exact, international inch).
pub const INCH_M: f64 = 0.0254;
/// 1 ft in m (exact).
pub const FOOT_M: f64 = 0.3048;
/// 1 lbf in N (exact: 0.45359237 kg × 9.80665 m/s²).
pub const LBF_N: f64 = 4.448_221_615_260_5;
/// 1 psi in Pa (exact: lbf/in²).
pub const PSI_PA: f64 = 6_894.757_293_168_361;
/// 1 lbm in kg (exact).
pub const LBM_KG: f64 = 0.453_592_37;
/// 1 Btu (International Table) in J (exact).
pub const BTU_J: f64 = 1_055.055_852_62;
/// 1 °F (or °R) temperature difference in K (exact: 5/9).
pub const FAHRENHEIT_DEGREE_K: f64 = 5.0 / 9.0;
/// 1 K (or °C) temperature difference in °F (exact: 1.8). Kept as the literal, not
/// `1.0 / FAHRENHEIT_DEGREE_K`: the two differ in the last bit, and the thermal deck and
/// the reports convert with 1.8, so deriving it would change answers in the last digit.
pub const FAHRENHEIT_PER_KELVIN: f64 = 1.8;
/// 1 rpm in rad/s (exact: π/30).
pub const RPM_RAD_S: f64 = std::f64::consts::PI / 30.0;
/// 1 hour in s.
pub const HOUR_S: f64 = 3_600.0;
/// 1 in·lbf in N·m (exact: 0.0254 m × 4.448 221 615 260 5 N).
pub const INCH_LBF_N_M: f64 = INCH_M * LBF_N;
/// Btu/hr per watt (International Table Btu): 1 W = 3.412141633 Btu/hr. Kept as the
/// published 10-digit literal, not `HOUR_S / BTU_J` (= 3.412 141 633 128, 3.7e-11
/// relative above it): the reports have always used the literal, and deriving it would
/// change every Btu/hr in the last digits.
pub const BTU_PER_HOUR_PER_WATT: f64 = 3.412_141_633;
/// 0 °C in K.
pub const CELSIUS_ZERO_K: f64 = 273.15;

/// The unit system a deck is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Units {
    /// SI: m, N, Pa, rpm, Pa·s, kg, J/(kg·K), W/(m·K), °C, µm for surface finish.
    #[default]
    Si,
    /// US customary: in, lbf, psi, rpm, reyn, lbm, Btu/(lbm·°F), Btu/(hr·ft·°F), °F, µin for finish.
    Us,
}

impl Units {
    /// The deck spelling: `"si"` or `"us"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Units::Si => "si",
            Units::Us => "us",
        }
    }
}

impl fmt::Display for Units {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for Units {
    type Err = String;
    /// Parses `"si"` or `"us"` (case-insensitive).
    fn from_str(s: &str) -> Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "si" => Ok(Units::Si),
            "us" => Ok(Units::Us),
            other => Err(format!(
                "unknown unit system \"{other}\" (expected \"si\" or \"us\")"
            )),
        }
    }
}

/// A physical quantity as it appears in a deck: knows its unit in each system and the
/// factor to SI. Conversions are linear (v_SI = v·factor) except [`Quantity::Temperature`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Pure number (ratios, coefficients), same in both systems.
    Dimensionless,
    /// A count (rollers, laminae, iterations), same in both systems.
    Count,
    /// Length: in | m.
    Length,
    /// Surface finish (RMS): µin | µm, SI value in m.
    Roughness,
    /// Force: lbf | N.
    Force,
    /// Pressure, stress or modulus: psi | Pa.
    Pressure,
    /// Rotational speed: rpm in both systems, SI value in rad/s.
    Speed,
    /// Angle: degrees in both systems, SI value in rad.
    Angle,
    /// Absolute (dynamic) viscosity: reyn (lbf·s/in²) | Pa·s.
    Viscosity,
    /// Pressure-viscosity coefficient: in²/lbf | 1/Pa.
    PressureViscosity,
    /// Mass density: lbm/in³ | kg/m³.
    Density,
    /// Specific heat capacity: Btu/(lbm·°F) | J/(kg·K).
    SpecificHeat,
    /// Thermal conductivity: Btu/(hr·ft·°F) | W/(m·K).
    Conductivity,
    /// Mass: lbm | kg.
    Mass,
    /// Kinematic viscosity given in cSt in both systems, SI value in m²/s.
    KinematicViscosityCst,
    /// Volume flow given in litre/min in both systems, SI value in m³/s.
    VolumeFlowLMin,
    /// A coefficient per degree of temperature (viscosity–temperature β), given in 1/°C
    /// in both systems (= 1/K, the SI value).
    PerDegreeCelsius,
    /// Time in s in both systems (e.g. the lubricant parameter 1e11·η·α is in these units ×1e11).
    Time,
    /// Temperature: °F | °C, SI value in K (affine).
    Temperature,
    /// Moment (torque): in·lbf | N·m.
    Moment,
    /// Power (heat rate): Btu/hr | W.
    Power,
    /// Lineal stiffness: lbf/in | N/m.
    LinearStiffness,
    /// Angular stiffness: lbf·in/rad | N·m/rad.
    AngularStiffness,
}

impl Quantity {
    /// Multiplicative factor from one deck unit to SI (for temperature, the size of one degree in K).
    pub fn factor(self, units: Units) -> f64 {
        use Quantity::*;
        match (self, units) {
            (Dimensionless | Count | Time, _) => 1.0,
            (Speed, _) => RPM_RAD_S,
            (Angle, _) => std::f64::consts::PI / 180.0,
            (KinematicViscosityCst, _) => 1e-6,
            (VolumeFlowLMin, _) => 1e-3 / 60.0,
            (PerDegreeCelsius, _) => 1.0,
            (Temperature, Units::Si) => 1.0,
            (Temperature, Units::Us) => FAHRENHEIT_DEGREE_K,
            (_, Units::Si) => match self {
                Roughness => 1e-6,
                _ => 1.0,
            },
            (Length, Units::Us) => INCH_M,
            (Roughness, Units::Us) => 1e-6 * INCH_M,
            (Force, Units::Us) => LBF_N,
            (Pressure, Units::Us) => PSI_PA,
            (Viscosity, Units::Us) => PSI_PA,
            (PressureViscosity, Units::Us) => 1.0 / PSI_PA,
            (Density, Units::Us) => LBM_KG / (INCH_M * INCH_M * INCH_M),
            (SpecificHeat, Units::Us) => BTU_J / (LBM_KG * FAHRENHEIT_DEGREE_K),
            (Conductivity, Units::Us) => BTU_J / (HOUR_S * FOOT_M * FAHRENHEIT_DEGREE_K),
            (Mass, Units::Us) => LBM_KG,
            (Moment, Units::Us) => LBF_N * INCH_M,
            (Power, Units::Us) => BTU_J / HOUR_S,
            (LinearStiffness, Units::Us) => LBF_N / INCH_M,
            (AngularStiffness, Units::Us) => LBF_N * INCH_M,
        }
    }

    /// Converts a value written in `units` to SI.
    pub fn to_si(self, value: f64, units: Units) -> f64 {
        match (self, units) {
            (Quantity::Temperature, Units::Si) => value + CELSIUS_ZERO_K,
            (Quantity::Temperature, Units::Us) => {
                (value - 32.0) * FAHRENHEIT_DEGREE_K + CELSIUS_ZERO_K
            }
            _ => value * self.factor(units),
        }
    }

    /// Converts an SI value to the unit of `units` (inverse of [`Quantity::to_si`]).
    pub fn from_si(self, value_si: f64, units: Units) -> f64 {
        match (self, units) {
            (Quantity::Temperature, Units::Si) => value_si - CELSIUS_ZERO_K,
            (Quantity::Temperature, Units::Us) => {
                (value_si - CELSIUS_ZERO_K) / FAHRENHEIT_DEGREE_K + 32.0
            }
            _ => value_si / self.factor(units),
        }
    }

    /// Display string of the unit in `units` ("" for pure numbers). `const` so that the
    /// deck's static field table can use it.
    pub const fn unit(self, units: Units) -> &'static str {
        use Quantity::*;
        match (self, units) {
            (Dimensionless | Count, _) => "",
            (Speed, _) => "rpm",
            (Angle, _) => "deg",
            (KinematicViscosityCst, _) => "cSt",
            (VolumeFlowLMin, _) => "l/min",
            (PerDegreeCelsius, _) => "1/°C",
            (Time, _) => "s",
            (Length, Units::Si) => "m",
            (Length, Units::Us) => "in",
            (Roughness, Units::Si) => "µm",
            (Roughness, Units::Us) => "µin",
            (Force, Units::Si) => "N",
            (Force, Units::Us) => "lbf",
            (Pressure, Units::Si) => "Pa",
            (Pressure, Units::Us) => "psi",
            (Viscosity, Units::Si) => "Pa·s",
            (Viscosity, Units::Us) => "reyn",
            (PressureViscosity, Units::Si) => "1/Pa",
            (PressureViscosity, Units::Us) => "in²/lbf",
            (Density, Units::Si) => "kg/m³",
            (Density, Units::Us) => "lbm/in³",
            (SpecificHeat, Units::Si) => "J/(kg·K)",
            (SpecificHeat, Units::Us) => "Btu/(lbm·°F)",
            (Conductivity, Units::Si) => "W/(m·K)",
            (Conductivity, Units::Us) => "Btu/(hr·ft·°F)",
            (Mass, Units::Si) => "kg",
            (Mass, Units::Us) => "lbm",
            (Temperature, Units::Si) => "°C",
            (Temperature, Units::Us) => "°F",
            (Moment, Units::Si) => "N·m",
            (Moment, Units::Us) => "in·lbf",
            (Power, Units::Si) => "W",
            (Power, Units::Us) => "Btu/hr",
            (LinearStiffness, Units::Si) => "N/m",
            (LinearStiffness, Units::Us) => "lbf/in",
            (AngularStiffness, Units::Si) => "N·m/rad",
            (AngularStiffness, Units::Us) => "in·lbf/rad",
        }
    }
}

/// 1 US gallon in litres (exact: 231 in³).
pub const US_GALLON_L: f64 = 3.785_411_784;

/// A quantity that a deck writes in one unit in both systems although US customary
/// practice has its own (oil flow in l/min, the viscosity–temperature β in 1/°C): the
/// key's unit is a contract, so a US deck keeps the metric unit, and the screen says so
/// and gives the US value beside it (issue 30 item 7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UsCustomary {
    /// The unit a US deck shows, marked as the metric one it stays (`"l/min (SI)"`).
    pub label: &'static str,
    /// The US customary unit an engineer expects (`"gal/min"`).
    pub unit: &'static str,
    /// Factor from the deck's unit to [`UsCustomary::unit`].
    pub factor: f64,
}

impl Quantity {
    /// The US customary counterpart of a quantity written in a metric unit in every
    /// deck; `None` for the others (converted with the deck's units, or the same in both:
    /// rpm, degrees, cSt, s).
    pub fn us_customary(self) -> Option<UsCustomary> {
        match self {
            Quantity::VolumeFlowLMin => Some(UsCustomary {
                label: "l/min (SI)",
                unit: "gal/min",
                factor: 1.0 / US_GALLON_L,
            }),
            // A coefficient per degree: per °F is per °C times 5/9.
            Quantity::PerDegreeCelsius => Some(UsCustomary {
                label: "1/°C (SI)",
                unit: "1/°F",
                factor: FAHRENHEIT_DEGREE_K,
            }),
            _ => None,
        }
    }
}

/// Converts °F to °C.
pub fn fahrenheit_to_celsius(f: f64) -> f64 {
    (f - 32.0) * FAHRENHEIT_DEGREE_K
}

/// Converts °C to °F.
pub fn celsius_to_fahrenheit(c: f64) -> f64 {
    c / FAHRENHEIT_DEGREE_K + 32.0
}

/// The display units of a text report: (factor from SI, label) per quantity (SI: mm,
/// µm, N, MPa, N·m, W, kg; US: in, µin, lbf, ksi, in·lbf, Btu/hr, lbm).
#[derive(Debug, Clone, Copy)]
pub struct Disp {
    /// Lengths (mm, in).
    pub len: (f64, &'static str),
    /// Small lengths: films, deflections (µm, µin).
    pub small_len: (f64, &'static str),
    /// Forces (N, lbf).
    pub force: (f64, &'static str),
    /// Stresses (MPa, ksi).
    pub stress: (f64, &'static str),
    /// Moments (N·m, in·lbf).
    pub moment: (f64, &'static str),
    /// Powers (W, Btu/hr).
    pub power: (f64, &'static str),
    /// Masses (kg, lbm).
    pub mass: (f64, &'static str),
}

impl Disp {
    /// The conversion set of `units`.
    pub fn of(units: Units) -> Disp {
        match units {
            Units::Si => Disp {
                len: (1e3, "mm"),
                small_len: (1e6, "µm"),
                force: (1.0, "N"),
                stress: (1e-6, "MPa"),
                moment: (1.0, "N·m"),
                power: (1.0, "W"),
                mass: (1.0, "kg"),
            },
            Units::Us => Disp {
                len: (1.0 / INCH_M, "in"),
                small_len: (1e6 / INCH_M, "µin"),
                force: (1.0 / LBF_N, "lbf"),
                stress: (1.0 / PSI_PA * 1e-3, "ksi"),
                moment: (1.0 / INCH_LBF_N_M, "in·lbf"),
                power: (BTU_PER_HOUR_PER_WATT, "Btu/hr"),
                mass: (1.0 / LBM_KG, "lbm"),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ALL: [Quantity; 23] = [
        Quantity::LinearStiffness,
        Quantity::AngularStiffness,
        Quantity::Moment,
        Quantity::Power,
        Quantity::Dimensionless,
        Quantity::Count,
        Quantity::Length,
        Quantity::Roughness,
        Quantity::Force,
        Quantity::Pressure,
        Quantity::Speed,
        Quantity::Angle,
        Quantity::Viscosity,
        Quantity::PressureViscosity,
        Quantity::Density,
        Quantity::SpecificHeat,
        Quantity::Conductivity,
        Quantity::Mass,
        Quantity::KinematicViscosityCst,
        Quantity::VolumeFlowLMin,
        Quantity::PerDegreeCelsius,
        Quantity::Time,
        Quantity::Temperature,
    ];

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
    }

    /// SI → US → SI and US → SI → US are identities to 1e-12 relative (a few ulps of
    /// round-off from one multiply and one divide). For the affine temperature the
    /// error is measured against the offset size (~500 degrees), since adding and
    /// removing 273.15 costs ~1e-13 K absolute however small the value.
    #[test]
    fn round_trip_both_ways() {
        for q in ALL {
            let scale = if q == Quantity::Temperature {
                500.0
            } else {
                0.0
            };
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(scale);
            for v in [
                1e-9, 0.0127, 1.0, 3.3, 17_000.0, 6.5e-7, 2.9e11, -40.0, 300.0,
            ] {
                let us = q.from_si(v, Units::Us);
                assert!(close(q.to_si(us, Units::Us), v), "{q:?} {v}");
                let si = q.to_si(v, Units::Us);
                assert!(close(q.from_si(si, Units::Us), v), "{q:?} {v}");
                assert!(close(q.from_si(q.to_si(v, Units::Si), Units::Si), v));
            }
        }
    }

    /// Hand-checked numbers (textbook conversion values), 1e-9 relative because the
    /// reference values are quoted to ~10 significant digits.
    #[test]
    fn hand_checked_values() {
        let u = Units::Us;
        assert!(rel(Quantity::Length.to_si(3.3, u), 0.08382) < 1e-12);
        assert!(rel(Quantity::Force.to_si(1000.0, u), 4_448.221_615_260_5) < 1e-12);
        assert!(rel(Quantity::Pressure.to_si(29.0e6, u), 1.999_479_615e11) < 1e-9);
        // 1 Btu/(lbm·°F) = 4186.8 J/(kg·K) exactly (IT calorie definition).
        assert!(rel(Quantity::SpecificHeat.to_si(1.0, u), 4_186.8) < 1e-12);
        // 1 Btu/(hr·ft·°F) = 1.730 734 666 W/(m·K).
        assert!(rel(Quantity::Conductivity.to_si(1.0, u), 1.730_734_666) < 1e-9);
        // 1 lbm/in³ = 27 679.904 71 kg/m³.
        assert!(rel(Quantity::Density.to_si(1.0, u), 27_679.904_71) < 1e-9);
        // 1 reyn = 6894.757 Pa·s; 1 in²/lbf = 1.450 377 377e-4 1/Pa.
        assert!(rel(Quantity::Viscosity.to_si(1.0, u), 6_894.757_293_168_361) < 1e-12);
        assert!(rel(Quantity::PressureViscosity.to_si(1.0, u), 1.450_377_377e-4) < 1e-9);
        assert!(rel(Quantity::Roughness.to_si(4.0, u), 1.016e-7) < 1e-12);
        assert!(rel(Quantity::Speed.to_si(30.0, u), std::f64::consts::PI) < 1e-15);
        assert!(rel(Quantity::Temperature.to_si(212.0, u), 373.15) < 1e-12);
        assert!(rel(Quantity::Temperature.to_si(-40.0, Units::Si), 233.15) < 1e-12);
        assert!(rel(fahrenheit_to_celsius(-40.0), -40.0) < 1e-12);
        assert!(rel(celsius_to_fahrenheit(100.0), 212.0) < 1e-12);
        // The two literal (not derived) factors agree with their definitions.
        assert!(rel(FAHRENHEIT_PER_KELVIN, 1.0 / FAHRENHEIT_DEGREE_K) < 1e-15);
        assert!(rel(BTU_PER_HOUR_PER_WATT, HOUR_S / BTU_J) < 1e-10);
        assert!(rel(INCH_LBF_N_M, 0.112_984_829_027_616_7) < 1e-15);
        assert_eq!("US".parse::<Units>(), Ok(Units::Us));
        assert!("cgs".parse::<Units>().is_err());
    }
}

/// `text` with every SI quantity written as a number followed by one of the units `N`,
/// `N·m`, `Pa`, `m` restated in `units` (US: lbf, in·lbf, psi, in), keeping the number's
/// form (fixed decimals or scientific, as many digits). Solver messages are written in SI
/// deep inside the solver; a US deck's user reads them in US units (issue 15). SI text is
/// returned unchanged.
pub fn restate_si(text: &str, units: Units) -> String {
    if units == Units::Si {
        return text.to_string();
    }
    // (SI unit, factor to divide by, US unit), longest first so `N·m` wins over `N`.
    const TABLE: [(&str, f64, &str); 4] = [
        ("N·m", INCH_LBF_N_M, "in·lbf"),
        ("Pa", PSI_PA, "psi"),
        ("N", LBF_N, "lbf"),
        ("m", INCH_M, "in"),
    ];
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < chars.len() {
        // A number starts at a digit or a sign before a digit, not inside a word.
        let starts = |k: usize| {
            let c = chars[k];
            let prev_ok = k == 0 || !(chars[k - 1].is_alphanumeric() || chars[k - 1] == '_');
            prev_ok
                && (c.is_ascii_digit()
                    || (c == '-' && chars.get(k + 1).is_some_and(|d| d.is_ascii_digit())))
        };
        if !starts(i) {
            out.push(chars[i]);
            i += 1;
            continue;
        }
        let mut j = i + 1;
        while j < chars.len() {
            let c = chars[j];
            let exp_sign = (c == '-' || c == '+') && matches!(chars[j - 1], 'e' | 'E');
            if c.is_ascii_digit() || c == '.' || c == 'e' || c == 'E' || exp_sign {
                j += 1;
            } else {
                break;
            }
        }
        let number: String = chars[i..j].iter().collect();
        let rest: String = chars[j..].iter().collect();
        let unit = TABLE.iter().find(|(u, _, _)| {
            rest.strip_prefix(' ')
                .and_then(|r| r.strip_prefix(u))
                .is_some_and(|after| {
                    after
                        .chars()
                        .next()
                        .is_none_or(|c| !(c.is_alphanumeric() || c == '·' || c == '/' || c == '²'))
                })
        });
        match (number.parse::<f64>(), unit) {
            (Ok(v), Some(&(si, factor, us))) => {
                let x = v / factor;
                let formatted = match number.find(['e', 'E']) {
                    Some(e) => {
                        let decimals = number[..e].split_once('.').map_or(0, |(_, d)| d.len());
                        format!("{x:.decimals$e}")
                    }
                    None => {
                        let decimals = number.split_once('.').map_or(0, |(_, d)| d.len());
                        format!("{x:.decimals$}")
                    }
                };
                out.push_str(&formatted);
                out.push(' ');
                out.push_str(us);
                i = j + 1 + si.chars().count();
            }
            _ => {
                out.push_str(&number);
                i = j;
            }
        }
    }
    out
}

#[cfg(test)]
mod restate_tests {
    use super::*;

    /// The message: a US deck's solver failure read in lbf and in; words, rpm,
    /// degrees and keys are left alone; the number keeps its form.
    #[test]
    fn solver_messages_restated_in_us_units() {
        let si = "the rings moved 1.785e-2 m axially (more than D/2 = 6.350e-3 m) under F_r = 13344.7 N, F_a = 4448.2 N at contact angle 12.00 deg; residual 2.5e-3 N·m, 17000.0 rpm, 2.1e9 Pa, solver.max_roller_iterations 100 m2";
        let us = restate_si(si, Units::Us);
        assert_eq!(
            us,
            "the rings moved 7.028e-1 in axially (more than D/2 = 2.500e-1 in) under F_r = 3000.0 lbf, F_a = 1000.0 lbf at contact angle 12.00 deg; residual 2.2e-2 in·lbf, 17000.0 rpm, 3.0e5 psi, solver.max_roller_iterations 100 m2"
        );
        assert_eq!(restate_si(si, Units::Si), si);
    }
}
