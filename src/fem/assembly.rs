//! Global assembly of the shell stiffness (skyline storage, RCM-ordered equations) and the
//! lumped mass diagonal, with clamped DOFs eliminated.

use super::blocksparse::BlockSym;
use super::element::{global_stiffness, lumped_mass, Frame, Mat18, ShellMaterial};
use super::mesh::Mesh;
use super::sparse::{rcm_order, Skyline};
use crate::error::{Result, WingbeatError};

/// Marker for a clamped (eliminated) DOF in [`Assembled::eq`].
pub const CLAMPED: usize = usize::MAX;

/// Assembled system K φ = λ M φ over the free DOFs.
#[derive(Debug, Clone)]
pub struct Assembled<K = Skyline> {
    /// Stiffness (N/m, N, N·m blocks): skyline storage ([`assemble`]) or 6 × 6 node blocks
    /// ([`assemble_blocks`]).
    pub k: K,
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
    /// Entries of the skyline envelope of K (8 bytes each, stored twice: K and its factor);
    /// for the sparse backend ([`system_size_for`]), the entries of its factor.
    pub envelope: usize,
    /// Multiply–adds of one LDLᵀ factorisation, Σ_i h_i² / 2 over the envelope heights h_i
    /// (skyline), or the block-sparse factor's count ([`system_size_for`]).
    pub factor_work: f64,
}

/// Above this many free nodes the run is priced by the RCM envelope (an upper bound of the
/// sparse factor's size and work) instead of the minimum-degree analysis: the exact
/// minimum-degree ordering has no supervariables, and on the 17 289-node mesh of a
/// 5 000-point outline it ran for over a minute (measured; docs/fem.md, "Known limits").
pub const SPARSE_ANALYSIS_MAX_NODES: usize = 12_000;

