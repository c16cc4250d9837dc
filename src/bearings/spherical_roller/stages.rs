//! Downstream stages of the SASHBEAN pipeline, each a function of the load distribution and
//! the contact geometry: stresses (§4), EHD film (§5), life (§6), internal speeds (§7),
//! sliding (§8) and heat (§9).

use serde::Serialize;

use super::contacts::{LaminaContact, RollerContacts};
use super::load_distribution::{DynamicSpeeds, LoadDistribution, RollerResult};
use crate::bearings::spherical_roller::{Bearing, Material};
use crate::physics::contact::line::{self, Elastic, LineContact};
use crate::physics::contact::subsurface::{self, SubsurfaceStress};
use crate::physics::heat::{self, HeatBreakdown};
use crate::physics::kinematics::{self, ContactPointPair, InternalSpeeds};
use crate::physics::life::{self, LifeInputs, LifeResult};
use crate::physics::lubrication::film::{self, FilmInputs};
use crate::physics::lubrication::traction::{self, TractionModel};

const RPM: f64 = 30.0 / std::f64::consts::PI;

fn elastic(m: &Material) -> Elastic {
    Elastic {
        youngs_modulus_pa: m.youngs_modulus_pa,
        poisson_ratio: m.poisson_ratio,
    }
}

/// E* of the roller against the inner and the outer ring, Pa.
fn reduced_moduli(b: &Bearing) -> [f64; 2] {
    let r = elastic(&b.materials.roller);
    [
        line::reduced_modulus(r, elastic(&b.materials.inner_ring)),
        line::reduced_modulus(r, elastic(&b.materials.outer_ring)),
    ]
}

// ---------------------------------------------------------------- §4 stresses

/// One raceway contact of one roller, seed 000 §4.1–4.5.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct RacewayStress {
    /// Max of the laminae's maximum Hertz pressure (edge laminae × the concentration factor), Pa.
    pub max_stress_pa: f64,
    /// Max of the laminae's mean pressure, Pa.
    pub mean_stress_pa: f64,
    /// §4.3 major axis: cumulative width of the loaded laminae, m.
    pub contact_major_axis_m: f64,
    /// §4.3 minor axis: contact width 2b at the most loaded lamina, m.
    pub contact_minor_axis_m: f64,
    /// §4.3 eccentricity: offset of the most loaded lamina from the roller mid-plane, m.
    pub eccentricity_m: f64,
    /// §4.4 maximum subsurface (principal, Tresca) shear stress, Pa — the report's "max shear".
    pub subsurface_shear_pa: f64,
    /// Depth of the maximum principal shear, m.
    pub subsurface_depth_m: f64,
    /// Maximum orthogonal shear τ₀ (Lundberg–Palmgren), Pa, and its depth, m.
    pub orthogonal_shear_pa: f64,
    pub orthogonal_depth_m: f64,
    /// Maximum von Mises stress on the axis, Pa, and its depth, m.
    pub von_mises_pa: f64,
    pub von_mises_depth_m: f64,
}

/// Hertz results of every lamina: `[inner, outer]`, with the edge factor applied to the
/// pressures of loaded edge laminae (§4.2: the seed multiplies the edge laminae's stresses
/// by the user's factor; the half-width is the plain Hertz one).
pub type LaminaHertz = Vec<[LineContact; 2]>;

/// §4 results.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Stresses {
    pub rollers: Vec<[RacewayStress; 2]>,
    pub laminae: Vec<LaminaHertz>,
}

