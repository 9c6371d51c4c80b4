//! wingbeat's paper case against a compiled general-purpose integrator: DOP853 from the
//! `ode_solvers` crate, on the same eight responses (the paper's two modes, each driven by the
//! Euler, centrifugal and Coriolis terms and by their sum; zero initial state; 2 s sampled at
//! 10 kHz), at rtol 1e-10 and 1e-13 (atol 1e-20). The DOP853 right-hand side is written here
//! from the paper's equations (the same formulas as `benches/scipy_compare.py`), not taken from
//! wingbeat. Prints the median times over repeated runs, their ratio and the largest difference
//! of each DOP853 run from wingbeat's, relative to each series' peak.

use ode_solvers::{Dop853, Vector3};
use std::time::Instant;
use wingbeat::config::SimConfig;
use wingbeat::simulate::{simulate, simulate_reusing};

const FD: f64 = 25.0;
const A0: f64 = 0.8;
const B0: f64 = 0.5;
const G0: f64 = 0.2;
/// The paper's Table 4: f (Hz) and the mode's (a_x, a_y).
const MODES: [(f64, [f64; 2]); 2] = [
    (62.5, [0.7552e-5, 0.0934e-5]),
    (86.9, [-0.1728e-5, -0.0033e-5]),
];
const TERMS: [&str; 4] = ["euler", "centrifugal", "coriolis", "total"];
const N: usize = 20_001;
const DT: f64 = 1e-4;
/// Absolute tolerance (from PEER_ATOL, default 1e-20 as in benches/scipy_compare.py).
static ATOL: std::sync::LazyLock<f64> = std::sync::LazyLock::new(|| {
    std::env::var("PEER_ATOL")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1e-20)
});

/// q̈ = f_term(t) − (ω² − |Ω_xy|²) q for one mode and one forcing term, written autonomous: the
/// state is (q, q̇, t) with ṫ = 1. ode_solvers 0.6.2's DOP853 evaluates stages 12 and 13 at the
/// step's start time (its nodes c₁₂ = c₁₃ = 0 instead of 1: srenevey/ode-solvers pull request
/// #42, open), which ruins any non-autonomous problem (a plain ∫cos: 300 000 steps for 0.1 s and
/// a relative error of 6e-4 at rtol 1e-10); with time as a state the nodes are never read. The
/// time component is integrated exactly (the weights sum to one), so it does not steer the steps.
struct Eq13 {
    w2: f64,
    a: [f64; 2],
    term: usize,
}

impl ode_solvers::System<f64, Vector3<f64>> for Eq13 {
    fn system(&self, _t: f64, y: &Vector3<f64>, dy: &mut Vector3<f64>) {
        let t = y[2];
        let wd = 2.0 * std::f64::consts::PI * FD;
        let (s, c) = (wd * t).sin_cos();
        let (al_d, al_dd) = (A0 * wd * c, -A0 * wd * wd * s);
        let (be, be_d, be_dd) = (B0 * s, B0 * wd * c, -B0 * wd * wd * s);
        let (ga, ga_d) = (G0 * s, G0 * wd * c);
        let (sb, cb) = be.sin_cos();
        let (ox, oy, oz) = (al_d * cb, be_d, al_d * sb);
        let odx = al_dd * cb - al_d * be_d * sb;
        let ody = be_dd;
        let [ax, ay] = self.a;
        let (bx, by) = (-ay, ax);
        let fe = -(odx * (ga * ax - bx) + ody * (ga * ay - by));
        let fc = -oz * (ox * (ax + ga * bx) + oy * (ay + ga * by));
        let fr = -2.0 * ga_d * (ox * ax + oy * ay);
        let f = [fe, fc, fr, fe + fc + fr][self.term];
        let k = self.w2 - (ox * ox + oy * oy);
        dy[0] = y[1];
        dy[1] = f - k * y[0];
        dy[2] = 1.0;
    }
}

