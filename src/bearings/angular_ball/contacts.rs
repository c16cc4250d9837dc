//! Each contact's evaluation at its load and race-control kinematics: Hertz ellipse,
//! spin moment and heat (2-13), EHD film (4-10, 4-11) and the film temperature of ch. 6;
//! the film thermal data; and the rheology traction curve tabulated at the most loaded
//! rolling contact before the analysis proper. Apart from the driver (`analysis`) so that
//! the driver reads as the sequence of stages.

use super::error::BallError;
use super::geometry::BallGeometry;
use super::input::{BallInput, TractionPreset};
use super::load_conditions::{axial_condition, conditions};
use super::load_distribution;
use super::race_control::{spin_moment_nm, ContactKinematics};
use super::results::{ContactResult, RheologyContact};
use crate::numerics::cancel::Cancel;
use crate::physics::contact::point::{Axis, PointContact, Race};
use crate::physics::lubrication::film::FilmInputs;
use crate::physics::lubrication::film_point::PointFilmInputs;
use crate::physics::lubrication::rheology::{self, ContactStrip, FilmThermal};
use crate::physics::lubrication::rolling_resistance;
use crate::physics::lubrication::traction_curve::TractionCurve;
use std::borrow::Cow;

/// Film thermal data of ch. 6 from the deck: the oil of `[lubricant]`, the rings'
/// steel for both solids.
pub fn film_thermal(input: &BallInput) -> FilmThermal {
    let (l, r) = (&input.lubricant, &input.materials.rings);
    FilmThermal {
        oil_density_kg_m3: l.density_kg_m3,
        oil_specific_heat_j_kg_k: l.specific_heat_j_kg_k,
        oil_conductivity_w_m_k: l.conductivity_w_m_k,
        solid_density_kg_m3: r.density_kg_m3,
        solid_specific_heat_j_kg_k: r.specific_heat_j_kg_k,
        solid_conductivity_w_m_k: r.conductivity_w_m_k,
    }
}

/// (transverse, rolling) semi-axes of a Hertz contact, m.
pub(super) fn semi_axes(h: &PointContact) -> (f64, f64) {
    match h.major_axis {
        Axis::Transverse => (h.semi_major_m, h.semi_minor_m),
        Axis::Rolling => (h.semi_minor_m, h.semi_major_m),
    }
}

/// For `traction.curve = "rheology"`, the input with the curve tabulated (ch. 4: "the
/// traction curve … is better to be determined before performing bearing analysis"):
/// a first load solve with the Coulomb µ of `traction.mu` (friction enters the load
/// distribution only through a skidding ball's cap) finds the contacts; the curve is
/// computed (`rheology::traction_curve`) on the centre strip of the contact with the
/// highest Hertz pressure that has a film (p₀, rolling semi-axis b, central film 4-11,
/// rolling speed, oil at the supply temperature) and then used as a table by every
/// stage (load distribution's cap, spin heat, skid search, dynamics). Other curves: the
/// input unchanged.
pub fn resolve_traction<'a>(
    input: &'a BallInput,
    cancel: Cancel,
) -> Result<(Cow<'a, BallInput>, Option<RheologyContact>), BallError> {
    if input.traction.preset != TractionPreset::Rheology {
        return Ok((Cow::Borrowed(input), None));
    }
    let rheo = input.lubricant.rheology();
    rheo.validate()
        .map_err(|e| BallError::InvalidInput(format!("lubricant: {e}")))?;
    let mut first = input.clone();
    first.traction.preset = TractionPreset::Constant;
    let geom = BallGeometry::new(&first)?;
    let (axial, _) = axial_condition(&first, &geom, cancel)?;
    let load = load_distribution::solve(&geom, &conditions(&first, axial, 1.0), cancel)?;
    let lub = &input.lubricant;
    let mut best: Option<RheologyContact> = None;
    for (i, b) in load.balls.iter().enumerate() {
        for (race, c, k) in [
            (Race::Inner, &b.equilibrium.inner, &b.kinematics.inner),
            (Race::Outer, &b.equilibrium.outer, &b.kinematics.outer),
        ] {
            if !(c.load_n > 0.0 && k.rolling_speed_m_s > 0.0) {
                continue;
            }
            let name = if race == Race::Inner {
                "inner"
            } else {
                "outer"
            };
            let model = geom.contact(race, c.angle_rad)?;
            let h = model
                .solve(c.load_n)
                .map_err(|source| BallError::Contact { race: name, source })?;
            if best
                .as_ref()
                .is_some_and(|b| b.strip.max_pressure_pa >= h.max_pressure_pa)
            {
                continue;
            }
            let film = PointFilmInputs::from_contact(
                &model,
                c.load_n,
                lub.viscosity_pa_s,
                lub.pressure_viscosity_pa_inv,
                k.rolling_speed_m_s,
            )
            .central_film_thickness_m()
            .map_err(|e| BallError::InvalidInput(format!("rheology traction: film: {e}")))?;
            best = Some(RheologyContact {
                ball: i,
                race,
                strip: ContactStrip {
                    max_pressure_pa: h.max_pressure_pa,
                    semi_width_m: semi_axes(&h).1,
                    film_m: film,
                    rolling_speed_m_s: k.rolling_speed_m_s,
                    inlet_temperature_k: lub.supply_temperature_k,
                },
            });
        }
    }
    let Some(at) = best else {
        return Err(BallError::InvalidInput(
            "traction.curve = \"rheology\" needs a loaded, rolling contact (zero speed or no load: no film to tabulate the curve at)".into(),
        ));
    };
    let curve = rheology::traction_curve(&rheo, &film_thermal(input), &at.strip)
        .map_err(|e| BallError::InvalidInput(format!("rheology traction: {e}")))?;
    let TractionCurve::Table { points } = curve else {
        return Err(BallError::InvalidInput(
            "rheology traction: the tabulated curve is not a table".into(),
        ));
    };
    let mut out = input.clone();
    out.traction.tabulated = points;
    Ok((Cow::Owned(out), Some(at)))
}