/// §4: line-contact Hertz per lamina (eq. 4.1–4.3), edge factor (§4.2), ellipse (§4.3),
/// subsurface shear from the elastic field under the equivalent ellipse (§4.4).
pub fn stresses(b: &Bearing, ld: &LoadDistribution, contacts: &[RollerContacts]) -> Stresses {
    let e_star = reduced_moduli(b);
    let edge_factor = b.life.edge_stress_factor;
    let nu = [
        b.materials.inner_ring.poisson_ratio,
        b.materials.outer_ring.poisson_ratio,
    ];
    let mut rollers = Vec::with_capacity(contacts.len());
    let mut laminae: Vec<LaminaHertz> = Vec::with_capacity(contacts.len());
    for (j, rc) in contacts.iter().enumerate() {
        if let Some(i) = ld.mirror.get(j).copied().flatten() {
            // A mirrored roller: same state, same stresses.
            rollers.push(rollers[i]);
            laminae.push(laminae[i].clone());
            continue;
        }
        let lam: LaminaHertz = rc
            .iter()
            .map(|pair| {
                let mut out = [LineContact::default(); 2];
                for k in 0..2 {
                    let c = &pair[k];
                    if c.load_n > 0.0 && c.width_m > 0.0 {
                        let mut lc = line::line_contact_reduced(
                            c.line_load_n_m(),
                            c.reduced_radius_m,
                            e_star[k],
                        );
                        if c.edge {
                            lc.max_pressure_pa *= edge_factor;
                            lc.mean_pressure_pa *= edge_factor;
                        }
                        out[k] = lc;
                    }
                }
                out
            })
            .collect();
        let mut summary = [RacewayStress::default(); 2];
        for k in 0..2 {
            let loaded: Vec<usize> = (0..rc.len()).filter(|&i| rc[i][k].load_n > 0.0).collect();
            // The most loaded lamina (highest line load) as §4.5 picked it.
            let r = &ld.rollers[j];
            let Some(imax) = (if k == 0 {
                r.inner.max_lamina
            } else {
                r.outer.max_lamina
            }) else {
                continue;
            };
            let major: f64 = loaded.iter().map(|&i| rc[i][k].width_m).sum();
            let half_b = lam[imax][k].half_width_m;
            let p_max = loaded
                .iter()
                .map(|&i| lam[i][k].max_pressure_pa)
                .fold(0.0, f64::max);
            let p_mean = loaded
                .iter()
                .map(|&i| lam[i][k].mean_pressure_pa)
                .fold(0.0, f64::max);
            // The equivalent ellipse: semi-axes ½·major and b at the most loaded lamina; its
            // peak pressure is the most loaded lamina's (the roller's "max of max").
            let sub: SubsurfaceStress =
                subsurface::subsurface_stress(p_max, 0.5 * major, half_b, nu[k]);
            summary[k] = RacewayStress {
                max_stress_pa: p_max,
                mean_stress_pa: p_mean,
                contact_major_axis_m: major,
                contact_minor_axis_m: 2.0 * half_b,
                eccentricity_m: ld.rollers[j].laminae[imax].offset_m,
                subsurface_shear_pa: sub.principal_shear_pa,
                subsurface_depth_m: sub.principal_shear_depth_m,
                orthogonal_shear_pa: sub.orthogonal_shear_pa,
                orthogonal_depth_m: sub.orthogonal_shear_depth_m,
                von_mises_pa: sub.von_mises_pa,
                von_mises_depth_m: sub.von_mises_depth_m,
            };
        }
        rollers.push(summary);
        laminae.push(lam);
    }
    Stresses { rollers, laminae }
}

// ---------------------------------------------------------------- §7 speeds

/// Internal speeds (seed 000 §7, App. C).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Speeds {
    pub inner_rpm: f64,
    pub outer_rpm: f64,
    /// Cage speed from §7 at the final equilibrium, rpm.
    pub cage_rpm: f64,
    /// App. C's first estimate, rpm.
    pub cage_rpm_estimate: f64,
    /// Roller spin relative to the cage per roller, rpm (§7.2; App. C's value for a roller
    /// touching neither raceway).
    pub spin_rpm: Vec<f64>,
    /// App. C's roller spin estimate, rpm.
    pub spin_rpm_estimate: f64,
    /// Number of rollers loaded at both raceways (Z_eff, eq. 7.7).
    pub controlling_rollers: usize,
    /// Which speeds set the dynamic loads of the reported load distribution.
    pub dynamic_loads: crate::bearings::spherical_roller::DynamicLoads,
    /// Dynamic-load iterations (1 = App. C only).
    pub iterations: usize,
    /// Relative difference of §7's cage speed from App. C's estimate.
    pub cage_difference: f64,
}

/// §7's most heavily loaded contact points of each roller: at the most loaded lamina (the
/// highest line load), moved to the peak of the line load between its neighbours
/// ([`kinematics::load_peak`]).
pub fn contact_pairs(ld: &LoadDistribution, contacts: &[RollerContacts]) -> Vec<ContactPointPair> {
    ld.rollers
        .iter()
        .zip(contacts)
        .map(|(r, rc)| ContactPointPair {
            inner: r.inner.max_lamina.map(|i| contact_point(r, rc, 0, i)),
            outer: r.outer.max_lamina.map(|i| contact_point(r, rc, 1, i)),
        })
        .collect()
}

