//! The loaded rollers' self-guidance: skew ψ and axial walk solved with each roller's
//! balance (issue 27, `[cage] skew = "self-guided"`; a child of `losses`), SI.
//!
//! # Physics (Kellström, *Rolling contact guidance of rollers in spherical roller
//! bearings*, ASME 79-Lub-23, 1979; Harris & Kotzalas, *Advanced Concepts of Bearing
//! Technology*, 5th ed., roller skewing)
//! A roller with a yaw moment M_s = Σ y·F_θ (the circumferential tractions at axial
//! offsets y along it) skews by ψ about n = a × ê_θ. Its raceway contacts then slide
//! axially, v_a = ψ·ω_s·m at a lamina with spin arm m (`skew.rs`, derived there), and the
//! isotropic traction law turns part of each lamina's force axial:
//! F_a = F(|v|)·v_a/|v|, F_θ = F(|v|)·v_θ/|v| (`skew::skewed_lamina`). The inner and outer
//! contacts have opposite m, so opposite axial tractions. In `losses_skewed` the loads were
//! held: a Newtonian lamina's F_θ does not depend on ψ, so the raceways did not resist the
//! skew and nearly every roller ran to its pocket stop. What that left out is the roller's
//! response to its axial tractions: they are forces on the roller, along each contact's
//! tangent t in the meridian plane (⊥ the lamina's normal, along +a), with a pitch moment
//! about the roller centre. The roller **walks** along its raceways (its meridian
//! equilibrium — axial, radial, pitch, and the guide ring's unilateral end contact — moves
//! until the lamina normal forces and the end contact balance the tractions): the load
//! shifts along the roller at both raceways, and with it the circumferential tractions'
//! yaw moment. So M_s depends on ψ through the walk, and the roller runs to the ψ where
//!
//! h(ψ) = M_s(ψ, q(ψ)) + M_g(ψ) = 0, q(ψ): the roller's meridian equilibrium with the
//! generalised traction load e(ψ, q) = Σ_k F_a,k·(t_k, (p_k − c) × t_k),
//!
//! M_g = −(r_e − L/2)·ψ·Q_end the guide ring's yaw moment (the end contact off the roller
//! axis, `skew.rs`), Q_end the end load of the re-solved roller (it holds the axial
//! tractions' push). Within the pocket play |ψ| ≤ ψ_max = c_p/L; if h keeps its sign to the
//! stop, the pocket stops it at ±ψ_max and reacts h. This is Kellström's self-guidance read
//! in the lamina model: the skew drives axial sliding, the axial tractions walk the roller,
//! the walk moves the load under the circumferential tractions and so the yaw moment.
//! Whether the walk restores (a small ψ) or not is what the solve finds; nothing here sets
//! its sign.
//!
//! # Solution
//! * **Roller balance** ([`resolve`]): every roller re-solved at the statics' ring deflection
//!   and guide-ring offset with its traction load held constant
//!   (`load_distribution::resolve_rollers_with_loads`; energy −e·q), then its contacts and
//!   Hertz widths re-derived; the film stays the statics' (the walk moves a lamina's load by
//!   a few %, h ∝ load^(−0.13)).
//! * **Traction fixed point** ([`settle`]): e → q(e) → e(q) repeated until no roller's load
//!   changes by more than [`TRACTION_LOAD_TOLERANCE`] of the largest roller load (the
//!   moment over L/2), else [`LossError::SelfGuidanceNotConverged`] naming the roller.
//! * **Yaw root** ([`self_guide`]): per roller, ψ has the sign of h(0) = M_s(0); if h keeps
//!   that sign at ψ_max the pocket stops it; otherwise Illinois false position on
//!   (0, ψ_max], all rollers advanced together (each evaluation is one fixed point over
//!   all of them; at a fixed ring they do not interact), to |h| ≤ [`YAW_TOLERANCE`]·|h(0)|
//!   or a bracket below 1e-12·ψ_max, else the typed error naming the roller and |h|.
//! * ψ = 0 for every roller gives zero traction loads: the statics' rollers bit for bit
//!   and exactly today's answers (tested).
//!
//! # Held, and said
//! * The ring deflection and the guide ring's offset are the frictionless statics': the
//!   tractions' net force on the inner ring (printed by `self_guided_print`) is not fed back
//!   to the ring balance, nor the rows' changed end loads to the floating guide ring's
//!   (`net_axial_n` reports what is left on it).
//! * The spins and the cage speed are those of the unskewed balance (`losses`): at ψ the
//!   circumferential tractions change and the spin and cage balances keep a residual
//!   (`cage_torque_imbalance_nm` reports the cage's).
//! * The guide-ring end contact's own traction is not in the yaw or meridian balances
//!   (≤ μ_fl·Q_end; module notes of `losses`).