/// The eight DOP853 runs: per mode and term, the times and q of the dense output.
fn dop853(rtol: f64) -> Vec<(Vec<f64>, Vec<f64>)> {
    let mut out = Vec::new();
    for (f, a) in MODES {
        for term in 0..4 {
            let w2 = (2.0 * std::f64::consts::PI * f).powi(2);
            // Hairer's defaults (safety 0.9, β 0, step factor in [1/3, 6]) but no stiffness test (its
            // heuristic fires in the first steps, where the zero state makes q̇ ≈ 0) and room
            // for many steps at the tight tolerance.
            let mut s = Dop853::from_param(
                Eq13 { w2, a, term },
                0.0,
                2.0,
                DT,
                Vector3::zeros(),
                rtol,
                *ATOL,
                0.9,
                0.0,
                1.0 / 3.0,
                6.0,
                2.0,
                0.0,
                10_000_000,
                u32::MAX,
                ode_solvers::dop_shared::OutputType::Dense,
            );
            let st = s.integrate().expect("DOP853 integration");
            if std::env::var_os("PEER_DEBUG").is_some() {
                eprintln!("mode {f} Hz, term {}: {st}", TERMS[term]);
            }
            let t = s.x_out().clone();
            let q = s.y_out().iter().map(|y| y[0]).collect();
            out.push((t, q));
        }
    }
    out
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let cfg = SimConfig::paper();
    let reference = simulate(&cfg).expect("wingbeat simulate");
    let ours: Vec<&Vec<f64>> = reference
        .modes
        .iter()
        .flat_map(|m| [&m.q.euler, &m.q.centrifugal, &m.q.coriolis, &m.q.total])
        .collect();
    assert_eq!(ours[0].len(), N);

    // wingbeat: the whole paper case (8 responses, free responses, velocities, strains, Floquet).
    let mut wb = Vec::new();
    for _ in 0..41 {
        let t0 = Instant::now();
        let r = simulate(&cfg).expect("simulate");
        wb.push(t0.elapsed().as_secs_f64() * 1e3);
        std::hint::black_box(r);
    }
    let wb_ms = median(wb);
    println!("wingbeat simulate, paper case (8 responses + Floquet + strains): median {wb_ms:.3} ms (41 runs)");
    // The same, each run writing into the previous result's series (a loop's steady state).
    let mut pool = wingbeat::pool::SeriesPool::new();
    let mut reused = Vec::new();
    for _ in 0..41 {
        let t0 = Instant::now();
        let r = simulate_reusing(&cfg, &mut pool).expect("simulate");
        reused.push(t0.elapsed().as_secs_f64() * 1e3);
        r.recycle(&mut pool);
    }
    println!(
        "wingbeat simulate_reusing, the same run into recycled series: median {:.3} ms (41 runs)",
        median(reused)
    );

    for rtol in [1e-10, 1e-13, 1e-15] {
        let mut ts = Vec::new();
        let mut runs = Vec::new();
        for _ in 0..7 {
            let t0 = Instant::now();
            let r = dop853(rtol);
            ts.push(t0.elapsed().as_secs_f64() * 1e3);
            runs = r;
        }
        let ms = median(ts);
        // The dense output's times are accumulated sums of dt (they drift by up to ~1e-12 s):
        // wingbeat's q is moved to each DOP853 time with its central-difference slope.
        let (mut worst, mut drift) = (0.0_f64, 0.0_f64);
        for (k, (t, q)) in runs.iter().enumerate() {
            assert_eq!(t.len(), N, "{}: dense output length", TERMS[k % 4]);
            let o = ours[k];
            let peak = o.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            for i in 0..N {
                let d = t[i] - i as f64 * DT;
                drift = drift.max(d.abs());
                let slope = if i == 0 || i == N - 1 {
                    0.0
                } else {
                    (o[i + 1] - o[i - 1]) / (2.0 * DT)
                };
                worst = worst.max((q[i] - (o[i] + slope * d)).abs() / peak);
            }
        }
        println!(
            "DOP853 (ode_solvers 0.6.2) rtol {rtol:.0e}, 8 integrations: median {ms:.2} ms (7 runs); \
             ratio DOP853 / wingbeat {:.0}x; max |difference| / peak {worst:.1e} (dense-output time drift ≤ {drift:.1e} s)",
            ms / wb_ms
        );
    }
}
