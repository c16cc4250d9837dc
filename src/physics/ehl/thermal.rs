//! The energy equation of a line-contact film with the solids as moving half-spaces
//! (seed 003 eqs. 23–34), SI, over plain slices: given x, p(x), h(x) and the two surface
//! speeds, the temperature across the film and into both solids, and where the heat goes.
//!
//! # Equations
//!
//! - **Film** (eq. 23 without side leakage): ρc_p u ∂T/∂x − k_f ∂²T/∂z² = q_shear + q_comp
//!   with the viscous dissipation q_shear = τ ∂u/∂z = τ²/η and the compression heating
//!   q_comp = −(T/ρ)(∂ρ/∂T) u ∂p/∂x = ε T u ∂p/∂x, ε = 0.65·10⁻³/(1 − 0.65·10⁻³(T − T₀))
//!   from the Dowson–Higginson density (eq. 11). The velocity is eq. 24,
//!   u = (1/2η)(∂p/∂x)(z² − zh) + (u₂ − u₁) z/h + u₁, with η = η(p, T̄) of Houpert (eq. 10)
//!   at the column's mean temperature (eq. 24 takes η uniform across the film), so that
//!   τ = (∂p/∂x)(z − h/2) + η Δu/h. With a limiting shear stress τ_L = τ₀ + γp given, a
//!   column whose Couette stress η|Δu|/h would exceed τ_L is computed with the effective
//!   viscosity τ_L h/|Δu| (its dissipation is then τ_L|Δu|/h per volume, the friction's
//!   cap in `friction`). The seed's w ∂T/∂z term is absent from its print (eq. 23); here
//!   the vertical mass flux that continuity requires is kept (it is what makes the
//!   convection conserve energy, module note below).
//! - **Solids** (eqs. 29–30): ρ_s c_s U_s ∂T/∂x = k_s ∂²T/∂z², each moving with its
//!   surface. The seed's conduction along x and y in the solids is dropped: its Péclet
//!   number U b/κ is ~40 for the truck bearing (b ≈ 50 µm, U ≈ 10 m/s,
//!   κ = 1.25·10⁻⁵ m²/s), so it changes the flux by ~1/Pe.
//! - **Boundaries**: T = T₀ at the inlet, in the film and in the solids entering there
//!   (eq. 28); T = T₀ at the penetration depth ±d (eqs. 31–32); temperature and heat flux
//!   continuous at both surfaces (eqs. 33–34). The depth is not given by the seed ("large
//!   enough to attain a zero gradient"): the default is d = [`DEFAULT_DEPTH_FACTOR`] ·
//!   √(κ_s L/U_s) with L the length of the domain, the depth where a surface temperature
//!   imposed for the transit time L/U has decayed to erfc(3) = 2·10⁻⁵; doubling it moves the
//!   maximum temperature by less than 1 % (tested; measured 0.034 %). A solid that does not move
//!   (U_s < κ_s/L) takes d = factor · L.
//!
//! # Scheme
//!
//! Finite volumes, cell-centred: N_z film cells across h (default 11), N_s solid cells
//! across each depth, graded towards the surface (faces at d(k/N_s)²). The surface
//! temperature is eliminated by flux continuity (the series resistance of the two half
//! cells), so each x column is one tridiagonal line from −d through the film to +d.
//! Convection is first-order upwind in x and, in the film, in z along the vertical mass
//! flux obtained from continuity cell by cell; conduction is central. The nodes are
//! implicit in z and swept line by line in x (line Gauss–Seidel); properties (η, ρ, ε, the
//! velocities) are updated between sweeps (Picard). With no reverse flow one sweep solves
//! the linear system exactly; reverse flow in the inlet needs more. The sweeps stop when
//! the largest temperature change is below `tolerance_k`, and fail with a typed error
//! after `max_sweeps`.
//!
//! **Heat balance.** Summed over the domain, the upwind convection of the advective form
//! equals the enthalpy carried out through the domain's boundaries plus the enthalpy of
//! any mass that the given p(x), h(x) do not conserve: a pressure that is not the Reynolds
//! solution of the film (e.g. a Hertz profile over a flat film) makes the flow rate vary
//! with x; that mass is removed in proportion to the cell heights, at the cell's
//! temperature, and reported as `mass_sink_heat_w_per_m` (with `mass_imbalance`). For a
//! Reynolds-consistent input it vanishes and generated = convected + conducted is the
//! plain balance (tested to 1 %; measured 8.4e-4 on a rigid-gap Reynolds film).

// Every public item of this physics module must say what it computes and in which units.
#![warn(missing_docs)]

use crate::physics::lubrication::houpert::{Houpert, HoupertError};
use thiserror::Error;

/// Film cells across h when the caller has no reason to choose.
pub const DEFAULT_FILM_CELLS: usize = 11;
/// Solid cells across each penetration depth.
pub const DEFAULT_SOLID_CELLS: usize = 24;
/// d = factor · √(κ L/U) (module note).
pub const DEFAULT_DEPTH_FACTOR: f64 = 6.0;
/// Largest temperature change between sweeps at convergence, K.
pub const DEFAULT_TOLERANCE_K: f64 = 1e-7;
/// Sweeps allowed.
pub const DEFAULT_MAX_SWEEPS: usize = 500;
/// Dowson–Higginson's thermal expansion coefficient of eq. 11, 1/K.
const EXPANSION_PER_K: f64 = 0.65e-3;

