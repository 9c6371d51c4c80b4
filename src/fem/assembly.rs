//! Global assembly of the shell stiffness (skyline storage, RCM-ordered equations) and the
//! lumped mass diagonal, with clamped DOFs eliminated.

use super::element::{global_stiffness, lumped_mass, Frame, ShellMaterial};
use super::mesh::Mesh;
use super::sparse::{rcm_order, Skyline};
use crate::error::{Result, WingbeatError};

/// Marker for a clamped (eliminated) DOF in [`Assembled::eq`].
pub const CLAMPED: usize = usize::MAX;

/// Assembled system K φ = λ M φ over the free DOFs.
#[derive(Debug, Clone)]
pub struct Assembled {
    /// Stiffness (N/m, N, N·m blocks), skyline storage.
    pub k: Skyline,
    /// Lumped mass diagonal (kg for translations, kg·m² for rotations).
    pub m: Vec<f64>,
    /// Equation number of each node's 6 DOFs (u, v, w, θx, θy, θz), or [`CLAMPED`].
    pub eq: Vec<[usize; 6]>,
    /// Translational lumped mass of each node, kg (clamped nodes included).
    pub node_mass: Vec<f64>,
}

/// The equation numbering of a mesh: each node's 6 DOF equations in RCM order (clamped
/// ones [`CLAMPED`]), the number of equations and each equation's first envelope column.
fn equations(mesh: &Mesh, clamped: &[bool]) -> (Vec<[usize; 6]>, usize, Vec<usize>) {
    let nn = mesh.nodes.len();
    let mut adj: Vec<Vec<usize>> = vec![Vec::new(); nn];
    for t in &mesh.triangles {
        for a in 0..3 {
            for b in 0..3 {
                if a != b && !adj[t[a]].contains(&t[b]) {
                    adj[t[a]].push(t[b]);
                }
            }
        }
    }
    let order = rcm_order(&adj);
    let mut eq = vec![[CLAMPED; 6]; nn];
    let mut neq = 0;
    for &node in &order {
        if clamped.get(node).copied().unwrap_or(false) {
            continue;
        }
        for d in 0..6 {
            eq[node][d] = neq;
            neq += 1;
        }
    }
    let mut first: Vec<usize> = (0..neq).collect();
    for t in &mesh.triangles {
        let lo = t
            .iter()
            .flat_map(|&n| eq[n].iter().copied())
            .filter(|&e| e != CLAMPED)
            .min();
        if let Some(lo) = lo {
            for &n in t {
                for &e in &eq[n] {
                    if e != CLAMPED {
                        first[e] = first[e].min(lo);
                    }
                }
            }
        }
    }
    (eq, neq, first)
}

/// The size of the system [`assemble`] would build, known before anything is allocated
/// for it: what the FE work and memory budget ([`super::check_fe_work`]) is checked on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SystemSize {
    /// Free DOFs (equations).
    pub n_dofs: usize,
    /// Entries of the skyline envelope of K (8 bytes each, stored twice: K and its factor).
    pub envelope: usize,
    /// Multiply–adds of one LDLᵀ factorisation, Σ_i h_i² / 2 over the envelope heights h_i.
    pub factor_work: f64,
}

/// [`SystemSize`] of `mesh` with the nodes flagged in `clamped` held (the same RCM numbering
/// and envelope as [`assemble`]).
pub fn system_size(mesh: &Mesh, clamped: &[bool]) -> SystemSize {
    let (_, neq, first) = equations(mesh, clamped);
    let mut envelope = 0usize;
    let mut factor_work = 0.0;
    for (i, &f) in first.iter().enumerate() {
        let h = i - f;
        envelope += h + 1;
        factor_work += 0.5 * (h as f64) * (h as f64);
    }
    SystemSize {
        n_dofs: neq,
        envelope,
        factor_work,
    }
}

/// Assembles K and M for `mesh` with the nodes flagged in `clamped` fixed in all 6 DOFs.
pub fn assemble(mesh: &Mesh, mat: &ShellMaterial, clamped: &[bool]) -> Result<Assembled> {
    let nn = mesh.nodes.len();
    let (eq, neq, first) = equations(mesh, clamped);
    if neq == 0 {
        return Err(WingbeatError::Geometry(
            "every node is clamped: nothing can vibrate".into(),
        ));
    }
    let mut k = Skyline::new(first);
    let mut m = vec![0.0; neq];
    let mut node_mass = vec![0.0; nn];
    for (ti, t) in mesh.triangles.iter().enumerate() {
        let p = [mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]];
        let f = Frame::new(&p);
        let ke = global_stiffness(&p, mat);
        let (Some(f), Some(ke)) = (f, ke) else {
            return Err(WingbeatError::Geometry(format!(
                "triangle {ti} is degenerate (zero area)"
            )));
        };
        let (mt, mr) = lumped_mass(f.area, mat);
        for a in 0..3 {
            node_mass[t[a]] += mt;
            for d in 0..6 {
                let ea = eq[t[a]][d];
                if ea == CLAMPED {
                    continue;
                }
                m[ea] += if d < 3 { mt } else { mr };
                for b in 0..3 {
                    for e in 0..6 {
                        let eb = eq[t[b]][e];
                        if eb == CLAMPED || eb > ea {
                            continue;
                        }
                        k.add(ea, eb, ke[(6 * a + d, 6 * b + e)]);
                    }
                }
            }
        }
    }
    if k.data.iter().any(|v| !v.is_finite()) {
        return Err(WingbeatError::NonFinite {
            what: "stiffness assembly".into(),
            detail: "check the material values and the outline".into(),
        });
    }
    Ok(Assembled {
        k,
        m,
        eq,
        node_mass,
    })
}