/// §7's point A of raceway `k` (0 inner, 1 outer) of roller `r` whose most loaded lamina is
/// `i`: (radius from the bearing axis, radius from the roller axis), m, at the peak of the
/// line load between that lamina and its neighbours, or at the lamina centre when there is
/// no interior peak (an end lamina, an unloaded neighbour, a flat or convex profile).
fn contact_point(r: &RollerResult, rc: &RollerContacts, k: usize, i: usize) -> (f64, f64) {
    let c: &LaminaContact = &rc[i][k];
    let at_centre = (c.ring_axis_distance_m, c.roller_axis_distance_m);
    if i == 0 || i + 1 >= rc.len().min(r.laminae.len()) {
        return at_centre;
    }
    let three = [i - 1, i, i + 1];
    let x = three.map(|n| r.laminae[n].offset_m);
    let q = three.map(|n| rc[n][k].line_load_n_m());
    let half = 0.5 * r.laminae[i].width_m;
    match kinematics::load_peak(x, q, x[1] - half, x[1] + half) {
        Some((_, w)) => {
            let mix = |f: fn(&LaminaContact) -> f64| {
                (0..3).map(|n| w[n] * f(&rc[three[n]][k])).sum::<f64>()
            };
            (
                mix(|c| c.ring_axis_distance_m),
                mix(|c| c.roller_axis_distance_m),
            )
        }
        None => at_centre,
    }
}

/// App. C's cage speed and roller spin (eq. C.1–C.2), rad/s.
fn app_c_speeds(b: &Bearing) -> (f64, f64) {
    let s = DynamicSpeeds::app_c_estimate(b);
    (s.cage_rad_s, s.roller_spin_rad_s)
}

/// §7 speeds at the equilibrium; falls back to App. C when no roller touches both raceways
/// (e.g. zero load at zero speed), and says so through `controlling_rollers = 0`.
pub fn internal_speeds(
    b: &Bearing,
    ld: &LoadDistribution,
    contacts: &[RollerContacts],
) -> InternalSpeeds {
    let (w1, w2) = (b.operating.inner_speed_rad_s, b.operating.outer_speed_rad_s);
    let (est_cage, est_spin) = app_c_speeds(b);
    let pairs = contact_pairs(ld, contacts);
    match kinematics::internal_speeds(w1, w2, b.geometry.pitch_diameter_m, &pairs) {
        Ok(s) => s,
        Err(_) => InternalSpeeds {
            cage_speed_rad_s: est_cage,
            controlling_rollers: 0,
            roller_spin_rad_s: vec![Some(est_spin); pairs.len()],
        },
    }
}

/// Build the report struct of the speeds.
pub fn speeds_report(b: &Bearing, s: &InternalSpeeds, iterations: usize) -> Speeds {
    let (w1, w2) = (b.operating.inner_speed_rad_s, b.operating.outer_speed_rad_s);
    let (est_cage, est_spin) = app_c_speeds(b);
    Speeds {
        inner_rpm: w1 * RPM,
        outer_rpm: w2 * RPM,
        cage_rpm: s.cage_speed_rad_s * RPM,
        cage_rpm_estimate: est_cage * RPM,
        spin_rpm: s
            .roller_spin_rad_s
            .iter()
            .map(|x| x.unwrap_or(est_spin) * RPM)
            .collect(),
        spin_rpm_estimate: est_spin * RPM,
        controlling_rollers: s.controlling_rollers,
        dynamic_loads: b.solver.dynamic_loads,
        iterations,
        cage_difference: if est_cage.abs() > 0.0 {
            s.cage_speed_rad_s / est_cage - 1.0
        } else {
            0.0
        },
    }
}

/// Spins per roller with App. C's value where §7 leaves it undetermined, rad/s.
fn spins(b: &Bearing, s: &InternalSpeeds) -> Vec<f64> {
    let (_, est) = app_c_speeds(b);
    s.roller_spin_rad_s
        .iter()
        .map(|x| x.unwrap_or(est))
        .collect()
}

// ---------------------------------------------------------------- §5 film