/// Why the film temperature cannot be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ThermalError {
    /// An input outside its allowed range.
    #[error("film energy equation: {field} = {value:e} is outside its range: {allowed}")]
    OutOfRange {
        /// The input's name (units in it).
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    /// Slices of different lengths.
    #[error(
        "film energy equation: x_m has {x} nodes but {field} has {len}; give one value per node"
    )]
    Length {
        /// The slice's name.
        field: &'static str,
        /// Its length.
        len: usize,
        /// The length of x_m.
        x: usize,
    },
    /// The sweeps did not settle.
    #[error(
        "film energy equation: not converged after {sweeps} sweeps: the temperature still \
         changed by {change_k:e} K (tolerance {tolerance_k:e} K); largest temperature \
         {max_temperature_k:.1} K"
    )]
    NotConverged {
        /// Sweeps done.
        sweeps: usize,
        /// Largest change in the last sweep, K.
        change_k: f64,
        /// The tolerance, K.
        tolerance_k: f64,
        /// The largest temperature reached, K.
        max_temperature_k: f64,
    },
    /// A temperature became NaN or infinite (thermal runaway).
    #[error(
        "film energy equation: the temperature at x = {x_m:e} m (node {node}) is not finite \
         after {sweeps} sweeps (thermal runaway: give a limiting shear stress or check the \
         viscosity)"
    )]
    NonFinite {
        /// The node.
        node: usize,
        /// Its position, m.
        x_m: f64,
        /// Sweeps done.
        sweeps: usize,
    },
    /// The lubricant's Houpert parameters.
    #[error("film energy equation: {0}")]
    Lubricant(#[from] HoupertError),
}

/// A bounding solid's thermal properties, SI (Table A2: 46 W/(m·K), 7850 kg/m³, 470 J/(kg·K)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solid {
    /// k_s, W/(m·K).
    pub conductivity_w_m_k: f64,
    /// ρ_s, kg/m³.
    pub density_kg_m3: f64,
    /// c_s, J/(kg·K).
    pub specific_heat_j_kg_k: f64,
}

/// What bounds the film at a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Wall {
    /// The surface is held at the inlet temperature (a limit for checks).
    Isothermal,
    /// A solid moving with the surface, to the penetration depth (eqs. 29–32).
    HalfSpace(Solid),
}

/// The limiting shear stress τ_L = τ₀ + γp (seed eq. 40; Table 2: 2.3 MPa, 0.047).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitingShear {
    /// τ₀, Pa.
    pub stress_pa: f64,
    /// γ, dimensionless.
    pub slope: f64,
}

/// One film's inputs, SI. The lower surface (z = 0) moves at u₁, the upper (z = h) at u₂,
/// both ≥ 0 along +x (x increasing from the inlet).
#[derive(Debug, Clone, Copy)]
pub struct ThermalFilm<'a> {
    /// Node positions, m, strictly increasing; x_m[0] is the inlet (eq. 28).
    pub x_m: &'a [f64],
    /// Pressure at the nodes, Pa (negative read as 0).
    pub pressure_pa: &'a [f64],
    /// Film at the nodes, m (> 0).
    pub film_m: &'a [f64],
    /// u₁, speed of the lower surface, m/s (≥ 0).
    pub lower_speed_m_s: f64,
    /// u₂, speed of the upper surface, m/s (≥ 0).
    pub upper_speed_m_s: f64,
    /// η(p, T) and ρ(p, T) (eqs. 10–11).
    pub lubricant: Houpert,
    /// k_f, W/(m·K) (Table A2 prints 0.14 with the units of c_p: swapped).
    pub oil_conductivity_w_m_k: f64,
    /// c_p, J/(kg·K) (Table A2: 2000, printed with k_f's units). 0 removes convection.
    pub oil_specific_heat_j_kg_k: f64,
    /// The solid under z = 0.
    pub lower_wall: Wall,
    /// The solid over z = h.
    pub upper_wall: Wall,
    /// T₀, the inlet (housing) temperature, K (eq. 28).
    pub inlet_temperature_k: f64,
    /// The cap of the shear stress, if any.
    pub limiting_shear: Option<LimitingShear>,
}

/// Discretisation and stopping.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalOptions {
    /// Film cells across h (1 … 201; default 11).
    pub film_cells: usize,
    /// Solid cells across each depth (1 … 400; default 24).
    pub solid_cells: usize,
    /// d = factor · √(κ L/U) (module note; default 6).
    pub depth_factor: f64,
    /// Penetration depth of both solids if given, m (overrides the factor).
    pub depth_m: Option<f64>,
    /// Largest temperature change between sweeps at convergence, K.
    pub tolerance_k: f64,
    /// Sweeps allowed.
    pub max_sweeps: usize,
}

impl Default for ThermalOptions {
    fn default() -> Self {
        ThermalOptions {
            film_cells: DEFAULT_FILM_CELLS,
            solid_cells: DEFAULT_SOLID_CELLS,
            depth_factor: DEFAULT_DEPTH_FACTOR,
            depth_m: None,
            tolerance_k: DEFAULT_TOLERANCE_K,
            max_sweeps: DEFAULT_MAX_SWEEPS,
        }
    }
}

