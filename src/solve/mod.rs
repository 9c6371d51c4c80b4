//! Solvers for linear, time-periodic, second-order modal equations such as Eq. 13.
//!
//! Every equation handled here has the form
//!
//! ```text
//! q̈ + c q̇ + k(t) q = f_j(t),   j = 0..n_forces,
//! ```
//!
//! with constant damping c (1/s), stiffness k(t) and forcings f_j(t) periodic with period T.
//! Several right-hand sides share one homogeneous part, so one sweep produces the partial
//! responses to the Euler, centrifugal and Coriolis terms and to their sum.
//!
//! * [`propagator`] — the production solver: integrate one period once (Gauss–Legendre
//!   collocation, order 8), store the state-transition matrix and particular solutions at every
//!   output phase, then step period to period by exact affine maps. Exact to rounding apart from
//!   the one-period integration, whose error is estimated and reported.
//! * [`gauss`] — the order-8 Gauss–Legendre step for linear systems (A-stable, symplectic).
//! * [`rk4`] — the classical explicit Runge–Kutta method, an independent second method used to
//!   cross-check the propagator.

pub mod coupled;
pub mod gauss;
pub mod propagator;
pub mod rk4;
pub mod stats;

/// Number of stages of the Gauss–Legendre method ([`gauss`]).
pub const STAGES: usize = 4;

/// A linear second-order ODE with periodic coefficients and several forcings.
pub trait LinearOde {
    /// Number of forcing functions f_j (≤ [`MAX_FORCES`]).
    fn n_forces(&self) -> usize;
    /// Constant damping coefficient c, 1/s (2 ζ ω for a modal equation).
    fn damping(&self) -> f64;
    /// Stiffness k(t) (1/s²); writes f_j(t) into `f` (length `n_forces`).
    fn eval(&self, t: f64, f: &mut [f64]) -> f64;
    /// Stiffness and forcings at the stage times t0 + c_i h of one Gauss–Legendre step: k into
    /// `ks[i]`, f_j into `fs[i][..n_forces]`. The default calls [`LinearOde::eval`] at each
    /// time; an equation may share work between the four, giving `eval`'s values to rounding
    /// (`ModalOde` turns the kinematics' sines from the step start: within 8 ε of them).
    fn eval_stages(
        &self,
        t0: f64,
        h: f64,
        c: &[f64; STAGES],
        ks: &mut [f64; STAGES],
        fs: &mut [[f64; MAX_FORCES]; STAGES],
    ) {
        let nf = self.n_forces();
        for i in 0..STAGES {
            ks[i] = self.eval(t0 + c[i] * h, &mut fs[i][..nf]);
        }
    }
    /// Period T of the coefficients, s.
    fn period(&self) -> f64;
    /// Period of the homogeneous part (k and c) alone; a divisor of T (T/2 for the paper's
    /// symmetric sinusoids). Default: T.
    fn homogeneous_period(&self) -> f64 {
        self.period()
    }
    /// The highest angular frequency (rad/s) the solution or forcings contain to relevant
    /// accuracy; the step size is chosen from it.
    fn freq_scale(&self) -> f64;
}

/// Most forcing columns one solve carries.
pub const MAX_FORCES: usize = 4;

/// The homogeneous part of an equation alone (no forcing columns): for the state-transition
/// matrix, whose steps then carry two columns instead of two plus the forcings. The
/// equation's stiffness and damping are read unchanged, so Φ comes out the same bits.
pub struct Homogeneous<'a, O: LinearOde + ?Sized>(pub &'a O);