use super::*;
use crate::bearings::double_row_spherical::statics::split;
use crate::bearings::spherical_roller::contacts::contacts;
use crate::bearings::spherical_roller::load_distribution::resolve_rollers_with_loads;
use crate::bearings::spherical_roller::stages;
use crate::bearings::SolveError;

use super::super::skew::skewed_lamina;

/// The traction fixed point stops when no roller's load changes by more than this × the
/// largest roller contact load (forces; moments over L/2).
pub const TRACTION_LOAD_TOLERANCE: f64 = 1e-10;
/// The yaw root stops when |h(ψ)| ≤ this × |h(0)|.
pub const YAW_TOLERANCE: f64 = 1e-8;
const MAX_FIXED_POINT: usize = 60;
const MAX_YAW_ITERATIONS: usize = 100;

/// One roller's yaw balance at its skew with its current loads.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RollerYaw {
    /// M_s = Σ y·F_θ over both raceways, N·m.
    pub yaw_nm: f64,
    /// M_g, the guide ring's yaw moment, N·m.
    pub ring_nm: f64,
    /// The axial tractions' generalised load on the roller in its row's frame: axial N,
    /// radial N, pitch N·m.
    pub load: [f64; 3],
    /// Σ F_a along the contact tangents (+a), N.
    pub axial_n: f64,
}

impl RollerYaw {
    /// h = M_s + M_g, N·m (what the pocket must react).
    pub fn residual_nm(&self) -> f64 {
        self.yaw_nm + self.ring_nm
    }
}

/// The self-guided rollers (module notes).
#[derive(Debug, Clone)]
pub struct SelfGuided {
    /// The statics with every roller re-solved with its tractions.
    pub analysis: DoubleRowAnalysis,
    /// ψ per roller, rad.
    pub skew_rad: Vec<f64>,
    /// Whether the pocket stops the roller (|ψ| = ψ_max).
    pub pocket_limited: Vec<bool>,
    /// h(0) = M_s(0) per roller, N·m.
    pub unskewed_yaw_nm: Vec<f64>,
    /// The balance at the solution per roller.
    pub yaw: Vec<RollerYaw>,
    /// Fixed-point evaluations of all rollers (yaw root iterations + 3).
    pub evaluations: usize,
    /// Roller re-solves in all (each a Newton of every unique roller).
    pub resolves: usize,
}