/// The film's temperatures and heat, per x node and in total (per unit length of line).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ThermalSolution {
    /// Mean film temperature across h, K.
    pub mean_temperature_k: Vec<f64>,
    /// Lower surface (z = 0) temperature, K.
    pub lower_surface_temperature_k: Vec<f64>,
    /// Upper surface (z = h) temperature, K.
    pub upper_surface_temperature_k: Vec<f64>,
    /// Largest temperature across the film, surfaces included, K.
    pub max_temperature_k: Vec<f64>,
    /// Film cell temperatures, bottom to top, per node, K.
    pub film_temperature_k: Vec<Vec<f64>>,
    /// Viscous dissipation integrated across h, W/m².
    pub shear_heat_w_m2: Vec<f64>,
    /// Compression heating integrated across h, W/m² (negative where the oil expands).
    pub compression_heat_w_m2: Vec<f64>,
    /// Heat flux from the film into the lower solid, W/m².
    pub conducted_lower_w_m2: Vec<f64>,
    /// Heat flux from the film into the upper solid, W/m².
    pub conducted_upper_w_m2: Vec<f64>,
    /// The column's remainder, generated − conducted: carried on by the oil, W/m².
    pub convected_w_m2: Vec<f64>,
    /// Σ shear heat, W per m of line.
    pub shear_heat_w_per_m: f64,
    /// Σ compression heat, W per m of line.
    pub compression_heat_w_per_m: f64,
    /// Enthalpy the oil carries out of the domain (above T₀), W per m of line.
    pub convected_w_per_m: f64,
    /// Enthalpy of the mass the input does not conserve (module note), W per m of line.
    pub mass_sink_heat_w_per_m: f64,
    /// Largest drift of the flow rate from the inlet's (the mass the input fails to
    /// conserve up to a node) over the inlet mass flow, dimensionless.
    pub mass_imbalance: f64,
    /// Heat into the lower solid through its surface, W per m of line.
    pub conducted_lower_w_per_m: f64,
    /// Heat into the upper solid through its surface, W per m of line.
    pub conducted_upper_w_per_m: f64,
    /// Heat the solids carry out (downstream and through the depth), W per m of line.
    pub solids_out_w_per_m: f64,
    /// (generated − convected − mass-sink heat − solids out)/generated, dimensionless.
    pub heat_balance_residual: f64,
    /// Penetration depth used below the lower surface, m (0 for an isothermal wall).
    pub lower_depth_m: f64,
    /// Penetration depth used above the upper surface, m.
    pub upper_depth_m: f64,
    /// The largest temperature anywhere, K.
    pub peak_temperature_k: f64,
    /// Sweeps done.
    pub sweeps: usize,
}

/// A solid's column geometry: cell thicknesses from the surface down, m.
struct SolidGrid {
    solid: Solid,
    speed: f64,
    /// Thickness of cell k (k = 0 at the surface).
    dz: Vec<f64>,
    depth: f64,
}

fn solid_grid(wall: Wall, speed: f64, length: f64, opt: &ThermalOptions) -> Option<SolidGrid> {
    match wall {
        Wall::Isothermal => None,
        Wall::HalfSpace(solid) => {
            let kappa =
                solid.conductivity_w_m_k / (solid.density_kg_m3 * solid.specific_heat_j_kg_k);
            let depth = opt.depth_m.unwrap_or_else(|| {
                let u = speed.max(kappa / length);
                opt.depth_factor * (kappa * length / u).sqrt()
            });
            let n = opt.solid_cells;
            let face = |k: usize| depth * (k as f64 / n as f64).powi(2);
            let dz = (0..n).map(|k| face(k + 1) - face(k)).collect();
            Some(SolidGrid {
                solid,
                speed,
                dz,
                depth,
            })
        }
    }
}

fn check(
    field: &'static str,
    value: f64,
    ok: bool,
    allowed: &'static str,
) -> Result<(), ThermalError> {
    if value.is_finite() && ok {
        Ok(())
    } else {
        Err(ThermalError::OutOfRange {
            field,
            value,
            allowed,
        })
    }
}

fn validate(f: &ThermalFilm, o: &ThermalOptions) -> Result<(), ThermalError> {
    let n = f.x_m.len();
    check("x_m (node count)", n as f64, n >= 2, "at least 2 nodes")?;
    for (field, len) in [
        ("pressure_pa", f.pressure_pa.len()),
        ("film_m", f.film_m.len()),
    ] {
        if len != n {
            return Err(ThermalError::Length { field, len, x: n });
        }
    }
    for w in f.x_m.windows(2) {
        check("x_m", w[1], w[1] > w[0], "strictly increasing")?;
    }
    for &p in f.pressure_pa {
        check("pressure_pa", p, true, "finite")?;
    }
    for &h in f.film_m {
        check("film_m", h, h > 0.0, "> 0 m")?;
    }
    check(
        "lower_speed_m_s",
        f.lower_speed_m_s,
        f.lower_speed_m_s >= 0.0,
        "≥ 0 m/s (along +x)",
    )?;
    check(
        "upper_speed_m_s",
        f.upper_speed_m_s,
        f.upper_speed_m_s >= 0.0,
        "≥ 0 m/s (along +x)",
    )?;
    check(
        "oil_conductivity_w_m_k",
        f.oil_conductivity_w_m_k,
        f.oil_conductivity_w_m_k > 0.0,
        "> 0 W/(m·K)",
    )?;
    check(
        "oil_specific_heat_j_kg_k",
        f.oil_specific_heat_j_kg_k,
        f.oil_specific_heat_j_kg_k >= 0.0,
        "≥ 0 J/(kg·K)",
    )?;
    check(
        "inlet_temperature_k",
        f.inlet_temperature_k,
        f.inlet_temperature_k > 138.0,
        "above 138 K",
    )?;
    for wall in [f.lower_wall, f.upper_wall] {
        if let Wall::HalfSpace(s) = wall {
            check(
                "solid conductivity_w_m_k",
                s.conductivity_w_m_k,
                s.conductivity_w_m_k > 0.0,
                "> 0 W/(m·K)",
            )?;
            check(
                "solid density_kg_m3",
                s.density_kg_m3,
                s.density_kg_m3 > 0.0,
                "> 0 kg/m³",
            )?;
            check(
                "solid specific_heat_j_kg_k",
                s.specific_heat_j_kg_k,
                s.specific_heat_j_kg_k > 0.0,
                "> 0 J/(kg·K)",
            )?;
        }
    }
    if let Some(l) = f.limiting_shear {
        check(
            "limiting shear stress_pa",
            l.stress_pa,
            l.stress_pa >= 0.0,
            "≥ 0 Pa",
        )?;
        check("limiting shear slope", l.slope, l.slope >= 0.0, "≥ 0")?;
    }
    check(
        "film_cells",
        o.film_cells as f64,
        (1..=201).contains(&o.film_cells),
        "1 … 201",
    )?;
    check(
        "solid_cells",
        o.solid_cells as f64,
        (1..=400).contains(&o.solid_cells),
        "1 … 400",
    )?;
    check("depth_factor", o.depth_factor, o.depth_factor > 0.0, "> 0")?;
    if let Some(d) = o.depth_m {
        check("depth_m", d, d > 0.0, "> 0 m")?;
    }
    check("tolerance_k", o.tolerance_k, o.tolerance_k > 0.0, "> 0 K")?;
    check("max_sweeps", o.max_sweeps as f64, o.max_sweeps >= 1, "≥ 1")?;
    f.lubricant.validate()?;
    Ok(())
}

