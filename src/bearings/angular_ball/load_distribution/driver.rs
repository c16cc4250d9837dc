//! The load distribution's iteration: the fixed point between the ring solve
//! (`problem`) and race-control kinematics, stiffness and the friction of 2-7
//! ([`solve_warm`]), the continuation from rest when Newton from the unloaded geometry
//! fails ([`solve_recorded`]), and the solved distribution assembled with each ball's
//! race control ([`finish`]). Apart from the Newton systems it drives (`ball`,
//! `problem`) and the results (`load_distribution`).

use nalgebra::{Vector2, Vector3};

use super::ball::{reason, BallEquilibrium, BallParams, OuterAlone};
use super::problem::{inner_centre_radius, Layout, RingProblem, Tilt};
use super::{Axial, BallLoad, Conditions, LoadDistribution, LoadStats, LoadStep};
use crate::bearings::angular_ball::error::BallError;
use crate::bearings::angular_ball::geometry::BallGeometry;
use crate::bearings::angular_ball::input::{FrictionSplit, GyroscopicFriction, RaceControl};
use crate::bearings::angular_ball::race_control::{
    controlling_race, race_control, KinematicsInput,
};
use crate::numerics::cancel::Cancel;
use crate::numerics::newton::{Backtracking, Newton, Termination, TrustRegion};
use crate::physics::contact::point::{HertzPointContact, Race};

/// A first axial displacement for a force-held ring: the approach that puts F_a/(Z sin α₀)
/// on each ball (or F_a/Z at α₀ = 0), turned into δ_a through the geometry.
fn axial_guess(geom: &BallGeometry, fa: f64, stiff: (f64, f64)) -> f64 {
    let z = geom.ball_count as f64;
    let a0 = geom.free_contact_angle_rad;
    let q = (fa.abs() / (z * a0.sin().max(0.1))).max(1e-3);
    let total = (q / stiff.0).powf(2.0 / 3.0) + (q / stiff.1).powf(2.0 / 3.0);
    let a = geom.centre_distance_m;
    let ac = a * a0.cos();
    ((a + total).powi(2) - ac * ac).sqrt() - a * a0.sin()
}

/// A first ring displacement for a pure radial load with the axial force held at zero
/// (issue 29): the inner groove centres moved axially onto the outer ones' plane
/// (δ_a = −A sin α₀, where the grooves face each other and a radial load gives no axial
/// force but through the friction), and radially through the play P_d/2 = A(1 − cos α₀)
/// plus the Hertz approach of both contacts in series under Stribeck's largest ball load
/// 5F_r/Z. From the unloaded geometry (δ = 0) no ball is loaded, the ring Jacobian is
/// zero and Newton has no direction; nor can the continuation from rest start, for at
/// rest with neither load the ring's place is not determined.
fn radial_guess(geom: &BallGeometry, fr: f64, stiff: (f64, f64)) -> Vector2<f64> {
    let z = geom.ball_count as f64;
    let a0 = geom.free_contact_angle_rad;
    let a = geom.centre_distance_m;
    let q = (5.0 * fr.abs() / z).max(1e-3);
    let total = (q / stiff.0).powf(2.0 / 3.0) + (q / stiff.1).powf(2.0 / 3.0);
    Vector2::new(-a * a0.sin(), (a * (1.0 - a0.cos()) + total).copysign(fr))
}

/// The inner contact angle race control (2-9) is given for a ball: its own, but for a
/// ball the inner race does not touch (`inner_load_n` = 0) whose inner line of centres
/// has turned more than 135° from the outer contact's (the phantom side of the torus, see
/// `ball::ContactLoad::new`). That happens under a pure radial
/// load with a large play (issue 29: Bearing B's 60° play centred, F_a = 0): opposite the
/// load the inner groove centre passes radially inside the outer one, the open inner line
/// points at ~180°, and 2-9 with the two contact normals parallel is singular. Such a
/// ball rolls on the outer race alone; its kinematics take the outer line for both
/// (α_i = α_o). Every ball the inner race loads keeps its own angle, and so does an open
/// one within 135° (Bearing B force-held under 500 N radial has open inner lines at ~91°
/// whose kinematics solved before), so no answer that solved before moves.
fn kinematic_inner_angle(inner_rad: f64, outer_rad: f64, inner_load_n: f64) -> f64 {
    if inner_load_n == 0.0 && (inner_rad - outer_rad).abs() > 0.75 * std::f64::consts::PI {
        outer_rad
    } else {
        inner_rad
    }
}

