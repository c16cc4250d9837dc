//! Steady-state temperatures (seed 000 §10.2, eq. 10.1–10.3) and the energy balance.

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use super::error::ThermalError;
use super::network::{HeatInput, Network, Resolved};

/// The linear heat balance of the free nodes: `A·T = Q + b` (eq. 10.2 rearranged), with
/// `A_ii = Σ_j F_ij` and `A_ij = −F_ij` for free j; fixed-temperature neighbours are moved
/// to `b` (seed: "T_j substituted for the known T_given").
#[derive(Debug, Clone)]
pub(crate) struct System {
    /// Node index of each free unknown.
    pub free: Vec<usize>,
    /// Conductance matrix A, W/K (free × free).
    pub a: DMatrix<f64>,
    /// Contribution of fixed-temperature neighbours, W (Σ F_ij·T_j over fixed j).
    pub b: DVector<f64>,
    /// Capacities of the free nodes, J/K.
    pub capacity: DVector<f64>,
    /// Temperature of every node, °C: fixed values set, free entries 0.
    pub base_c: Vec<f64>,
}

impl System {
    /// Assembles eq. 10.2 for `network` (already resolved).
    pub fn assemble(network: &Network, resolved: &Resolved) -> System {
        let n = network.nodes.len();
        let mut slot: Vec<Option<usize>> = vec![None; n];
        let mut free = Vec::new();
        for (i, node) in network.nodes.iter().enumerate() {
            if !node.is_fixed() {
                slot[i] = Some(free.len());
                free.push(i);
            }
        }
        let base_c: Vec<f64> = network
            .nodes
            .iter()
            .map(|nd| nd.fixed_c.unwrap_or(0.0))
            .collect();
        let m = free.len();
        let mut a = DMatrix::<f64>::zeros(m, m);
        let mut b = DVector::<f64>::zeros(m);
        // Adds the term F·(T_j − T_i) to the balance of node i (eq. 10.1).
        let mut couple = |i: usize, j: usize, f: f64| {
            if let Some(si) = slot[i] {
                a[(si, si)] += f;
                match slot[j] {
                    Some(sj) => a[(si, sj)] -= f,
                    None => b[si] += f * base_c[j],
                }
            }
        };
        for (link, &(from, to)) in network.links.iter().zip(&resolved.ends) {
            let f = link.coefficient_w_k();
            if link.is_mass_transport() {
                // Directed: the downstream node gains ṁc(T_up − T_down); upstream unaffected.
                couple(to, from, f);
            } else {
                couple(from, to, f);
                couple(to, from, f);
            }
        }
        let capacity =
            DVector::from_iterator(m, free.iter().map(|&i| network.nodes[i].capacity_j_k));
        System {
            free,
            a,
            b,
            capacity,
            base_c,
        }
    }

    /// Free-node heat vector, W.
    pub fn free_heat(&self, node_heat_w: &[f64]) -> DVector<f64> {
        DVector::from_iterator(self.free.len(), self.free.iter().map(|&i| node_heat_w[i]))
    }

    /// Full temperature vector (°C) from the free unknowns.
    pub fn scatter(&self, t_free: &DVector<f64>) -> Vec<f64> {
        let mut t = self.base_c.clone();
        for (k, &i) in self.free.iter().enumerate() {
            t[i] = t_free[k];
        }
        t
    }

    /// Free unknowns from a full temperature vector.
    pub fn gather(&self, t_all: &[f64]) -> DVector<f64> {
        DVector::from_iterator(self.free.len(), self.free.iter().map(|&i| t_all[i]))
    }
}

/// Steady temperature of one node.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SteadyNode {
    /// Node name.
    pub name: String,
    /// Temperature, °C.
    pub temperature_c: f64,
    /// True when the temperature was given, not solved.
    pub fixed: bool,
}

/// Steady-state solution with its energy balance.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SteadyResult {
    /// Node temperatures in network order.
    pub nodes: Vec<SteadyNode>,
    /// Heat generated in the network (all sources), W.
    pub heat_in_w: f64,
    /// Heat leaving: into fixed-temperature nodes through conductive links, plus the
    /// enthalpy rise ṁc(T_down − T_up) of the oil across every free downstream node, W.
    pub heat_out_w: f64,
    /// `heat_in_w − heat_out_w`, W (round-off at a converged solution).
    pub balance_w: f64,
}

impl SteadyResult {
    /// Temperatures of all nodes, °C, in network order.
    pub fn temperatures_c(&self) -> Vec<f64> {
        self.nodes.iter().map(|n| n.temperature_c).collect()
    }

    /// Temperature of a named node, °C.
    pub fn temperature_c(&self, name: &str) -> Option<f64> {
        self.nodes
            .iter()
            .find(|n| n.name == name)
            .map(|n| n.temperature_c)
    }
}

/// Solves the steady heat balance (eq. 10.2) of `network` under `heat` by LU with
/// partial pivoting, and reports the energy balance.
///
/// Errors: any validation error, [`ThermalError::Ungrounded`] for a floating free node,
/// [`ThermalError::Singular`] if the factorisation fails anyway.
pub fn solve_steady(network: &Network, heat: &HeatInput) -> Result<SteadyResult, ThermalError> {
    let resolved = network.resolve()?;
    network.check_grounded_resolved(&resolved)?;
    let q = network.node_heat_w(heat)?;
    let sys = System::assemble(network, &resolved);
    let rhs = sys.free_heat(&q) + &sys.b;
    let t_free = if sys.free.is_empty() {
        DVector::zeros(0)
    } else {
        sys.a
            .clone()
            .lu()
            .solve(&rhs)
            .ok_or(ThermalError::Singular {
                context: "solving the steady state",
            })?
    };
    let t = sys.scatter(&t_free);
    let (heat_in_w, heat_out_w) = energy_balance(network, &resolved, &q, &t);
    let nodes = network
        .nodes
        .iter()
        .zip(&t)
        .map(|(n, &temperature_c)| SteadyNode {
            name: n.name.clone(),
            temperature_c,
            fixed: n.is_fixed(),
        })
        .collect();
    Ok(SteadyResult {
        nodes,
        heat_in_w,
        heat_out_w,
        balance_w: heat_in_w - heat_out_w,
    })
}

/// (heat in, heat out), W, computed link by link from the temperatures, independently of
/// the matrix: a check on the solve.
fn energy_balance(network: &Network, resolved: &Resolved, q: &[f64], t: &[f64]) -> (f64, f64) {
    let heat_in: f64 = network
        .nodes
        .iter()
        .zip(q)
        .filter(|(n, _)| !n.is_fixed())
        .map(|(_, &qi)| qi)
        .sum();
    let mut heat_out = 0.0;
    for (link, &(a, b)) in network.links.iter().zip(&resolved.ends) {
        let f = link.coefficient_w_k();
        let (fa, fb) = (network.nodes[a].is_fixed(), network.nodes[b].is_fixed());
        if link.is_mass_transport() {
            // Oil enthalpy picked up across the downstream node; a fixed downstream node
            // is a sink outside the network and changes no free balance.
            if !fb {
                heat_out += f * (t[b] - t[a]);
            }
        } else if fa != fb {
            let (free, fixed) = if fa { (b, a) } else { (a, b) };
            heat_out += f * (t[free] - t[fixed]);
        }
    }
    (heat_in, heat_out)
}