/// Thomas algorithm for a tridiagonal system a_i x_{i−1} + b_i x_i + c_i x_{i+1} = d_i
/// (a_0 = c_{n−1} = 0), in place into `d`. The systems here are diagonally dominant
/// (conduction and upwind convection), so no pivoting is needed.
fn thomas(a: &[f64], b: &[f64], c: &mut [f64], d: &mut [f64]) {
    let n = d.len();
    let mut beta = b[0];
    d[0] /= beta;
    for i in 1..n {
        c[i - 1] /= beta;
        beta = b[i] - a[i] * c[i - 1];
        d[i] = (d[i] - a[i] * d[i - 1]) / beta;
    }
    for i in (0..n.saturating_sub(1)).rev() {
        d[i] -= c[i] * d[i + 1];
    }
}

/// Per-column film properties at the current temperatures.
#[derive(Clone, Copy, Default)]
struct Column {
    /// Effective viscosity, Pa·s.
    eta: f64,
    /// Density, kg/m³.
    rho: f64,
    /// ∂p/∂x, Pa/m.
    dpdx: f64,
}

/// Mean velocity over a film cell centred at height z, thickness dz, m/s (eq. 24
/// averaged exactly: the profile is quadratic, so its mean is the centre value plus
/// (p′/2η)·dz²/12). Exact cell means make the discrete flow rate the Reynolds one.
fn velocity(col: &Column, h: f64, z: f64, dz: f64, u1: f64, u2: f64) -> f64 {
    col.dpdx / (2.0 * col.eta) * (z * z - z * h + dz * dz / 12.0) + (u2 - u1) * z / h + u1
}

/// Mean viscous dissipation τ²/η over the same cell, W/m³: τ = p′(z − h/2) + ηΔu/h is
/// linear in z, so the mean of τ² is τ(z)² + p′²dz²/12.
fn dissipation(col: &Column, h: f64, z: f64, dz: f64, du: f64) -> f64 {
    let tau = col.dpdx * (z - 0.5 * h) + col.eta * du / h;
    (tau * tau + col.dpdx * col.dpdx * dz * dz / 12.0) / col.eta
}

