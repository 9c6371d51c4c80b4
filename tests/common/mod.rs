//! Small ODEs with known answers, shared by the integration tests.
#![allow(dead_code)]

use wingbeat::solve::LinearOde;

/// q̈ + c q̇ + ω² q = F cos(Ω t) (column 0) and = G sin(Ω t) (column 1); period 2π/Ω.
pub struct ConstOsc {
    pub w: f64,
    pub c: f64,
    pub f: f64,
    pub g: f64,
    pub wf: f64,
}

impl LinearOde for ConstOsc {
    fn n_forces(&self) -> usize {
        2
    }
    fn damping(&self) -> f64 {
        self.c
    }
    fn eval(&self, t: f64, f: &mut [f64]) -> f64 {
        f[0] = self.f * (self.wf * t).cos();
        f[1] = self.g * (self.wf * t).sin();
        self.w * self.w
    }
    fn period(&self) -> f64 {
        2.0 * std::f64::consts::PI / self.wf
    }
    fn freq_scale(&self) -> f64 {
        self.w.max(self.wf)
    }
}

/// Mathieu's equation in standard form y″ + (a − 2 q cos 2t) y = 0 (period π), with a forcing
/// column f = sin 3t for the order tests.
pub struct Mathieu {
    pub a: f64,
    pub q: f64,
    pub c: f64,
}

impl LinearOde for Mathieu {
    fn n_forces(&self) -> usize {
        1
    }
    fn damping(&self) -> f64 {
        self.c
    }
    fn eval(&self, t: f64, f: &mut [f64]) -> f64 {
        f[0] = (3.0 * t).sin();
        self.a - 2.0 * self.q * (2.0 * t).cos()
    }
    fn period(&self) -> f64 {
        std::f64::consts::PI
    }
    fn freq_scale(&self) -> f64 {
        self.a.abs().sqrt().max(3.0)
    }
}

/// Largest |x| of a series.
pub fn max_abs(x: &[f64]) -> f64 {
    x.iter().fold(0.0, |m, v| m.max(v.abs()))
}

/// Largest |x − y| over two series.
pub fn max_diff(x: &[f64], y: &[f64]) -> f64 {
    assert_eq!(x.len(), y.len());
    x.iter().zip(y).fold(0.0, |m, (a, b)| m.max((a - b).abs()))
}
