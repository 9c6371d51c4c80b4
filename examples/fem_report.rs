//! Prints the numbers quoted in docs/fem.md (convergence table of the default wing, camber
//! effect, root-clamp sensitivity, a_k, strains) and optionally writes the default wing's
//! modes as JSON for plotting: `cargo run --release --example fem_report -- [modes.json]`.

use std::time::Instant;
use wingbeat::fem::*;

fn run(input: &FemInput) -> (FemModes, f64) {
    let t = Instant::now();
    let r = compute_modes(input).expect("solves");
    (r, t.elapsed().as_secs_f64())
}

fn main() {
    let out = std::env::args().nth(1);
    println!("Outline: {}", geometry::MANDUCA_NOTE);
    println!("\n## Convergence, default wing (camber 0.13, root clamp, E = {PAPER_FREQUENCIES_E_PA:.4e} Pa)\n");
    println!("| mesh size (mm) | nodes | free DOFs | f1 | f2 | f3 | f4 | f5 | f6 | time (s) |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for h in [3.0, 2.0, 1.5, 1.25, 1.0, 0.75, 0.5] {
        let (r, t) = run(&FemInput {
            mesh_size_mm: Some(h),
            ..FemInput::default()
        });
        let f: Vec<String> = r.freq_hz.iter().map(|f| format!("{f:.1}")).collect();
        println!(
            "| {h} | {} | {} | {} | {t:.2} |",
            r.nodes.len(),
            r.n_dofs,
            f.join(" | ")
        );
    }
    let (d, _) = run(&FemInput::default());
    println!("\nDefault: kinds {:?}", d.kinds);
    let res: Vec<String> = d.residuals.iter().map(|r| format!("{r:.1e}")).collect();
    println!(
        "residuals [{}], mass-orthonormality error {:.1e}",
        res.join(", "),
        d.mass_orthonormality_error
    );
    let c = d.centre_of_mass_m;
    println!(
        "mass {:.4e} kg, centre of mass [{:.4e}, {:.4e}, {:.4e}] m",
        d.mass_kg, c[0], c[1], c[2]
    );
    for k in 0..2 {
        println!(
            "a_{} = [{:.4e}, {:.4e}] kg^0.5 m",
            k + 1,
            d.a[k][0],
            d.a[k][1]
        );
    }
    for (name, x, y) in [
        ("root (3, -3) mm", 3.0, -3.0),
        ("mid (20, -10) mm", 20.0, -10.0),
    ] {
        for k in 0..2 {
            let e = d.strain_at(k, x, y).unwrap();
            println!("strain mode {} at {name}: eps_x {:.3e}, eps_y {:.3e}, gamma_xy {:.3e} (per unit q)", k + 1, e[0], e[1], e[2]);
        }
    }
    println!("\n## Camber effect (root clamp)\n");
    for h in [2.0, 1.0, 0.75] {
        let (flat, _) = run(&FemInput {
            mesh_size_mm: Some(h),
            camber: 0.0,
            ..FemInput::default()
        });
        for c in [0.05, 0.13] {
            let (cam, _) = run(&FemInput {
                mesh_size_mm: Some(h),
                camber: c,
                ..FemInput::default()
            });
            println!(
                "h {h}: camber {c}: f1 {:.2} vs flat {:.2} → ×{:.3}; f2 {:.1} vs {:.1}",
                cam.freq_hz[0],
                flat.freq_hz[0],
                cam.freq_hz[0] / flat.freq_hz[0],
                cam.freq_hz[1],
                flat.freq_hz[1]
            );
        }
    }
    println!("\n## Root boundary condition (h = 1 mm)\n");
    for clamp in [
        Clamp::Root,
        Clamp::Strip { x_mm: 1.0 },
        Clamp::Strip { x_mm: 2.0 },
        Clamp::Strip { x_mm: 3.0 },
        Clamp::Strip { x_mm: 5.0 },
    ] {
        let (r, _) = run(&FemInput {
            clamp,
            ..FemInput::default()
        });
        println!(
            "{clamp:?}: clamped nodes {}, f1 {:.1}, f2 {:.1}, f2/f1 {:.3}, kinds {:?}",
            r.clamped_nodes.len(),
            r.freq_hz[0],
            r.freq_hz[1],
            r.freq_hz[1] / r.freq_hz[0],
            &r.kinds[..2]
        );
    }
    let (p, _) = run(&FemInput {
        material: ShellMaterial::paper_as_printed(),
        ..FemInput::default()
    });
    println!(
        "\npaper-as-printed (E = 10 MPa): f1 {:.3} Hz, f2 {:.3} Hz",
        p.freq_hz[0], p.freq_hz[1]
    );
    if let Some(path) = out {
        std::fs::write(&path, serde_json::to_string(&d).unwrap()).unwrap();
        println!("wrote {path}");
    }
}