/// The film's temperature field and heat (module note; seed eqs. 23–34).
pub fn solve_film_temperature(
    f: &ThermalFilm,
    opt: &ThermalOptions,
) -> Result<ThermalSolution, ThermalError> {
    validate(f, opt)?;
    let n = f.x_m.len();
    let nz = opt.film_cells;
    let x = f.x_m;
    let length = x[n - 1] - x[0];
    let (u1, u2) = (f.lower_speed_m_s, f.upper_speed_m_s);
    let du = u2 - u1;
    let t0 = f.inlet_temperature_k;
    let cp = f.oil_specific_heat_j_kg_k;
    let kf = f.oil_conductivity_w_m_k;
    let lower = solid_grid(f.lower_wall, u1, length, opt);
    let upper = solid_grid(f.upper_wall, u2, length, opt);
    let ns1 = lower.as_ref().map_or(0, |g| g.dz.len());
    let ns2 = upper.as_ref().map_or(0, |g| g.dz.len());
    let line = ns1 + nz + ns2;
    // Line index of lower solid cell k (k = 0 at the surface), film cell j, upper cell k.
    let l_idx = |k: usize| ns1 - 1 - k;
    let f_idx = |j: usize| ns1 + j;
    let u_idx = |k: usize| ns1 + nz + k;

    // Cell widths in x: half-way to the neighbours.
    let dx: Vec<f64> = (0..n)
        .map(|i| {
            let a = if i > 0 { x[i] - x[i - 1] } else { 0.0 };
            let b = if i + 1 < n { x[i + 1] - x[i] } else { 0.0 };
            0.5 * (a + b)
        })
        .collect();
    // ∂p/∂x: central inside, second-order one-sided at the two ends (a first-order end
    // difference would break the flow rate of a Reynolds input by ~Δx·p″/p′ there).
    let pr = |i: usize| f.pressure_pa[i].max(0.0);
    let dpdx: Vec<f64> = (0..n)
        .map(|i| {
            if n < 3 {
                (pr(n - 1) - pr(0)) / (x[n - 1] - x[0])
            } else {
                // The quadratic through three nodes, differentiated at node i.
                let (a, b, c) = if i == 0 {
                    (0, 1, 2)
                } else if i + 1 == n {
                    (n - 3, n - 2, n - 1)
                } else {
                    (i - 1, i, i + 1)
                };
                let (xa, xb, xc) = (x[a], x[b], x[c]);
                let xi = x[i];
                // Written on differences so that a uniform pressure gives exactly 0.
                (pr(a) - pr(b)) * (2.0 * xi - xb - xc) / ((xa - xb) * (xa - xc))
                    + (pr(c) - pr(b)) * (2.0 * xi - xa - xb) / ((xc - xa) * (xc - xb))
            }
        })
        .collect();
    let dzeta = 1.0 / nz as f64;
    let zeta = |j: usize| (j as f64 + 0.5) * dzeta;

    // θ = T − T₀ on every line; column 0 stays 0 (eq. 28).
    let mut theta = vec![vec![0.0; line]; n];
    let mut cols = vec![Column::default(); n];
    // Mass flux per layer at each node (ρ u h Δζ), kg/(m·s) per unit length of line.
    let mut mflux = vec![vec![0.0; nz]; n];

    let update = |theta: &[Vec<f64>], cols: &mut [Column], mflux: &mut [Vec<f64>]| {
        for i in 0..n {
            let tm = t0 + (0..nz).map(|j| theta[i][f_idx(j)]).sum::<f64>() / nz as f64;
            let p = f.pressure_pa[i].max(0.0);
            let h = f.film_m[i];
            let mut eta = f.lubricant.at_temperature(tm).viscosity_pa_s(p);
            if let Some(l) = f.limiting_shear {
                let cap = l.stress_pa + l.slope * p;
                if du != 0.0 && eta * du.abs() / h > cap {
                    eta = cap * h / du.abs();
                }
            }
            cols[i] = Column {
                eta,
                rho: f.lubricant.density_kg_m3(p, tm),
                dpdx: dpdx[i],
            };
            for (j, m) in mflux[i].iter_mut().enumerate() {
                let z = zeta(j) * h;
                *m = cols[i].rho * velocity(&cols[i], h, z, h * dzeta, u1, u2) * h * dzeta;
            }
        }
    };

    let mut sweeps = 0;
    let mut a = vec![0.0; line];
    let mut b = vec![0.0; line];
    let mut c = vec![0.0; line];
    let mut d = vec![0.0; line];
    // Face mass fluxes of column i: west (i−½) and east (i+½) per layer, and the vertical
    // fluxes F_{j+½} (upward positive) from continuity with the imbalance removed.
    let faces =
        |mflux: &[Vec<f64>], i: usize, w: &mut [f64], e: &mut [f64], fz: &mut [f64]| -> f64 {
            for j in 0..nz {
                w[j] = if i > 0 {
                    0.5 * (mflux[i - 1][j] + mflux[i][j])
                } else {
                    mflux[i][j]
                };
                e[j] = if i + 1 < n {
                    0.5 * (mflux[i][j] + mflux[i + 1][j])
                } else {
                    mflux[i][j]
                };
            }
            let imbalance: f64 = (0..nz).map(|j| w[j] - e[j]).sum();
            let mut acc = 0.0;
            for j in 0..nz {
                acc += w[j] - e[j] - imbalance * dzeta;
                fz[j] = acc;
            }
            imbalance
        };
    let mut west = vec![0.0; nz];
    let mut east = vec![0.0; nz];
    let mut fz = vec![0.0; nz];
    let film_wall_resistance = |h: f64| 0.5 * h * dzeta / kf;
    let solid_resistance = |g: &Option<SolidGrid>| {
        g.as_ref()
            .map_or(0.0, |g| 0.5 * g.dz[0] / g.solid.conductivity_w_m_k)
    };

    loop {
        update(&theta, &mut cols, &mut mflux);
        sweeps += 1;
        let mut change: f64 = 0.0;
        for i in 1..n {
            let h = f.film_m[i];
            let col = cols[i];
            faces(&mflux, i, &mut west, &mut east, &mut fz);
            a.iter_mut().for_each(|v| *v = 0.0);
            c.iter_mut().for_each(|v| *v = 0.0);
            b.iter_mut().for_each(|v| *v = 0.0);
            d.iter_mut().for_each(|v| *v = 0.0);
            // Film cells.
            for j in 0..nz {
                let r = f_idx(j);
                let z = zeta(j) * h;
                let vol = h * dzeta * dx[i];
                let u = velocity(&col, h, z, h * dzeta, u1, u2);
                let q_shear = dissipation(&col, h, z, h * dzeta, du);
                let t_abs = t0 + theta[i][r];
                let eps = EXPANSION_PER_K
                    / (1.0 - EXPANSION_PER_K * (t_abs - f.lubricant.reference_temperature_k));
                // ε T u p' = ε u p' (T₀ + θ): the θ part implicit.
                let comp = eps * u * col.dpdx;
                b[r] -= comp * vol;
                d[r] += (q_shear + comp * t0) * vol;
                // Upwind convection in x (advective form).
                if west[j] > 0.0 {
                    b[r] += cp * west[j];
                    d[r] += cp * west[j] * theta[i - 1][r];
                }
                if east[j] < 0.0 && i + 1 < n {
                    b[r] += cp * -east[j];
                    d[r] += cp * -east[j] * theta[i + 1][r];
                }
                // Upwind convection in z.
                if j > 0 && fz[j - 1] > 0.0 {
                    b[r] += cp * fz[j - 1];
                    a[r] -= cp * fz[j - 1];
                }
                if j + 1 < nz && fz[j] < 0.0 {
                    b[r] += cp * -fz[j];
                    c[r] -= cp * -fz[j];
                }
                // Conduction to the film cell above.
                if j + 1 < nz {
                    let g = kf * dx[i] / (h * dzeta);
                    b[r] += g;
                    c[r] -= g;
                    b[r + 1] += g;
                    a[r + 1] -= g;
                }
            }
            // Surfaces: series resistance of the film half cell and the solid half cell.
            for (grid, film_row, solid_row) in [
                (
                    &lower,
                    f_idx(0),
                    if ns1 > 0 { Some(l_idx(0)) } else { None },
                ),
                (
                    &upper,
                    f_idx(nz - 1),
                    if ns2 > 0 { Some(u_idx(0)) } else { None },
                ),
            ] {
                let g = dx[i] / (film_wall_resistance(h) + solid_resistance(grid));
                b[film_row] += g;
                if let Some(s) = solid_row {
                    b[s] += g;
                    // The solid row is adjacent to the film row on the line.
                    if s < film_row {
                        a[film_row] -= g;
                        c[s] -= g;
                    } else {
                        c[film_row] -= g;
                        a[s] -= g;
                    }
                }
            }
            // Solid cells.
            for (grid, idx, down) in [(&lower, 0usize, true), (&upper, 1usize, false)] {
                let Some(g) = grid else { continue };
                let ns = g.dz.len();
                let row = |k: usize| if idx == 0 { l_idx(k) } else { u_idx(k) };
                let ks = g.solid.conductivity_w_m_k;
                let rc = g.solid.density_kg_m3 * g.solid.specific_heat_j_kg_k;
                for k in 0..ns {
                    let r = row(k);
                    let m = rc * g.speed * g.dz[k];
                    b[r] += m;
                    d[r] += m * theta[i - 1][r];
                    if k + 1 < ns {
                        let cond = ks * dx[i] / (0.5 * (g.dz[k] + g.dz[k + 1]));
                        let r2 = row(k + 1);
                        b[r] += cond;
                        b[r2] += cond;
                        // Deeper cells sit further from the film on the line.
                        if down {
                            a[r] -= cond;
                            c[r2] -= cond;
                        } else {
                            c[r] -= cond;
                            a[r2] -= cond;
                        }
                    } else {
                        // T = T₀ at the depth (eqs. 31–32).
                        b[r] += ks * dx[i] / (0.5 * g.dz[k]);
                    }
                }
            }
            thomas(&a, &b, &mut c, &mut d);
            for r in 0..line {
                let v = d[r];
                if !v.is_finite() {
                    return Err(ThermalError::NonFinite {
                        node: i,
                        x_m: x[i],
                        sweeps,
                    });
                }
                change = change.max((v - theta[i][r]).abs());
                theta[i][r] = v;
            }
        }
        if change <= opt.tolerance_k {
            break;
        }
        if sweeps >= opt.max_sweeps {
            let peak = theta.iter().flatten().fold(0.0f64, |m, &v| m.max(v)) + t0;
            return Err(ThermalError::NotConverged {
                sweeps,
                change_k: change,
                tolerance_k: opt.tolerance_k,
                max_temperature_k: peak,
            });
        }
    }
    // Final properties at the converged temperatures for the heat accounting (the
    // equations above used the previous sweep's, which agree within the tolerance).
    Ok(account(
        f, opt, &theta, &cols, &mflux, &dx, &lower, &upper, sweeps, &faces,
    ))
}

