//! Hairer's DOP853: the explicit Runge–Kutta pair of order 8 with embedded error
//! estimators of orders 5 and 3 and a continuous extension of order 7.
//!
//! Coefficients from E. Hairer, S. P. Nørsett and G. Wanner, *Solving Ordinary
//! Differential Equations I*, 2nd ed., §II.5 (the 12-stage method of Dormand and
//! Prince, 1981) and §II.6 (the dense output with three extra stages), as tabulated in
//! Hairer's `dop853.f` and SciPy's `dop853_coefficients.py` (constants only, rounded
//! to f64). The eighth-order solution is propagated; the step's last stage
//! f(t + h, y_new) is the next step's first (FSAL), so a step costs 11 new evaluations
//! plus one after acceptance, and the dense output 3 more, taken only for steps whose
//! interval holds an output time or an event crossing.
//!
//! Error estimate (Hairer's "stretched" 5(3) combination): with
//! e5 = Σ E5_j k_j, e3 = Σ E3_j k_j and the weights sk = atol + rtol·max(|y|, |y_new|),
//! err = |h|·‖e5‖² / √(n (‖e5‖² + 0.01 ‖e3‖²)) in the sk-weighted Euclidean norm; it
//! behaves like h⁸ and drives the step with the exponent 1/8.

use super::dense::Interpolant;
use super::{Counted, OdeSystem, Tol, TrialError};

pub(super) const C: [f64; 16] = [
    0.0,
    0.05260015195876773,
    0.0789002279381516,
    0.1183503419072274,
    0.2816496580927726,
    0.3333333333333333,
    0.25,
    0.3076923076923077,
    0.6512820512820513,
    0.6,
    0.8571428571428571,
    1.0,
    1.0,
    0.1,
    0.2,
    0.7777777777777778,
];
/// Rows 1..=15 of the extended tableau (row s uses stages 0..s); row 12 is b.
pub(super) const A: [[f64; 15]; 16] = [
    [
        0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    ],
    [
        0.05260015195876773,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.0197250569845379,
        0.0591751709536137,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.02958758547680685,
        0.0,
        0.08876275643042054,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.2413651341592667,
        0.0,
        -0.8845494793282861,
        0.924834003261792,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.037037037037037035,
        0.0,
        0.0,
        0.17082860872947386,
        0.12546768756682242,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.037109375,
        0.0,
        0.0,
        0.17025221101954405,
        0.06021653898045596,
        -0.017578125,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.03709200011850479,
        0.0,
        0.0,
        0.17038392571223998,
        0.10726203044637328,
        -0.015319437748624402,
        0.008273789163814023,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.6241109587160757,
        0.0,
        0.0,
        -3.3608926294469414,
        -0.868219346841726,
        27.59209969944671,
        20.154067550477894,
        -43.48988418106996,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.47766253643826434,
        0.0,
        0.0,
        -2.4881146199716677,
        -0.590290826836843,
        21.230051448181193,
        15.279233632882423,
        -33.28821096898486,
        -0.020331201708508627,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        -0.9371424300859873,
        0.0,
        0.0,
        5.186372428844064,
        1.0914373489967295,
        -8.149787010746927,
        -18.52006565999696,
        22.739487099350505,
        2.4936055526796523,
        -3.0467644718982196,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        2.273310147516538,
        0.0,
        0.0,
        -10.53449546673725,
        -2.0008720582248625,
        -17.9589318631188,
        27.94888452941996,
        -2.8589982771350235,
        -8.87285693353063,
        12.360567175794303,
        0.6433927460157636,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.054293734116568765,
        0.0,
        0.0,
        0.0,
        0.0,
        4.450312892752409,
        1.8915178993145003,
        -5.801203960010585,
        0.3111643669578199,
        -0.1521609496625161,
        0.20136540080403034,
        0.04471061572777259,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.056167502283047954,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.25350021021662483,
        -0.2462390374708025,
        -0.12419142326381637,
        0.15329179827876568,
        0.00820105229563469,
        0.007567897660545699,
        -0.008298,
        0.0,
        0.0,
    ],
    [
        0.03183464816350214,
        0.0,
        0.0,
        0.0,
        0.0,
        0.028300909672366776,
        0.053541988307438566,
        -0.05492374857139099,
        0.0,
        0.0,
        -0.00010834732869724932,
        0.0003825710908356584,
        -0.00034046500868740456,
        0.1413124436746325,
        0.0,
    ],
    [
        -0.42889630158379194,
        0.0,
        0.0,
        0.0,
        0.0,
        -4.697621415361164,
        7.683421196062599,
        4.06898981839711,
        0.3567271874552811,
        0.0,
        0.0,
        0.0,
        -0.0013990241651590145,
        2.9475147891527724,
        -9.15095847217987,
    ],
];
pub(super) const E3: [f64; 12] = [
    -0.18980075407240762,
    0.0,
    0.0,
    0.0,
    0.0,
    4.450312892752409,
    1.8915178993145003,
    -5.801203960010585,
    -0.4226823213237919,
    -0.1521609496625161,
    0.20136540080403034,
    0.02265179219836082,
];
pub(super) const E5: [f64; 12] = [
    0.01312004499419488,
    0.0,
    0.0,
    0.0,
    0.0,
    -1.2251564463762044,
    -0.4957589496572502,
    1.6643771824549864,
    -0.35032884874997366,
    0.3341791187130175,
    0.08192320648511571,
    -0.022355307863886294,
];
pub(super) const D: [[f64; 16]; 4] = [
    [
        -8.428938276109013,
        0.0,
        0.0,
        0.0,
        0.0,
        0.5667149535193777,
        -3.0689499459498917,
        2.38466765651207,
        2.117034582445028,
        -0.871391583777973,
        2.2404374302607883,
        0.6315787787694688,
        -0.08899033645133331,
        18.148505520854727,
        -9.194632392478356,
        -4.436036387594894,
    ],
    [
        10.427508642579134,
        0.0,
        0.0,
        0.0,
        0.0,
        242.28349177525817,
        165.20045171727028,
        -374.5467547226902,
        -22.113666853125306,
        7.733432668472264,
        -30.674084731089398,
        -9.332130526430229,
        15.697238121770845,
        -31.139403219565178,
        -9.35292435884448,
        35.81684148639408,
    ],
    [
        19.985053242002433,
        0.0,
        0.0,
        0.0,
        0.0,
        -387.0373087493518,
        -189.17813819516758,
        527.8081592054236,
        -11.57390253995963,
        6.8812326946963,
        -1.0006050966910838,
        0.7777137798053443,
        -2.778205752353508,
        -60.19669523126412,
        84.32040550667716,
        11.99229113618279,
    ],
    [
        -25.69393346270375,
        0.0,
        0.0,
        0.0,
        0.0,
        -154.18974869023643,
        -231.5293791760455,
        357.6391179106141,
        93.40532418362432,
        -37.45832313645163,
        104.0996495089623,
        29.8402934266605,
        -43.53345659001114,
        96.32455395918828,
        -39.17726167561544,
        -149.72683625798564,
    ],
];