/// The state a load solve starts from and leaves: ring displacement, ball positions,
/// contact angles, loads and ball-centre radii (for warm starts along a continuation).
#[derive(Debug, Clone, PartialEq)]
struct Warm {
    x: Vector2<f64>,
    /// φ = θ·ℜ_i, m.
    phi: f64,
    balls: Vec<Option<Vector2<f64>>>,
    angles: Vec<(f64, f64)>,
    loads: Vec<(f64, f64)>,
    radii: Vec<f64>,
}

/// `mirror`: solve the balls at ψ ≤ π only under a radial load ([`Layout`]); always true
/// but in the test that proves it exact.
pub(super) fn solve_recorded(
    geom: &BallGeometry,
    cond: &Conditions,
    cancel: Cancel,
    trace: &mut Option<(usize, Vec<LoadStep>)>,
    mirror: bool,
) -> Result<LoadDistribution, BallError> {
    let first = match solve_warm(geom, cond, cancel, None, trace, mirror) {
        Ok((l, _)) => return Ok(l),
        Err(
            e @ (BallError::Cancelled
            | BallError::InvalidInput(_)
            | BallError::Contact { .. }
            | BallError::SingularKinematics { .. }),
        ) => return Err(e),
        Err(e) => e,
    };
    // With the axial force held at zero the radial load alone places the ring (a rest
    // solve without it has no answer): only the speed is raised then.
    let radial_scaled = cond.axial != Axial::Force(0.0);
    let at = |s: f64| Conditions {
        inner_speed_rad_s: cond.inner_speed_rad_s * s,
        outer_speed_rad_s: cond.outer_speed_rad_s * s,
        radial_load_n: if radial_scaled {
            cond.radial_load_n * s
        } else {
            cond.radial_load_n
        },
        tilt: match cond.tilt {
            Tilt::Moment(m) => Tilt::Moment(m * s),
            t => t,
        },
        ..*cond
    };
    // Rest, axial load only (axisymmetric; the radial load too when F_a = 0); then the
    // way up.
    let (mut done, mut state) = match solve_warm(geom, &at(0.0), cancel, None, trace, mirror) {
        Ok(r) => r,
        Err(_) => return Err(first),
    };
    let mut stats = done.stats;
    let (mut s, mut h) = (0.0f64, 0.25f64);
    while s < 1.0 {
        let next = (s + h).min(1.0);
        match solve_warm(geom, &at(next), cancel, Some(&state), trace, mirror) {
            Ok((l, w)) => {
                stats.fixed_point_iterations += l.stats.fixed_point_iterations;
                stats.ring_iterations += l.stats.ring_iterations;
                stats.ring_evaluations += l.stats.ring_evaluations;
                done = l;
                state = w;
                s = next;
                h = (2.0 * h).min(0.5);
            }
            Err(BallError::Cancelled) => return Err(BallError::Cancelled),
            Err(_) => {
                h *= 0.25;
                if h < 1e-3 {
                    return Err(first);
                }
            }
        }
    }
    done.stats = stats;
    Ok(done)
}