/// The face mass fluxes of a column (west, east, vertical), returning its imbalance.
type FaceFluxes<'a> = dyn Fn(&[Vec<f64>], usize, &mut [f64], &mut [f64], &mut [f64]) -> f64 + 'a;

/// The per-node and total heat of a converged field.
#[allow(clippy::too_many_arguments)]
fn account(
    f: &ThermalFilm,
    opt: &ThermalOptions,
    theta: &[Vec<f64>],
    cols: &[Column],
    mflux: &[Vec<f64>],
    dx: &[f64],
    lower: &Option<SolidGrid>,
    upper: &Option<SolidGrid>,
    sweeps: usize,
    faces: &FaceFluxes<'_>,
) -> ThermalSolution {
    let n = f.x_m.len();
    let nz = opt.film_cells;
    let ns1 = lower.as_ref().map_or(0, |g| g.dz.len());
    let t0 = f.inlet_temperature_k;
    let (u1, u2) = (f.lower_speed_m_s, f.upper_speed_m_s);
    let du = u2 - u1;
    let cp = f.oil_specific_heat_j_kg_k;
    let kf = f.oil_conductivity_w_m_k;
    let dzeta = 1.0 / nz as f64;
    let f_idx = |j: usize| ns1 + j;
    let mut s = ThermalSolution {
        sweeps,
        lower_depth_m: lower.as_ref().map_or(0.0, |g| g.depth),
        upper_depth_m: upper.as_ref().map_or(0.0, |g| g.depth),
        ..ThermalSolution::default()
    };
    let mut west = vec![0.0; nz];
    let mut east = vec![0.0; nz];
    let mut fz = vec![0.0; nz];
    let mut inlet_mass = 0.0;
    // Mass removed so far (the flow rate's drift from the inlet's) and its largest value.
    let (mut sunk, mut largest_sunk) = (0.0f64, 0.0f64);
    for i in 0..n {
        let h = f.film_m[i];
        let col = cols[i];
        let film: Vec<f64> = (0..nz).map(|j| t0 + theta[i][f_idx(j)]).collect();
        let rf = 0.5 * h * dzeta / kf;
        // Surface temperature from flux continuity: T_w = T_film − q R_f.
        let wall = |grid: &Option<SolidGrid>, film_t: f64, solid_t: f64| -> (f64, f64) {
            let rs = grid
                .as_ref()
                .map_or(0.0, |g| 0.5 * g.dz[0] / g.solid.conductivity_w_m_k);
            let q = (film_t - solid_t) / (rf + rs);
            (film_t - q * rf, q)
        };
        let solid_top = |grid: &Option<SolidGrid>, row: usize| {
            if grid.is_some() {
                t0 + theta[i][row]
            } else {
                t0
            }
        };
        let (tw1, q1) = wall(lower, film[0], solid_top(lower, ns1.saturating_sub(1)));
        let (tw2, q2) = wall(upper, film[nz - 1], solid_top(upper, ns1 + nz));
        let (mut shear, mut comp) = (0.0, 0.0);
        for (j, &t) in film.iter().enumerate() {
            let z = (j as f64 + 0.5) * dzeta * h;
            let u = velocity(&col, h, z, h * dzeta, u1, u2);
            shear += dissipation(&col, h, z, h * dzeta, du) * h * dzeta;
            let eps = EXPANSION_PER_K
                / (1.0 - EXPANSION_PER_K * (t - f.lubricant.reference_temperature_k));
            comp += eps * t * u * col.dpdx * h * dzeta;
        }
        // t0 + mean θ: exactly T₀ when no heat is generated.
        let mean = t0 + (0..nz).map(|j| theta[i][f_idx(j)]).sum::<f64>() / nz as f64;
        let peak = film.iter().fold(tw1.max(tw2), |m, &v| m.max(v));
        s.mean_temperature_k.push(mean);
        s.lower_surface_temperature_k.push(tw1);
        s.upper_surface_temperature_k.push(tw2);
        s.max_temperature_k.push(peak);
        s.peak_temperature_k = s.peak_temperature_k.max(peak);
        s.film_temperature_k.push(film);
        if i == 0 {
            // The inlet column is held at T₀ (eq. 28): no heat is counted there.
            s.shear_heat_w_m2.push(0.0);
            s.compression_heat_w_m2.push(0.0);
            s.conducted_lower_w_m2.push(0.0);
            s.conducted_upper_w_m2.push(0.0);
            s.convected_w_m2.push(0.0);
            continue;
        }
        s.shear_heat_w_m2.push(shear);
        s.compression_heat_w_m2.push(comp);
        s.conducted_lower_w_m2.push(q1);
        s.conducted_upper_w_m2.push(q2);
        s.convected_w_m2.push(shear + comp - q1 - q2);
        s.shear_heat_w_per_m += shear * dx[i];
        s.compression_heat_w_per_m += comp * dx[i];
        s.conducted_lower_w_per_m += q1 * dx[i];
        s.conducted_upper_w_per_m += q2 * dx[i];
        // Convection across the domain's boundaries and the mass sink.
        let imbalance = faces(mflux, i, &mut west, &mut east, &mut fz);
        sunk += imbalance;
        largest_sunk = largest_sunk.max(sunk.abs());
        for j in 0..nz {
            let th = theta[i][f_idx(j)];
            if i == 1 {
                if west[j] > 0.0 {
                    inlet_mass += west[j];
                } else {
                    s.convected_w_per_m += cp * -west[j] * th;
                }
            }
            if i + 1 == n && east[j] > 0.0 {
                s.convected_w_per_m += cp * east[j] * th;
            }
            s.mass_sink_heat_w_per_m += cp * imbalance * dzeta * th;
        }
    }
    // The solids: enthalpy out downstream plus conduction through the depth.
    for (grid, base, down) in [(lower, 0usize, true), (upper, ns1 + nz, false)] {
        let Some(g) = grid else { continue };
        let ns = g.dz.len();
        let row = |k: usize| if down { base + ns - 1 - k } else { base + k };
        let rc = g.solid.density_kg_m3 * g.solid.specific_heat_j_kg_k;
        for k in 0..ns {
            s.solids_out_w_per_m += rc * g.speed * g.dz[k] * theta[n - 1][row(k)];
        }
        for i in 1..n {
            s.solids_out_w_per_m +=
                g.solid.conductivity_w_m_k * theta[i][row(ns - 1)] / (0.5 * g.dz[ns - 1]) * dx[i];
        }
    }
    // Isothermal walls: what they take is what crossed the surface.
    if lower.is_none() {
        s.solids_out_w_per_m += s.conducted_lower_w_per_m;
    }
    if upper.is_none() {
        s.solids_out_w_per_m += s.conducted_upper_w_per_m;
    }
    s.mass_imbalance = if inlet_mass > 0.0 {
        largest_sunk / inlet_mass
    } else {
        0.0
    };
    let generated = s.shear_heat_w_per_m + s.compression_heat_w_per_m;
    let out = s.convected_w_per_m + s.mass_sink_heat_w_per_m + s.solids_out_w_per_m;
    s.heat_balance_residual = if generated.abs() > 0.0 {
        (generated - out) / generated.abs()
    } else {
        out
    };
    s
}

