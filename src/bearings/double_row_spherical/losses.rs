//! Where the power goes in a double-row spherical roller bearing (seed 002 §3, issue 27
//! Model 2–4): the friction loss by mechanism, the friction torques, and the cage's torque
//! imbalance at a measured cage speed, SI.
//!
//! The breakdown ([`loss_breakdown`]) reads a plain [`LossInputs`]; [`losses`] builds it
//! from the solved statics of the double-row system. The physics is the shared
//! lubrication code (`lamina_friction`, `guide_ring`, `cage_film`, `heat`): this file
//! holds only what is the double-row bearing's own (its mechanisms and their wiring).
//!
//! # Mechanisms (the output's contract names)
//! * `raceway_inner_w`, `raceway_outer_w`: Σ F·v_sl over the laminae of each raceway
//!   (seed eq. 3 under the deck's law): the whole contact power, its differential
//!   (Heathcote-type) sliding along the roller included;
//! * `skew_w`: the dissipation of the forces that hold each roller against its **skew
//!   (yaw) moment** (below), at its cage pocket: a mechanism of its own, added to the
//!   others;
//! * `guide_ring_w`: the roller-end EHD contacts plus the ring's bore film, at the ring
//!   speed of its torque balance (`guide_ring`), 0 without a guide ring;
//! * `cage_pockets_w`: Martin's rigid-isoviscous pocket film, drag × roller surface speed;
//! * `cage_land_w`: the cage's Petroff land on the guide ring or the inner ring;
//! * `drag_w`: Palmgren viscous drag (`heat::viscous_drag_power_w`), off unless a drag
//!   factor is given (not in the seed); 0 for η = 0 (the formula's low-speed floor would
//!   otherwise churn an oil that is not there);
//! * `total_w`: their sum; `shares_pct`: each over the total, %.
//!
//! # Skew (seed §6: "the contact angles modification … makes possible the appearance of the
//! skew moments (2 … 3 % of the total friction losses)")
//! The seed's "skew moments" are read as the roller's yaw moment (Harris & Kotzalas,
//! *Advanced Concepts of Bearing Technology*, 5th ed., roller skewing in spherical roller
//! bearings): the raceway laminae's tractions F_k·ê_θ at axial offsets y_k along the roller
//! have the moment M_s = Σ y_k·F_k (both raceways) about the roller's skew axis
//! n = a × ê_θ (normal to the roller axis a in the meridian plane), which turns the roller
//! axis out of the meridian plane. Where the two raceways' contact angles differ under load
//! the two contacts' sliding fields along the roller differ, and M_s ≠ 0. The roller is held
//! by reaction forces at its pocket and at its guide-ring end. In [`losses`] (the default)
//! it does not skew (ψ = 0) and its skew loss is the
//! dissipation of those reactions (`skew_w`), a new friction at contacts the other terms
//! do not load:
//! * **pocket**: the couple w(y) = 12·M_s·y/L³ along the pocket contact, each half a Martin
//!   film (`cage_film::pocket_skew_reaction`: F_s = 3|M_s|/(2L) per half, loss over the
//!   unloaded films), at the roller's surface speed ω_s·D_W/2 relative to the cage;
//! * **guide ring**: its normal force acts along the face normal through the end contact,
//!   on the roller axis, so it has no yaw moment until the roller has skewed by ψ (the
//!   contact then moves by (r_e − L/2)·ψ off the axis): with ψ ≤ c_p/L (the pocket's play
//!   over the roller length) that is ≤ Q_end·|r_e − L/2|·c_p/L = 4e-4 m·Q_end on the
//!   shipped deck; the end contact's tangential traction has the yaw arm L/2
//!   (≤ μ_fl·Q_end·L/2). At the shipped deck's end loads (≤ 1.1 N per roller) the two
//!   are ≤ 4.3e-4 + 3.9e-4 N·m, against yaw moments up to 0.011 N·m (radial) / 0.013 N·m
//!   (combined) / 0.003 N·m (axial) (`seed_shapes_print` prints them): neglected, the
//!   pockets take all of M_s (the skew loss an upper bound by ≲ 8 %).
//! * The raceways' own resistance to skew (axial tractions once the roller axis turns) needs
//!   a skew degree of freedom the quasi-static model does not have: neglected, so the
//!   pockets take the whole moment (an upper bound on the reaction).
//!
//! Couplings: the reaction drag opposes the roller surface's motion, so its moment
//! −D_s·D_W/2 about the roller axis enters each roller's spin balance (below) and the
//! raceway tractions pay for it (the power identity stays exact). The couple on the pocket
//! is a free moment M_s·n; n = a × ê_θ = (a_r, −a_x, 0) in (axial, radial, θ) has the
//! axial component a_r (the roller axis' radial component, −sin α in the row's frame),
//! so the cage receives the torque
//! M_s·a_r about the bearing axis from each roller (summed in the cage balance; a row's
//! mirrored frame keeps a torque's axial component). The drags' own torque on the cage
//! (forces along n at the pocket faces, arm D_W/2) is neglected with the net-force pocket
//! drag's (≤ D·D_W/2·cos α ≈ 2e-3 N·m per roller).
//!
//! With [`losses_skewed`] (srb-skew; not the default, see its doc) the roller **skews**
//! until its pocket and guide ring hold it (`skew.rs`): a skew ψ about n makes each raceway lamina slide axially
//! at v_a = ψ·ω_s·m (m the spin arm), so the lamina's traction (the law's force at
//! |v| = √(v_θ² + v_a²), along v) turns partly axial; the raceways' yaw moment
//! M_s(ψ) = Σ y·F_θ falls where the law saturates, and the axial tractions' sum N along the
//! roller axis presses the roller's end on the guide ring when it points at it
//! (Q = max(0, −N)); that end touches the ring off the roller axis by δ = (r_e − L/2)·ψ, so
//! the ring's normal force has the restoring yaw moment M_g = −δ·Q. ψ solves
//! M_s(ψ) + M_g(ψ) = 0 within the pocket play |ψ| ≤ c_p/L, else the pocket stops it at
//! ±c_p/L and reacts the rest h = M_s + M_g. The skew's loss (`skew_w`) is
//! * the raceways' axial sliding dissipation Σ F_a·v_a (the lamina's F·|v| splits exactly
//!   into F_θ·v_θ, booked to the raceway terms, and F_a·v_a, booked here), and
//! * the pocket's reaction h as the couple w(y) = 12·h·y/L³ along the pocket contact, each
//!   half a Martin film (`cage_film::pocket_skew_reaction`: F_s = 3|h|/(2L) per half, loss
//!   over the unloaded films), at the roller's surface speed ω_s·D_W/2.
//!
//! The guide ring (`guide_ring_w`) carries the statics' (centrifugal) end loads plus the
//! skew's; the floating ring passes no axial load to the inner ring, so the row pressing it
//! less receives the difference of the rows' sums, shared by its rollers
//! ([`skew_end_loads`]). A skewed roller's end contact slides across the ring's face at
//! ω_s·δ beside its circumferential sliding (`guide_ring`: the traction along the whole
//! sliding vector). Without skew input (`RollerLossInput::skew = None`) ψ = 0 and every
//! term is the unskewed one (`hand_built_case`).
//!
//! [`kellstrom`] (srb-kellstrom; opt-in, [`kellstrom::losses_self_guided`]) adds the
//! roller's response to its axial tractions, the axial walk, solved with the yaw balance;
//! its module notes say what it finds on the shipped deck and what it still holds.
//!
//! Neglected couplings (sizes printed by `losses_tests::skew_couplings_print`):
//! * the statics: the lamina normal loads are the statics' at ψ = 0; the skew's end load Q
//!   and the axial tractions' pitch couple (±ρ·F_a at the two raceways) would shift them;
//! * the spins: each roller's spin is solved at ψ = 0 (the spin balance's tractions are
//!   F(v_θ)); at ψ the circumferential tractions F_θ are smaller, which leaves a residual
//!   moment about the roller axis;
//! * the ring's yaw share −M_g·a_r about the bearing axis (the off-axis normal force) is
//!   not in the guide ring's torque balance; the cage receives the pocket's share h·a_r;
//! * the end contact's traction about the skew axis (arm L/2) and its radial traction about
//!   the roller axis (arm δ) are not in the yaw or spin balances.
//!
//! # Torques
//! M_fi, M_fo (`friction_torque_inner_nm`, `friction_torque_outer_nm`) are the loss at the
//! inner / outer raceway contacts over |ω_i − ω_o|; the bearing's
//! friction torque is total/|ω_i − ω_o| (power identity). All three are 0 when the rings
//! turn together (|ω_i − ω_o| below `heat::MIN_RELATIVE_SPEED_RAD_S`).
//!
//! # Cage imbalance
//! Quasi-statically each roller passes its net circumferential traction (inner + outer
//! raceway laminae + guide-ring end, all along the bearing's rotation) to its pocket, which
//! acts on the cage at the pitch radius, and its skew reaction's axial component M_s·a_r
//! (above); the land film adds its Petroff torque. The net is
//! `cage_torque_imbalance_nm`: 0 at a cage speed from the cage's torque balance, and the
//! torque that would accelerate (+) or brake (−) the cage at a measured one.
//!
//! # Roller spin
//! Each roller spins at the rate where the traction moments about its own axis balance
//! (the quasi-static friction analysis of roller bearings, Harris & Kotzalas, *Advanced
//! Concepts of Bearing Technology*, 5th ed.: every roller's speed from its friction
//! moments, not from a kinematic assumption). With m_k = (a × (p_k − c))·ê_θ the roller
//! surface's speed per unit spin at lamina k (the same arm carries the traction's moment
//! about the axis), the sliding is v_k(ω_s) = u_k − ω_s·m_k and
//! M(ω_s) = Σ_k F_k(v_k)·m_k − (D_p + D_s)(ω_s)·(D_W/2)·sgn ω_s over both raceways' loaded
//! laminae, D_s the skew reaction's added drag (above), D_p the pocket's hydrodynamic drag
//! (Martin's film at the roller's net raceway traction;
//! the breakdown's pocket film also adds the guide-ring end's tangential force, a few % of
//! it). Each F_k grows with v_k (Newtonian eq. 3, or ATZ: non-decreasing), so
//! dM/dω_s = −Σ F_k'·m_k² − … ≤ 0 for the pocket's own drag: one root (or a flat stretch
//! where every lamina is at its limiting shear); D_s follows |M_s(ω_s)|, which need not be
//! monotone, but it is a small part of the moment and the bracketed root is checked by
//! evaluating the balance afresh (`roller_spin_closes_its_moment_balance`). It is bracketed from the statics' spin (scaled to the cage speed),
//! by Newton steps on the analytic slope dM/dω_s (or an expanding step), and closed by a
//! safeguarded Newton (bisection when the step leaves the bracket or the bracket stalls)
//! to |M| ≤ [`SPIN_MOMENT_TOLERANCE`]·Σ|F_k·m_k| (`solve_spin`). A roller with no loaded lamina keeps the
//! statics' spin (nothing drives it but the pocket film; reported). Neglected: the
//! guide-ring end's friction moment about the roller axis — its contact lies on the axis
//! but for the roller's tilt, the arm is ≤ 4e-5 m against m_k ≈ 6 mm: μ_fl·Q_end·arm
//! ≤ 3e-6 N·m on the shipped deck against traction moments of ~1 N·m (`seed_shapes_print`
//! prints it); the film thickness is the statics' (at the statics'
//! spin), the spin moving the entrainment by a few %.
//!
//! # Cage speed
//! `cage.speed = "measured"`: the deck's speed, the imbalance reported. `"computed"` (the
//! shipped deck's): the root of the cage's torque balance (imbalance 0) from the statics'
//! §7 estimate, by secant steps until it is accepted or bracketed (within the rings'
//! speeds), then Illinois, with every roller's spin solved inside each evaluation,
//! warm-started from the previous cage speeds' spins ([`LossKinematics::balanced_cage`]).
//! An evaluation computes only what the balance reads afresh (srb12): each roller's
//! raceway sums come from its spin solve's last moment evaluation (the breakdown's own
//! numbers, not integrated again), the guide ring's search starts from the previous cage
//! speeds' ring speed (its tolerance unchanged), and every lamina's ATZ kink search
//! starts from its previous root (`lamina_friction_and_slope_hinted`); the breakdown at
//! the accepted speed is the last evaluation's. Accepted within
//! [`CAGE_TORQUE_TOLERANCE`] of its scale or the torque's resolution
//! ([`LossBreakdown::cage_torque_noise_nm`]), or, where the torque steps across the balance
//! (ATZ laminae at their rolling points), once the speed is bracketed to
//! [`CAGE_SPEED_RESOLUTION`] of the ring speed, the step reported as the resolution. The loads stay the statics' (their
//! centrifugal force used the §7 speed; F_c ∝ ω_c², so a cage speed δ % off moves it by
//! 2δ %: `centrifugal_cage_speed_rpm` is reported beside `cage_speed_rpm`). The slip
//! `cage_slip_pct` is against the kinematic speed (App. C, rolling without slip at α⁰).
//!
//! # Signs
//! Every sliding speed and force is along the bearing's rotation (+θ, the direction of a
//! positive inner-ring speed), sliding = raceway (or ring) surface minus roller surface;
//! the traction on the roller acts along +v.

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use std::cell::Cell;

use serde::{Deserialize, Serialize};
use thiserror::Error;