/// §5 results: film per lamina and raceway (None where unloaded), Λ per raceway.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Films {
    pub laminae: Vec<Vec<[Option<f64>; 2]>>,
    /// Thinnest film of each roller at each raceway, m.
    pub min_film: Vec<[Option<f64>; 2]>,
    /// Λ of eq. 6.8 from the thinnest film of each raceway (0 when no lamina is loaded).
    pub lambda_inner: f64,
    pub lambda_outer: f64,
}

/// Entrainment speed ½(u_ring + u_roller) of a lamina contact in the cage frame, m/s.
fn entrainment(ring_rel: f64, spin: f64, c: &LaminaContact) -> f64 {
    0.5 * ((ring_rel * c.ring_axis_distance_m).abs() + (spin * c.roller_axis_distance_m).abs())
}

/// §5: film per loaded lamina (eq. 5.1–5.3 or the selected alternative), Λ (eq. 6.7–6.8).
pub fn films(b: &Bearing, contacts: &[RollerContacts], speeds: &InternalSpeeds) -> Films {
    let e_star = reduced_moduli(b);
    let spin = spins(b, speeds);
    let rel = [
        b.operating.inner_speed_rad_s - speeds.cage_speed_rad_s,
        b.operating.outer_speed_rad_s - speeds.cage_speed_rad_s,
    ];
    let lub = &b.lubricant;
    let mut laminae = Vec::with_capacity(contacts.len());
    let mut min_film = Vec::with_capacity(contacts.len());
    let mut hmin = [f64::INFINITY; 2];
    for (j, rc) in contacts.iter().enumerate() {
        let mut rmin = [None::<f64>; 2];
        let lam: Vec<[Option<f64>; 2]> = rc
            .iter()
            .map(|pair| {
                let mut out = [None; 2];
                for k in 0..2 {
                    let c = &pair[k];
                    if c.load_n <= 0.0 {
                        continue;
                    }
                    let inputs = FilmInputs {
                        viscosity_pa_s: lub.viscosity_pa_s,
                        pressure_viscosity_pa_inv: lub.pressure_viscosity_pa_inv,
                        entrainment_speed_m_s: entrainment(rel[k], spin[j], c),
                        reduced_radius_m: c.reduced_radius_m,
                        load_per_length_n_m: c.load_n / c.width_m,
                        effective_modulus_pa: 2.0 * e_star[k],
                    };
                    out[k] = film::min_film(lub.film_model, &inputs);
                    if let Some(h) = out[k] {
                        rmin[k] = Some(rmin[k].map_or(h, |m: f64| m.min(h)));
                        hmin[k] = hmin[k].min(h);
                    }
                }
                out
            })
            .collect();
        laminae.push(lam);
        min_film.push(rmin);
    }
    let s = &b.surfaces;
    let lambda = |h: f64, race: f64| {
        if h.is_finite() {
            film::film_parameter(h, s.roller_rms_m, race)
        } else {
            0.0
        }
    };
    Films {
        laminae,
        min_film,
        lambda_inner: lambda(hmin[0], s.inner_rms_m),
        lambda_outer: lambda(hmin[1], s.outer_rms_m),
    }
}

// ---------------------------------------------------------------- §6 life

/// §6 results plus the equivalent roller loads.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Life {
    pub result: LifeResult,
    /// P_e per roller, `[inner, outer]`, N (eq. 6.1).
    pub equivalent_loads_n: Vec<[f64; 2]>,
}

/// ISO 281 dynamic equivalent load of a single-row radial roller bearing, N:
/// P = F_r for α = 0; otherwise X = 1, Y = 0 when F_a/F_r ≤ e = 1.5·tan α, else X = 0.4,
/// Y = 0.4·cot α (ISO 281:2007 §7.2.2). Used only for a_ISO's e_C·C_u/P.
pub fn iso_equivalent_load(b: &Bearing) -> f64 {
    let (fr, fa) = (
        b.operating.radial_load_n.abs(),
        b.operating.axial_load_n.abs(),
    );
    let a = b.geometry.contact_angle_rad;
    if a <= 0.0 || fa <= 1.5 * a.tan() * fr {
        fr.max(if a > 0.0 { 0.0 } else { fa })
    } else {
        0.4 * fr + 0.4 / a.tan() * fa
    }
}