impl<O: LinearOde + ?Sized> LinearOde for Homogeneous<'_, O> {
    fn n_forces(&self) -> usize {
        0
    }
    fn damping(&self) -> f64 {
        self.0.damping()
    }
    fn eval(&self, t: f64, _f: &mut [f64]) -> f64 {
        let mut f = [0.0; MAX_FORCES];
        self.0.eval(t, &mut f[..self.0.n_forces()])
    }
    fn eval_stages(
        &self,
        t0: f64,
        h: f64,
        c: &[f64; STAGES],
        ks: &mut [f64; STAGES],
        _fs: &mut [[f64; MAX_FORCES]; STAGES],
    ) {
        let mut fs = [[0.0; MAX_FORCES]; STAGES];
        self.0.eval_stages(t0, h, c, ks, &mut fs);
    }
    fn period(&self) -> f64 {
        self.0.period()
    }
    fn homogeneous_period(&self) -> f64 {
        self.0.homogeneous_period()
    }
    fn freq_scale(&self) -> f64 {
        self.0.freq_scale()
    }
}

/// The modal equation (Eq. 13) of one mode as a [`LinearOde`], with forcing columns
/// `[euler, centrifugal, coriolis, total]` in that order.
pub struct ModalOde<'a> {
    /// Compiled kinematics.
    pub kin: &'a crate::kinematics::Compiled,
    /// The mode.
    pub mode: &'a crate::model::Mode,
    /// Largest harmonic number present in the kinematics, body rate included (for the step size).
    pub max_harmonic: f64,
    /// Whether the softening has period T/2.
    pub half_period: bool,
    /// The rotations already worked out for another mode of the same run, when shared
    /// ([`ModalOde::sharing`]).
    pub memo: Option<&'a RotationMemo>,
    /// The harmonics' turns to the stage times of the current step length
    /// ([`crate::kinematics::Compiled::stage_states`]).
    turns: std::cell::RefCell<crate::kinematics::StageTurns>,
}

/// The rotations ([`crate::model::Rotation`]) at the four stage times of each step the solver
/// took, in the order taken, kept for the next mode of the same run: every mode whose step
/// sizes are the same takes the same steps in the same order (the paper's two modes do; so do
/// most FE modes below the kinematics' frequency scale), and then reads them here instead of
/// evaluating the kinematics again. A step that differs from the recorded one at that position
/// (a mode with other steps) is worked out afresh, so the results are the same bits either way.
#[derive(Debug, Default)]
pub struct RotationMemo {
    steps: std::cell::RefCell<Vec<MemoStep>>,
    next: std::cell::Cell<usize>,
}

/// One recorded step: its start and length (as bits) and the rotations at its stage times.
type MemoStep = (u64, u64, [crate::model::Rotation; STAGES]);

impl RotationMemo {
    /// Most rotations kept (≈ 80 B each: 8 MB); later steps are worked out every time.
    pub const MAX_ENTRIES: usize = 100_000;

    /// An empty memo.
    pub fn new() -> Self {
        Self::default()
    }

    /// Starts the next mode: reads from the first recorded step again.
    pub fn rewind(&self) {
        self.next.set(0);
    }

    /// Number of rotations recorded (four per step).
    pub fn len(&self) -> usize {
        self.steps.borrow().len() * STAGES
    }

    /// Whether nothing is recorded yet.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// `read` of the rotations of the step from `t0` over `h`: the recorded ones when the next
    /// recorded step is this one (bit for bit), else `work()`'s, recorded when the memo is at its
    /// end and has room.
    fn with<R>(
        &self,
        t0: f64,
        h: f64,
        work: impl FnOnce() -> [crate::model::Rotation; STAGES],
        read: impl FnOnce(&[crate::model::Rotation; STAGES]) -> R,
    ) -> R {
        let i = self.next.get();
        let key = (t0.to_bits(), h.to_bits());
        let mut v = self.steps.borrow_mut();
        if let Some((t, hh, r)) = v.get(i) {
            if (*t, *hh) == key {
                self.next.set(i + 1);
                return read(r);
            }
            return read(&work());
        }
        let r = work();
        if (v.len() + 1) * STAGES <= Self::MAX_ENTRIES {
            v.push((key.0, key.1, r));
            self.next.set(i + 1);
        }
        read(&r)
    }
}

impl<'a> ModalOde<'a> {
    /// Column indices of the forcings.
    pub const EULER: usize = 0;
    /// Centrifugal column.
    pub const CENTRIFUGAL: usize = 1;
    /// Coriolis column.
    pub const CORIOLIS: usize = 2;
    /// Total (sum of the three) column.
    pub const TOTAL: usize = 3;

