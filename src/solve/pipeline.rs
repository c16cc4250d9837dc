//! The staged SASHBEAN pipeline: load distribution → stresses → film → life → speeds →
//! sliding/heat → thermal. Each stage runs only when a view or report asks for it.

use std::sync::atomic::AtomicBool;

use serde::Serialize;

use super::load_distribution::{self, DynamicSpeeds, LoadDistribution, SolveOptions, TraceStep};
use super::SolveError;
use crate::model::Bearing;

/// What the caller needs computed.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Request {
    /// Record the equilibrium iterations of this roller (0-based) for the stepper.
    pub trace_roller: Option<usize>,
    /// Run the thermal transient (expensive; only when shown or reported).
    pub thermal_transient: bool,
}

/// Everything computed for one bearing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Analysis {
    /// The resolved input, SI, exactly as solved.
    pub input: Bearing,
    /// Load distribution (seed 000 §3).
    pub load: LoadDistribution,
    /// Stepper trace of the requested roller (empty unless requested).
    #[serde(skip)]
    pub trace: Vec<TraceStep>,
}

/// Run the pipeline on `bearing`.
pub fn run(
    bearing: &Bearing,
    request: &Request,
    cancel: Option<&AtomicBool>,
) -> Result<Analysis, SolveError> {
    let speeds = DynamicSpeeds::app_c_estimate(bearing);
    let opts = SolveOptions {
        warm_start: None,
        trace_roller: request.trace_roller,
    };
    let mut load = load_distribution::solve(bearing, &speeds, &opts, cancel)?;
    let trace = std::mem::take(&mut load.trace);
    Ok(Analysis {
        input: bearing.clone(),
        load,
        trace,
    })
}
