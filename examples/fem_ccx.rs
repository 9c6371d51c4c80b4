//! Writes the default wing (or a given mesh size) as a CalculiX input deck with S6 shells
//! (mid-side nodes added at the straight-edge midpoints, i.e. the same flat facets) and
//! prints wingbeat's own frequencies and solve time for comparison.
//! `cargo run --release --example fem_ccx -- MESH_MM OUT.inp`

use std::fmt::Write as _;
use std::time::Instant;
use wingbeat::fem::*;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let h: f64 = args
        .get(1)
        .map(|s| s.parse().expect("mesh size"))
        .unwrap_or(1.0);
    let path = args.get(2).cloned().unwrap_or_else(|| "wing.inp".into());
    let input = FemInput {
        mesh_size_mm: Some(h),
        ..FemInput::default()
    };
    let t = Instant::now();
    let r = compute_modes(&input).expect("solves");
    let secs = t.elapsed().as_secs_f64();
    let f: Vec<String> = r.freq_hz.iter().map(|f| format!("{f:.2}")).collect();
    println!(
        "wingbeat: h {h} mm, {} nodes, {} DOFs, {secs:.3} s, f = {}",
        r.nodes.len(),
        r.n_dofs,
        f.join(" ")
    );
    let mut deck = String::new();
    let nn = r.nodes.len();
    let mut nodes = r.nodes.clone();
    let mut mid = std::collections::HashMap::new();
    let mut clamped: Vec<bool> = vec![false; nn];
    for &c in &r.clamped_nodes {
        clamped[c] = true;
    }
    let mut elems = Vec::new();
    for t in &r.triangles {
        let mut m = [0usize; 3];
        for (k, (a, b)) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]
            .into_iter()
            .enumerate()
        {
            let key = (a.min(b), a.max(b));
            m[k] = *mid.entry(key).or_insert_with(|| {
                let (p, q) = (nodes[a], nodes[b]);
                nodes.push([
                    (p[0] + q[0]) / 2.0,
                    (p[1] + q[1]) / 2.0,
                    (p[2] + q[2]) / 2.0,
                ]);
                clamped.push(clamped[a] && clamped[b]);
                nodes.len() - 1
            });
        }
        elems.push([t[0], t[1], t[2], m[0], m[1], m[2]]);
    }
    writeln!(
        deck,
        "** default wingbeat wing (SYNTHETIC Manduca-like outline), SI units"
    )
    .unwrap();
    writeln!(deck, "*NODE, NSET=NALL").unwrap();
    for (i, p) in nodes.iter().enumerate() {
        writeln!(
            deck,
            "{}, {:.12e}, {:.12e}, {:.12e}",
            i + 1,
            p[0],
            p[1],
            p[2]
        )
        .unwrap();
    }
    writeln!(deck, "*ELEMENT, TYPE=S6, ELSET=EALL").unwrap();
    for (i, e) in elems.iter().enumerate() {
        writeln!(
            deck,
            "{}, {}, {}, {}, {}, {}, {}",
            i + 1,
            e[0] + 1,
            e[1] + 1,
            e[2] + 1,
            e[3] + 1,
            e[4] + 1,
            e[5] + 1
        )
        .unwrap();
    }
    writeln!(deck, "*NSET, NSET=ROOT").unwrap();
    for (i, c) in clamped.iter().enumerate() {
        if *c {
            writeln!(deck, "{},", i + 1).unwrap();
        }
    }
    let m = r.material;
    writeln!(
        deck,
        "*MATERIAL, NAME=CUTICLE\n*ELASTIC\n{:.6e}, {}\n*DENSITY\n{}",
        m.e_pa, m.nu, m.rho_kg_m3
    )
    .unwrap();
    writeln!(
        deck,
        "*SHELL SECTION, ELSET=EALL, MATERIAL=CUTICLE\n{:.6e}",
        m.thickness_m
    )
    .unwrap();
    writeln!(deck, "*BOUNDARY\nROOT, 1, 6, 0.0").unwrap();
    writeln!(deck, "*STEP\n*FREQUENCY\n6\n*END STEP").unwrap();
    std::fs::write(&path, deck).expect("write deck");
    println!(
        "wrote {path}: {} nodes, {} S6 elements",
        nodes.len(),
        elems.len()
    );
}
