//! The optimiser on the shipped deck.

use super::*;
use crate::bearings::double_row_spherical::input::DoubleRowInput;

/// A proxy objective that reads only the geometry: (k_Ci − 1.002)², in W. Its free
/// minimum is inside the band at k_Ci = 1.002, but a less conforming inner raceway raises
/// the contact pressure, so the p_max constraint stops k_Ci at 1 from above.
#[test]
fn a_proxy_objective_is_stopped_by_p_max() {
    let mut b = DoubleRowInput::example_22308();
    b.optimise.variables = vec!["k_ci".into()];
    b.optimise.grid = 5;
    b.solver.laminae = 21;
    let r0 = b.geometry.inner_raceway_radius_m;
    let obj = move |a: &DoubleRowAnalysis| -> Result<CaseLoss, String> {
        let k = a.input.geometry.inner_raceway_radius_m / r0;
        Ok(CaseLoss {
            total_w: 1.0 + (k - 1.002).powi(2) * 1e4,
            ..CaseLoss::default()
        })
    };
    let o = optimise(&b, "t", &obj, Cancel::NONE).unwrap_or_else(|e| panic!("{e}"));
    eprintln!("{}", report::text(&o, crate::units::Units::Si));
    assert!(o.optimum.binding.iter().any(|s| s == "p_max"), "{:?}", o.optimum.binding);
}