/// Eq. 6.1 for laminae of any widths w_l: P_e = L^(7/9)·[Σ w_l·(Q_l/w_l)^4.5]^(2/9) with
/// L = Σ w_l — the product law over line-load slices. For equal widths it is exactly
/// eq. 6.1's Γ^(7/9)·(Σ Q_l^4.5)^(2/9) (the library's [`life::equivalent_roller_load`]).
pub fn equivalent_load(loads_n: &[f64], widths_m: &[f64]) -> f64 {
    life::equivalent_roller_load_widths(loads_n, widths_m)
}

/// §6: equivalent loads (eq. 6.1), capacities, mean loads, L-10 (eq. 6.2–6.6), adjustments.
pub fn life(b: &Bearing, ld: &LoadDistribution, films: &Films) -> Life {
    let eq: Vec<[f64; 2]> = ld
        .rollers
        .iter()
        .map(|r| {
            let w: Vec<f64> = r.laminae.iter().map(|l| l.width_m).collect();
            let qi: Vec<f64> = r.laminae.iter().map(|l| l.inner_load_n).collect();
            let qo: Vec<f64> = r.laminae.iter().map(|l| l.outer_load_n).collect();
            [equivalent_load(&qi, &w), equivalent_load(&qo, &w)]
        })
        .collect();
    let inner: Vec<f64> = eq.iter().map(|e| e[0]).collect();
    let outer: Vec<f64> = eq.iter().map(|e| e[1]).collect();
    let (w1, w2) = (b.operating.inner_speed_rad_s, b.operating.outer_speed_rad_s);
    let result = life::bearing_life(&LifeInputs {
        inner_equivalent_loads_n: &inner,
        outer_equivalent_loads_n: &outer,
        geometry: b.geometry.capacity_geometry(),
        rotating: life::rotating_raceway(w1, w2),
        relative_speed_rad_s: (w1 - w2).abs(),
        lambda_inner: films.lambda_inner,
        lambda_outer: films.lambda_outer,
        factors: b.life,
        kinematic_viscosity_m2_s: heat::kinematic_viscosity_m2_s(&b.lubricant),
        iso_equivalent_load_n: iso_equivalent_load(b),
    });
    Life {
        result,
        equivalent_loads_n: eq,
    }
}

// ---------------------------------------------------------------- §8–9 sliding and heat

/// Sliding, traction and heat of one lamina contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct LaminaFriction {
    /// Raceway minus roller surface velocity in the rolling direction, m/s (§8).
    pub sliding_m_s: f64,
    /// Traction force on the roller along the sliding direction, N (§9.1–9.2).
    pub traction_n: f64,
    /// Heat = |traction × sliding|, W.
    pub heat_w: f64,
}

/// §8–9 results.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Friction {
    pub laminae: Vec<Vec<[LaminaFriction; 2]>>,
    /// Contact heat per roller, `[inner, outer]`, W.
    pub roller_heat_w: Vec<[f64; 2]>,
    pub heat: HeatBreakdown,
    /// Whether the lost-lubrication traction (constant coefficient) was used.
    pub lost_lubrication: bool,
}

/// §9's heat by mechanism from the contact heat at the inner and outer raceways (W) and
/// the cage: rail friction (eq. 9.3–9.4) and viscous drag, at §7's cage speed.
fn heat_breakdown(
    b: &Bearing,
    contact_w: [f64; 2],
    speeds: &InternalSpeeds,
) -> Result<HeatBreakdown, crate::bearings::SolveError> {
    let ring_w = [b.operating.inner_speed_rad_s, b.operating.outer_speed_rad_s];
    let lub = &b.lubricant;
    let wc = speeds.cage_speed_rad_s;
    let cage = heat::cage_rail_power_for(&b.cage, lub.viscosity_pa_s, ring_w[0], ring_w[1], wc)
        .map_err(|e| crate::bearings::SolveError::Stage {
            stage: "cage rail heat (eq. 9.3-9.4)",
            message: e.to_string(),
        })?;
    let drag = heat::viscous_drag_power_w(
        b.cage.drag_factor,
        heat::kinematic_viscosity_m2_s(lub),
        ring_w[0] - ring_w[1],
        b.geometry.pitch_diameter_m,
    );
    Ok(HeatBreakdown::new(
        contact_w[0],
        contact_w[1],
        cage,
        drag,
        ring_w[0],
        ring_w[1],
    ))
}