    /// Wraps one mode under compiled kinematics.
    pub fn new(kin: &'a crate::kinematics::Compiled, mode: &'a crate::model::Mode) -> Self {
        // A body rate's own harmonics count like the angles' (Rᵀ ω_b mixes both).
        let body = kin.body_rate.iter().flatten();
        let max_harmonic = [&kin.alpha, &kin.beta, &kin.gamma]
            .into_iter()
            .chain(body)
            .flat_map(|s| s.terms.iter().map(|t| t.n))
            .fold(1.0_f64, f64::max);
        ModalOde {
            kin,
            mode,
            max_harmonic,
            half_period: kin.stiffness_coefficient_has_half_period(),
            memo: None,
            turns: Default::default(),
        }
    }

    /// [`ModalOde::new`] reading and recording the kinematics' rotations in `memo`, shared
    /// with the run's other modes (rewind it before each mode's integration).
    pub fn sharing(
        kin: &'a crate::kinematics::Compiled,
        mode: &'a crate::model::Mode,
        memo: &'a RotationMemo,
    ) -> Self {
        ModalOde {
            memo: Some(memo),
            ..ModalOde::new(kin, mode)
        }
    }

    /// The rotation at `t`.
    fn rotation(&self, t: f64) -> crate::model::Rotation {
        crate::model::Rotation::of(&self.kin.state(t))
    }

    /// `read` of the rotations at the stage times t0 + c_i h, from the memo when there is one.
    fn with_stage_rotations<R>(
        &self,
        t0: f64,
        h: f64,
        c: &[f64; STAGES],
        read: impl FnOnce(&[crate::model::Rotation; STAGES]) -> R,
    ) -> R {
        let work = || {
            let states = self
                .kin
                .stage_states(t0, h, c, &mut self.turns.borrow_mut());
            states.map(|s| crate::model::Rotation::of(&s))
        };
        match self.memo {
            Some(m) => m.with(t0, h, work, read),
            None => read(&work()),
        }
    }
}

impl LinearOde for ModalOde<'_> {
    fn n_forces(&self) -> usize {
        4
    }
    fn damping(&self) -> f64 {
        2.0 * self.mode.zeta * self.mode.omega()
    }
    fn eval(&self, t: f64, f: &mut [f64]) -> f64 {
        let c = crate::model::coefficients_of(self.mode, &self.rotation(t));
        f[0] = c.euler;
        f[1] = c.centrifugal;
        f[2] = c.coriolis;
        f[3] = c.total_force();
        c.stiffness
    }
    fn eval_stages(
        &self,
        t0: f64,
        h: f64,
        c: &[f64; STAGES],
        ks: &mut [f64; STAGES],
        fs: &mut [[f64; MAX_FORCES]; STAGES],
    ) {
        self.with_stage_rotations(t0, h, c, |rots| {
            for ((k, f), r) in ks.iter_mut().zip(fs.iter_mut()).zip(rots) {
                let co = crate::model::coefficients_of(self.mode, r);
                *k = co.stiffness;
                f[0] = co.euler;
                f[1] = co.centrifugal;
                f[2] = co.coriolis;
                f[3] = co.total_force();
            }
        });
    }
    fn period(&self) -> f64 {
        2.0 * std::f64::consts::PI / self.kin.wd
    }
    fn homogeneous_period(&self) -> f64 {
        if self.half_period {
            0.5 * self.period()
        } else {
            self.period()
        }
    }
    fn freq_scale(&self) -> f64 {
        // Forcing terms are products of up to three kinematic series, so they carry harmonics
        // up to ~3× the highest kinematic one (and decaying tails beyond).
        let w = self.mode.omega();
        let damp = 2.0 * self.mode.zeta * w;
        w.max(4.0 * self.max_harmonic * self.kin.wd).max(damp)
    }
}

#[cfg(test)]
mod tests {
    use super::propagator::propagate_responses;
    use super::*;
    use crate::kinematics::Kinematics;
    use crate::model::Mode;