/// Order of the error estimate plus one: the step-size exponent is 1/8.
pub(crate) const ERROR_EXPONENT: f64 = 0.125;

/// Stage storage for DOP853: stage `j` is `k[j·n..(j + 1)·n]` (one flat buffer: no
/// pointer chase per stage); `k_0` is a copy of the driver's f(t, y); `k_12` is
/// f(t + h, y_new); `k_13..16` are the dense output's extra stages.
#[derive(Debug, Clone)]
pub(crate) struct Dop853 {
    n: usize,
    k: Vec<f64>,
    stage: Vec<f64>,
    /// Σ_j A[s][j]·k_j per component, before the `y + h·acc` of [`Dop853::stage_point`].
    acc: Vec<f64>,
}

impl Dop853 {
    pub(crate) fn new(n: usize) -> Self {
        Dop853 {
            n,
            k: vec![0.0; 16 * n],
            stage: vec![0.0; n],
            acc: vec![0.0; n],
        }
    }

    fn kj(&self, j: usize) -> &[f64] {
        &self.k[j * self.n..(j + 1) * self.n]
    }

    /// `out = y + h·Σ_{j<s} A[s][j]·k_j`, summed over j in ascending order for every
    /// component (the same rounding as a per-component loop), zero coefficients skipped
    /// once per stage rather than once per component.
    fn stage_point(k: &[f64], acc: &mut [f64], out: &mut [f64], y: &[f64], h: f64, s: usize) {
        let n = y.len();
        acc.iter_mut().for_each(|a| *a = 0.0);
        for (j, &a) in A[s].iter().enumerate().take(s) {
            if a != 0.0 {
                for (acc_i, &kji) in acc.iter_mut().zip(&k[j * n..(j + 1) * n]) {
                    *acc_i += a * kji;
                }
            }
        }
        for ((o, &yi), &ai) in out.iter_mut().zip(y).zip(acc.iter()) {
            *o = yi + h * ai;
        }
    }