/// Each roller's yaw balance at skews `psi` (spins `spins`, cage speed `wc`).
///
/// # Errors
/// [`LossError::Lamina`] naming the roller, raceway and lamina.
pub fn yaw_at(
    k: &LossKinematics,
    wc: f64,
    spins: &[RollerSpin],
    psi: &[f64],
) -> Result<Vec<RollerYaw>, LossError> {
    let lub = &k.common.lubricant;
    let ring_w = [k.common.inner_speed_rad_s, k.common.outer_speed_rad_s];
    let off = k
        .common
        .guide_ring
        .as_ref()
        .map(|g| g.roller_end_radius_m - 0.5 * k.common.pocket.length_m);
    k.rollers
        .iter()
        .enumerate()
        .map(|(j, r)| {
            let s = spins.get(j).map_or(0.0, |x| x.spin_rad_s);
            let ps = psi.get(j).copied().unwrap_or(0.0);
            let mut y = RollerYaw::default();
            for (side, lams) in r.sides.iter().enumerate() {
                for (i, l) in lams.iter().enumerate() {
                    let slice = slice_at(l, ring_w[side], wc, s);
                    let t = skewed_lamina(lub.law, &lub.rheology, &slice, ps * s * l.spin_arm_m)
                        .map_err(|source| LossError::Lamina {
                            roller: j,
                            raceway: if side == 0 { "inner" } else { "outer" },
                            lamina: i,
                            source,
                        })?;
                    y.yaw_nm += l.slice.axial_offset_m * t.circumferential_n;
                    if t.axial_n != 0.0 {
                        let f = [t.axial_n * l.tangent[0], t.axial_n * l.tangent[1]];
                        y.load[0] += f[0];
                        y.load[1] += f[1];
                        // (p − c) × F in the meridian plane: a pitch moment of the sign of
                        // a positive tilt (`geometry::Pitch` rotates (x, r) counter-clockwise).
                        y.load[2] += l.arm_m[0] * f[1] - l.arm_m[1] * f[0];
                        y.axial_n += t.axial_n;
                    }
                }
            }
            if let Some(o) = off {
                if ps != 0.0 {
                    y.ring_nm = -o * ps * r.guide_ring_load_n.max(0.0);
                }
            }
            Ok(y)
        })
        .collect()
}

fn solve_error(e: SolveError) -> LossError {
    match e {
        SolveError::RollerNotConverged {
            roller,
            iterations,
            residual,
            tolerance,
        } => LossError::SelfGuidanceNotConverged {
            roller,
            what: "meridian equilibrium with its tractions, N",
            residual,
            tolerance,
            iterations,
        },
        SolveError::NonFinite { .. } => LossError::SelfGuidanceStatics {
            what: "a non-finite value in a roller's equilibrium",
        },
        _ => LossError::SelfGuidanceStatics {
            what: "the roller equilibrium stage",
        },
    }
}

/// `base` with every roller re-solved under its traction load `loads[r]` (module notes
/// "Roller balance"): contacts and Hertz widths re-derived, the films kept, the guide ring's
/// row forces re-summed. All-zero loads return `base` unchanged.
///
/// # Errors
/// [`LossError::SelfGuidanceNotConverged`] / [`LossError::SelfGuidanceStatics`].
pub fn resolve(
    base: &DoubleRowAnalysis,
    loads: &[[f64; 3]],
) -> Result<DoubleRowAnalysis, LossError> {
    if loads.iter().all(|e| *e == [0.0; 3]) {
        return Ok(base.clone());
    }
    let b = &base.row_bearing;
    let ld = resolve_rollers_with_loads(b, base.input.layout(), &base.combined, loads)
        .map_err(solve_error)?;
    let z = b.geometry.roller_count;
    let mut a = base.clone();
    for (row, ra) in a.rows.iter_mut().enumerate() {
        let l = split(&ld, row, z);
        let cts = contacts(b, &l);
        ra.stresses = Some(stages::stresses(b, &l, &cts));
        ra.contacts = cts;
        ra.load = l;
    }
    let force_row = |row: usize| -> f64 {
        ld.rollers
            .iter()
            .filter(|r| r.row == row)
            .map(|r| r.guide_force_n)
            .sum()
    };
    let (f1, f2) = (force_row(1), force_row(2));
    a.guide.force_row1_n = f1;
    a.guide.force_row2_n = f2;
    a.guide.net_axial_n = (f2 - f1) * base.input.geometry.contact_angle_rad.cos();
    a.combined = ld;
    Ok(a)
}

/// The traction fixed point at skews `psi` from the loads `start` (module notes): the
/// re-solved statics, its loss kinematics, each roller's balance, the loads used, and the
/// re-solves spent.
///
/// # Errors
/// [`LossError::SelfGuidanceNotConverged`] naming the roller whose load kept changing.
#[allow(clippy::type_complexity)]
pub fn settle(
    base: &DoubleRowAnalysis,
    wc: f64,
    spins: &[RollerSpin],
    psi: &[f64],
    start: &[[f64; 3]],
) -> Result<
    (
        DoubleRowAnalysis,
        LossKinematics,
        Vec<RollerYaw>,
        Vec<[f64; 3]>,
        usize,
    ),
    LossError,