use super::input::{CageLand as DeckCageLand, CageSpeedSource, DoubleRowInput, Traction};
use super::skew::{
    roller_skew, roller_skew_at, unskewed_from_contacts, RollerSkew, SkewGeometry, SkewedContact,
};
use super::statics::DoubleRowAnalysis;
use crate::bearings::spherical_roller::load_distribution::DynamicSpeeds;
use crate::physics::heat::{viscous_drag_power_w, MIN_RELATIVE_SPEED_RAD_S};
use crate::physics::kinematics::sliding_velocity;
use crate::physics::lubrication::cage_film::{
    land_power_w, land_torque_on_cage_nm, pocket_film, pocket_skew_reaction, CageFilmError,
    PocketGeometry,
};
use crate::physics::lubrication::guide_ring::{
    guide_ring_balance_near, CageLandOnRing, EndContactInput, GuideRingError, GuideRingGeometry,
    GuideRingSolution, RingSpeedGuess,
};
use crate::physics::lubrication::lamina_friction::{
    lamina_friction_and_slope_hinted, FilmRheology, LaminaFrictionError, LaminaSlice,
    RacewayTractionLaw,
};
use crate::physics::lubrication::traction::{HertzStrip, KinkHint};
use crate::physics::lubrication::walther::WaltherError;

/// Which surface pilots the cage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum CageLandKind {
    /// The cage runs on the guide ring (deck `land = "guide-ring"`).
    #[default]
    GuideRing,
    /// The cage runs on the inner ring (deck `land = "inner-ring"`).
    InnerRing,
}

/// The cage's piloting land, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CageLand {
    /// Which surface pilots the cage.
    pub kind: CageLandKind,
    /// R, land radius, m.
    pub radius_m: f64,
    /// L, land width, m.
    pub width_m: f64,
    /// c, radial clearance, m.
    pub radial_clearance_m: f64,
}

/// One roller's contacts and forces from the statics.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RollerLossInput {
    /// Row, 1 or 2.
    pub row: u8,
    /// Laminae at the inner raceway.
    pub inner: Vec<LaminaSlice>,
    /// Laminae at the outer raceway.
    pub outer: Vec<LaminaSlice>,
    /// Normal load of the roller end on the guide ring, N.
    pub guide_ring_load_n: f64,
    /// Force between roller and cage pocket, N (its magnitude sets the pocket film);
    /// `None`: the roller's net circumferential traction (inner + outer laminae + guide-ring
    /// end), the quasi-static roller passing it all to its pocket (module notes).
    pub pocket_force_n: Option<f64>,
    /// Orbital (cage) speed of the roller, rad/s.
    pub orbital_speed_rad_s: f64,
    /// Speed of the roller end's guide-ring contact point relative to the cage, along +θ,
    /// m/s.
    pub roller_end_speed_m_s: f64,
    /// Roller surface speed relative to the cage at the pocket (ω_R·D/2), m/s.
    pub surface_speed_m_s: f64,
    /// ω_s, the roller's spin about its axis relative to the cage, rad/s (reported; the
    /// laminae's sliding speeds and the two speeds above already carry it).
    pub spin_rad_s: f64,
    /// a_r, the radial component of the roller axis in its row's frame (−sin α for a
    /// roller at contact angle α): the axial component of its skew axis n = a × ê_θ, so its
    /// yaw reaction M_s·n has the torque M_s·a_r about the bearing axis on the cage.
    pub skew_axis_axial_component: f64,
    /// The roller surface's circumferential speed ω_s·m at each lamina (inner, outer; the
    /// laminae's order), m/s: what a skew ψ turns into the axial sliding ψ·ω_s·m
    /// (`skew.rs`). `None`: the roller does not skew (the pocket reacts its yaw moment at
    /// ψ = 0).
    #[serde(default)]
    pub skew: Option<RollerSkewSpeeds>,
}

/// The roller surface's circumferential speed ω_s·m per lamina, m/s (module notes "Skew").
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RollerSkewSpeeds {
    /// Inner raceway laminae, m/s.
    pub inner_m_s: Vec<f64>,
    /// Outer raceway laminae, m/s.
    pub outer_m_s: Vec<f64>,
    /// The skew solved with the roller's balance (`[cage] skew = "self-guided"`,
    /// `kellstrom`), rad: the breakdown evaluates the roller at this ψ (the pocket reacts
    /// the yaw balance's residual, the guide ring's end load is the statics' own) instead
    /// of searching ψ with the loads held. `None`: searched (`skew.rs`).
    #[serde(default)]
    pub prescribed_skew_rad: Option<f64>,
}

/// Lubricant of the loss model, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LossLubricant {
    /// η, α, τ_tr, μ_fl at the measured temperature.
    pub rheology: FilmRheology,
    /// The raceway (and end-contact) traction law.
    pub law: RacewayTractionLaw,
    /// ρ, density at the measured temperature, kg/m³ (ν = η/ρ for the drag).
    pub density_kg_m3: f64,
    /// f₀ of Palmgren's viscous drag; `None` (the default) leaves drag out.
    pub drag_factor: Option<f64>,
}

/// Everything the loss breakdown reads.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LossInputs {
    /// Both rows' rollers.
    pub rollers: Vec<RollerLossInput>,
    /// ω_i, rad/s.
    pub inner_speed_rad_s: f64,
    /// ω_o, rad/s.
    pub outer_speed_rad_s: f64,
    /// ω_c, cage speed (measured or computed), rad/s.
    pub cage_speed_rad_s: f64,
    /// The kinematic cage speed (App. C: rolling without slip at the free contact angle),
    /// rad/s: the reference of the reported cage slip.
    pub kinematic_cage_speed_rad_s: f64,
    /// The guide ring, if present.
    pub guide_ring: Option<GuideRingGeometry>,
    /// A roller in its pocket.
    pub pocket: PocketGeometry,
    /// The cage land.
    pub cage_land: CageLand,
    /// d_m, pitch diameter, m (pocket moment arm d_m/2, Palmgren drag).
    pub pitch_diameter_m: f64,
    /// The lubricant.
    pub lubricant: LossLubricant,
}

/// Each mechanism as a percentage of the total.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct LossShares {
    /// Inner raceway contacts, %.
    pub raceway_inner: f64,
    /// Outer raceway contacts, %.
    pub raceway_outer: f64,
    /// Guide ring (roller ends and bore), %.
    pub guide_ring: f64,
    /// Cage pockets, %.
    pub cage_pockets: f64,
    /// Cage land, %.
    pub cage_land: f64,
    /// Skew, %.
    pub skew: f64,
    /// Churning drag, %.
    pub drag: f64,
}

/// The loss by mechanism and the torques (report contract `losses`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Losses {
    /// Inner raceway laminae, W.
    pub raceway_inner_w: f64,
    /// Outer raceway laminae, W.
    pub raceway_outer_w: f64,
    /// Roller ends and bore film of the guide ring, W.
    pub guide_ring_w: f64,
    /// Roller / pocket films, W.
    pub cage_pockets_w: f64,
    /// Cage / land Petroff film, W.
    pub cage_land_w: f64,
    /// The pockets' skew (yaw) reactions, W.
    pub skew_w: f64,
    /// Palmgren viscous drag, W (0 when off).
    pub drag_w: f64,
    /// Sum of the seven terms, W.
    pub total_w: f64,
    /// Each term over the total, % (all 0 when the total is 0).
    pub shares_pct: LossShares,
    /// M_fi, inner raceway loss over |ω_i − ω_o|, N·m.
    pub friction_torque_inner_nm: f64,
    /// M_fo, outer raceway loss over |ω_i − ω_o|, N·m.
    pub friction_torque_outer_nm: f64,
    /// total/|ω_i − ω_o|, N·m.
    pub friction_torque_nm: f64,
    /// Net torque on the cage about the bearing axis, N·m (0 at a balanced cage speed).
    pub cage_torque_imbalance_nm: f64,
    /// ω_c, the cage speed of the breakdown (measured, or of the cage's torque balance),
    /// rpm.
    pub cage_speed_rpm: f64,
    /// Cage slip against the kinematic speed ω_k (App. C), 100·(ω_k − ω_c)/ω_k, % (0 when
    /// ω_k = 0).
    pub cage_slip_pct: f64,
}

/// One roller's share.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct RollerLoss {
    /// Row, 1 or 2.
    pub row: u8,
    /// ω_s, the roller's spin about its axis relative to the cage, rad/s (its moment
    /// balance; the statics' spin for a roller with no loaded lamina).
    pub spin_rad_s: f64,
    /// M_s = Σ y·F over both raceways' laminae, the yaw moment about the roller's skew axis
    /// n = a × ê_θ through its centre, N·m (module notes "Skew").
    pub skew_moment_nm: f64,
    /// Inner raceway power, W.
    pub inner_w: f64,
    /// Outer raceway power, W.
    pub outer_w: f64,
    /// The pocket's skew reaction: the loss it adds, W.
    pub skew_w: f64,
    /// The pocket's skew reaction: each half's force F_s = 3|M_s|/(2L), N.
    pub skew_reaction_force_n: f64,
    /// Roller end / guide ring contact, W.
    pub guide_ring_end_w: f64,
    /// Pocket film, W.
    pub pocket_w: f64,
    /// Pocket minimum film, m.
    pub pocket_film_m: f64,
    /// Net circumferential traction passed to the pocket (along +θ), N.
    pub circumferential_force_n: f64,
    /// Force of the roller on its pocket that set the pocket film, N: the given one, or
    /// the net circumferential traction (signed along +θ).
    pub pocket_force_n: f64,
    /// Normal load of the roller end on the guide ring, N.
    pub guide_ring_load_n: f64,
    /// Laminae where the printed eq. 3 exceeds μ = 0.2.
    pub eq3_flagged_laminae: usize,
    /// ψ, the roller's skew angle, rad (`skew.rs`; 0 without skew input).
    pub skew_angle_rad: f64,
    /// M_s(0), the raceways' yaw moment of the unskewed roller, N·m.
    pub unskewed_skew_moment_nm: f64,
    /// M_g, the guide ring's yaw moment on the roller (its off-axis end contact), N·m.
    pub skew_ring_moment_nm: f64,
    /// The yaw moment the pocket reacts, N·m (M_s(ψ) + M_g; 0 to the search's tolerance
    /// when the ring holds the skew).
    pub skew_pocket_moment_nm: f64,
    /// N, the raceways' net axial traction on the roller along its axis (+ away from the
    /// guide ring), N.
    pub skew_axial_traction_n: f64,
    /// The skew's end load on the guide ring (max(0, −N), plus this roller's share of the
    /// other row's excess through the floating ring), N; `guide_ring_load_n` is the
    /// statics' (centrifugal) end load, and the end contact carries their sum.
    pub skew_guide_ring_load_n: f64,
    /// Σ F_a·v_a, the raceways' axial sliding dissipation (inner + outer), W (part of
    /// `skew_w`).
    pub skew_raceway_w: f64,
}

/// The breakdown with its details.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LossBreakdown {
    /// The contract numbers.
    pub losses: Losses,
    /// Per roller, in input order.
    pub rollers: Vec<RollerLoss>,
    /// The guide ring at its balance (absent without a guide ring).
    pub guide_ring: Option<GuideRingSolution>,
    /// Laminae (both raceways, all rollers) where the printed eq. 3 exceeds μ = 0.2.
    pub eq3_flagged_laminae: usize,
    /// The land film's torque on the cage, N·m (part of the imbalance).
    pub cage_land_torque_nm: f64,
    /// True when the cage speed is the cage's torque balance (deck `speed = "computed"`).
    pub cage_speed_computed: bool,
    /// The cage speed the statics' centrifugal force used, rpm (0 when not from a solved
    /// bearing).
    pub centrifugal_cage_speed_rpm: f64,
    /// The resolution of the cage's torque at a computed cage speed, N·m: Σ over the
    /// rollers of their net traction's spread across the spin's final bracket (a lamina on
    /// eq. 3's Newtonian branch at its rolling point makes the spin balance near-vertical)
    /// times d_m/2; the balance is accepted within the larger of it and
    /// [`CAGE_TORQUE_TOLERANCE`] of the torque's scale; where the torque steps across the
    /// balance (the speed bracketed to [`CAGE_SPEED_RESOLUTION`]) it is at least the step.
    /// 0 at a measured cage speed.
    pub cage_torque_noise_nm: f64,
}

/// Why the loss breakdown cannot be computed.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum LossError {
    /// A lamina is unusable.
    #[error("roller {roller}, {raceway} raceway, lamina {lamina}: {source}")]
    Lamina {
        /// Roller index (0-based, input order).
        roller: usize,
        /// "inner" or "outer".
        raceway: &'static str,
        /// Lamina index.
        lamina: usize,
        /// The lamina's error.
        source: LaminaFrictionError,
    },
    /// The guide ring failed.
    #[error(transparent)]
    GuideRing(#[from] GuideRingError),
    /// A cage film failed.
    #[error(transparent)]
    Cage(#[from] CageFilmError),
    /// The lubricant's viscosity line (ASTM D341) cannot be evaluated.
    #[error("lubricant viscosity: {0}")]
    Viscosity(#[from] WaltherError),
    /// A stage of the statics the losses read did not run.
    #[error("row {row}: the {stage} stage of the statics did not run; the losses need it")]
    MissingStage {
        /// The stage.
        stage: &'static str,
        /// Row, 1 or 2.
        row: usize,
    },
    /// A roller's moment balance about its axis could not be bracketed.
    #[error("roller {roller}: no spin balances the traction moments about its axis (searched up to {spin_rad_s} rad/s, moment still {moment_nm} N·m)")]
    SpinBracket {
        /// Roller index (0-based, input order).
        roller: usize,
        /// The last spin tried, rad/s.
        spin_rad_s: f64,
        /// The moment there, N·m.
        moment_nm: f64,
    },
    /// A roller's moment balance did not close.
    #[error("roller {roller}: the spin balance did not converge: {moment_nm} N·m left at {spin_rad_s} rad/s (scale {scale_nm} N·m)")]
    SpinNotConverged {
        /// Roller index (0-based, input order).
        roller: usize,
        /// The last spin, rad/s.
        spin_rad_s: f64,
        /// The moment there, N·m.
        moment_nm: f64,
        /// Σ|F·m| there, N·m.
        scale_nm: f64,
    },
    /// The cage's torque balance could not be bracketed between the rings' speeds.
    #[error("cage speed = \"computed\": the cage's torque imbalance keeps its sign from {start_rpm} rpm ({imbalance_start_nm} N·m) to {end_rpm} rpm ({imbalance_end_nm} N·m), the ring speed; no balanced cage speed")]
    CageBracket {
        /// The start (the statics' §7 speed), rpm.
        start_rpm: f64,
        /// The last speed tried, rpm.
        end_rpm: f64,
        /// The imbalance at the start, N·m.
        imbalance_start_nm: f64,
        /// The imbalance at the last speed, N·m.
        imbalance_end_nm: f64,
    },
    /// The cage's torque balance did not close.
    #[error("cage speed = \"computed\": the cage's torque balance did not converge: {imbalance_nm} N·m left at {cage_rpm} rpm")]
    CageNotConverged {
        /// The last cage speed, rpm.
        cage_rpm: f64,
        /// The imbalance there, N·m.
        imbalance_nm: f64,
    },
    /// The roller balance with the skew's tractions (`[cage] skew = "self-guided"`) did not
    /// converge for a roller.
    #[error("cage skew = \"self-guided\": roller {roller} ({what}) did not converge: {residual} left against a tolerance of {tolerance} after {iterations} iterations")]
    SelfGuidanceNotConverged {
        /// Roller index (1-based over both rows).
        roller: usize,
        /// Which balance: the yaw moment (N·m), the traction loads' fixed point (N) or the
        /// roller's meridian equilibrium (N).
        what: &'static str,
        /// What was left.
        residual: f64,
        /// Its tolerance.
        tolerance: f64,
        /// Iterations spent.
        iterations: usize,
    },
    /// The roller re-solve with the skew's tractions left the model.
    #[error("cage skew = \"self-guided\": re-solving the rollers with their tractions failed ({what}); set cage.skew = \"pocket\" to compute the losses without it")]
    SelfGuidanceStatics {
        /// What failed.
        what: &'static str,
    },
    /// An input outside its range.
    #[error("{name} = {value} is not usable: it must be {allowed}")]
    BadInput {
        /// The field.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The allowed range.
        allowed: &'static str,
    },
}

fn finite(name: &'static str, value: f64) -> Result<f64, LossError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(LossError::BadInput {
            name,
            value,
            allowed: "finite",
        })
    }
}