/// [`SystemSize`] of `mesh` with the nodes flagged in `clamped` held, for the factorisation
/// `backend` uses: the minimum-degree symbolic factorisation of the node graph for
/// [`super::Backend::Sparse`] (`envelope` = entries of L and D, `factor_work` = its
/// multiply–adds, [`super::blocksparse::Symbolic`]); the RCM envelope ([`system_size`])
/// for the skyline (and faer, for which it is an upper bound).
pub fn system_size_for(mesh: &Mesh, clamped: &[bool], backend: super::Backend) -> SystemSize {
    let free = clamped.iter().filter(|&&c| !c).count();
    if backend != super::Backend::Sparse || free > SPARSE_ANALYSIS_MAX_NODES {
        return system_size(mesh, clamped);
    }
    let (block, nb) = free_blocks(mesh, clamped);
    let mut adj = block_adjacency(mesh, &block, nb);
    for a in &mut adj {
        a.sort_unstable();
        a.dedup();
    }
    let sym = super::blocksparse::minimum_degree(adj);
    SystemSize {
        n_dofs: 6 * nb,
        envelope: 36 * sym.fill_blocks() + 21 * nb,
        factor_work: sym.factor_work(),
    }
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
    let (eq, neq, first) = equations(mesh, clamped);
    if neq == 0 {
        return Err(WingbeatError::Geometry(
            "every node is clamped: nothing can vibrate".into(),
        ));
    }
    let mut k = Skyline::new(first);
    let mut m = vec![0.0; neq];
    let node_mass = walk_elements(mesh, mat, |t, ke, mt, mr| {
        for a in 0..3 {
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
    })?;
    check_finite(&k.data)?;
    Ok(Assembled {
        k,
        m,
        eq,
        node_mass,
    })
}

/// Assembles K (as 6 × 6 node blocks, [`BlockSym`]) and M for `mesh` with the nodes flagged
/// in `clamped` fixed in all 6 DOFs. The free nodes keep their mesh order (block j is the
/// j-th free node, its equations 6j .. 6j + 5): the factorisation orders them itself.
pub fn assemble_blocks(
    mesh: &Mesh,
    mat: &ShellMaterial,
    clamped: &[bool],
) -> Result<Assembled<BlockSym>> {
    let (block, nb) = free_blocks(mesh, clamped);
    let eq: Vec<[usize; 6]> = block
        .iter()
        .map(|&b| {
            if b == CLAMPED {
                [CLAMPED; 6]
            } else {
                std::array::from_fn(|d| 6 * b + d)
            }
        })
        .collect();
    if nb == 0 {
        return Err(WingbeatError::Geometry(
            "every node is clamped: nothing can vibrate".into(),
        ));
    }
    let adj = block_adjacency(mesh, &block, nb);
    let mut k = BlockSym::with_pattern(&adj);
    drop(adj);
    let mut m = vec![0.0; 6 * nb];
    let node_mass = walk_elements(mesh, mat, |t, ke, mt, mr| {
        for a in 0..3 {
            let ba = block[t[a]];
            if ba == CLAMPED {
                continue;
            }
            for d in 0..6 {
                m[6 * ba + d] += if d < 3 { mt } else { mr };
            }
            for b in 0..3 {
                let bb = block[t[b]];
                if bb == CLAMPED || bb > ba {
                    continue;
                }
                let pos = k.find(ba, bb).expect("block in the pattern");
                let blk = &mut k.val[pos];
                for d in 0..6 {
                    for e in 0..6 {
                        blk[6 * d + e] += ke[(6 * a + d, 6 * b + e)];
                    }
                }
            }
        }
    })?;
    check_finite(k.val.iter().flatten())?;
    Ok(Assembled {
        k,
        m,
        eq,
        node_mass,
    })
}

/// The one walk over the elements that both assemblies share: each triangle's global
/// stiffness `ke` (18 × 18, node-major, 6 DOFs per node) and lumped masses (`mt` per node
/// for each translation, `mr` for each rotation) go to `scatter` with the triangle's nodes,
/// in mesh order. Returns each node's translational mass; a degenerate triangle is an error
/// naming it.
fn walk_elements(
    mesh: &Mesh,
    mat: &ShellMaterial,
    mut scatter: impl FnMut(&[usize; 3], &Mat18, f64, f64),
) -> Result<Vec<f64>> {
    let mut node_mass = vec![0.0; mesh.nodes.len()];
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
        for &n in t {
            node_mass[n] += mt;
        }
        scatter(t, &ke, mt, mr);
    }
    Ok(node_mass)
}

/// Refuses an assembled stiffness with a non-finite entry.
fn check_finite<'a>(entries: impl IntoIterator<Item = &'a f64>) -> Result<()> {
    if entries.into_iter().any(|v| !v.is_finite()) {
        return Err(WingbeatError::NonFinite {
            what: "stiffness assembly".into(),
            detail: "check the material values and the outline".into(),
        });
    }
    Ok(())
}

/// Each node's block number among the free nodes in mesh order ([`CLAMPED`] for a clamped
/// node), and the number of free nodes.
fn free_blocks(mesh: &Mesh, clamped: &[bool]) -> (Vec<usize>, usize) {
    let nn = mesh.nodes.len();
    let mut block = vec![CLAMPED; nn];
    let mut nb = 0;
    for (node, b) in block.iter_mut().enumerate() {
        if !clamped.get(node).copied().unwrap_or(false) {
            *b = nb;
            nb += 1;
        }
    }
    (block, nb)
}

/// The free nodes' graph: for each block, the blocks of the nodes it shares a triangle with,
/// once per shared triangle (unsorted, with repeats).
fn block_adjacency(mesh: &Mesh, block: &[usize], nb: usize) -> Vec<Vec<usize>> {
    let mut adj: Vec<Vec<usize>> = vec![Vec::new(); nb];
    for t in &mesh.triangles {
        for a in 0..3 {
            for b in 0..3 {
                let (ba, bb) = (block[t[a]], block[t[b]]);
                if a != b && ba != CLAMPED && bb != CLAMPED {
                    adj[ba].push(bb);
                }
            }
        }
    }
    adj
}
