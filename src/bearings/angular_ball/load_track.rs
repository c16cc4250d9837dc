//! The quasi-static loads of a ball as it orbits (seed 001 ch. 6, Figs. 6-9/6-10): under
//! radial load each ball's contact loads, angles and ellipses follow its azimuth; the
//! ball dynamics (`dynamics`) reads them here, linear in azimuth between the balls of
//! the load distribution (the seed gives no rule between balls; linear keeps every
//! ball's own loads exactly).

use super::results::BallResult;

/// The loads of one contact that the slices need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLoads {
    /// Q, N.
    pub load_n: f64,
    /// α, rad.
    pub angle_rad: f64,
    /// Semi-major axis a (transverse), m.
    pub semi_major_m: f64,
}

/// Both contacts of a ball at one orbit position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallLoads {
    /// Inner contact.
    pub inner: ContactLoads,
    /// Outer contact.
    pub outer: ContactLoads,
}

impl BallLoads {
    fn lerp(&self, o: &BallLoads, w: f64) -> BallLoads {
        let c = |x: &ContactLoads, y: &ContactLoads| ContactLoads {
            load_n: x.load_n + w * (y.load_n - x.load_n),
            angle_rad: x.angle_rad + w * (y.angle_rad - x.angle_rad),
            semi_major_m: x.semi_major_m + w * (y.semi_major_m - x.semi_major_m),
        };
        BallLoads {
            inner: c(&self.inner, &o.inner),
            outer: c(&self.outer, &o.outer),
        }
    }
}

/// The quasi-static loads around the orbit: the load distribution's balls, read as a
/// periodic function of azimuth, linear between the balls (the loads of a ball follow its
/// orbit position under radial load).
#[derive(Debug, Clone, PartialEq)]
pub struct LoadTrack {
    /// Ascending azimuths in [0, 2π), rad, and the loads there.
    points: Vec<(f64, BallLoads)>,
}

impl LoadTrack {
    /// From the race-control analysis' balls.
    pub fn new(balls: &[BallResult]) -> Self {
        let c = |r: &super::results::ContactResult| ContactLoads {
            load_n: r.load_n,
            angle_rad: r.angle_rad,
            semi_major_m: r.hertz.semi_major_m,
        };
        let mut points: Vec<(f64, BallLoads)> = balls
            .iter()
            .map(|b| {
                (
                    b.azimuth_rad.rem_euclid(std::f64::consts::TAU),
                    BallLoads {
                        inner: c(&b.inner),
                        outer: c(&b.outer),
                    },
                )
            })
            .collect();
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        LoadTrack { points }
    }

    /// The azimuths of the track's points in [0, 2π), rad, ascending: where its loads
    /// change slope (the right-hand side of the ball equations has a kink there).
    pub fn azimuths(&self) -> impl Iterator<Item = f64> + '_ {
        self.points.iter().map(|p| p.0)
    }

    /// The angle (rad, > `min_gap`) from azimuth ψ to the next point of the track met
    /// going `forward` (ψ increasing) or backward: where the ball's loads next change
    /// slope. Points closer than `min_gap` ahead are passed over (the free orbit's
    /// piecewise integration lands on a point only to within its prediction error and
    /// must not aim at it again); with every point that close, the next one is a turn
    /// further. `None` for an empty track.
    pub fn angle_to_next_point(&self, psi: f64, forward: bool, min_gap: f64) -> Option<f64> {
        let tau = std::f64::consts::TAU;
        let psi = psi.rem_euclid(tau);
        self.points
            .iter()
            .map(|p| {
                let d = if forward { p.0 - psi } else { psi - p.0 }.rem_euclid(tau);
                if d <= min_gap {
                    d + tau
                } else {
                    d
                }
            })
            .min_by(f64::total_cmp)
    }

    /// Whether every point has the same loads (an axisymmetric load): then there is no
    /// kink to respect.
    pub fn is_uniform(&self) -> bool {
        self.points.windows(2).all(|w| w[0].1 == w[1].1)
    }

    /// The loads at azimuth ψ (rad, any value).
    pub fn at(&self, psi: f64) -> BallLoads {
        let tau = std::f64::consts::TAU;
        let n = self.points.len();
        let psi = psi.rem_euclid(tau);
        let k = self.points.partition_point(|p| p.0 <= psi);
        // Between the last ball below ψ and the next one, wrapping round 2π.
        let (lo, hi) = if k == 0 || k == n {
            (&self.points[n - 1], &self.points[0])
        } else {
            (&self.points[k - 1], &self.points[k])
        };
        let mut span = hi.0 - lo.0;
        let mut off = psi - lo.0;
        if span <= 0.0 {
            span += tau;
        }
        if off < 0.0 {
            off += tau;
        }
        let w = if n == 1 { 0.0 } else { off / span };
        lo.1.lerp(&hi.1, w)
    }
}