> {
    let q_ref = base.max_roller_load_n().max(1e-9);
    let l_half = 0.5 * base.input.geometry.roller_length_m;
    let tol = TRACTION_LOAD_TOLERANCE * q_ref;
    let mut loads = start.to_vec();
    let mut state = resolve(base, &loads)?;
    let (mut worst, mut change) = (0usize, 0.0f64);
    // `resolves` re-solves so far: the first above, one more per step below.
    for resolves in 1..=MAX_FIXED_POINT {
        let k = loss_kinematics(&state)?;
        let ys = yaw_at(&k, wc, spins, psi)?;
        (worst, change) = (0, 0.0);
        for (j, (y, e)) in ys.iter().zip(&loads).enumerate() {
            let d = (y.load[0] - e[0])
                .abs()
                .max((y.load[1] - e[1]).abs())
                .max((y.load[2] - e[2]).abs() / l_half);
            if d > change {
                (worst, change) = (j, d);
            }
        }
        if change <= tol {
            return Ok((state, k, ys, loads, resolves));
        }
        loads = ys.iter().map(|y| y.load).collect();
        state = resolve(base, &loads)?;
    }
    Err(LossError::SelfGuidanceNotConverged {
        roller: worst + 1,
        what: "traction loads' fixed point (walk), N",
        residual: change,
        tolerance: tol,
        iterations: MAX_FIXED_POINT,
    })
}

#[derive(Clone, Copy)]
enum Root {
    Fixed {
        psi: f64,
        pocket: bool,
    },
    Bracket {
        a: f64,
        fa: f64,
        b: f64,
        fb: f64,
        side: i8,
    },
}