pub(super) fn contact_result(
    input: &BallInput,
    geom: &BallGeometry,
    race: Race,
    load: &load_distribution::ContactLoad,
    kin: ContactKinematics,
) -> Result<ContactResult, BallError> {
    let name = match race {
        Race::Inner => "inner",
        Race::Outer => "outer",
    };
    let model = geom.contact(race, load.angle_rad)?;
    let hertz = model
        .solve(load.load_n)
        .map_err(|source| BallError::Contact { race: name, source })?;
    let e2 = model.shape().second_kind;
    let mu = input.traction.curve().max_mu();
    let ms = spin_moment_nm(mu, load.load_n, hertz.semi_major_m, e2);
    let lub = &input.lubricant;
    let film = PointFilmInputs::from_contact(
        &model,
        load.load_n,
        lub.viscosity_pa_s,
        lub.pressure_viscosity_pa_inv,
        kin.rolling_speed_m_s,
    );
    let ok = load.load_n > 0.0 && kin.rolling_speed_m_s > 0.0;
    let central = if ok {
        film.central_film_thickness_m().ok()
    } else {
        None
    };
    // Film temperature of the spinning contact (seed ch. 6, Figs. 6-16…6-18): 40 strips
    // across the transverse axis × 60 cells along the rolling one (within 2 % of a
    // 80 × 200 grid, `rheology` tests).
    let thermal = match central {
        Some(h) if h > 0.0 => {
            let (ax, bx) = semi_axes(&hertz);
            let t = rheology::spin_film_temperature(
                &film_thermal(input),
                &input.traction.curve(),
                ax,
                bx,
                hertz.max_pressure_pa,
                h,
                kin.rolling_speed_m_s,
                kin.spin_rad_s,
                40,
                60,
            )
            .map_err(|e| BallError::InvalidInput(format!("{name} film temperature: {e}")))?;
            Some(t)
        }
        _ => None,
    };
    // EHL rolling resistance by strips of the line fit over the ellipse's transverse
    // axis (issue 28 item 4; `rolling_resistance` module docs).
    let rolling_resistance_n = if ok {
        let (a_transverse, _) = semi_axes(&hertz);
        rolling_resistance::point_force_n(
            &FilmInputs {
                viscosity_pa_s: lub.viscosity_pa_s,
                pressure_viscosity_pa_inv: lub.pressure_viscosity_pa_inv,
                entrainment_speed_m_s: kin.rolling_speed_m_s,
                reduced_radius_m: film.reduced_radius_rolling_m,
                load_per_length_n_m: 0.0,
                effective_modulus_pa: film.effective_modulus_pa,
            },
            load.load_n,
            a_transverse,
        )
    } else {
        None
    };
    Ok(ContactResult {
        rolling_resistance_n,
        rolling_resistance_w: rolling_resistance_n.map_or(0.0, |f| {
            rolling_resistance::power_w(f, kin.rolling_speed_m_s)
        }),
        load_n: load.load_n,
        angle_rad: load.angle_rad,
        deflection_m: load.deflection_m,
        hertz,
        second_kind: e2,
        kinematics: kin,
        spin_moment_nm: ms,
        spin_heat_w: ms * kin.spin_rad_s.abs(),
        central_film_m: central,
        min_film_m: if ok {
            film.minimum_film_thickness_m().ok()
        } else {
            None
        },
        film_temperature_rise_k: thermal.map(|t| t.max_rise_k),
        surface_temperature_rise_k: thermal.map(|t| t.max_surface_rise_k),
    })
}