/// Stopping of the viscosity ↔ temperature iteration (seed eq. 44 and step 5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CouplingOptions {
    /// Solve the energy equation at all; off, the isothermal solve at T₀ is returned as is.
    pub thermal: bool,
    /// ε_T of eq. 44: stop when Σ|T_new − T_old|/ΣT_old ≤ ε_T (seed: 1e-5 … 1e-4).
    pub tolerance: f64,
    /// Under-relaxation ω of the temperature, T ← T + ω(T_new − T), in (0, 1].
    pub relaxation: f64,
    /// Iterations allowed.
    pub max_iterations: usize,
}

impl Default for CouplingOptions {
    fn default() -> Self {
        CouplingOptions {
            thermal: true,
            tolerance: 1e-5,
            relaxation: 1.0,
            max_iterations: 50,
        }
    }
}

/// Why the coupled solve failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CouplingError<E: std::fmt::Display> {
    /// The isothermal solver failed.
    #[error("thermal iteration {iteration}: the pressure solver failed: {source}")]
    Solver {
        /// The iteration (1 = the first solve).
        iteration: usize,
        /// The solver's error.
        source: E,
    },
    /// The solver returned slices of the wrong length.
    #[error(
        "thermal iteration {iteration}: the pressure solver returned {pressure} pressures and \
         {film} films for {x} nodes"
    )]
    Length {
        /// The iteration.
        iteration: usize,
        /// Pressures returned.
        pressure: usize,
        /// Films returned.
        film: usize,
        /// Nodes of x_m.
        x: usize,
    },
    /// The energy equation failed.
    #[error("thermal iteration {iteration}: {source}")]
    Thermal {
        /// The iteration.
        iteration: usize,
        /// The energy equation's error.
        source: ThermalError,
    },
    /// The temperatures did not settle.
    #[error(
        "thermal iteration: not converged after {iterations} iterations: the temperatures \
         still change by {change:e} (relative, eq. 44; tolerance {tolerance:e})"
    )]
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// The last Σ|ΔT|/ΣT.
        change: f64,
        /// ε_T.
        tolerance: f64,
    },
}