/// Every roller's skew from its yaw balance with its walk (module notes "Solution") at cage
/// speed `wc` and spins `spins` (the unskewed balance's).
///
/// # Errors
/// [`LossError::SelfGuidanceNotConverged`] naming the roller and its |h| (yaw) or its load
/// change (fixed point); the statics' and laminae's errors.
pub fn self_guide(
    base: &DoubleRowAnalysis,
    wc: f64,
    spins: &[RollerSpin],
) -> Result<SelfGuided, LossError> {
    let l = base.input.geometry.roller_length_m;
    let psi_max = if l > 0.0 {
        base.input.cage.pocket_clearance_m / l
    } else {
        0.0
    };
    let n = base.combined.rollers.len();
    let zeros = vec![[0.0; 3]; n];
    let mut psi = vec![0.0; n];
    let (_, _, y0, _, mut resolves) = settle(base, wc, spins, &psi, &zeros)?;
    let h0: Vec<f64> = y0.iter().map(RollerYaw::residual_nm).collect();
    let sigma: Vec<f64> = h0
        .iter()
        .map(|&h| {
            if h != 0.0 && psi_max > 0.0 {
                h.signum()
            } else {
                0.0
            }
        })
        .collect();
    for (p, s) in psi.iter_mut().zip(&sigma) {
        *p = s * psi_max;
    }
    let (_, _, y1, mut loads, r1) = settle(base, wc, spins, &psi, &zeros)?;
    resolves += r1;
    let mut evaluations = 2;
    let mut roots: Vec<Root> = (0..n)
        .map(|j| {
            if sigma[j] == 0.0 {
                return Root::Fixed {
                    psi: 0.0,
                    pocket: false,
                };
            }
            let g = sigma[j] * y1[j].residual_nm();
            if g >= 0.0 {
                Root::Fixed {
                    psi: sigma[j] * psi_max,
                    pocket: true,
                }
            } else {
                Root::Bracket {
                    a: 0.0,
                    fa: h0[j].abs(),
                    b: psi_max,
                    fb: g,
                    side: 0,
                }
            }
        })
        .collect();
    let mut last = y1;
    for _ in 0..MAX_YAW_ITERATIONS {
        if roots.iter().all(|r| matches!(r, Root::Fixed { .. })) {
            break;
        }
        let mut trial = vec![0.0; n];
        for (j, r) in roots.iter().enumerate() {
            trial[j] = match *r {
                Root::Fixed { psi, .. } => psi,
                Root::Bracket { a, fa, b, fb, .. } => {
                    let t = (a * fb - b * fa) / (fb - fa);
                    sigma[j]
                        * if t.is_finite() && t > a && t < b {
                            t
                        } else {
                            0.5 * (a + b)
                        }
                }
            };
        }
        let (_, _, ys, used, r) = settle(base, wc, spins, &trial, &loads)?;
        resolves += r;
        evaluations += 1;
        loads = used;
        for (j, root) in roots.iter_mut().enumerate() {
            let Root::Bracket {
                mut a,
                mut fa,
                mut b,
                mut fb,
                mut side,
            } = *root
            else {
                continue;
            };
            let t = sigma[j] * trial[j];
            let g = sigma[j] * ys[j].residual_nm();
            if g.abs() <= YAW_TOLERANCE * h0[j].abs() || b - a <= 1e-12 * psi_max {
                *root = Root::Fixed {
                    psi: trial[j],
                    pocket: false,
                };
                continue;
            }
            if g > 0.0 {
                a = t;
                fa = g;
                if side == 1 {
                    fb *= 0.5;
                }
                side = 1;
            } else {
                b = t;
                fb = g;
                if side == -1 {
                    fa *= 0.5;
                }
                side = -1;
            }
            *root = Root::Bracket { a, fa, b, fb, side };
        }
        last = ys;
    }
    if let Some((j, _)) = roots
        .iter()
        .enumerate()
        .find(|(_, r)| matches!(r, Root::Bracket { .. }))
    {
        return Err(LossError::SelfGuidanceNotConverged {
            roller: j + 1,
            what: "yaw moment balance, N·m",
            residual: last[j].residual_nm().abs(),
            tolerance: YAW_TOLERANCE * h0[j].abs(),
            iterations: MAX_YAW_ITERATIONS,
        });
    }
    let (skew_rad, pocket_limited): (Vec<f64>, Vec<bool>) = roots
        .iter()
        .map(|r| match *r {
            Root::Fixed { psi, pocket } => (psi, pocket),
            Root::Bracket { .. } => (0.0, false),
        })
        .unzip();
    let (analysis, _, yaw, _, r) = settle(base, wc, spins, &skew_rad, &loads)?;
    resolves += r;
    Ok(SelfGuided {
        analysis,
        skew_rad,
        pocket_limited,
        unskewed_yaw_nm: h0,
        yaw,
        evaluations: evaluations + 1,
        resolves,
    })
}