/// The loss breakdown of one operating point (module notes).
///
/// # Errors
/// [`LossError`] naming the roller, raceway and lamina, or the guide-ring / cage input at
/// fault; [`LossError::BadInput`] for a non-finite speed, a non-positive pitch diameter or
/// density with drag on, or a guide-ring land without a guide ring.
pub fn loss_breakdown(inputs: &LossInputs) -> Result<LossBreakdown, LossError> {
    breakdown_with(inputs, None, None)
}

/// [`loss_breakdown`] with each roller's skew given when the caller has it (`skews`, in
/// roller order: the cage balance's unskewed rollers from their spin solves,
/// [`unskewed_from_contacts`], the numbers [`roller_skews`] would integrate again) and the
/// guide ring's search started from `ring` (a previous cage speed's ring speed,
/// `guide_ring::guide_ring_balance_near`: the same tolerance, fewer residuals).
fn breakdown_with(
    inputs: &LossInputs,
    skews: Option<Vec<RollerSkew>>,
    ring: Option<RingSpeedGuess>,
) -> Result<LossBreakdown, LossError> {
    let wi = finite("inner_speed_rad_s", inputs.inner_speed_rad_s)?;
    let wo = finite("outer_speed_rad_s", inputs.outer_speed_rad_s)?;
    let wc = finite("cage_speed_rad_s", inputs.cage_speed_rad_s)?;
    let dm = inputs.pitch_diameter_m;
    if !(dm.is_finite() && dm > 0.0) {
        return Err(LossError::BadInput {
            name: "pitch_diameter_m",
            value: dm,
            allowed: "positive and finite",
        });
    }
    let lub = &inputs.lubricant;
    let rh = &lub.rheology;
    let eta = rh.viscosity_pa_s;
    if !(eta.is_finite() && eta >= 0.0) {
        return Err(LossError::BadInput {
            name: "viscosity_pa_s",
            value: eta,
            allowed: "finite and not negative",
        });
    }

    // Each roller's skew first (`skew.rs`): it sets the raceway tractions and the end loads.
    let skews = match skews {
        Some(s) if s.len() == inputs.rollers.len() => s,
        _ => roller_skews(inputs)?,
    };
    let skew_end = skew_end_loads(inputs, &skews);
    let end_offset = inputs.guide_ring.as_ref().map_or(0.0, |g| {
        g.roller_end_radius_m - 0.5 * inputs.pocket.length_m
    });

    // Guide ring next: its speed sets the end contacts and, for a guide-ring land, the cage
    // land's relative speed.
    let guide = match &inputs.guide_ring {
        Some(g) => {
            let ends: Vec<EndContactInput> = inputs
                .rollers
                .iter()
                .zip(&skews)
                .zip(&skew_end)
                .map(|((r, sk), &q)| EndContactInput {
                    load_n: r.guide_ring_load_n + q,
                    roller_end_speed_m_s: r.roller_end_speed_m_s,
                    orbital_speed_rad_s: r.orbital_speed_rad_s,
                    // The off-axis end point δ = (r_e − L/2)·ψ swept by the spin.
                    radial_sliding_m_s: r.spin_rad_s * end_offset * sk.skew_rad,
                })
                .collect();
            // A cage piloted on the ring drives it through the land film (Newton's third
            // law: the land's torque on the cage below, opposite on the ring; srb10).
            let land = &inputs.cage_land;
            let on_ring = (land.kind == CageLandKind::GuideRing).then_some(CageLandOnRing {
                radius_m: land.radius_m,
                width_m: land.width_m,
                radial_clearance_m: land.radial_clearance_m,
                cage_speed_rad_s: wc,
            });
            Some(guide_ring_balance_near(
                g,
                lub.law,
                rh,
                wi,
                &ends,
                on_ring.as_ref(),
                ring,
            )?)
        }
        None => None,
    };

    let mut rollers = Vec::with_capacity(inputs.rollers.len());
    let mut l = Losses::default();
    let (mut inner_total, mut outer_total, mut flagged) = (0.0, 0.0, 0usize);
    let mut cage_torque = 0.0;
    for (k, r) in inputs.rollers.iter().enumerate() {
        let sk = &skews[k];
        let (i, o) = (&sk.inner, &sk.outer);
        let (pi, fi, ni) = (i.rolling_power_w, i.circumferential_n, i.flagged);
        let (po, fo, no) = (o.rolling_power_w, o.circumferential_n, o.flagged);
        let yaw = sk.yaw_moment_nm();
        // The pocket reacts what the ring does not (all of it at ψ = 0).
        let pocket_yaw = sk.pocket_moment_nm;
        let skew = pocket_skew_reaction(&inputs.pocket, eta, pocket_yaw, r.surface_speed_m_s)?;
        let raceway_skew = i.skew_power_w + o.skew_power_w;
        let end = guide.as_ref().and_then(|g| g.contacts.get(k)).copied();
        let (end_w, end_f) = end.map_or((0.0, 0.0), |c| (c.power_w, c.force_on_roller_n));
        let circumferential = fi + fo + end_f;
        let pocket_force = r.pocket_force_n.unwrap_or(circumferential);
        let pocket = pocket_film(&inputs.pocket, eta, pocket_force, r.surface_speed_m_s)?;
        inner_total += pi;
        outer_total += po;
        l.raceway_inner_w += pi;
        l.raceway_outer_w += po;
        l.skew_w += skew.power_w + raceway_skew;
        l.cage_pockets_w += pocket.power_w;
        flagged += ni + no;
        cage_torque += circumferential * 0.5 * dm + pocket_yaw * r.skew_axis_axial_component;
        rollers.push(RollerLoss {
            row: r.row,
            spin_rad_s: r.spin_rad_s,
            skew_moment_nm: yaw,
            inner_w: pi,
            outer_w: po,
            skew_w: skew.power_w + raceway_skew,
            skew_reaction_force_n: skew.half_force_n,
            guide_ring_end_w: end_w,
            pocket_w: pocket.power_w,
            pocket_film_m: pocket.min_film_m,
            circumferential_force_n: circumferential,
            pocket_force_n: pocket_force,
            guide_ring_load_n: r.guide_ring_load_n,
            eq3_flagged_laminae: ni + no,
            skew_angle_rad: sk.skew_rad,
            unskewed_skew_moment_nm: sk.unskewed_yaw_moment_nm,
            skew_ring_moment_nm: sk.ring_moment_nm,
            skew_pocket_moment_nm: pocket_yaw,
            skew_axial_traction_n: sk.axial_traction_n,
            skew_guide_ring_load_n: skew_end[k],
            skew_raceway_w: raceway_skew,
        });
    }
    if let Some(g) = &guide {
        l.guide_ring_w = g.ends_power_w + g.bore_power_w;
    }

    let land = &inputs.cage_land;
    let land_speed = match land.kind {
        CageLandKind::InnerRing => wi,
        CageLandKind::GuideRing => match &guide {
            Some(g) => g.speed_rad_s,
            None => {
                return Err(LossError::BadInput {
                    name: "cage land = \"guide-ring\" without a guide ring; present",
                    value: 0.0,
                    allowed: "true (or land = \"inner-ring\")",
                })
            }
        },
    };
    let dw_land = wc - land_speed;
    l.cage_land_w = land_power_w(
        eta,
        land.radius_m,
        land.width_m,
        land.radial_clearance_m,
        dw_land,
    )?;
    let land_torque = land_torque_on_cage_nm(
        eta,
        land.radius_m,
        land.width_m,
        land.radial_clearance_m,
        dw_land,
    )?;
    cage_torque += land_torque;

    let rel = (wi - wo).abs();
    if let Some(f0) = lub.drag_factor {
        let rho = lub.density_kg_m3;
        if !(rho.is_finite() && rho > 0.0) {
            return Err(LossError::BadInput {
                name: "density_kg_m3",
                value: rho,
                allowed: "positive and finite when drag is on",
            });
        }
        // Palmgren's floor 160·10⁻⁷·f₀·d_m³ (νn < 2000) stands for oil that is there: with
        // η = 0 there is nothing to churn.
        if eta > 0.0 {
            l.drag_w = viscous_drag_power_w(f0, eta / rho, wi - wo, dm);
        }
    }

    l.total_w = l.raceway_inner_w
        + l.raceway_outer_w
        + l.guide_ring_w
        + l.cage_pockets_w
        + l.cage_land_w
        + l.skew_w
        + l.drag_w;
    if l.total_w != 0.0 {
        let pct = |x: f64| 100.0 * x / l.total_w;
        l.shares_pct = LossShares {
            raceway_inner: pct(l.raceway_inner_w),
            raceway_outer: pct(l.raceway_outer_w),
            guide_ring: pct(l.guide_ring_w),
            cage_pockets: pct(l.cage_pockets_w),
            cage_land: pct(l.cage_land_w),
            skew: pct(l.skew_w),
            drag: pct(l.drag_w),
        };
    }
    if rel.is_finite() && rel >= MIN_RELATIVE_SPEED_RAD_S {
        l.friction_torque_inner_nm = inner_total / rel;
        l.friction_torque_outer_nm = outer_total / rel;
        l.friction_torque_nm = l.total_w / rel;
    }
    l.cage_torque_imbalance_nm = cage_torque;
    l.cage_speed_rpm = wc * RPM;
    let wk = inputs.kinematic_cage_speed_rad_s;
    if wk.is_finite() && wk != 0.0 {
        l.cage_slip_pct = 100.0 * (wk - wc) / wk;
    }
    Ok(LossBreakdown {
        losses: l,
        rollers,
        guide_ring: guide,
        eq3_flagged_laminae: flagged,
        cage_land_torque_nm: land_torque,
        cage_speed_computed: false,
        centrifugal_cage_speed_rpm: 0.0,
        cage_torque_noise_nm: 0.0,
    })
}

/// The skew geometry of a roller without skew input ([`roller_skews`]' ψ_max = 0): the
/// end contact's offset per unit skew r_e − L/2 from the guide ring (none without one).
fn unskewed_geometry(inputs: &LossInputs) -> SkewGeometry {
    SkewGeometry {
        max_skew_rad: 0.0,
        end_offset_per_rad_m: inputs
            .guide_ring
            .as_ref()
            .map(|g| g.roller_end_radius_m - 0.5 * inputs.pocket.length_m),
    }
}

/// Each roller at its skew (`skew.rs`): ψ_max = c_p/L from the pocket, the end contact's
/// offset per unit skew r_e − L/2 from the guide ring (none without one). A roller without
/// skew input is evaluated at ψ = 0 (its laminae as given).
///
/// # Errors
/// [`LossError::Lamina`] naming the roller, raceway and lamina; [`LossError::BadInput`]
/// when a roller's skew speeds do not match its laminae.
fn roller_skews(inputs: &LossInputs) -> Result<Vec<RollerSkew>, LossError> {
    let lub = &inputs.lubricant;
    let l = inputs.pocket.length_m;
    let on = SkewGeometry {
        max_skew_rad: if l > 0.0 {
            inputs.pocket.pocket_clearance_m / l
        } else {
            0.0
        },
        end_offset_per_rad_m: inputs
            .guide_ring
            .as_ref()
            .map(|g| g.roller_end_radius_m - 0.5 * l),
    };
    let off = unskewed_geometry(inputs);
    let none: &[f64] = &[];
    inputs
        .rollers
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let (geometry, speeds) = match &r.skew {
                Some(sp) => {
                    if sp.inner_m_s.len() != r.inner.len() || sp.outer_m_s.len() != r.outer.len() {
                        return Err(LossError::BadInput {
                            name: "roller skew speeds (one per lamina)",
                            value: sp.inner_m_s.len() as f64,
                            allowed: "as many as the roller's laminae",
                        });
                    }
                    (&on, [sp.inner_m_s.as_slice(), sp.outer_m_s.as_slice()])
                }
                None => (&off, [none, none]),
            };
            match r.skew.as_ref().and_then(|sp| sp.prescribed_skew_rad) {
                Some(psi) => roller_skew_at(
                    lub.law,
                    &lub.rheology,
                    geometry,
                    [&r.inner, &r.outer],
                    speeds,
                    psi,
                    r.guide_ring_load_n,
                ),
                None => roller_skew(
                    lub.law,
                    &lub.rheology,
                    geometry,
                    [&r.inner, &r.outer],
                    speeds,
                ),
            }
            .map_err(|e| LossError::Lamina {
                roller: k,
                raceway: if e.raceway == 0 { "inner" } else { "outer" },
                lamina: e.lamina,
                source: e.source,
            })
        })
        .collect()
}