/// The converged pressure, film and temperatures of a coupled solve.
#[derive(Debug, Clone, PartialEq)]
pub struct Coupled {
    /// Pressure, Pa.
    pub pressure_pa: Vec<f64>,
    /// Film, m.
    pub film_m: Vec<f64>,
    /// The temperature the solver last saw (the mean film temperature), K.
    pub temperature_k: Vec<f64>,
    /// The energy equation's solution at that pressure and film (None when switched off).
    pub thermal: Option<ThermalSolution>,
    /// Solver calls.
    pub iterations: usize,
    /// The last Σ|ΔT|/ΣT (0 when switched off).
    pub change: f64,
}

/// Alternate an isothermal pressure solver with the energy equation until the film
/// temperatures settle (seed step 5, eq. 44). `solver` maps the film temperature per node
/// (K) to (pressure_pa, film_m) at the nodes of `film.x_m`; `film`'s own pressure and
/// film slices are ignored (its speeds, lubricant, walls and T₀ are used). The first call
/// is at T₀ everywhere; with `coupling.thermal` off that is the answer, unchanged.
pub fn thermal_iteration<S, E>(
    mut solver: S,
    film: &ThermalFilm,
    options: &ThermalOptions,
    coupling: &CouplingOptions,
) -> Result<Coupled, CouplingError<E>>
where
    S: FnMut(&[f64]) -> Result<(Vec<f64>, Vec<f64>), E>,
    E: std::fmt::Display,
{
    let n = film.x_m.len();
    let mut temperature = vec![film.inlet_temperature_k; n];
    let bad = |source| CouplingError::Thermal {
        iteration: 0,
        source,
    };
    check(
        "relaxation",
        coupling.relaxation,
        coupling.relaxation > 0.0 && coupling.relaxation <= 1.0,
        "(0, 1]",
    )
    .map_err(bad)?;
    check(
        "tolerance",
        coupling.tolerance,
        coupling.tolerance > 0.0,
        "> 0",
    )
    .map_err(bad)?;
    check(
        "max_iterations",
        coupling.max_iterations as f64,
        coupling.max_iterations >= 1,
        "≥ 1",
    )
    .map_err(bad)?;
    let omega = coupling.relaxation;
    let mut iteration = 0;
    loop {
        iteration += 1;
        let (pressure_pa, film_m) =
            solver(&temperature).map_err(|source| CouplingError::Solver { iteration, source })?;
        if pressure_pa.len() != n || film_m.len() != n {
            return Err(CouplingError::Length {
                iteration,
                pressure: pressure_pa.len(),
                film: film_m.len(),
                x: n,
            });
        }
        if !coupling.thermal {
            return Ok(Coupled {
                pressure_pa,
                film_m,
                temperature_k: temperature,
                thermal: None,
                iterations: iteration,
                change: 0.0,
            });
        }
        let this = ThermalFilm {
            pressure_pa: &pressure_pa,
            film_m: &film_m,
            ..*film
        };
        let sol = solve_film_temperature(&this, options)
            .map_err(|source| CouplingError::Thermal { iteration, source })?;
        let (mut diff, mut sum) = (0.0, 0.0);
        for (t, new) in temperature.iter().zip(&sol.mean_temperature_k) {
            diff += (new - t).abs();
            sum += t.abs();
        }
        let change = diff / sum;
        if change <= coupling.tolerance {
            return Ok(Coupled {
                pressure_pa,
                film_m,
                temperature_k: temperature,
                thermal: Some(sol),
                iterations: iteration,
                change,
            });
        }
        if iteration >= coupling.max_iterations {
            return Err(CouplingError::NotConverged {
                iterations: iteration,
                change,
                tolerance: coupling.tolerance,
            });
        }
        for (t, new) in temperature.iter_mut().zip(&sol.mean_temperature_k) {
            *t += omega * (new - *t);
        }
    }
}

#[cfg(test)]
#[path = "thermal_tests.rs"]
mod tests;