    fn mode(freq_hz: f64, a: [f64; 2]) -> Mode {
        Mode {
            name: String::new(),
            freq_hz,
            a,
            zeta: 0.01,
            strains: vec![],
        }
    }

    /// Modes that step alike (62.5 and 86.9 Hz under 25 Hz flapping) read the first mode's
    /// rotations; one that steps differently (900 Hz: a shorter step) works its own out. Every
    /// response is the same bits as without the memo, and the memo grows only with the first.
    #[test]
    fn shared_rotations_give_the_same_bits_as_fresh_ones() {
        let kin = Kinematics::paper_forward_flight().compile();
        let modes = [
            mode(62.5, [0.7552e-5, 0.0934e-5]),
            mode(900.0, [0.3e-5, -0.2e-5]),
            mode(86.9, [-0.1728e-5, -0.0033e-5]),
        ];
        let memo = RotationMemo::new();
        let mut recorded = None;
        for m in &modes {
            memo.rewind();
            let shared = ModalOde::sharing(&kin, m, &memo);
            let a = propagate_responses(&shared, 1e-4, 2001, ModalOde::TOTAL, [1e-6, 0.0]).unwrap();
            let b = propagate_responses(
                &ModalOde::new(&kin, m),
                1e-4,
                2001,
                ModalOde::TOTAL,
                [1e-6, 0.0],
            )
            .unwrap();
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&a.total), bits(&b.total), "{} Hz", m.freq_hz);
            assert_eq!(bits(&a.qdot_total), bits(&b.qdot_total), "{} Hz", m.freq_hz);
            for j in 0..3 {
                assert_eq!(bits(&a.q[j]), bits(&b.q[j]), "{} Hz, column {j}", m.freq_hz);
            }
            assert_eq!(a.monodromy, b.monodromy);
            let n = *recorded.get_or_insert(memo.len());
            assert_eq!(memo.len(), n, "only the first mode records");
        }
        // 400 steps at the output phases and 157 for the error estimate (twice the largest
        // step), 4 stage times each.
        assert_eq!(recorded, Some(4 * (400 + 157)));
    }

    /// A step other than the recorded one at that position is worked out, not recorded; the
    /// values are the same bits as without a memo, and agree with single evaluations.
    #[test]
    fn another_step_is_worked_out_not_recorded() {
        let kin = Kinematics::paper_forward_flight().compile();
        let m = mode(62.5, [1e-5, 0.0]);
        let memo = RotationMemo::new();
        let ode = ModalOde::sharing(&kin, &m, &memo);
        let c = gauss::Tableau::new().c;
        let stages = |ode: &ModalOde<'_>, t0: f64| {
            let (mut ks, mut fs) = ([0.0; STAGES], [[0.0; MAX_FORCES]; STAGES]);
            ode.eval_stages(t0, 1e-4, &c, &mut ks, &mut fs);
            (ks, fs)
        };
        let a = stages(&ode, 0.001);
        assert_eq!(memo.len(), STAGES);
        // A different step at the recorded position: worked out, not recorded.
        memo.rewind();
        let b = stages(&ode, 0.002);
        assert_eq!(memo.len(), STAGES);
        assert_ne!(a.0, b.0);
        let fresh = stages(&ModalOde::new(&kin, &m), 0.002);
        assert_eq!(b, fresh);
        // Each stage agrees with a single evaluation at its time (to rounding: the stages turn
        // the step start's sines instead of taking their own).
        for (i, ci) in c.iter().enumerate() {
            let mut f = [0.0; MAX_FORCES];
            let k = ModalOde::new(&kin, &m).eval(0.002 + ci * 1e-4, &mut f);
            assert!(
                (k - b.0[i]).abs() <= 1e-15 * k.abs(),
                "stage {i}: {k} vs {}",
                b.0[i]
            );
            let scale = f.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
            for j in 0..MAX_FORCES {
                assert!(
                    (f[j] - b.1[i][j]).abs() <= 1e-14 * scale,
                    "stage {i}, force {j}"
                );
            }
        }
    }
}