/// The skew's end loads on the guide ring, N per roller (module notes "Skew"): each
/// roller's max(0, −N) from [`roller_skew`]; the guide ring floats (it passes no axial load
/// to the inner ring, `float.rs`), so the row that presses less receives the difference of
/// the two rows' sums (both rows' end forces act along mirrored axes, so the sums compare
/// directly), shared equally by that row's rollers (the ring is rigid; which of their ends
/// it meets first is not resolved). 0 without a guide ring.
fn skew_end_loads(inputs: &LossInputs, skews: &[RollerSkew]) -> Vec<f64> {
    let mut q: Vec<f64> = skews.iter().map(|s| s.guide_ring_load_n).collect();
    if inputs.guide_ring.is_none() {
        q.iter_mut().for_each(|x| *x = 0.0);
        return q;
    }
    let sum = |row: u8, q: &[f64]| -> (f64, usize) {
        inputs
            .rollers
            .iter()
            .zip(q)
            .filter(|(r, _)| r.row == row)
            .fold((0.0, 0), |(s, n), (_, &x)| (s + x, n + 1))
    };
    let ((s1, n1), (s2, n2)) = (sum(1, &q), sum(2, &q));
    let (row, excess, n) = if s1 > s2 {
        (2, s1 - s2, n2)
    } else {
        (1, s2 - s1, n1)
    };
    if excess > 0.0 && n > 0 {
        let share = excess / n as f64;
        for (r, x) in inputs.rollers.iter().zip(q.iter_mut()) {
            if r.row == row {
                *x += share;
            }
        }
    }
    q
}

// ------------------------------------------------------------------ wiring to the statics

/// The guide ring and the cage land of the double-row deck, derived from its geometry
/// (the 22308's are not published; the deck holds no keys for them yet):
///
/// * r_g, the end contacts' distance from the axis: the statics' end sphere touches the
///   guide ring's face (normal to the nominal roller axis a = (cos α⁰, −sin α⁰)) on the
///   roller axis, L/2 from the roller centre: r_g = d_m/2 + (L/2)·sin α⁰;
/// * R_b, the guide ring's bore on the inner ring: the inner raceway's radius below the
///   roller's inner end, r_g − ρ_e·cos α⁰ with ρ_e = D_W/2 − (L/2)²/(R_W + √(R_W² − (L/2)²))
///   the crowned roller's radius at its end (the crown drop without cancellation);
/// * the bore film's width is the deck's `guide_ring.width` and its radial clearance half
///   the deck's diametral `guide_ring.bore_clearance`;
/// * the cage land: on the guide ring's outer surface (radius r_g) or on the inner ring's
///   central land (radius R_b), the guide ring's width wide, with the radial play half the
///   deck's `cage.pocket_clearance` (the clearance the statics' cage already reads).
pub struct DerivedGeometry {
    /// r_g, m.
    pub guide_contact_radius_m: f64,
    /// R_b, m.
    pub guide_bore_radius_m: f64,
}

/// [`DerivedGeometry`] of `input`.
pub fn derived_geometry(input: &DoubleRowInput) -> DerivedGeometry {
    let g = &input.geometry;
    let half_l = 0.5 * g.roller_length_m;
    let rw = g.roller_crown_radius_m;
    let drop = half_l * half_l / (rw + (rw * rw - half_l * half_l).max(0.0).sqrt());
    let rho_end = 0.5 * g.roller_diameter_m - drop;
    let (s, c) = g.contact_angle_rad.sin_cos();
    let rg = 0.5 * g.pitch_diameter_m + half_l * s;
    DerivedGeometry {
        guide_contact_radius_m: rg,
        guide_bore_radius_m: rg - rho_end * c,
    }
}

/// The reduced modulus E* of roller and inner ring (the guide ring is of the inner ring's
/// steel), Pa: 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂, as the statics' guide contact reads it.
fn guide_reduced_modulus_pa(input: &DoubleRowInput) -> f64 {
    let (r, ring) = (&input.materials.roller, &input.materials.inner_ring);
    1.0 / ((1.0 - r.poisson_ratio.powi(2)) / r.youngs_modulus_pa
        + (1.0 - ring.poisson_ratio.powi(2)) / ring.youngs_modulus_pa)
}

/// One loaded lamina contact with the speeds factored out. In the cage frame the sliding
/// speed (`kinematics::sliding_velocity`, raceway minus roller along +θ) is linear in the
/// ring's speed relative to the cage and in the roller's spin:
/// v = ring_arm·(ω_ring − ω_c) − spin_arm·ω_s, where spin_arm m = (a × (p − c))·ê_θ is the
/// roller surface's speed per unit spin at the contact point p, and the same arm carries the
/// lamina traction's moment about the roller axis (a·((p − c) × F·ê_θ) = F·m).
#[derive(Debug, Clone)]
struct LaminaKinematics {
    /// Load, half-width, length, p₀, film and offset of the statics; the two speeds are
    /// filled per evaluation.
    slice: LaminaSlice,
    /// Sliding per unit (ω_ring − ω_c), m.
    ring_arm_m: f64,
    /// m, roller surface speed per unit spin, m.
    spin_arm_m: f64,
    /// Distance of the raceway point from the bearing axis, m (entrainment).
    ring_axis_distance_m: f64,
    /// Distance of the roller point from the roller axis, m (entrainment).
    roller_axis_distance_m: f64,
    /// The contact point minus the roller centre, (axial, radial) in the row's frame, m:
    /// the arm of an axial traction's pitch moment (`kellstrom`).
    arm_m: [f64; 2],
    /// The unit tangent of the contact in the meridian plane (normal to the lamina's
    /// contact normal, along +a): the direction of an axial traction (`kellstrom`).
    tangent: [f64; 2],
    /// What the ATZ kink search found at this lamina's last evaluation: the next starts
    /// there (`lamina_friction_and_slope_hinted`; the spin and cage balances evaluate each
    /// lamina ~20–60 times at nearby sliding speeds).
    hint: Cell<KinkHint>,
}

/// One roller's contacts with the speeds factored out.
#[derive(Debug, Clone)]
struct RollerKinematics {
    row: u8,
    /// Inner, outer raceway.
    sides: [Vec<LaminaKinematics>; 2],
    guide_ring_load_n: f64,
    /// a_r, the roller axis' radial component (the skew axis' axial component).
    skew_axis_axial_component: f64,
    /// The roller end's guide-ring contact point: speed relative to the cage per unit spin
    /// along +θ, m (nearly 0: the point lies on the roller axis but for the roller's tilt).
    end_spin_arm_m: f64,
}

/// The solved statics reduced to what the loss model reads at any cage speed and roller
/// spins ([`loss_kinematics`]); [`LossKinematics::inputs_at`] builds the [`LossInputs`].
#[derive(Debug, Clone)]
pub struct LossKinematics {
    rollers: Vec<RollerKinematics>,
    /// Everything but the rollers (their vector is empty here).
    common: LossInputs,
    /// The cage speed and the one roller spin the statics used, rad/s.
    statics_cage_rad_s: f64,
    statics_spin_rad_s: f64,
    /// Whether the deck asks for the cage speed from the cage's torque balance.
    computed_cage: bool,
    /// Whether the rollers skew (`skew.rs`; [`losses_skewed`]): off in [`losses`].
    with_skew: bool,
}

/// Tolerance of a roller's moment balance: |M(ω_s)| ≤ this × Σ|F_k·m_k| (plus the pocket
/// drag's moment), the traction moments' own scale; the bracket is also accepted once it is
/// narrower than 1e-12 of the spin (a flat stretch of a saturated ATZ law).
pub const SPIN_MOMENT_TOLERANCE: f64 = 1e-9;

/// Tolerance of the cage's torque balance at a computed cage speed: |imbalance| ≤ this ×
/// (Σ|F_circ|·d_m/2 + |T_land| + M, M the bearing's friction torque: under a pure axial
/// load every roller's net traction is nearly 0 at balance, and M keeps the scale), or
/// the torque's own resolution if larger ([`LossBreakdown::cage_torque_noise_nm`]): each
/// evaluation re-solves the spins, whose moment is near-vertical at the root (eq. 3's
/// Newtonian slope η·e^{αp}/h), so the net traction is fixed only to its spread across the
/// spin's final bracket.
pub const CAGE_TORQUE_TOLERANCE: f64 = 1e-6;

/// A roller's moment balance about its own axis at spin `spin` (rad/s, relative to the
/// cage) and cage speed `wc`: (moment N·m, its scale Σ|F·m| + |pocket moment| N·m, the net
/// raceway circumferential traction N).
fn spin_moment(
    r: &RollerKinematics,
    roller: usize,
    common: &LossInputs,
    wc: f64,
    spin: f64,
) -> Result<(f64, f64, f64), LossError> {
    spin_moment_and_slope(r, roller, common, wc, spin, false).map(|e| (e.moment, e.scale, e.circ))
}

/// One evaluation of a roller's moment balance ([`spin_moment_and_slope`]).
struct SpinEval {
    /// M(ω_s), N·m.
    moment: f64,
    /// Σ|F·m| + |pocket moment|, N·m.
    scale: f64,
    /// Σ F over both raceways, N.
    circ: f64,
    /// dM/dω_s, N·m·s (0 unless asked for).
    slope: f64,
    /// Each raceway's sums at this spin exactly as the breakdown's unskewed roller forms
    /// them (`skew::contacts_at` at ψ = 0: the same laminae, forces and order of addition,
    /// so the same numbers bit for bit): the cage balance reads them instead of
    /// integrating every lamina once more per cage speed.
    contacts: [SkewedContact; 2],
}

#[cfg(test)]
thread_local! {
    /// (spin solves, moment evaluations, lamina evaluations) on this thread: the cost
    /// counts `losses_stage_cost_print` reports.
    pub(super) static SPIN_COUNTS: std::cell::Cell<(usize, usize, usize)> =
        const { std::cell::Cell::new((0, 0, 0)) };
}