/// The loss breakdown with the self-guided skew (module notes): the unskewed balance's cage
/// speed and spins, every roller at its solved skew and walk, the pocket reacting the yaw
/// balance's residual (0 inside the play), the guide ring the re-solved end loads.
///
/// # Errors
/// As [`losses`] and [`self_guide`].
pub fn losses_self_guided(a: &DoubleRowAnalysis) -> Result<(LossBreakdown, SelfGuided), LossError> {
    let k0 = loss_kinematics(a)?;
    let wc = if k0.computed_cage {
        k0.balanced_cage(k0.statics_cage_rad_s)?.0
    } else {
        k0.statics_cage_rad_s
    };
    let spins = k0.spins_at(wc)?;
    let sg = self_guide(a, wc, &spins)?;
    let k = loss_kinematics(&sg.analysis)?;
    let mut inputs = k.inputs_with(wc, &spins);
    for ((r, kr), &psi) in inputs.rollers.iter_mut().zip(&k.rollers).zip(&sg.skew_rad) {
        let s = r.spin_rad_s;
        r.skew = Some(RollerSkewSpeeds {
            inner_m_s: kr.sides[0].iter().map(|l| l.spin_arm_m * s).collect(),
            outer_m_s: kr.sides[1].iter().map(|l| l.spin_arm_m * s).collect(),
            prescribed_skew_rad: Some(psi),
        });
    }
    let mut b = loss_breakdown(&inputs)?;
    b.losses.cage_speed_rpm = wc * RPM;
    b.cage_speed_computed = k0.computed_cage;
    b.centrifugal_cage_speed_rpm = k0.statics_cage_rad_s * RPM;
    Ok((b, sg))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::double_row_spherical::input::{CageSpeedSource, DoubleRowInput};
    use crate::bearings::double_row_spherical::statics::analyse;

    /// The example 22308 with the seed's measured cage speed (1200 rpm) at the loads (N):
    /// no cage balance, so the tests stay quick.
    fn measured(fr: f64, fa: f64) -> DoubleRowInput {
        let mut b = DoubleRowInput::example_22308();
        assert_eq!(b.cage.speed, CageSpeedSource::Measured);
        b.operating.radial_load_n = fr;
        b.operating.axial_load_n = fa;
        b
    }

    fn solved(b: &DoubleRowInput) -> DoubleRowAnalysis {
        analyse(b, "test", None).unwrap_or_else(|e| panic!("{e}"))
    }

    fn spins(a: &DoubleRowAnalysis) -> (f64, Vec<RollerSpin>) {
        let k = loss_kinematics(a).expect("kinematics");
        let wc = k.statics_cage_rad_s;
        (wc, k.spins_at(wc).expect("spins"))
    }

    /// ψ = 0 ⇒ today's answers exactly: zero traction loads (bit for bit), the statics
    /// untouched, each roller's yaw moment the unskewed breakdown's, and the breakdown with
    /// every roller prescribed at ψ = 0 equal to the unskewed one in every mechanism.
    #[test]
    fn zero_skew_is_todays_answer() {
        let a = solved(&measured(20_000.0, 2_000.0));
        let (wc, sp) = spins(&a);
        let k = loss_kinematics(&a).expect("kinematics");
        let n = k.rollers.len();
        let ys = yaw_at(&k, wc, &sp, &vec![0.0; n]).expect("yaw");
        assert!(ys.iter().all(|y| y.load == [0.0; 3] && y.ring_nm == 0.0));
        let same = resolve(&a, &vec![[0.0; 3]; n]).expect("resolve");
        assert_eq!(same.combined.rollers, a.combined.rollers);
        let inputs = k.inputs_with(wc, &sp);
        let plain = loss_breakdown(&inputs).expect("breakdown");
        let mut at_zero = inputs.clone();
        for (r, kr) in at_zero.rollers.iter_mut().zip(&k.rollers) {
            let s = r.spin_rad_s;
            r.skew = Some(RollerSkewSpeeds {
                inner_m_s: kr.sides[0].iter().map(|l| l.spin_arm_m * s).collect(),
                outer_m_s: kr.sides[1].iter().map(|l| l.spin_arm_m * s).collect(),
                prescribed_skew_rad: Some(0.0),
            });
        }
        let z = loss_breakdown(&at_zero).expect("breakdown");
        assert_eq!(z.losses, plain.losses);
        for ((y, p), q) in ys.iter().zip(&plain.rollers).zip(&z.rollers) {
            // The same lamina forces summed in another order (raceway by raceway there).
            assert!((y.yaw_nm - p.skew_moment_nm).abs() <= 1e-14 * p.skew_moment_nm.abs());
            assert_eq!(q.skew_pocket_moment_nm, p.skew_pocket_moment_nm);
        }
    }

    /// A roller rolling without sliding has no traction, so no yaw moment and no skew: at
    /// 0 rpm (cage at rest) every roller's h(0) is 0 and ψ = 0, the statics unchanged.
    #[test]
    fn pure_rolling_roller_does_not_skew() {
        let mut b = measured(20_000.0, 2_000.0);
        b.operating.inner_speed_rad_s = 0.0;
        b.cage.measured_speed_rad_s = 0.0;
        let a = solved(&b);
        let (wc, sp) = spins(&a);
        let sg = self_guide(&a, wc, &sp).expect("self-guidance");
        assert!(sg.unskewed_yaw_nm.iter().all(|&h| h == 0.0));
        assert!(sg.skew_rad.iter().all(|&p| p == 0.0));
        assert_eq!(sg.analysis.combined.rollers, a.combined.rollers);
    }

    /// At the solution, re-evaluated from the returned state: each roller's traction load is
    /// the one its meridian equilibrium was solved with (the fixed point, to
    /// TRACTION_LOAD_TOLERANCE of the largest load, ×10 for the re-evaluation), its yaw
    /// balance closes (|h| ≤ 1e-6·|h(0)|; the root's own tolerance is 1e-8, the final fixed
    /// point re-settles the loads once more) unless the pocket stops it, the roller
    /// equilibrium residual is within the deck's tolerance, and the breakdown's pocket
    /// moment (skew::roller_skew_at, a separate evaluation of M_s + M_g) agrees with h.
    /// The power identity holds for the self-guided breakdown (1e-9).
    #[test]
    fn self_guided_balances_close() {
        let a = solved(&measured(20_000.0, 0.0));
        let (wc, sp) = spins(&a);
        let sg = self_guide(&a, wc, &sp).expect("self-guidance");
        let k = loss_kinematics(&sg.analysis).expect("kinematics");
        let ys = yaw_at(&k, wc, &sp, &sg.skew_rad).expect("yaw");
        let q_ref = a.max_roller_load_n();
        let l_half = 0.5 * a.input.geometry.roller_length_m;
        for (j, (y, used)) in ys.iter().zip(&sg.yaw).enumerate() {
            let d = (y.load[0] - used.load[0])
                .abs()
                .max((y.load[1] - used.load[1]).abs())
                .max((y.load[2] - used.load[2]).abs() / l_half);
            assert!(
                d <= 10.0 * TRACTION_LOAD_TOLERANCE * q_ref,
                "roller {j}: {d}"
            );
            if !sg.pocket_limited[j] {
                let h = y.residual_nm();
                assert!(
                    h.abs() <= 1e-6 * sg.unskewed_yaw_nm[j].abs(),
                    "roller {j}: h {h} of {}",
                    sg.unskewed_yaw_nm[j]
                );
            }
        }
        let tol = a.row_bearing.solver.force_tolerance * a.input.operating.radial_load_n;
        assert!(sg.analysis.combined.residuals.roller_force_n <= tol);
        let (l, sg2) = losses_self_guided(&a).expect("losses");
        assert_eq!(sg2.skew_rad, sg.skew_rad);
        for (j, r) in l.rollers.iter().enumerate() {
            let h = sg.yaw[j].residual_nm();
            assert!(
                (r.skew_pocket_moment_nm - h).abs()
                    <= 1e-9 * sg.unskewed_yaw_nm[j].abs().max(1e-12),
                "roller {j}: pocket {} against h {h}",
                r.skew_pocket_moment_nm
            );
            assert_eq!(r.skew_angle_rad, sg.skew_rad[j]);
        }
        let x = &l.losses;
        let sum = x.raceway_inner_w
            + x.raceway_outer_w
            + x.guide_ring_w
            + x.cage_pockets_w
            + x.cage_land_w
            + x.skew_w
            + x.drag_w;
        assert!((sum - x.total_w).abs() <= 1e-9 * x.total_w);
        let rel = (a.input.operating.inner_speed_rad_s).abs();
        assert!((x.friction_torque_nm * rel - x.total_w).abs() <= 1e-9 * x.total_w);
    }

    /// A roller whose meridian Newton fails is named with its residual (1-based over both
    /// rows): one Newton iteration with a 1 kN traction load on roller 4.
    #[test]
    fn failed_roller_balance_names_the_roller() {
        let mut a = solved(&measured(20_000.0, 0.0));
        a.row_bearing.solver.max_roller_iterations = 1;
        let mut loads = vec![[0.0; 3]; a.combined.rollers.len()];
        loads[3] = [1_000.0, 0.0, 0.0];
        match resolve(&a, &loads) {
            Err(e @ LossError::SelfGuidanceNotConverged { roller: 4, .. }) => {
                let m = e.to_string();
                assert!(m.contains("roller 4") && m.contains("self-guided"), "{m}");
            }
            other => panic!("{other:?}"),
        }
    }

    /// The self-guided rollers on the shipped geometry's three cases, the cage speed
    /// measured (the seed's 1200 rpm) and computed (the shipped deck's): how many skew
    /// inside the play, ψ, the walk, the end loads and the loss split.
    #[test]
    fn self_guided_print() {
        for (what, fr, fa, cage) in [
            ("radial", 20_000.0, 0.0, CageSpeedSource::Measured),
            ("axial", 0.0, 6_000.0, CageSpeedSource::Measured),
            ("combined", 20_000.0, 2_000.0, CageSpeedSource::Measured),
            ("radial", 20_000.0, 0.0, CageSpeedSource::Computed),
            ("axial", 0.0, 6_000.0, CageSpeedSource::Computed),
            ("combined", 20_000.0, 2_000.0, CageSpeedSource::Computed),
        ] {
            let mut b = measured(fr, fa);
            b.cage.speed = cage;
            let a = solved(&b);
            let what = format!("{cage:?} {what}");
            let t = std::time::Instant::now();
            let (l, sg) = losses_self_guided(&a).expect("losses");
            let dt = t.elapsed().as_secs_f64();
            let loaded: Vec<usize> = (0..sg.skew_rad.len())
                .filter(|&j| sg.unskewed_yaw_nm[j] != 0.0)
                .collect();
            let stopped = sg.pocket_limited.iter().filter(|&&p| p).count();
            let psi_max = sg.skew_rad.iter().map(|p| p.abs()).fold(0.0, f64::max);
            let psi_min = loaded
                .iter()
                .map(|&j| sg.skew_rad[j].abs())
                .fold(f64::INFINITY, f64::min);
            let s = &l.losses.shares_pct;
            eprintln!(
                "{what}: {} rollers with a yaw moment, {stopped} at the pocket stop; |ψ| {psi_min:.3e}–{psi_max:.3e} rad; guide ring rows {:.2} / {:.2} N (statics {:.2} / {:.2}), net {:.3} N; total {:.2} W: raceways {:.1} %, guide ring {:.2} %, skew {:.2} %, pockets {:.2} %, land {:.2} %; M_fi {:.4} M_fo {:.4} N·m; imbalance {:.4} N·m; {} evaluations, {} re-solves, {dt:.2} s",
                loaded.len(),
                sg.analysis.guide.force_row1_n,
                sg.analysis.guide.force_row2_n,
                a.guide.force_row1_n,
                a.guide.force_row2_n,
                sg.analysis.guide.net_axial_n,
                l.losses.total_w,
                s.raceway_inner + s.raceway_outer,
                s.guide_ring,
                s.skew,
                s.cage_pockets,
                s.cage_land,
                l.losses.friction_torque_inner_nm,
                l.losses.friction_torque_outer_nm,
                l.losses.cage_torque_imbalance_nm,
                sg.evaluations,
                sg.resolves,
            );
            for j in 0..sg.skew_rad.len().min(4) {
                let r = &sg.analysis.combined.rollers[j];
                let r0 = &a.combined.rollers[j];
                eprintln!(
                    "  roller {j}: h0 {:.3e} ψ {:.3e} stop {} walk Δaxial {:.3e} m Δradial {:.3e} m Δtilt {:.3e}; end load {:.3} N (statics {:.3}); traction load {:?}",
                    sg.unskewed_yaw_nm[j],
                    sg.skew_rad[j],
                    sg.pocket_limited[j],
                    r.axial_displacement_m - r0.axial_displacement_m,
                    r.radial_displacement_m - r0.radial_displacement_m,
                    r.tilt_rad - r0.tilt_rad,
                    r.guide_force_n,
                    r0.guide_force_n,
                    sg.yaw[j].load,
                );
            }
        }
    }
}