    /// One trial step from `(t, y)` with `f0 = f(t, y)` and step `h`, landing at
    /// `t_new`. Writes the eighth-order solution to `y_new` and returns the error norm
    /// (≤ 1: acceptable). f(t_new, y_new) is left to [`Dop853::finish`].
    #[allow(clippy::too_many_arguments)] // all are distinct step inputs
    pub(crate) fn step<S: OdeSystem + ?Sized>(
        &mut self,
        rhs: &mut Counted<'_, S>,
        t: f64,
        y: &[f64],
        f0: &[f64],
        h: f64,
        t_new: f64,
        y_new: &mut [f64],
        tol: Tol,
    ) -> Result<f64, TrialError> {
        let n = self.n;
        self.k[..n].copy_from_slice(f0);
        for (s, &cs) in C.iter().enumerate().take(12).skip(1) {
            Self::stage_point(&self.k, &mut self.acc, &mut self.stage, y, h, s);
            // C[11] = 1: land on t_new bit-exactly.
            let ts = if s == 11 { t_new } else { t + cs * h };
            if !rhs.eval(ts, &self.stage, &mut self.k[s * n..(s + 1) * n]) {
                return Err(TrialError::NonFinite);
            }
        }
        Self::stage_point(&self.k, &mut self.acc, y_new, y, h, 12);
        let (mut e5, mut e3) = (0.0, 0.0);
        for (i, (&a, &b)) in y.iter().zip(y_new.iter()).enumerate() {
            if !b.is_finite() {
                return Err(TrialError::NonFinite);
            }
            let sk = tol.atol + tol.rtol * a.abs().max(b.abs());
            let (mut r5, mut r3) = (0.0, 0.0);
            for j in 0..12 {
                let kji = self.k[j * n + i];
                r5 += E5[j] * kji;
                r3 += E3[j] * kji;
            }
            e5 += (r5 / sk) * (r5 / sk);
            e3 += (r3 / sk) * (r3 / sk);
        }
        let denom = e5 + 0.01 * e3;
        let err = if denom > 0.0 {
            h.abs() * e5 / (denom * y.len() as f64).sqrt()
        } else {
            0.0
        };
        if err.is_finite() {
            Ok(err)
        } else {
            Err(TrialError::NonFinite)
        }
    }

    /// Evaluate f(t_new, y_new) after acceptance (the FSAL stage); `false` if it is not
    /// finite.
    pub(crate) fn finish<S: OdeSystem + ?Sized>(
        &mut self,
        rhs: &mut Counted<'_, S>,
        t_new: f64,
        y_new: &[f64],
    ) -> bool {
        let n = self.n;
        rhs.eval(t_new, y_new, &mut self.k[12 * n..13 * n])
    }

    /// f(t_new, y_new) from the last [`Dop853::finish`].
    pub(crate) fn f_new(&self) -> &[f64] {
        self.kj(12)
    }

    /// Fill `ip` with the seventh-order continuous extension of the last accepted
    /// step (three more evaluations); `false` if one of them is not finite.
    #[allow(clippy::too_many_arguments)] // all are distinct step data
    pub(crate) fn dense<S: OdeSystem + ?Sized>(
        &mut self,
        rhs: &mut Counted<'_, S>,
        ip: &mut Interpolant,
        t: f64,
        h: f64,
        y: &[f64],
        y_new: &[f64],
    ) -> bool {
        let n = self.n;
        for (s, &cs) in C.iter().enumerate().skip(13) {
            Self::stage_point(&self.k, &mut self.acc, &mut self.stage, y, h, s);
            if !rhs.eval(t + cs * h, &self.stage, &mut self.k[s * n..(s + 1) * n]) {
                return false;
            }
        }
        ip.set_hermite(t, h, y, y_new, self.kj(0), self.kj(12));
        let (r5, r6, r7, r8) = ip.high_mut();
        for (i, (((a, b), c), d)) in r5
            .iter_mut()
            .zip(r6.iter_mut())
            .zip(r7.iter_mut())
            .zip(r8.iter_mut())
            .enumerate()
        {
            let mut acc = [0.0; 4];
            for j in 0..16 {
                let kji = self.k[j * n + i];
                for (row, out) in D.iter().zip(acc.iter_mut()) {
                    *out += row[j] * kji;
                }
            }
            *a = h * acc[0];
            *b = h * acc[1];
            *c = h * acc[2];
            *d = h * acc[3];
        }
        true
    }
}