#[cfg(test)]
thread_local! {
    /// The cage speeds (rad/s) [`CageEvaluations::eval`] was called at on this thread, in
    /// order: the cage balance's iteration count for `losses_stage_cost_print`.
    pub(super) static CAGE_TRACE: std::cell::RefCell<Vec<f64>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// [`spin_moment`] and, with `want_slope`, dM/dω_s (N·m·s): the laminae's part is
/// −Σ F_k'(v_k)·m_k² exactly (v_k = u_k − m_k·ω_s, F' from
/// [`lamina_friction_and_slope`](crate::physics::lubrication::lamina_friction::lamina_friction_and_slope)); the pocket's drag depends on ω_s directly and through
/// the net traction and the yaw moment (dcirc/dω_s = −Σ F_k'·m_k, dyaw/dω_s =
/// −Σ y_k·F_k'·m_k), taken as one directional difference of the two pocket formulas
/// (closed forms, no lamina evaluated) — a slope for Newton's step only, so its accuracy
/// sets the convergence rate, never the root.
fn spin_moment_and_slope(
    r: &RollerKinematics,
    roller: usize,
    common: &LossInputs,
    wc: f64,
    spin: f64,
    want_slope: bool,
) -> Result<SpinEval, LossError> {
    let lub = &common.lubricant;
    let ring_w = [common.inner_speed_rad_s, common.outer_speed_rad_s];
    let (mut m, mut scale, mut circ, mut yaw) = (0.0, 0.0, 0.0, 0.0);
    let (mut dm, mut dcirc, mut dyaw) = (0.0, 0.0, 0.0);
    let mut contacts = [SkewedContact::default(); 2];
    // The law's constants once per moment, not per lamina (the same numbers:
    // `lamina_friction_and_slope_prepared`), and each lamina's kink search started from its
    // last (`lamina_friction_and_slope_hinted`: the same force to round-off).
    let atz = lub.rheology.atz().prepared();
    #[cfg(test)]
    let mut laminae = 0usize;
    for (k, side) in r.sides.iter().enumerate() {
        let raceway = if k == 0 { "inner" } else { "outer" };
        let c = &mut contacts[k];
        for (j, l) in side.iter().enumerate() {
            let s = slice_at(l, ring_w[k], wc, spin);
            let (f, slope) = lamina_friction_and_slope_hinted(
                lub.law,
                &lub.rheology,
                &atz,
                &s,
                want_slope,
                &l.hint,
            )
            .map_err(|source| LossError::Lamina {
                roller,
                raceway,
                lamina: j,
                source,
            })?;
            #[cfg(test)]
            {
                laminae += 1;
            }
            m += f.force_n * l.spin_arm_m;
            scale += (f.force_n * l.spin_arm_m).abs();
            circ += f.force_n;
            yaw += f.skew_moment_nm;
            dm -= slope * l.spin_arm_m * l.spin_arm_m;
            dcirc -= slope * l.spin_arm_m;
            dyaw -= slope * l.spin_arm_m * s.axial_offset_m;
            // `skew::contacts_at` at ψ = 0 (`skewed_lamina` with v_a = 0), term by term (its
            // skew power and axial force stay 0).
            c.rolling_power_w += f.power_w;
            c.yaw_moment_nm += s.axial_offset_m * f.force_n;
            c.circumferential_n += f.force_n;
            c.flagged += usize::from(f.exceeds_newtonian_bound);
        }
    }
    #[cfg(test)]
    SPIN_COUNTS.with(|c| {
        let (a, b, n) = c.get();
        c.set((a, b + 1, n + laminae));
    });
    // The pocket's hydrodynamic drag opposes the roller surface's motion relative to the
    // cage (Martin's film at the pocket force: the given one or this net traction), and so
    // does the drag its skew reaction adds (module notes "Skew").
    let rr = common.pocket.roller_radius_m;
    let eta = lub.rheology.viscosity_pa_s;
    let pocket = |spin: f64, circ: f64, yaw: f64| -> Result<f64, LossError> {
        let p = pocket_film(&common.pocket, eta, circ, spin * rr)?;
        let sk = pocket_skew_reaction(&common.pocket, eta, yaw, spin * rr)?;
        Ok(-(p.drag_n + sk.drag_n) * rr * spin.signum())
    };
    let mp = pocket(spin, circ, yaw)?;
    if want_slope {
        // One-sided, away from ω_s = 0 (the drag's sign flips there).
        let d = 1e-7 * spin.abs().max(1.0) * if spin < 0.0 { -1.0 } else { 1.0 };
        let mp_d = pocket(spin + d, circ + d * dcirc, yaw + d * dyaw)?;
        dm += (mp_d - mp) / d;
    }
    Ok(SpinEval {
        moment: m + mp,
        scale: scale + mp.abs(),
        circ,
        slope: dm,
        contacts,
    })
}

/// The lamina at the given speeds: sliding v = ring_arm·(ω_ring − ω_c) − m·ω_s and the
/// entrainment ½(|(ω_ring − ω_c)·R_ring| + |ω_s·r_roller|) in the cage frame.
fn slice_at(l: &LaminaKinematics, ring_w: f64, wc: f64, spin: f64) -> LaminaSlice {
    LaminaSlice {
        sliding_speed_m_s: l.ring_arm_m * (ring_w - wc) - l.spin_arm_m * spin,
        rolling_speed_m_s: 0.5
            * (((ring_w - wc) * l.ring_axis_distance_m).abs()
                + (spin * l.roller_axis_distance_m).abs()),
        ..l.slice
    }
}

/// A roller's spin from its moment balance (module notes "Roller spin"): the root of the
/// monotone M(ω_s) by a safeguarded Newton. Each evaluation also gives the analytic slope
/// dM/dω_s ([`spin_moment_and_slope`]); on eq. 3's Newtonian branch the lamina force is
/// linear in v, so Newton lands on a rolling point's near-vertical stretch in one step,
/// where the Illinois false position it replaces crawled at bisection speed. Newton steps
/// from `guess` toward the root until M changes sign (the bracket; where the slope is no
/// use, bracket expansion from step `step`, doubling); inside the bracket a Newton step
/// that leaves it, or a bracket that did not halve in two steps, falls back to bisection
/// (Brent's safeguard), so the bracket always closes. Stops when |M| ≤
/// [`SPIN_MOMENT_TOLERANCE`]·Σ|F·m| or when the bracket is below 1e-12·max(|ω_s|, 1):
/// M is then vertical to round-off (a lamina on the Newtonian branch exactly at its
/// rolling point, slope η·e^{αp}·A/h·m² ~ 1e15 N·m·s and more), the root is known to
/// that width, and the spread below says what it leaves in the traction.
/// Returns the [`SpinRoot`]: its spread is the change of the roller's net circumferential
/// traction across the final bracket when the bracket's width stopped the search, 0 when
/// the residual did; its contacts are the last evaluation's, at the returned spin.
fn solve_spin(
    r: &RollerKinematics,
    roller: usize,
    common: &LossInputs,
    wc: f64,
    guess: f64,
    step: f64,
) -> Result<SpinRoot, LossError> {
    #[cfg(test)]
    SPIN_COUNTS.with(|c| {
        let (a, b, n) = c.get();
        c.set((a + 1, b, n));
    });
    let eval = |s: f64| spin_moment_and_slope(r, roller, common, wc, s, true);
    let root = |s: f64, e: &SpinEval, spread: f64| SpinRoot {
        spin_rad_s: s,
        residual_nm: e.moment,
        scale_nm: e.scale,
        spread_n: spread,
        contacts: Some(e.contacts),
    };
    let e0 = eval(guess)?;
    let (m0, sc0, c0, d0) = (e0.moment, e0.scale, e0.circ, e0.slope);
    if m0.abs() <= SPIN_MOMENT_TOLERANCE * sc0 {
        return Ok(root(guess, &e0, 0.0));
    }
    // M falls with ω_s: a positive moment means the root lies above.
    let dir = if m0 > 0.0 { 1.0 } else { -1.0 };
    let mut h = if step.is_finite() && step > 0.0 {
        step
    } else {
        0.05 * guess.abs().max(1.0)
    };
    // Bracket: from the last point on the guess's side, Newton's step when it points
    // toward the root (a falling M), else the expanding step.
    let (mut a, mut fa, mut ca, mut da) = (guess, m0, c0, d0);
    let (mut b, mut fb, mut cb, mut db);
    let mut tries = 0;
    loop {
        let newton = a - fa / da;
        b = if da < 0.0 && newton.is_finite() && (newton - a) * dir > 0.0 {
            // A little past Newton's point, so a convex stretch still crosses.
            a + (newton - a) * 1.0001
        } else {
            a + dir * h
        };
        (fb, cb, db) = {
            let e = eval(b)?;
            if e.moment.abs() <= SPIN_MOMENT_TOLERANCE * e.scale {
                return Ok(root(b, &e, 0.0));
            }
            (e.moment, e.circ, e.slope)
        };
        if fb.signum() != m0.signum() {
            break;
        }
        tries += 1;
        if tries >= 80 {
            return Err(LossError::SpinBracket {
                roller,
                spin_rad_s: b,
                moment_nm: fb,
            });
        }
        h = h.max((b - a).abs()) * 2.0;
        (a, fa, ca, da) = (b, fb, cb, db);
    }
    // [a, b] brackets the root; (x, fx, dx) is the latest point, Newton's base.
    let (mut x, mut fx, mut dx) = (b, fb, db);
    let mut widths = [f64::INFINITY; 2];
    let (mut s, mut fs, mut scale) = (b, fb, sc0);
    for _ in 0..200 {
        let (lo, hi) = (a.min(b), a.max(b));
        let width = hi - lo;
        let newton = x - fx / dx;
        let inside = dx < 0.0 && newton.is_finite() && newton > lo && newton < hi;
        // widths[1] is the bracket two steps ago (∞ at first).
        s = if inside && (width <= 0.5 * widths[1] || widths[1].is_infinite()) {
            newton
        } else {
            0.5 * (a + b)
        };
        widths = [width, widths[0]];
        let e = eval(s)?;
        let (m, sc, c, d) = (e.moment, e.scale, e.circ, e.slope);
        fs = m;
        scale = sc;
        if m.abs() <= SPIN_MOMENT_TOLERANCE * sc {
            return Ok(root(s, &e, 0.0));
        }
        if m.signum() == fb.signum() {
            b = s;
            fb = m;
            cb = c;
        } else {
            a = s;
            fa = m;
            ca = c;
        }
        if (b - a).abs() <= 1e-12 * s.abs().max(1.0) {
            let spread = (ca - cb).abs().max((c - ca).abs()).max((c - cb).abs());
            return Ok(root(s, &e, spread));
        }
        (x, fx, dx) = (s, m, d);
    }
    let _ = fa;
    Err(LossError::SpinNotConverged {
        roller,
        spin_rad_s: s,
        moment_nm: fs,
        scale_nm: scale,
    })
}

/// A spin root ([`solve_spin`]).
struct SpinRoot {
    /// ω_s, rad/s.
    spin_rad_s: f64,
    /// M(ω_s), N·m.
    residual_nm: f64,
    /// Σ|F·m| + |pocket moment| there, N·m.
    scale_nm: f64,
    /// The net traction's spread across the final bracket, N.
    spread_n: f64,
    /// Each raceway's sums at ω_s ([`SpinEval::contacts`]); `None` from a solver that does
    /// not keep them (the tests' reference).
    contacts: Option<[SkewedContact; 2]>,
}

/// The Illinois false position the Newton replaced, kept as the tests' reference.
#[cfg(test)]
fn solve_spin_illinois(
    r: &RollerKinematics,
    roller: usize,
    common: &LossInputs,
    wc: f64,
    guess: f64,
    step: f64,
) -> Result<SpinRoot, LossError> {
    let root = |s: f64, m: f64, sc: f64, spread: f64| SpinRoot {
        spin_rad_s: s,
        residual_nm: m,
        scale_nm: sc,
        spread_n: spread,
        contacts: None,
    };
    let eval = |s: f64| spin_moment(r, roller, common, wc, s);
    let (m0, sc0, c0) = eval(guess)?;
    if m0.abs() <= SPIN_MOMENT_TOLERANCE * sc0 {
        return Ok(root(guess, m0, sc0, 0.0));
    }
    // M falls with ω_s: a positive moment means the root lies above.
    let dir = if m0 > 0.0 { 1.0 } else { -1.0 };
    let mut h = if step.is_finite() && step > 0.0 {
        step
    } else {
        0.05 * guess.abs().max(1.0)
    };
    let (mut a, mut fa, mut ca) = (guess, m0, c0);
    let (mut b, mut fb, mut cb) = (guess, m0, c0);
    let mut found = false;
    for _ in 0..80 {
        b = guess + dir * h;
        (fb, _, cb) = eval(b)?;
        if fb.signum() != m0.signum() {
            found = true;
            break;
        }
        a = b;
        fa = fb;
        ca = cb;
        h *= 2.0;
    }
    if !found {
        return Err(LossError::SpinBracket {
            roller,
            spin_rad_s: b,
            moment_nm: fb,
        });
    }
    // Illinois false position on [a, b] with M(a), M(b) of opposite signs.
    let mut side = 0i8;
    let (mut s, mut fs, mut scale) = (b, fb, sc0);
    for _ in 0..200 {
        s = (a * fb - b * fa) / (fb - fa);
        if !s.is_finite() || s <= a.min(b) || s >= a.max(b) {
            s = 0.5 * (a + b);
        }
        let (m, sc, c) = eval(s)?;
        fs = m;
        scale = sc;
        if m.abs() <= SPIN_MOMENT_TOLERANCE * sc {
            return Ok(root(s, m, sc, 0.0));
        }
        if (b - a).abs() <= 1e-12 * s.abs().max(1.0) {
            return Ok(root(
                s,
                m,
                sc,
                (ca - cb).abs().max((c - ca).abs()).max((c - cb).abs()),
            ));
        }
        if m.signum() == fb.signum() {
            b = s;
            fb = m;
            cb = c;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            a = s;
            fa = m;
            ca = c;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        }
    }
    Err(LossError::SpinNotConverged {
        roller,
        spin_rad_s: s,
        moment_nm: fs,
        scale_nm: scale,
    })
}

/// A spin root finder's signature ([`solve_spin`]).
type SpinSolver =
    fn(&RollerKinematics, usize, &LossInputs, f64, f64, f64) -> Result<SpinRoot, LossError>;

/// One roller's spin at a cage speed: the solved spin and its balance.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RollerSpin {
    /// ω_s about the roller axis relative to the cage, rad/s.
    pub spin_rad_s: f64,
    /// M(ω_s), the residual moment about the roller axis, N·m.
    pub residual_nm: f64,
    /// Σ|F_k·m_k| + |pocket moment|, N·m (the residual's scale).
    pub scale_nm: f64,
    /// False for a roller with no loaded lamina: it keeps the statics' spin.
    pub balanced: bool,
    /// The change of the roller's net circumferential traction across the spin's final
    /// bracket when M is near-vertical at the root (0 when the residual closed it), N: the
    /// resolution of the force it passes to its pocket.
    pub circumferential_spread_n: f64,
    /// The spins at which the inner / outer contact rolls without sliding at its load
    /// centroid, Σq·(ring_arm·Δω)/Σq·m, rad/s (`None` for an unloaded contact).
    pub rolling_spin_inner_rad_s: Option<f64>,
    /// As `rolling_spin_inner_rad_s`, outer contact.
    pub rolling_spin_outer_rad_s: Option<f64>,
    /// Each raceway's sums at this spin, as the breakdown's unskewed roller forms them
    /// ([`SpinEval::contacts`]; all 0 for a roller with no loaded lamina): what the cage
    /// balance reads per cage speed. `None` from a solver that does not keep them.
    #[serde(skip)]
    pub(super) contacts: Option<[SkewedContact; 2]>,
}

impl LossKinematics {
    /// The same kinematics with the rollers' skew on ([`losses_skewed`]).
    pub fn skewed(mut self) -> Self {
        self.with_skew = true;
        self
    }

    /// The statics' spin carried to cage speed `wc`: App. C's spin scales with the inner
    /// ring's speed relative to the cage (as the statics scale it for a measured cage).
    fn spin_guess(&self, wc: f64) -> f64 {
        let wi = self.common.inner_speed_rad_s;
        let d = wi - self.statics_cage_rad_s;
        if d != 0.0 && (wi - wc).is_finite() {
            self.statics_spin_rad_s * (wi - wc) / d
        } else {
            self.statics_spin_rad_s
        }
    }

    /// Each roller's spin at cage speed `wc`, rad/s (module notes "Roller spin").
    ///
    /// # Errors
    /// [`LossError::SpinBracket`] / [`LossError::SpinNotConverged`] with the numbers, or a
    /// lamina / pocket input error.
    pub fn spins_at(&self, wc: f64) -> Result<Vec<RollerSpin>, LossError> {
        self.spins_from(wc, None)
    }

    /// Each roller's spin at cage speed `wc` from a start per roller: `warm[k]` = (guess,
    /// first bracket step), rad/s (a previous cage speed's spins carried over); without
    /// it, the middle of the roller's two rolling spins with half their difference as the
    /// step (the balance lies between them for a roller in the load zone), or for a
    /// roller loaded at one raceway that contact's rolling spin and a step of 5 %.
    fn spins_from(
        &self,
        wc: f64,
        warm: Option<&[(f64, f64)]>,
    ) -> Result<Vec<RollerSpin>, LossError> {
        self.spins_with(wc, warm, solve_spin)
    }