fn solve_warm(
    geom: &BallGeometry,
    cond: &Conditions,
    cancel: Cancel,
    start: Option<&Warm>,
    trace: &mut Option<(usize, Vec<LoadStep>)>,
    mirror: bool,
) -> Result<(LoadDistribution, Warm), BallError> {
    let z = geom.ball_count;
    let a0 = geom.free_contact_angle_rad;
    // A tilt (held or solved against a moment) breaks the axial symmetry as a radial
    // load does.
    let axisymmetric = cond.radial_load_n == 0.0 && cond.tilt == Tilt::Held(0.0);
    let ri = inner_centre_radius(geom);
    let (mut phi, moment_force) = match cond.tilt {
        Tilt::Held(t) => (t * ri, 0.0),
        Tilt::Moment(m) => (start.map_or(0.0, |w| w.phi), m / ri),
    };
    // A moment on a ring no preload loads (held at δ_a = 0, the balls just touching): at
    // φ = 0 no ball is loaded and the Jacobian is zero. Start tilted so that the ball at
    // ψ = 0 carries what the moment asks of it, M = Q sin α·ℜ_i·Z/2, taken as an axial
    // force 2M/ℜ_i on the whole ring through `axial_guess`.
    if let (Tilt::Moment(m), None, Axial::Displacement(d)) = (cond.tilt, start, cond.axial) {
        if d == 0.0 && m != 0.0 {
            let a = geom.centre_distance_m;
            let ring = axial_guess(
                geom,
                2.0 * m.abs() / ri,
                (
                    geom.contact(Race::Inner, a0)?.stiffness_n_per_m1_5(),
                    geom.contact(Race::Outer, a0)?.stiffness_n_per_m1_5(),
                ),
            );
            // axial_guess's δ_a from the unloaded place, at least a round-off's worth
            // of the groove distance.
            phi = ring.max(1e-9 * a).copysign(m);
        }
    }
    let azimuths: Vec<f64> = (0..z)
        .map(|j| 2.0 * std::f64::consts::PI * j as f64 / z as f64)
        .collect();
    let sign = match cond.gyroscopic_friction {
        GyroscopicFriction::Resisting => 1.0,
        GyroscopicFriction::SeedSign => -1.0,
    };
    let layout = Layout::new(&azimuths, axisymmetric, mirror);
    // Initial state: free angles, no load, kinematics at the free angle on the pitch circle.
    let mut angles = start.map_or_else(|| vec![(a0, a0); z], |w| w.angles.clone());
    let mut loads = start.map_or_else(|| vec![(0.0, 0.0); z], |w| w.loads.clone());
    let mut radii = start.map_or_else(|| vec![0.5 * geom.pitch_diameter_m; z], |w| w.radii.clone());
    let stiff0 = (
        geom.contact(Race::Inner, a0)?.stiffness_n_per_m1_5(),
        geom.contact(Race::Outer, a0)?.stiffness_n_per_m1_5(),
    );
    let wm_est = 0.5 * (cond.inner_speed_rad_s.abs() + cond.outer_speed_rad_s.abs());
    let f_ref = cond
        .radial_load_n
        .abs()
        .max(match cond.axial {
            Axial::Force(f) => f.abs(),
            // The load the held displacement puts on the balls (both contacts in series,
            // on the line of centres).
            Axial::Displacement(d) => {
                let a = geom.centre_distance_m;
                let overlap = (a * a0.sin() + d).hypot(a * a0.cos()) - a;
                let k = (stiff0.0.powf(-2.0 / 3.0) + stiff0.1.powf(-2.0 / 3.0)).powf(-1.5);
                z as f64 * k * overlap.max(0.0).powf(1.5)
            }
        })
        .max(z as f64 * geom.ball_mass_kg * wm_est * wm_est * 0.5 * geom.pitch_diameter_m)
        .max(moment_force.abs())
        .max(1.0);
    let ball_tolerance = 1e-11 * f_ref / z as f64;
    let ring_tolerance = 1e-10 * f_ref;
    let mut x = match start {
        Some(w) => w.x,
        None => match cond.axial {
            Axial::Force(fa) if fa == 0.0 && !axisymmetric => {
                radial_guess(geom, cond.radial_load_n, stiff0)
            }
            Axial::Force(fa) => Vector2::new(axial_guess(geom, fa, stiff0), 0.0),
            // A ring held where the balls just touch (a zero preload, issue 29): no ball
            // is loaded at δ_r = 0 and the ring Jacobian is zero there; start radially
            // displaced by the Hertz approach of Stribeck's largest ball load 5F_r/Z.
            Axial::Displacement(d) if d == 0.0 && !axisymmetric => Vector2::new(
                0.0,
                radial_guess(geom, cond.radial_load_n, stiff0)[1]
                    - geom.centre_distance_m * (1.0 - a0.cos()).copysign(cond.radial_load_n),
            ),
            Axial::Displacement(d) => Vector2::new(d, 0.0),
        },
    };
    if let Axial::Displacement(d) = cond.axial {
        x[0] = d;
    }
    if axisymmetric {
        x[1] = 0.0;
    }
    let mut warm: Vec<Option<Vector2<f64>>> =
        start.map_or_else(|| vec![None; z], |w| w.balls.clone());
    let mut stats = LoadStats::default();
    // Each distinct ball's Hertz contacts of the last fixed-point iteration.
    let mut contacts: Vec<Option<(HertzPointContact, HertzPointContact)>> =
        vec![None; layout.len()];
    const MAX_FIXED_POINT: usize = 200;
    let mut change = f64::INFINITY;
    for it in 0..MAX_FIXED_POINT {
        if cancel.is_cancelled() {
            return Err(BallError::Cancelled);
        }
        let n = layout.len();
        let mut params = Vec::with_capacity(n);
        let mut last: Option<((f64, f64), (HertzPointContact, HertzPointContact))> = None;
        for k in 0..n {
            let (ai, ao) = angles[k];
            // The Hertz contacts at this iteration's angles. The same angles as the last
            // ball's (every ball of a fresh solve starts at α₀): the same contacts.
            // Otherwise the κ iteration starts from this ball's κ of the last fixed-point
            // iteration (or the last ball's): the same contact to round-off, in one or
            // two Newton steps instead of five or six (`EllipseShape::solve_near`).
            let (ci, co) = match (last, contacts[k]) {
                (Some((a, c)), _) if a == (ai, ao) => c,
                (_, Some((pi, po))) | (Some((_, (pi, po))), None) => (
                    geom.contact_near(Race::Inner, ai, &pi)?,
                    geom.contact_near(Race::Outer, ao, &po)?,
                ),
                (None, None) => (
                    geom.contact(Race::Inner, ai)?,
                    geom.contact(Race::Outer, ao)?,
                ),
            };
            contacts[k] = Some((ci, co));
            last = Some(((ai, ao), (ci, co)));
            let (qi, qo) = loads[k];
            let control = match cond.race_control {
                RaceControl::Outer => Race::Outer,
                RaceControl::Inner => Race::Inner,
                RaceControl::Auto if qi > 0.0 && qo > 0.0 => {
                    let pi = ci.solve(qi).map_err(|source| BallError::Contact {
                        race: "inner",
                        source,
                    })?;
                    let po = co.solve(qo).map_err(|source| BallError::Contact {
                        race: "outer",
                        source,
                    })?;
                    controlling_race(
                        (qi, pi.semi_major_m, ci.shape().second_kind),
                        (qo, po.semi_major_m, co.shape().second_kind),
                        ai,
                        ao,
                    )
                }
                RaceControl::Auto => Race::Outer,
            };
            let kin = race_control(
                &KinematicsInput {
                    ball_diameter_m: geom.ball_diameter_m,
                    ball_centre_radius_m: radii[k],
                    inner_angle_rad: kinematic_inner_angle(ai, ao, qi),
                    outer_angle_rad: ao,
                    inner_speed_rad_s: cond.inner_speed_rad_s,
                    outer_speed_rad_s: cond.outer_speed_rad_s,
                },
                control,
            )?;
            let mg = kin.gyroscopic_moment_nm(geom.ball_inertia_kg_m2);
            let friction = if qi + qo > 0.0 {
                sign * (2.0 * mg / (geom.ball_diameter_m * (qi + qo)))
                    .clamp(-cond.max_friction, cond.max_friction)
            } else {
                0.0
            };
            // (µ_i, µ_o): Chen's one µ at both contacts, or Harris's whole friction
            // 2M_g/D at the controlling race (λ = 2), capped there at µ_m as 2-7 is.
            let at = |q: f64| {
                if q > 0.0 {
                    sign * (2.0 * mg / (geom.ball_diameter_m * q))
                        .clamp(-cond.max_friction, cond.max_friction)
                } else {
                    0.0
                }
            };
            let (friction, outer_friction) = match (cond.friction_split, control) {
                (FrictionSplit::Proportional, _) => (friction, friction),
                (FrictionSplit::ControllingRace, Race::Outer) => (0.0, at(qo)),
                (FrictionSplit::ControllingRace, Race::Inner) => (at(qi), 0.0),
            };
            params.push(BallParams {
                friction,
                outer_friction,
                centrifugal_coeff: geom.ball_mass_kg * kin.cage_rad_s * kin.cage_rad_s,
                inner_stiffness: ci.stiffness_n_per_m1_5(),
                outer_stiffness: co.stiffness_n_per_m1_5(),
            });
        }
        let alone: Vec<Option<OuterAlone>> =
            params.iter().map(|p| OuterAlone::new(geom, p)).collect();
        let mut ring = RingProblem {
            geom,
            params: &params,
            alone: &alone,
            layout: &layout,
            axial: cond.axial,
            radial: if axisymmetric {
                None
            } else {
                Some(cond.radial_load_n)
            },
            ball_tolerance,
            warm: std::mem::take(&mut warm),
            error: None,
            phi,
            moment_force,
        };
        let newton = Newton {
            max_iterations: 100,
            tolerance: ring_tolerance,
            trust: TrustRegion::new(1e-5, 1e-15, 1e-3),
            line_search: Backtracking::default(),
        };
        let r = match cond.tilt {
            Tilt::Held(_) => newton.solve(&mut ring, &mut x),
            Tilt::Moment(_) => {
                let mut x3 = Vector3::new(x[0], x[1], phi);
                let r = newton.solve(&mut ring, &mut x3);
                x = Vector2::new(x3[0], x3[1]);
                phi = x3[2];
                r
            }
        };
        stats.ring_iterations += r.stats.iterations;
        stats.ring_evaluations += r.stats.evaluations;
        let ring_residual = match r.termination {
            Termination::Converged { residual, .. } => residual,
            t => {
                if let Some(e) = ring.error.take() {
                    return Err(e);
                }
                return Err(BallError::RingNotConverged {
                    reason: reason(&t),
                    iterations: t.iterations(),
                    residual_n: match cond.tilt {
                        Tilt::Held(_) => r.eval.f.amax(),
                        Tilt::Moment(_) => r.eval.f3.amax(),
                    },
                    tolerance_n: ring_tolerance,
                });
            }
        };
        warm = ring.warm;
        let balls = &r.eval.balls;
        // Converged when the angles (hence stiffness and kinematics) and the loads (hence
        // µ of 2-7) are those this solve was made with.
        change = 0.0;
        let mut load_change: f64 = 0.0;
        for (k, b) in balls.iter().enumerate() {
            change = change
                .max((b.inner.angle_rad - angles[k].0).abs())
                .max((b.outer.angle_rad - angles[k].1).abs());
            let s = (b.inner.load_n + b.outer.load_n).max(1e-300);
            load_change = load_change
                .max((b.inner.load_n - loads[k].0).abs() / s)
                .max((b.outer.load_n - loads[k].1).abs() / s);
            // Plain substitution first; under-relaxed (½) after 30 iterations, for the
            // strongly coupled cases (high speed, soft contacts) where it oscillates.
            let w = if it < 30 { 1.0 } else { 0.5 };
            let mix = |old: f64, new: f64| old + w * (new - old);
            angles[k] = (
                mix(angles[k].0, b.inner.angle_rad),
                mix(angles[k].1, b.outer.angle_rad),
            );
            loads[k] = (
                mix(loads[k].0, b.inner.load_n),
                mix(loads[k].1, b.outer.load_n),
            );
            radii[k] = mix(radii[k], b.centre_radius_m);
        }
        stats.fixed_point_iterations = it + 1;
        if let Some((ball, steps)) = trace.as_mut() {
            // The distinct ball that stands for this one (ball 0 for all when axisymmetric).
            let k = layout.of[(*ball).min(z.saturating_sub(1))];
            if let (Some(b), Some(p)) = (balls.get(k), params.get(k)) {
                steps.push(LoadStep {
                    fixed_point: steps.last().map_or(1, |s: &LoadStep| s.fixed_point + 1),
                    ring_iterations: r.stats.iterations,
                    ring_m: [x[0], x[1]],
                    ring_residual_n: ring_residual,
                    angles_rad: [b.inner.angle_rad, b.outer.angle_rad],
                    loads_n: [b.inner.load_n, b.outer.load_n],
                    friction: p.friction,
                    angle_change_rad: change,
                    load_change,
                });
            }
        }
        if it > 0 && change < 1e-12 && load_change < 1e-10 {
            let l = finish(
                geom,
                cond,
                &azimuths,
                &layout,
                balls,
                x,
                r.eval.force,
                (phi / ri, r.eval.force_phi * ri),
                &params,
                ring_residual,
                stats,
            )?;
            // Warm state for every ball, each from the distinct ball standing for it.
            let w = Warm {
                x,
                phi,
                balls: layout.expand(&warm),
                angles: layout.expand(&angles),
                loads: layout.expand(&loads),
                radii: layout.expand(&radii),
            };
            return Ok((l, w));
        }
    }
    Err(BallError::FixedPointNotConverged {
        iterations: MAX_FIXED_POINT,
        change,
    })
}

