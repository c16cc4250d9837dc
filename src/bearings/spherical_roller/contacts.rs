//! Per-lamina contact geometry at the solved equilibrium: the radii in the rolling direction
//! and the distances from the bearing and roller axes that §4 (Hertz), §5 (EHD), §7 (speeds)
//! and §8 (sliding) need.
//!
//! Both bodies are surfaces of revolution (the ring about the bearing axis, the roller about
//! its own tilted axis). By Meusnier's theorem the principal radius of curvature in the
//! circumferential (rolling) direction is the length of the normal from the surface point to
//! the body's axis. The ring radius is convex (+) at the inner raceway and concave (−) at the
//! outer, the seed's sign convention of eq. 4.1 and eq. 5.1.

use serde::Serialize;

use super::load_distribution::{LoadDistribution, RollerResult};
use crate::bearings::spherical_roller::Bearing;

/// Contact state of one lamina at one raceway.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LaminaContact {
    /// Lamina normal load, N.
    pub load_n: f64,
    /// Lamina width, m.
    pub width_m: f64,
    /// Distance of the contact point from the bearing axis, m.
    pub ring_axis_distance_m: f64,
    /// Distance of the contact point from the roller axis, m.
    pub roller_axis_distance_m: f64,
    /// Roller's radius of curvature in the rolling direction, m (convex, > 0).
    pub roller_radius_m: f64,
    /// Ring's radius of curvature in the rolling direction, m (inner > 0, outer < 0).
    pub ring_radius_m: f64,
    /// Reduced radius 1/(1/r_roller + 1/r_ring), m.
    pub reduced_radius_m: f64,
    /// Whether the lamina is an edge lamina (first or last).
    pub edge: bool,
}

/// Contact states of one roller: `[inner, outer]` per lamina.
pub type RollerContacts = Vec<[LaminaContact; 2]>;

impl LaminaContact {
    /// Load per unit length Q/w, N/m (0 when unloaded or of no width): what ranks the
    /// laminae by how heavily they are loaded, whatever their widths.
    pub fn line_load_n_m(&self) -> f64 {
        if self.load_n > 0.0 && self.width_m > 0.0 {
            self.load_n / self.width_m
        } else {
            0.0
        }
    }
}

/// Build the contact states of every lamina of every roller.
pub fn contacts(b: &Bearing, ld: &LoadDistribution) -> Vec<RollerContacts> {
    let mut out: Vec<RollerContacts> = Vec::with_capacity(ld.rollers.len());
    for (j, r) in ld.rollers.iter().enumerate() {
        let c = match ld.mirror.get(j).copied().flatten() {
            Some(i) => out[i].clone(),
            None => roller_contacts(b, r),
        };
        out.push(c);
    }
    out
}

fn roller_contacts(b: &Bearing, r: &RollerResult) -> RollerContacts {
    let beta = b.geometry.contact_angle_rad;
    let tilt = r.tilt_rad;
    // Roller axis a = (cos β, −sin β) rotated by the pitch α.
    let a0 = [beta.cos(), -beta.sin()];
    let (s, c) = tilt.sin_cos();
    let a = [c * a0[0] - s * a0[1], s * a0[0] + c * a0[1]];
    let centre = [
        r.axial_displacement_m,
        r.radial_displacement_m + 0.5 * b.geometry.pitch_diameter_m,
    ];
    let n = r.laminae.len();
    r.laminae
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let edge = n > 1 && (i == 0 || i + 1 == n);
            let mk = |inner: bool| {
                // Unit normal of the contact (x, r): the contact angle direction.
                let (pt, load, nn) = if inner {
                    (l.inner_point_m, l.inner_load_n, l.inner_normal)
                } else {
                    (l.outer_point_m, l.outer_load_n, l.outer_normal)
                };
                // Ring: normal line from the point to the bearing axis (r = 0): length r/cos β'.
                let ring_len = pt[1] / nn[1].abs().max(1e-12);
                // Roller: normal line P + s·n meets the roller axis centre + t·a.
                let d = [pt[0] - centre[0], pt[1] - centre[1]];
                let det = nn[0] * (-a[1]) - nn[1] * (-a[0]);
                let roller_len = if det.abs() > 1e-12 {
                    // Solve P + s n = C + t a  →  s n − t a = C − P.
                    let rhs = [-d[0], -d[1]];
                    ((rhs[0] * (-a[1]) - rhs[1] * (-a[0])) / det).abs()
                } else {
                    0.5 * b.geometry.roller_diameter_m
                };
                let dist_axis = (d[0] * a[1] - d[1] * a[0]).abs();
                let ring_radius = if inner { ring_len } else { -ring_len };
                let curv = 1.0 / roller_len + 1.0 / ring_radius;
                LaminaContact {
                    load_n: load,
                    width_m: l.width_m,
                    ring_axis_distance_m: pt[1],
                    roller_axis_distance_m: dist_axis,
                    roller_radius_m: roller_len,
                    ring_radius_m: ring_radius,
                    reduced_radius_m: if curv > 0.0 { 1.0 / curv } else { f64::MAX },
                    edge,
                }
            };
            [mk(true), mk(false)]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearings::spherical_roller::load_distribution::solved_at_rest;

    #[test]
    fn radii_match_nominal_geometry() {
        // At the mid lamina of an unloaded bearing the rolling radii are the textbook ones:
        // roller D/2; inner ring (P_t/2 − D/2·cos β)/cos β; outer −(P_t/2 + D/2·cos β)/cos β.
        // Displacements are zero (no load, no speed): round-off tolerance 1e-9 relative.
        let (b, ld) = solved_at_rest();
        let c = contacts(&b, &ld);
        let mid = c[0][b.solver.laminae / 2];
        let (d, p, beta) = (
            b.geometry.roller_diameter_m,
            b.geometry.pitch_diameter_m,
            b.geometry.contact_angle_rad,
        );
        let close = |x: f64, y: f64| (x / y - 1.0).abs() < 1e-9;
        assert!(
            close(mid[0].roller_radius_m, d / 2.0),
            "{}",
            mid[0].roller_radius_m
        );
        assert!(close(mid[1].roller_radius_m, d / 2.0));
        assert!(close(
            mid[0].ring_radius_m,
            (p / 2.0 - d / 2.0 * beta.cos()) / beta.cos()
        ));
        assert!(close(
            mid[1].ring_radius_m,
            -(p / 2.0 + d / 2.0 * beta.cos()) / beta.cos()
        ));
        assert!(close(mid[0].roller_axis_distance_m, d / 2.0));
    }
}