    /// The spins by the Illinois false position the Newton replaced (tests' reference).
    #[cfg(test)]
    pub(super) fn spins_illinois(&self, wc: f64) -> Result<Vec<RollerSpin>, LossError> {
        self.spins_with(wc, None, solve_spin_illinois)
    }

    fn spins_with(
        &self,
        wc: f64,
        warm: Option<&[(f64, f64)]>,
        solver: SpinSolver,
    ) -> Result<Vec<RollerSpin>, LossError> {
        let guess = self.spin_guess(wc);
        let ring_w = [self.common.inner_speed_rad_s, self.common.outer_speed_rad_s];
        self.rollers
            .iter()
            .enumerate()
            .map(|(k, r)| {
                let rolling = |side: usize| {
                    let (mut num, mut den) = (0.0, 0.0);
                    for l in &r.sides[side] {
                        num += l.slice.load_n * l.ring_arm_m * (ring_w[side] - wc);
                        den += l.slice.load_n * l.spin_arm_m;
                    }
                    (den != 0.0).then(|| num / den)
                };
                let (ri, ro) = (rolling(0), rolling(1));
                if r.sides.iter().all(Vec::is_empty) {
                    return Ok(RollerSpin {
                        spin_rad_s: guess,
                        residual_nm: 0.0,
                        scale_nm: 0.0,
                        balanced: false,
                        circumferential_spread_n: 0.0,
                        rolling_spin_inner_rad_s: ri,
                        rolling_spin_outer_rad_s: ro,
                        contacts: Some([SkewedContact::default(); 2]),
                    });
                }
                let (g, step) = match (warm.and_then(|w| w.get(k)), ri, ro) {
                    (Some(&w), _, _) => w,
                    (None, Some(a), Some(b)) => (0.5 * (a + b), 0.5 * (a - b).abs()),
                    (None, Some(a), None) | (None, None, Some(a)) => (a, 0.05 * a.abs()),
                    (None, None, None) => (guess, 0.05 * guess.abs()),
                };
                let step = step.max(1e-9 * g.abs()).max(1e-12);
                let root = solver(r, k, &self.common, wc, g, step)?;
                Ok(RollerSpin {
                    spin_rad_s: root.spin_rad_s,
                    residual_nm: root.residual_nm,
                    scale_nm: root.scale_nm,
                    balanced: true,
                    circumferential_spread_n: root.spread_n,
                    rolling_spin_inner_rad_s: ri,
                    rolling_spin_outer_rad_s: ro,
                    contacts: root.contacts,
                })
            })
            .collect()
    }

    /// The moment about roller `k`'s axis at spin `spin` and cage speed `wc`, N·m (the
    /// balance [`Self::spins_at`] zeroes; for tests and reports).
    ///
    /// # Errors
    /// As [`Self::spins_at`]; [`LossError::BadInput`] for a roller index out of range.
    pub fn roller_moment_nm(&self, k: usize, wc: f64, spin: f64) -> Result<f64, LossError> {
        let r = self.rollers.get(k).ok_or(LossError::BadInput {
            name: "roller index",
            value: k as f64,
            allowed: "below the roller count",
        })?;
        spin_moment(r, k, &self.common, wc, spin).map(|(m, _, _)| m)
    }

    /// The loss inputs at cage speed `wc` with each roller at its spin.
    ///
    /// # Errors
    /// As [`Self::spins_at`].
    pub fn inputs_at(&self, wc: f64) -> Result<LossInputs, LossError> {
        let spins = self.spins_at(wc)?;
        Ok(self.inputs_with(wc, &spins))
    }

    /// The breakdown at cage speed `wc` with the rollers at `spins`: the unskewed rollers'
    /// raceway sums from their spin solves ([`RollerSpin::contacts`], what the breakdown's
    /// `roller_skews` would integrate once more; skewed rollers are searched by the
    /// breakdown), the guide ring's search from `ring`.
    ///
    /// # Errors
    /// As [`loss_breakdown`].
    pub(super) fn breakdown_at(
        &self,
        wc: f64,
        spins: &[RollerSpin],
        ring: Option<RingSpeedGuess>,
    ) -> Result<LossBreakdown, LossError> {
        let inputs = self.inputs_with(wc, spins);
        let skews = if self.with_skew {
            None
        } else {
            let geometry = unskewed_geometry(&inputs);
            spins
                .iter()
                .map(|x| x.contacts.map(|c| unskewed_from_contacts(&geometry, c)))
                .collect::<Option<Vec<_>>>()
        };
        breakdown_with(&inputs, skews, ring)
    }

    /// The loss inputs at cage speed `wc` with the rollers at `spins`.
    pub(super) fn inputs_with(&self, wc: f64, spins: &[RollerSpin]) -> LossInputs {
        let ring_w = [self.common.inner_speed_rad_s, self.common.outer_speed_rad_s];
        let mut out = self.common.clone();
        out.cage_speed_rad_s = wc;
        out.rollers = self
            .rollers
            .iter()
            .zip(spins)
            .map(|(r, sp)| {
                let s = sp.spin_rad_s;
                let [inner, outer] = [0, 1].map(|k| {
                    r.sides[k]
                        .iter()
                        .map(|l| slice_at(l, ring_w[k], wc, s))
                        .collect::<Vec<_>>()
                });
                RollerLossInput {
                    row: r.row,
                    inner,
                    outer,
                    guide_ring_load_n: r.guide_ring_load_n,
                    pocket_force_n: None,
                    orbital_speed_rad_s: wc,
                    roller_end_speed_m_s: r.end_spin_arm_m * s,
                    surface_speed_m_s: s * self.common.pocket.roller_radius_m,
                    spin_rad_s: s,
                    skew_axis_axial_component: r.skew_axis_axial_component,
                    skew: self.with_skew.then(|| RollerSkewSpeeds {
                        inner_m_s: r.sides[0].iter().map(|l| l.spin_arm_m * s).collect(),
                        outer_m_s: r.sides[1].iter().map(|l| l.spin_arm_m * s).collect(),
                        prescribed_skew_rad: None,
                    }),
                }
            })
            .collect();
        out
    }

    /// The cage speed of the cage's torque balance (imbalance 0), rad/s, with the
    /// breakdown there. The imbalance T(ω_c) is nearly linear near its root (the pockets'
    /// forces follow the rollers' mean slip), so: secant steps from `start` (the first
    /// step 1e-3 of the speed toward the root's side), each pushed 20 % past the secant's
    /// root until T changes sign (kept between the rings' speeds), then the Illinois false
    /// position on that bracket (srb12: the plain secant step, and a plain first Newton
    /// step in the spin solves, were tried and made the radial and axial cases slower,
    /// 139 → 195 and 250 → 523 ms in `double_row_losses`). Every evaluation re-solves each
    /// roller's spin, warm-started from the previous two cage speeds' spins (linear
    /// extrapolation per roller, the first bracket step half the extrapolated change): 2–4
    /// moment evaluations per roller instead of ~20 from a cold start; and the guide
    /// ring's balance from the previous speeds' ring speeds ([`CageEvaluations`]).
    ///
    /// # Errors
    /// [`LossError::CageBracket`] when the imbalance keeps its sign up to the ring speeds,
    /// [`LossError::CageNotConverged`], or the breakdown's errors.
    pub fn balanced_cage(&self, start: f64) -> Result<(f64, LossBreakdown), LossError> {
        let wi = self.common.inner_speed_rad_s;
        let wo = self.common.outer_speed_rad_s;
        let (lo, hi) = (wi.min(wo), wi.max(wo));
        let mut cage = CageEvaluations::new(self);
        let mut eval = |w: f64| {
            cage.eval(w)
                .map(|p| (p.imbalance_nm, p.tolerance_nm, p.breakdown))
        };
        if hi - lo <= 0.0 {
            let b = loss_breakdown(&self.inputs_at(start)?)?;
            return Ok((start, b));
        }
        let start = start.clamp(lo, hi);
        let (f0, tol0, b0) = eval(start)?;
        if f0.abs() <= tol0 {
            return Ok((start, b0));
        }
        // The net traction drives the cage forward while it lags: the imbalance falls as
        // the cage speeds up (toward ω_i when ω_i > ω_o).
        let up = if (f0 > 0.0) == (wi >= wo) { 1.0 } else { -1.0 };
        let (mut a, mut fa) = (start, f0);
        let mut b = (start + up * 1e-3 * start.abs().max(1e-3 * (hi - lo))).clamp(lo, hi);
        let (mut fb, mut scb, mut bb) = eval(b)?;
        let mut bracketed = fb.signum() != fa.signum();
        for _ in 0..60 {
            if bracketed || fb.abs() <= scb {
                break;
            }
            if b == lo || b == hi {
                return Err(LossError::CageBracket {
                    start_rpm: start * RPM,
                    end_rpm: b * RPM,
                    imbalance_start_nm: f0,
                    imbalance_end_nm: fb,
                });
            }
            // Secant root pushed 20 % further, at least doubling the last step when the
            // secant points the wrong way or stalls.
            let slope = (fb - fa) / (b - a);
            let by_secant = -fb / slope;
            let step = if by_secant.is_finite() && by_secant * up > 0.0 {
                1.2 * by_secant
            } else {
                2.0 * (b - a)
            };
            let w = (b + step).clamp(lo, hi);
            a = b;
            fa = fb;
            b = w;
            (fb, scb, bb) = eval(b)?;
            bracketed = fb.signum() != fa.signum();
        }
        if fb.abs() <= scb {
            return Ok((b, bb));
        }
        if !bracketed {
            return Err(LossError::CageBracket {
                start_rpm: start * RPM,
                end_rpm: b * RPM,
                imbalance_start_nm: f0,
                imbalance_end_nm: fb,
            });
        }
        // Illinois false position on [a, b], T(a)·T(b) < 0. `ta`, `tb` keep the true
        // imbalances at the ends (Illinois halves `fa`, `fb`).
        let (mut ta, mut tb) = (fa, fb);
        let mut side = 0i8;
        let mut last = (b, fb);
        for _ in 0..100 {
            let mut w = (a * fb - b * fa) / (fb - fa);
            if !w.is_finite() || w <= a.min(b) || w >= a.max(b) {
                w = 0.5 * (a + b);
            }
            let (f, tol, mut br) = eval(w)?;
            last = (w, f);
            if f.abs() <= tol {
                return Ok((w, br));
            }
            // A guard: before the ATZ law was regularised at its rolling point
            // (`lamina_friction` module notes) T(ω_c) stepped by up to ≈ 1.4 N·m across
            // 1e-9 rad/s (a lamina switching its limiting shear, e^{αp} ≈ 1e17 at 2 GPa);
            // now such a step is a chord over |v| < v_reg, steep but resolved (noise 0 on
            // the shipped deck). Should T still step, once the bracket is below 1e-9 of the
            // ring speed the cage speed is known to that, and the step across the bracket is
            // the torque's resolution, reported as `cage_torque_noise_nm`.
            if (b - a).abs() <= CAGE_SPEED_RESOLUTION * wi.abs().max(wo.abs()).max(1.0) {
                let jump = (ta - tb).abs().max(f.abs());
                br.cage_torque_noise_nm = br.cage_torque_noise_nm.max(jump);
                return Ok((w, br));
            }
            if f.signum() == fb.signum() {
                b = w;
                fb = f;
                tb = f;
                if side == 1 {
                    fa *= 0.5;
                }
                side = 1;
            } else {
                a = w;
                fa = f;
                ta = f;
                if side == -1 {
                    fb *= 0.5;
                }
                side = -1;
            }
        }
        Err(LossError::CageNotConverged {
            cage_rpm: last.0 * RPM,
            imbalance_nm: last.1,
        })
    }
}

/// One evaluation of the cage's torque balance: the breakdown at a cage speed with every
/// roller at its spin, the imbalance and the tolerance it is accepted within.
struct CagePoint {
    /// The cage's net torque, N·m.
    imbalance_nm: f64,
    /// The larger of [`CAGE_TORQUE_TOLERANCE`] × the torque's scale and the torque's
    /// resolution ([`LossBreakdown::cage_torque_noise_nm`]), N·m.
    tolerance_nm: f64,
    breakdown: LossBreakdown,
}

/// The cage-speed evaluations of [`LossKinematics::balanced_cage`] with their warm starts:
/// every evaluation re-solves each roller's spin from the previous cage speeds' spins
/// (one previous speed: its spins, the first bracket step the spin's relative change at
/// most, ω_s scaling with a ring's speed relative to the cage; two: linear extrapolation
/// per roller, the step half the extrapolated change), 1–3 moment evaluations per roller
/// instead of ~20 from a cold start. Per cage speed only what the balance reads is
/// computed afresh: the unskewed rollers' raceway sums come from their spin solves' last
/// evaluations ([`RollerSpin::contacts`], the numbers the breakdown would integrate once
/// more), and the guide ring's search starts from the previous speeds' ring speeds
/// (extrapolated like the spins; the same 1e-13 tolerance,
/// `guide_ring::RING_SPEED_TOLERANCE`); the rest of the breakdown is closed forms.
struct CageEvaluations<'a> {
    k: &'a LossKinematics,
    /// The last two (cage speed, spins, guide ring speed), oldest first.
    hist: Vec<(f64, Vec<f64>, Option<f64>)>,
}

impl<'a> CageEvaluations<'a> {
    fn new(k: &'a LossKinematics) -> Self {
        CageEvaluations {
            k,
            hist: Vec::with_capacity(2),
        }
    }