#[allow(clippy::too_many_arguments)]
fn finish(
    geom: &BallGeometry,
    cond: &Conditions,
    azimuths: &[f64],
    layout: &Layout,
    balls: &[BallEquilibrium],
    x: Vector2<f64>,
    force: Vector2<f64>,
    (tilt_rad, moment_nm): (f64, f64),
    params: &[BallParams],
    ring_residual: f64,
    stats: LoadStats,
) -> Result<LoadDistribution, BallError> {
    // Race control of each distinct ball, then every ball from the one standing for it.
    let mut distinct = Vec::with_capacity(balls.len());
    let mut ball_residual: f64 = 0.0;
    for &b in balls {
        ball_residual = ball_residual.max(b.residual_n);
        let (ai, ao) = (b.inner.angle_rad, b.outer.angle_rad);
        let control = match cond.race_control {
            RaceControl::Outer => Race::Outer,
            RaceControl::Inner => Race::Inner,
            RaceControl::Auto => {
                let ci = geom.contact(Race::Inner, ai)?;
                let co = geom.contact(Race::Outer, ao)?;
                let semi = |c: &HertzPointContact, q: f64| {
                    c.solve(q).map(|p| p.semi_major_m).unwrap_or(0.0)
                };
                controlling_race(
                    (
                        b.inner.load_n,
                        semi(&ci, b.inner.load_n),
                        ci.shape().second_kind,
                    ),
                    (
                        b.outer.load_n,
                        semi(&co, b.outer.load_n),
                        co.shape().second_kind,
                    ),
                    ai,
                    ao,
                )
            }
        };
        let kin = race_control(
            &KinematicsInput {
                ball_diameter_m: geom.ball_diameter_m,
                ball_centre_radius_m: b.centre_radius_m,
                inner_angle_rad: kinematic_inner_angle(ai, ao, b.inner.load_n),
                outer_angle_rad: ao,
                inner_speed_rad_s: cond.inner_speed_rad_s,
                outer_speed_rad_s: cond.outer_speed_rad_s,
            },
            control,
        )?;
        let mg = kin.gyroscopic_moment_nm(geom.ball_inertia_kg_m2);
        let s = b.inner.load_n + b.outer.load_n;
        distinct.push(BallLoad {
            azimuth_rad: f64::NAN,
            equilibrium: b,
            kinematics: kin,
            gyroscopic_moment_nm: mg,
            friction_needed: if s > 0.0 {
                2.0 * mg.abs() / (geom.ball_diameter_m * s)
            } else {
                0.0
            },
        });
    }
    let out = azimuths
        .iter()
        .zip(&layout.of)
        .map(|(&psi, &k)| BallLoad {
            azimuth_rad: psi,
            ..distinct[k]
        })
        .collect();
    Ok(LoadDistribution {
        axial_deflection_m: x[0],
        radial_deflection_m: x[1],
        axial_force_n: force[0],
        radial_force_n: force[1],
        tilt_rad,
        moment_nm,
        params: layout.expand(params),
        balls: out,
        ring_residual_n: ring_residual,
        ball_residual_n: ball_residual,
        stats,
    })
}