/// `fr` with its heat breakdown re-derived for `b`'s cage: the lamina traction and contact
/// heat do not depend on the cage, so a cage edit needs only this (the pipeline's cache).
pub fn with_cage(
    b: &Bearing,
    fr: &Friction,
    speeds: &InternalSpeeds,
) -> Result<Friction, crate::bearings::SolveError> {
    let contact_w = fr
        .roller_heat_w
        .iter()
        .fold([0.0; 2], |t, r| [t[0] + r[0], t[1] + r[1]]);
    Ok(Friction {
        heat: heat_breakdown(b, contact_w, speeds)?,
        ..fr.clone()
    })
}

/// §8 sliding at every lamina contact and §9 heat by mechanism. `lost_lubrication` selects
/// the constant-coefficient traction of §9.2's last paragraph.
pub fn friction(
    b: &Bearing,
    ld: &LoadDistribution,
    contacts: &[RollerContacts],
    stresses: &Stresses,
    films: &Films,
    speeds: &InternalSpeeds,
    lost_lubrication: bool,
) -> Result<Friction, crate::bearings::SolveError> {
    let spin = spins(b, speeds);
    let wc = speeds.cage_speed_rad_s;
    let ring_w = [b.operating.inner_speed_rad_s, b.operating.outer_speed_rad_s];
    // The law's constants once for every lamina (issue 31).
    let law = if lost_lubrication {
        TractionModel::lost_lubrication(&b.lubricant)
    } else {
        TractionModel::ehd(&b.lubricant)
    }
    .prepared();
    let beta = b.geometry.contact_angle_rad;
    let mut laminae: Vec<Vec<[LaminaFriction; 2]>> = Vec::with_capacity(contacts.len());
    let mut roller_heat: Vec<[f64; 2]> = Vec::with_capacity(contacts.len());
    let mut totals = [0.0f64; 2];
    for (j, (r, rc)) in ld.rollers.iter().zip(contacts).enumerate() {
        if let Some(i) = ld.mirror.get(j).copied().flatten() {
            // A mirrored roller: same state, same sliding and heat.
            let rh: [f64; 2] = roller_heat[i];
            totals[0] += rh[0];
            totals[1] += rh[1];
            roller_heat.push(rh);
            laminae.push(laminae[i].clone());
            continue;
        }
        let (s, c) = r.tilt_rad.sin_cos();
        let a0 = [beta.cos(), -beta.sin()];
        let axis = [c * a0[0] - s * a0[1], s * a0[0] + c * a0[1], 0.0];
        let centre = [
            r.axial_displacement_m,
            r.radial_displacement_m + 0.5 * b.geometry.pitch_diameter_m,
            0.0,
        ];
        let mut rh = [0.0f64; 2];
        let lam: Vec<[LaminaFriction; 2]> = r
            .laminae
            .iter()
            .enumerate()
            .map(|(i, l)| {
                let mut out = [LaminaFriction::default(); 2];
                for k in 0..2 {
                    let pt = if k == 0 {
                        l.inner_point_m
                    } else {
                        l.outer_point_m
                    };
                    let v = kinematics::sliding_velocity(
                        [pt[0], pt[1], 0.0],
                        ring_w[k],
                        wc,
                        centre,
                        axis,
                        spin[j],
                    );
                    out[k].sliding_m_s = v;
                    let contact = &rc[i][k];
                    if contact.load_n <= 0.0 {
                        continue;
                    }
                    let hz = &stresses.laminae[j][i][k];
                    let t = law.lamina_traction(
                        &traction::HertzStrip {
                            load_n: contact.load_n,
                            half_width_m: hz.half_width_m,
                            width_m: contact.width_m,
                        },
                        v,
                        films.laminae[j][i][k].unwrap_or(0.0),
                    );
                    out[k].traction_n = t.force_n;
                    out[k].heat_w = t.heat_w;
                    rh[k] += t.heat_w;
                }
                out
            })
            .collect();
        totals[0] += rh[0];
        totals[1] += rh[1];
        roller_heat.push(rh);
        laminae.push(lam);
    }
    let heat = heat_breakdown(b, totals, speeds)?;
    Ok(Friction {
        laminae,
        roller_heat_w: roller_heat,
        heat,
        lost_lubrication,
    })
}

#[cfg(test)]
#[path = "stages_tests.rs"]
mod tests;