    /// Per roller (guess, first bracket step) at cage speed `w` from the history.
    fn warm(&self, w: f64) -> Option<Vec<(f64, f64)>> {
        let (wi, wo) = (
            self.k.common.inner_speed_rad_s,
            self.k.common.outer_speed_rad_s,
        );
        match self.hist.as_slice() {
            [] => None,
            [(w1, s1, _)] => {
                let rel = (w - w1).abs() / (w1 - wo).abs().min((wi - w1).abs()).max(1e-9);
                Some(s1.iter().map(|&x| (x, x.abs() * rel.max(1e-6))).collect())
            }
            [.., (w0, s0, _), (w1, s1, _)] => {
                let d = w1 - w0;
                Some(
                    s0.iter()
                        .zip(s1)
                        .map(|(&x0, &x1)| {
                            let g = if d != 0.0 {
                                x1 + (x1 - x0) / d * (w - w1)
                            } else {
                                x1
                            };
                            (g, (0.5 * (g - x1).abs()).max(1e-6 * g.abs()))
                        })
                        .collect(),
                )
            }
        }
    }

    /// The guide ring's start at cage speed `w`: the last ring speed with a step of the
    /// cage's change (one previous speed), or the two last extrapolated linearly in the cage
    /// speed with half the extrapolated change as the step; `None` without a history.
    fn ring_guess(&self, w: f64) -> Option<RingSpeedGuess> {
        match self.hist.as_slice() {
            [.., (w0, _, Some(g0)), (w1, _, Some(g1))] if w1 != w0 => {
                let g = g1 + (g1 - g0) / (w1 - w0) * (w - w1);
                Some(RingSpeedGuess {
                    speed_rad_s: g,
                    step_rad_s: (0.5 * (g - g1).abs()).max(1e-9 * g1.abs()),
                })
            }
            [.., (w1, _, Some(g1))] => Some(RingSpeedGuess {
                speed_rad_s: *g1,
                step_rad_s: (w - w1).abs().max(1e-9 * g1.abs()),
            }),
            _ => None,
        }
    }

    /// The balance at cage speed `w` (rad/s), the spins and the guide ring warm-started and
    /// remembered.
    fn eval(&mut self, w: f64) -> Result<CagePoint, LossError> {
        #[cfg(test)]
        CAGE_TRACE.with(|t| t.borrow_mut().push(w));
        let warm = self.warm(w);
        let spins = self.k.spins_from(w, warm.as_deref())?;
        let mut b = self.k.breakdown_at(w, &spins, self.ring_guess(w))?;
        if self.hist.len() == 2 {
            self.hist.remove(0);
        }
        self.hist.push((
            w,
            spins.iter().map(|x| x.spin_rad_s).collect(),
            b.guide_ring.as_ref().map(|g| g.speed_rad_s),
        ));
        let dm = self.k.common.pitch_diameter_m;
        b.cage_torque_noise_nm = spins
            .iter()
            .map(|x| x.circumferential_spread_n)
            .sum::<f64>()
            * 0.5
            * dm;
        let scale: f64 = b
            .rollers
            .iter()
            .map(|r| r.circumferential_force_n.abs())
            .sum::<f64>()
            * 0.5
            * dm
            + b.cage_land_torque_nm.abs()
            + b.losses.friction_torque_nm;
        // Accepted within the larger of the tolerance and the noise (field doc).
        Ok(CagePoint {
            imbalance_nm: b.losses.cage_torque_imbalance_nm,
            tolerance_nm: (CAGE_TORQUE_TOLERANCE * scale).max(b.cage_torque_noise_nm),
            breakdown: b,
        })
    }
}

const RPM: f64 = 30.0 / std::f64::consts::PI;

/// The computed cage speed's resolution, relative to the faster ring: where the cage torque
/// steps across its balance (see [`LossKinematics::balanced_cage`]) the speed is accepted
/// once bracketed this closely, the step reported as `cage_torque_noise_nm`.
pub const CAGE_SPEED_RESOLUTION: f64 = 1e-9;

/// The statics reduced to the loss model's kinematics (module notes; issue 27 Model 2–4):
///
/// * per loaded lamina of each raceway: its load and width (the statics), the Hertz
///   half-width (the row's stress stage), p₀ = 2q/(π·b·L), the film (the row's film stage,
///   at the statics' spin: kept when the spin moves, a film ∝ u^0.67 changing by 2/3 of the
///   entrainment's relative change), and the two arms of the sliding speed
///   (`kinematics::sliding_velocity`, raceway minus roller, seed 000 eq. 8.1–8.5);
/// * per roller: the guide ring's end load (the statics' unilateral contact) and the
///   end contact point's arm ((a × (p − c))·ê_θ, nearly 0: the contact lies on the roller
///   axis but for the roller's tilt);
/// * the lubricant at the measured temperature (Walther), the deck's pressure–viscosity
///   and traction law, the ATZ constants the statics' row bearing carries; drag off (the
///   seed has none; no deck key yet).
///
/// # Errors
/// [`LossError::Viscosity`] for an oil outside D341's range, [`LossError::MissingStage`]
/// if a row's stresses or films are absent.
pub fn loss_kinematics(a: &DoubleRowAnalysis) -> Result<LossKinematics, LossError> {
    let input = &a.input;
    let g = &input.geometry;
    let eta = input.try_viscosity_pa_s()?;
    let lb = &a.row_bearing.lubricant;
    let rheology = FilmRheology {
        viscosity_pa_s: eta,
        pressure_viscosity_pa_inv: input.lubricant.pressure_viscosity_pa_inv,
        transition_shear_stress_pa: lb.transition_shear_stress_pa,
        limiting_traction_coefficient: lb.limiting_traction_coefficient,
    };
    let law = match input.lubricant.traction {
        Traction::Atz => RacewayTractionLaw::Atz,
        Traction::NewtonianEq3 => RacewayTractionLaw::NewtonianEq3,
    };
    let wi = input.operating.inner_speed_rad_s;
    let wc = a.dynamic.cage_rad_s;
    let beta = g.contact_angle_rad;
    let a0 = [beta.cos(), -beta.sin(), 0.0];
    let half_l = 0.5 * g.roller_length_m;
    let re = g.roller_end_radius_m;
    let with_guide = input.guide_ring.present && g.rows >= 2;
    let mut rollers = Vec::with_capacity(a.combined.rollers.len());
    for (row, ra) in a.rows.iter().enumerate() {
        let st = ra.stresses.as_ref().ok_or(LossError::MissingStage {
            stage: "stress",
            row: row + 1,
        })?;
        let films = ra.films.as_ref().ok_or(LossError::MissingStage {
            stage: "film",
            row: row + 1,
        })?;
        for (j, r) in ra.load.rollers.iter().enumerate() {
            let (Some(rc), Some(hz), Some(fl)) =
                (ra.contacts.get(j), st.laminae.get(j), films.laminae.get(j))
            else {
                return Err(LossError::MissingStage {
                    stage: "contact, stress or film (a roller is missing)",
                    row: row + 1,
                });
            };
            let (s, c) = r.tilt_rad.sin_cos();
            let axis = [c * a0[0] - s * a0[1], s * a0[0] + c * a0[1], 0.0];
            let centre = [
                r.axial_displacement_m,
                r.radial_displacement_m + 0.5 * g.pitch_diameter_m,
                0.0,
            ];
            let mut sides: [Vec<LaminaKinematics>; 2] = [Vec::new(), Vec::new()];
            for (i, l) in r.laminae.iter().enumerate() {
                for (k, side) in sides.iter_mut().enumerate() {
                    let (Some(ct), Some(h)) = (rc.get(i).map(|p| p[k]), hz.get(i).map(|p| p[k]))
                    else {
                        continue;
                    };
                    if ct.load_n <= 0.0 {
                        continue;
                    }
                    let pt = if k == 0 {
                        l.inner_point_m
                    } else {
                        l.outer_point_m
                    };
                    let p = [pt[0], pt[1], 0.0];
                    let strip = HertzStrip {
                        load_n: ct.load_n,
                        half_width_m: h.half_width_m,
                        width_m: ct.width_m,
                    };
                    side.push(LaminaKinematics {
                        slice: LaminaSlice {
                            load_n: ct.load_n,
                            half_width_m: h.half_width_m,
                            length_m: ct.width_m,
                            peak_pressure_pa: strip.peak_pressure_pa(),
                            rolling_speed_m_s: 0.0,
                            sliding_speed_m_s: 0.0,
                            film_m: fl.get(i).and_then(|p| p[k]).unwrap_or(0.0),
                            // y = (p − c)·a, the lamina's arm about the skew axis
                            // (exactly the projection, tilt included).
                            axial_offset_m: (p[0] - centre[0]) * axis[0]
                                + (p[1] - centre[1]) * axis[1],
                        },
                        ring_arm_m: sliding_velocity(p, 1.0, 0.0, centre, axis, 0.0),
                        spin_arm_m: -sliding_velocity(p, 0.0, 0.0, centre, axis, 1.0),
                        ring_axis_distance_m: ct.ring_axis_distance_m,
                        roller_axis_distance_m: ct.roller_axis_distance_m,
                        arm_m: [p[0] - centre[0], p[1] - centre[1]],
                        tangent: {
                            let n = if k == 0 {
                                l.inner_normal
                            } else {
                                l.outer_normal
                            };
                            let t = [n[1], -n[0]];
                            if t[0] * axis[0] + t[1] * axis[1] >= 0.0 {
                                t
                            } else {
                                [-t[0], -t[1]]
                            }
                        },
                        hint: Cell::default(),
                    });
                }
            }
            // The end contact point: the end sphere's centre (L/2 − r_e along −a from the
            // roller centre) less r_e along the face normal a⁰; its speed relative to the
            // cage is ω_s·(a × (p − c))·ê_θ (the ring term cancels at a ring speed equal to
            // the cage's).
            let end_point = [
                centre[0] - (half_l - re) * axis[0] - re * a0[0],
                centre[1] - (half_l - re) * axis[1] - re * a0[1],
                0.0,
            ];
            rollers.push(RollerKinematics {
                row: u8::try_from(row + 1).unwrap_or(u8::MAX),
                sides,
                guide_ring_load_n: if with_guide { r.guide_force_n } else { 0.0 },
                skew_axis_axial_component: axis[1],
                end_spin_arm_m: -sliding_velocity(end_point, 0.0, 0.0, centre, axis, 1.0),
            });
        }
    }
    let d = derived_geometry(input);
    let guide_ring = with_guide.then(|| GuideRingGeometry {
        roller_end_radius_m: re,
        reduced_modulus_pa: guide_reduced_modulus_pa(input),
        contact_radius_m: d.guide_contact_radius_m,
        bore_radius_m: d.guide_bore_radius_m,
        width_m: input.guide_ring.width_m,
        bore_clearance_m: 0.5 * input.guide_ring.bore_clearance_m,
    });
    let (kind, radius) = match input.cage.land {
        DeckCageLand::GuideRing => (CageLandKind::GuideRing, d.guide_contact_radius_m),
        DeckCageLand::InnerRing => (CageLandKind::InnerRing, d.guide_bore_radius_m),
    };
    let kinematic = DynamicSpeeds::app_c_estimate(&a.row_bearing).cage_rad_s;
    Ok(LossKinematics {
        rollers,
        common: LossInputs {
            rollers: Vec::new(),
            inner_speed_rad_s: wi,
            outer_speed_rad_s: 0.0,
            cage_speed_rad_s: wc,
            kinematic_cage_speed_rad_s: kinematic,
            guide_ring,
            pocket: PocketGeometry {
                roller_radius_m: 0.5 * g.roller_diameter_m,
                length_m: g.roller_length_m,
                pocket_clearance_m: input.cage.pocket_clearance_m,
            },
            cage_land: CageLand {
                kind,
                radius_m: radius,
                width_m: input.guide_ring.width_m,
                radial_clearance_m: 0.5 * input.cage.pocket_clearance_m,
            },
            pitch_diameter_m: g.pitch_diameter_m,
            lubricant: LossLubricant {
                rheology,
                law,
                density_kg_m3: input.lubricant.density_kg_m3,
                drag_factor: None,
            },
        },
        statics_cage_rad_s: wc,
        statics_spin_rad_s: a.dynamic.roller_spin_rad_s,
        computed_cage: input.cage.speed == CageSpeedSource::Computed,
        with_skew: false,
    })
}

/// The loss model's inputs at the cage speed the statics used (the measured one, or the
/// statics' §7 estimate), each roller at the spin of its moment balance
/// ([`loss_kinematics`] then [`LossKinematics::inputs_at`]).
///
/// # Errors
/// As [`loss_kinematics`] and [`LossKinematics::inputs_at`].
pub fn loss_inputs(a: &DoubleRowAnalysis) -> Result<LossInputs, LossError> {
    let k = loss_kinematics(a)?;
    k.inputs_at(k.statics_cage_rad_s)
}

/// The loss breakdown of a solved double-row bearing. With `cage.speed = "measured"` at
/// the measured cage speed (the imbalance reported); with `"computed"` at the cage speed of
/// the cage's torque balance, bracketed around the statics' §7 estimate (the loads stay the
/// statics', whose centrifugal force used the §7 speed: `centrifugal_cage_speed_rpm` beside
/// `cage_speed_rpm` shows the inconsistency). The signature is stable (the osculation
/// optimiser's objective).
///
/// # Errors
/// [`LossError`] naming the stage, roller, raceway, lamina or input at fault, or the
/// cage's or a roller's balance that could not be bracketed or closed.
pub fn losses(a: &DoubleRowAnalysis) -> Result<LossBreakdown, LossError> {
    losses_of(loss_kinematics(a)?)
}

/// [`losses`] with the loaded rollers' skew (`skew.rs`, module notes "Skew"): each roller at
/// the skew its yaw balance allows, the axial tractions' end loads on the guide ring.
/// Not the default: on the shipped deck nearly every loaded roller runs to the pocket's
/// stop ψ = c_p/L (the raceways' self-guidance needs a skew degree of freedom of the
/// statics), the skew's loss is 33–52 % of the total and the spins, solved at ψ = 0, are off
/// their balance by 12–15 % of the traction moments (`losses_tests::skew_couplings_print`).
///
/// # Errors
/// As [`losses`].
pub fn losses_skewed(a: &DoubleRowAnalysis) -> Result<LossBreakdown, LossError> {
    losses_of(loss_kinematics(a)?.skewed())
}

