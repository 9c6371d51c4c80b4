//! Where the FE time goes: meshing, ordering + assembly, factorisation, eigen iterations and
//! post-processing, for the default wing at the given mesh sizes (mm).
//! `cargo run --release --example fem_profile -- 0.7 0.45 0.32`

use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
use std::time::Instant;
use wingbeat::error::Result;
use wingbeat::fem::linalg::{SkylineLdlt, SparseLdlt, SpdFactor};
use wingbeat::fem::*;

static FACTOR_NS: AtomicU64 = AtomicU64::new(0);
static SOLVE_NS: AtomicU64 = AtomicU64::new(0);
static SOLVES: AtomicU64 = AtomicU64::new(0);
static FACTORS: AtomicU64 = AtomicU64::new(0);

/// A backend with its factor and solve times counted.
struct Timed<F>(F);

impl<F: SpdFactor> SpdFactor for Timed<F> {
    type Matrix = F::Matrix;
    fn factor(k: &F::Matrix, shift: f64, m_diag: &[f64]) -> Result<Self> {
        let t = Instant::now();
        let f = F::factor(k, shift, m_diag);
        FACTOR_NS.fetch_add(t.elapsed().as_nanos() as u64, Relaxed);
        FACTORS.fetch_add(1, Relaxed);
        f.map(Timed)
    }
    fn refactor(&self, k: &F::Matrix, shift: f64, m_diag: &[f64]) -> Result<Self> {
        let t = Instant::now();
        let f = self.0.refactor(k, shift, m_diag);
        FACTOR_NS.fetch_add(t.elapsed().as_nanos() as u64, Relaxed);
        FACTORS.fetch_add(1, Relaxed);
        f.map(Timed)
    }
    fn solve_in_place(&self, x: &mut [f64]) {
        let t = Instant::now();
        self.0.solve_in_place(x);
        SOLVE_NS.fetch_add(t.elapsed().as_nanos() as u64, Relaxed);
        SOLVES.fetch_add(1, Relaxed);
    }
    fn negative_pivots(&self) -> Option<usize> {
        self.0.negative_pivots()
    }
}

fn main() {
    let skyline = std::env::args().any(|a| a == "skyline");
    let sizes: Vec<f64> = std::env::args()
        .skip(1)
        .filter(|a| a != "skyline")
        .map(|s| s.parse().expect("mesh size in mm"))
        .collect();
    let sizes = if sizes.is_empty() { vec![1.0] } else { sizes };
    println!("| mesh | nodes | free DOFs | mesh | assemble | factor (count) | solves | rest of eigen | basis | post | total |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for h in sizes {
        let input = FemInput {
            mesh_size_mm: Some(h),
            max_nodes: Some(MAX_NODES),
            ..FemInput::default()
        };
        let t0 = Instant::now();
        let (outline, mesh, _) = mesh_input(&input).expect("meshes");
        let t_mesh = t0.elapsed().as_secs_f64();
        let clamped = clamp_nodes(&outline, &mesh, input.clamp).expect("clamp");
        FACTOR_NS.store(0, Relaxed);
        SOLVE_NS.store(0, Relaxed);
        SOLVES.store(0, Relaxed);
        FACTORS.store(0, Relaxed);
        let opt = EigenOptions {
            backend: if skyline {
                Backend::Skyline
            } else {
                Backend::Sparse
            },
            ..EigenOptions::default()
        };
        let t1 = Instant::now();
        let (t_asm, t2, e) = if skyline {
            let asm = assembly::assemble(&mesh, &input.material, &clamped).expect("assembles");
            let t_asm = t1.elapsed().as_secs_f64();
            let t2 = Instant::now();
            let e =
                eigen::lowest_modes_with::<Timed<SkylineLdlt>>(&asm.k, &asm.m, input.n_modes, opt);
            (t_asm, t2, e.expect("solves"))
        } else {
            let asm =
                assembly::assemble_blocks(&mesh, &input.material, &clamped).expect("assembles");
            let t_asm = t1.elapsed().as_secs_f64();
            let t2 = Instant::now();
            let e =
                eigen::lowest_modes_with::<Timed<SparseLdlt>>(&asm.k, &asm.m, input.n_modes, opt);
            (t_asm, t2, e.expect("solves"))
        };
        let factor_s = FACTOR_NS.load(Relaxed) as f64 * 1e-9;
        let solve_s = SOLVE_NS.load(Relaxed) as f64 * 1e-9;
        let solves = SOLVES.load(Relaxed);
        let t_eig = t2.elapsed().as_secs_f64();
        let t3 = Instant::now();
        let r = solve_mesh_with(&mesh, &clamped, &input.material, input.n_modes, "", opt)
            .expect("solves");
        let t_all = t3.elapsed().as_secs_f64();
        let t_post = (t_all - t_asm - t_eig).max(0.0);
        let size = assembly::system_size_for(&mesh, &clamped, opt.backend);
        println!(
            "f = {:?}; work {:.3e} units (factor {:.3e}, factor entries {:.3e})",
            r.freq_hz,
            fe_work(&size, input.n_modes, &opt),
            size.factor_work,
            size.envelope as f64
        );
        println!(
            "| {h} mm | {} | {} | {:.3} s | {:.3} s | {:.3} s ({}) | {:.3} s ({} × {:.1} ms) | {:.3} s | {} | {:.3} s | {:.3} s |",
            mesh.nodes.len(),
            r.n_dofs,
            t_mesh,
            t_asm,
            factor_s,
            FACTORS.load(Relaxed),
            solve_s,
            solves,
            1e3 * solve_s / solves.max(1) as f64,
            t_eig - factor_s - solve_s,
            e.basis,
            t_post,
            t_mesh + t_asm + t_eig + t_post,
        );
    }
}