/// The loaded rollers' self-guidance: skew and axial walk with each roller's balance
/// (`[cage] skew = "self-guided"`).
#[path = "kellstrom.rs"]
pub mod kellstrom;

fn losses_of(k: LossKinematics) -> Result<LossBreakdown, LossError> {
    let mut b = if k.computed_cage {
        let (wc, mut b) = k.balanced_cage(k.statics_cage_rad_s)?;
        b.losses.cage_speed_rpm = wc * RPM;
        b.cage_speed_computed = true;
        b
    } else {
        let wc = k.statics_cage_rad_s;
        k.breakdown_at(wc, &k.spins_at(wc)?, None)?
    };
    b.centrifugal_cage_speed_rpm = k.statics_cage_rad_s * RPM;
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rheology() -> FilmRheology {
        FilmRheology {
            viscosity_pa_s: 0.017,
            pressure_viscosity_pa_inv: 2.0e-8,
            transition_shear_stress_pa: 5.0e6,
            limiting_traction_coefficient: 0.06,
        }
    }

    fn lamina(q: f64, v: f64, y: f64) -> LaminaSlice {
        let (b, l) = (1.2e-4, 2.5e-4);
        LaminaSlice {
            load_n: q,
            half_width_m: b,
            length_m: l,
            peak_pressure_pa: 2.0 * q / (std::f64::consts::PI * b * l),
            rolling_speed_m_s: 8.0,
            sliding_speed_m_s: v,
            film_m: 2.5e-7,
            axial_offset_m: y,
        }
    }

    /// A 2 × 13-roller bearing with a spread of loads and sliding speeds that vary along
    /// the roller (so the skew term is not trivially 0).
    fn bearing(law: RacewayTractionLaw, speed_scale: f64) -> LossInputs {
        let (wi, wc) = (300.0 * speed_scale, 130.0 * speed_scale);
        let rollers = (0..26)
            .map(|k| {
                let q = 30.0 * (1.0 + (k % 13) as f64 / 13.0);
                let lam = |v0: f64| -> Vec<LaminaSlice> {
                    (0..9)
                        .map(|j| {
                            let y = (j as f64 - 4.0) * 1.3e-3;
                            let qj = q * (1.0 - (y / 7e-3).powi(2));
                            lamina(qj, speed_scale * (v0 + 40.0 * y), y)
                        })
                        .collect()
                };
                RollerLossInput {
                    row: if k < 13 { 1 } else { 2 },
                    inner: lam(0.05),
                    outer: lam(-0.03),
                    guide_ring_load_n: 20.0 + k as f64,
                    pocket_force_n: Some(5.0),
                    orbital_speed_rad_s: wc,
                    roller_end_speed_m_s: 0.02 * speed_scale,
                    surface_speed_m_s: 1.5 * speed_scale,
                    spin_rad_s: 250.0 * speed_scale,
                    skew_axis_axial_component: -0.2,
                    skew: None,
                }
            })
            .collect();
        LossInputs {
            rollers,
            inner_speed_rad_s: wi,
            outer_speed_rad_s: 0.0,
            cage_speed_rad_s: wc,
            kinematic_cage_speed_rad_s: wc,
            guide_ring: Some(GuideRingGeometry {
                roller_end_radius_m: 0.03,
                reduced_modulus_pa: 1.26e11,
                contact_radius_m: 0.031,
                bore_radius_m: 0.026,
                width_m: 0.006,
                bore_clearance_m: 1e-4,
            }),
            pocket: PocketGeometry {
                roller_radius_m: 0.006,
                length_m: 0.012,
                pocket_clearance_m: 3e-4,
            },
            cage_land: CageLand {
                kind: CageLandKind::GuideRing,
                radius_m: 0.033,
                width_m: 0.004,
                radial_clearance_m: 2e-4,
            },
            pitch_diameter_m: 0.065,
            lubricant: LossLubricant {
                rheology: rheology(),
                law,
                density_kg_m3: 860.0,
                drag_factor: Some(4.0),
            },
        }
    }

    /// Power identity: the seven terms sum to the total, and total = M·|ω_i − ω_o|, to
    /// 1e-12 relative; M_fi, M_fo are the raceway losses over the relative speed; shares
    /// sum to 100 %.
    #[test]
    fn power_identity() {
        for law in [RacewayTractionLaw::Atz, RacewayTractionLaw::NewtonianEq3] {
            let b = loss_breakdown(&bearing(law, 1.0)).expect("breakdown");
            let l = b.losses;
            let sum = l.raceway_inner_w
                + l.raceway_outer_w
                + l.guide_ring_w
                + l.cage_pockets_w
                + l.cage_land_w
                + l.skew_w
                + l.drag_w;
            assert!((sum - l.total_w).abs() < 1e-12 * l.total_w);
            assert!((l.friction_torque_nm * 300.0 - l.total_w).abs() < 1e-12 * l.total_w);
            let inner: f64 = b.rollers.iter().map(|r| r.inner_w).sum();
            assert!((l.friction_torque_inner_nm * 300.0 - inner).abs() < 1e-12 * inner);
            let s = l.shares_pct;
            let pct = s.raceway_inner
                + s.raceway_outer
                + s.guide_ring
                + s.cage_pockets
                + s.cage_land
                + s.skew
                + s.drag;
            assert!((pct - 100.0).abs() < 1e-10, "{pct}");
            // Every mechanism is active in this case, and the skew reaction dissipates.
            assert!(l.skew_w > 0.0 && l.guide_ring_w > 0.0 && l.cage_pockets_w > 0.0);
            assert!(l.cage_land_w > 0.0 && l.drag_w > 0.0);
        }
    }

    /// 0 rpm (every ring, cage and surface speed 0) ⇒ 0 W and 0 torques.
    #[test]
    fn zero_speed_zero_loss() {
        let b = loss_breakdown(&bearing(RacewayTractionLaw::Atz, 0.0)).expect("breakdown");
        assert_eq!(b.losses.total_w, 0.0);
        assert_eq!(b.losses.friction_torque_nm, 0.0);
        assert_eq!(b.losses.shares_pct, LossShares::default());
    }

    /// η = 0 ⇒ 0 W from every mechanism (drag included: ν = 0).
    #[test]
    fn inviscid_zero_loss() {
        for law in [RacewayTractionLaw::Atz, RacewayTractionLaw::NewtonianEq3] {
            let mut i = bearing(law, 1.0);
            i.lubricant.rheology.viscosity_pa_s = 0.0;
            let b = loss_breakdown(&i).expect("breakdown");
            assert_eq!(b.losses.total_w, 0.0, "{law:?}");
            assert_eq!(b.losses.cage_torque_imbalance_nm, 0.0);
        }
    }

    /// One roller, no guide ring, inner-ring land, drag off, the printed eq. 3 on two
    /// laminae per raceway: every term by hand from the formulas (eq. 3 slice force, the
    /// yaw moment Σy·F and its pocket reaction, Martin's pocket, Petroff, the cage torque
    /// with the yaw reaction's axial component), tolerance 1e-12.
    #[test]
    fn hand_built_case() {
        let rh = rheology();
        let inner = vec![lamina(20.0, 0.04, -3e-3), lamina(10.0, 0.10, 2e-3)];
        let outer = vec![lamina(25.0, -0.02, 0.0)];
        let inputs = LossInputs {
            rollers: vec![RollerLossInput {
                row: 1,
                inner: inner.clone(),
                outer: outer.clone(),
                guide_ring_load_n: 0.0,
                pocket_force_n: Some(3.0),
                orbital_speed_rad_s: 100.0,
                roller_end_speed_m_s: 0.0,
                surface_speed_m_s: 2.0,
                spin_rad_s: 2.0 / 0.006,
                skew_axis_axial_component: -0.2,
                skew: None,
            }],
            inner_speed_rad_s: 250.0,
            outer_speed_rad_s: 10.0,
            cage_speed_rad_s: 100.0,
            kinematic_cage_speed_rad_s: 100.0,
            guide_ring: None,
            pocket: PocketGeometry {
                roller_radius_m: 0.006,
                length_m: 0.012,
                pocket_clearance_m: 3e-4,
            },
            cage_land: CageLand {
                kind: CageLandKind::InnerRing,
                radius_m: 0.03,
                width_m: 0.005,
                radial_clearance_m: 1.5e-4,
            },
            pitch_diameter_m: 0.065,
            lubricant: LossLubricant {
                rheology: rh,
                law: RacewayTractionLaw::NewtonianEq3,
                density_kg_m3: 860.0,
                drag_factor: None,
            },
        };
        let b = loss_breakdown(&inputs).expect("breakdown");
        let l = b.losses;
        // Eq. 3 by hand: F = η·e^{α·q/A}·v/h·A, A = 2bL.
        let area = 2.0 * 1.2e-4 * 2.5e-4;
        let f = |q: f64, v: f64| 0.017 * f64::exp(2.0e-8 * q / area) * v / 2.5e-7 * area;
        let (f1, f2, f3) = (f(20.0, 0.04), f(10.0, 0.10), f(25.0, -0.02));
        let p_inner = f1 * 0.04 + f2 * 0.10;
        let p_outer = f3 * -0.02;
        // Yaw moment Σ y·F = −3e-3·f1 + 2e-3·f2 (the outer lamina at y = 0); its pocket
        // reaction: halves of length L/2 = 6 mm under F_s = 1.5·|M|/L, each a Martin film
        // (h₀ = C_w·η·ū·R·(L/2)/F_s, ū = 1 m/s, capped at c_p/2 = 1.5e-4 m) less the
        // half play's film, twice, times u_s = 2 m/s.
        let m = -3e-3 * f1 + 2e-3 * f2;
        let fs = 1.5 * m.abs() / 0.012;
        let per_len = |h0: f64| {
            0.017
                * 2.0
                * (2.0 * 0.006 / h0).sqrt()
                * (std::f64::consts::FRAC_PI_2 + 0.443_554_334_2)
                + 4.601_076_9 * 0.017 * 1.0 * (0.006 / h0).sqrt()
        };
        let hs: f64 = 4.894_968_5 * 0.017 * 1.0 * 0.006 * 0.006 / fs;
        assert!(
            hs < 1.5e-4,
            "{hs}: the couple lifts the film off the half play"
        );
        let skew = 2.0 * (per_len(hs) - per_len(1.5e-4)) * 0.006 * 2.0;
        assert!(
            (l.skew_w - skew).abs() < 1e-12 * skew,
            "{} {skew}",
            l.skew_w
        );
        assert!((l.raceway_inner_w - p_inner).abs() < 1e-12 * p_inner);
        assert!((l.raceway_outer_w - p_outer).abs() < 1e-12 * p_outer);
        // Pocket: h₀ = C_w·η·ū·R·L/F = 4.8949685·0.017·1·0.006·0.012/3, below c_p/2.
        let h0: f64 = 4.894_968_5 * 0.017 * 1.0 * 0.006 * 0.012 / 3.0;
        let drag = (0.017
            * 2.0
            * (2.0 * 0.006 / h0).sqrt()
            * (std::f64::consts::FRAC_PI_2 + 0.443_554_334_2)
            + 4.601_076_9 * 0.017 * 1.0 * (0.006 / h0).sqrt())
            * 0.012;
        assert!((l.cage_pockets_w - drag * 2.0).abs() < 1e-12 * drag);
        // Land on the inner ring: Δω = 100 − 250; T = 2πηR³LΔω/c, P = T·Δω.
        let t = 2.0 * std::f64::consts::PI * 0.017 * 0.03f64.powi(3) * 0.005 * 150.0 / 1.5e-4;
        assert!((l.cage_land_w - t * 150.0).abs() < 1e-12 * l.cage_land_w);
        assert_eq!((l.guide_ring_w, l.drag_w), (0.0, 0.0));
        let total = p_inner + p_outer + drag * 2.0 + t * 150.0 + skew;
        assert!((l.total_w - total).abs() < 1e-12 * total);
        assert!((l.friction_torque_nm - total / 240.0).abs() < 1e-12 * l.friction_torque_nm);
        assert!((l.friction_torque_inner_nm - p_inner / 240.0).abs() < 1e-12 * p_inner);
        // Cage: the roller's net traction at d_m/2, the yaw reaction's axial component
        // M·a_r, plus the land torque (+: the inner ring runs faster than the cage and drags
        // it forward).
        let imb = (f1 + f2 + f3) * 0.0325 + m * -0.2 + t;
        assert!((l.cage_torque_imbalance_nm - imb).abs() < 1e-12 * imb.abs());
        // Skew moment about the roller centre: Σ y·F.
        assert!((b.rollers[0].skew_moment_nm - m).abs() < 1e-15);
        assert!((b.rollers[0].skew_reaction_force_n - fs).abs() < 1e-12 * fs);
    }

    /// A guide-ring land without a guide ring is refused with both keys named.
    #[test]
    fn guide_ring_land_needs_a_guide_ring() {
        let mut i = bearing(RacewayTractionLaw::Atz, 1.0);
        i.guide_ring = None;
        let e = loss_breakdown(&i).expect_err("no ring");
        assert!(e.to_string().contains("guide-ring"), "{e}");
    }

    /// The contract's field names.
    #[test]
    fn contract_names() {
        let b = loss_breakdown(&bearing(RacewayTractionLaw::Atz, 1.0)).expect("breakdown");
        let j = serde_json::to_value(b.losses).expect("ser");
        for k in [
            "raceway_inner_w",
            "raceway_outer_w",
            "guide_ring_w",
            "cage_pockets_w",
            "cage_land_w",
            "skew_w",
            "drag_w",
            "total_w",
            "shares_pct",
            "friction_torque_inner_nm",
            "friction_torque_outer_nm",
            "friction_torque_nm",
            "cage_torque_imbalance_nm",
        ] {
            assert!(j.get(k).is_some(), "missing {k}");
        }
    }
}
