//! Node-block sparse symmetric matrices and their LDLᵀ factorisation with a minimum-degree
//! ordering: the default factorisation of the FE eigen-solver.
//!
//! Every free node of a shell mesh carries 6 DOFs, and the stiffness couples two nodes only
//! through a dense 6 × 6 block. [`BlockSym`] stores the lower triangle of K as those blocks
//! (compressed by block column). [`BlockLdlt`] orders the *node* graph by minimum degree
//! (eliminate, at each step, a node with the fewest neighbours in the current elimination
//! graph; ties to the lower index, so the order is deterministic), which is also its
//! symbolic factorisation: the neighbours of a node when it is eliminated are exactly the
//! row structure of its column of L. The numeric factorisation is left-looking over block
//! columns (Ng–Peyton linked lists), each update one 6 × 6 × 6 product, and each diagonal
//! block gets a dense LDLᵀ. No pivoting: the result is the scalar LDLᵀ of the permuted
//! matrix, so the count of negative pivots is the inertia (Sturm count) as for the skyline.
//!
//! On a planar mesh the fill of a minimum-degree order grows like N log N and the work like
//! N^1.5 (nested-dissection-like separators), against the RCM envelope's N^1.5 storage and N²
//! work; docs/fem.md ("Ordering and factorisation") has the measurements.

use super::sparse::Skyline;
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// DOFs per node (block size).
pub const B: usize = 6;
/// A 6 × 6 block, row-major: `b[6 r + c]`.
pub type Blk = [f64; 36];
const NONE: usize = usize::MAX;

/// Symmetric matrix of 6 × 6 blocks; the lower triangle stored by block column.
#[derive(Debug, Clone)]
pub struct BlockSym {
    /// Number of block rows/columns (free nodes); the dimension is 6 × `nb`.
    pub nb: usize,
    /// Start of each block column in `row`/`val` (length `nb + 1`).
    pub col_ptr: Vec<usize>,
    /// Block row of each stored block, ascending within a column; the first of a column is
    /// its diagonal block.
    pub row: Vec<usize>,
    /// The blocks: `val[p][6 r + c]` = `A[6 row[p] + r][6 j + c]` for block column j.
    pub val: Vec<Blk>,
}

impl BlockSym {
    /// An all-zero matrix with the block pattern of the symmetric graph `adj` (neighbours of
    /// each block; self-loops and duplicates allowed).
    pub fn with_pattern(adj: &[Vec<usize>]) -> BlockSym {
        let nb = adj.len();
        let mut col_ptr = Vec::with_capacity(nb + 1);
        let mut row = Vec::new();
        col_ptr.push(0);
        for (j, nbrs) in adj.iter().enumerate() {
            let mut r: Vec<usize> = nbrs.iter().copied().filter(|&i| i > j).collect();
            r.sort_unstable();
            r.dedup();
            row.push(j);
            row.extend(r);
            col_ptr.push(row.len());
        }
        let val = vec![[0.0; 36]; row.len()];
        BlockSym {
            nb,
            col_ptr,
            row,
            val,
        }
    }

    /// The blocks of a [`Skyline`] whose equations come in groups of 6 per node (as
    /// [`super::assembly::assemble`] numbers them); zero blocks are dropped.
    pub fn from_skyline(k: &Skyline) -> BlockSym {
        assert!(k.n % B == 0, "skyline dimension is not a multiple of 6");
        let nb = k.n / B;
        let mut adj: Vec<Vec<usize>> = vec![Vec::new(); nb];
        for i in 0..k.n {
            let f = k.first[i];
            for (c, &a) in k.data[k.start[i]..k.start[i + 1]].iter().enumerate() {
                if a != 0.0 && (f + c) / B != i / B {
                    adj[(f + c) / B].push(i / B);
                }
            }
        }
        let mut m = BlockSym::with_pattern(&adj);
        for i in 0..k.n {
            let f = k.first[i];
            for (c, &a) in k.data[k.start[i]..k.start[i + 1]].iter().enumerate() {
                if a != 0.0 {
                    m.add(i, f + c, a);
                    if i / B == (f + c) / B && i != f + c {
                        m.add(f + c, i, a);
                    }
                }
            }
        }
        m
    }

    /// Dimension (6 × blocks).
    pub fn n(&self) -> usize {
        B * self.nb
    }

    /// Index in `val` of block (i, j), i ≥ j, if stored.
    #[inline]
    pub fn find(&self, i: usize, j: usize) -> Option<usize> {
        let s = self.col_ptr[j];
        let e = self.col_ptr[j + 1];
        self.row[s..e].binary_search(&i).ok().map(|p| s + p)
    }

    /// Adds `v` to the scalar entry (r, c) with r, c in the same or in blocks i ≥ j (entries
    /// of the upper triangle are ignored, so a symmetric element matrix may be added whole;
    /// within a diagonal block both triangles are stored).
    #[inline]
    pub fn add(&mut self, r: usize, c: usize, v: f64) {
        let (i, j) = (r / B, c / B);
        if i < j {
            return;
        }
        let p = self.find(i, j).expect("entry inside the block pattern");
        self.val[p][B * (r % B) + c % B] += v;
    }

    /// Diagonal entry i.
    #[inline]
    pub fn diag(&self, i: usize) -> f64 {
        self.val[self.col_ptr[i / B]][7 * (i % B)]
    }

    /// Adds `v` to diagonal entry i.
    #[inline]
    pub fn add_diag(&mut self, i: usize, v: f64) {
        self.val[self.col_ptr[i / B]][7 * (i % B)] += v;
    }

    /// Number of stored blocks (lower triangle with the diagonal).
    pub fn blocks(&self) -> usize {
        self.row.len()
    }

    /// y = A x.
    pub fn matvec(&self, x: &[f64], y: &mut [f64]) {
        y.iter_mut().for_each(|v| *v = 0.0);
        for j in 0..self.nb {
            let xj: [f64; B] = x[B * j..B * j + B].try_into().unwrap();
            let mut yj = [0.0; B];
            for p in self.col_ptr[j]..self.col_ptr[j + 1] {
                let i = self.row[p];
                let a = &self.val[p];
                if i == j {
                    for r in 0..B {
                        for c in 0..B {
                            yj[r] += a[B * r + c] * xj[c];
                        }
                    }
                    continue;
                }
                let xi: [f64; B] = x[B * i..B * i + B].try_into().unwrap();
                let yi = &mut y[B * i..B * i + B];
                for r in 0..B {
                    let mut s = 0.0;
                    for c in 0..B {
                        s += a[B * r + c] * xj[c];
                        yj[c] += a[B * r + c] * xi[r];
                    }
                    yi[r] += s;
                }
            }
            for r in 0..B {
                y[B * j + r] += yj[r];
            }
        }
    }

    /// The symmetric block graph (neighbours of each block, no self-loops).
    fn graph(&self) -> Vec<Vec<usize>> {
        let mut adj: Vec<Vec<usize>> = vec![Vec::new(); self.nb];
        for j in 0..self.nb {
            for &i in &self.row[self.col_ptr[j] + 1..self.col_ptr[j + 1]] {
                adj[i].push(j);
                adj[j].push(i);
            }
        }
        for a in &mut adj {
            a.sort_unstable();
            a.dedup();
        }
        adj
    }
}

/// Symbolic LDLᵀ of a block matrix: the elimination order and the row structure of L.
#[derive(Debug, Clone)]
pub struct Symbolic {
    /// `perm[k]` = block (node) eliminated k-th.
    pub perm: Vec<usize>,
    /// Start of each column of L in `row` (length nb + 1), in elimination numbering.
    pub col_ptr: Vec<usize>,
    /// Rows (elimination positions > column), ascending within a column.
    pub row: Vec<usize>,
}

impl Symbolic {
    /// Off-diagonal blocks of L.
    pub fn fill_blocks(&self) -> usize {
        self.row.len()
    }

    /// Multiply–adds of the numeric factorisation, Σ_k 216 (c_k + 1)(c_k + 2)/2 over the
    /// column counts c_k (one 6 × 6 × 6 block product per updated block).
    pub fn factor_work(&self) -> f64 {
        (0..self.col_ptr.len() - 1)
            .map(|k| {
                let c = (self.col_ptr[k + 1] - self.col_ptr[k]) as f64;
                108.0 * (c + 1.0) * (c + 2.0)
            })
            .sum()
    }

    /// Multiply–adds of one solve with the factor (forward and back).
    pub fn solve_work(&self) -> f64 {
        let nb = (self.col_ptr.len() - 1) as f64;
        2.0 * 36.0 * (self.row.len() as f64 + nb)
    }
}

/// Minimum-degree order of a symmetric graph and the structure of its Cholesky factor.
/// `adj[v]`: neighbours of v (sorted, no self-loops).
pub fn minimum_degree(mut adj: Vec<Vec<usize>>) -> Symbolic {
    let n = adj.len();
    let mut heap: BinaryHeap<Reverse<(usize, usize)>> =
        (0..n).map(|v| Reverse((adj[v].len(), v))).collect();
    let mut done = vec![false; n];
    let mut perm = Vec::with_capacity(n);
    let mut cols: Vec<Vec<usize>> = Vec::with_capacity(n);
    let mut merged = Vec::new();
    while let Some(Reverse((d, v))) = heap.pop() {
        if done[v] || d != adj[v].len() {
            continue;
        }
        done[v] = true;
        perm.push(v);
        let nb = std::mem::take(&mut adj[v]);
        for &u in &nb {
            // adj[u] ← adj[u] ∪ nb, without u and v (both lists sorted)
            let a = std::mem::take(&mut adj[u]);
            merged.clear();
            let (mut p, mut q) = (0, 0);
            while p < a.len() || q < nb.len() {
                let x = match (a.get(p), nb.get(q)) {
                    (Some(&x), Some(&y)) if x == y => {
                        p += 1;
                        q += 1;
                        x
                    }
                    (Some(&x), Some(&y)) if x < y => {
                        p += 1;
                        x
                    }
                    (Some(&x), None) => {
                        p += 1;
                        x
                    }
                    (_, Some(&y)) => {
                        q += 1;
                        y
                    }
                    (None, None) => unreachable!(),
                };
                if x != u && x != v {
                    merged.push(x);
                }
            }
            adj[u] = merged.clone();
            heap.push(Reverse((adj[u].len(), u)));
        }
        cols.push(nb);
    }
    let mut inv = vec![0; n];
    for (k, &v) in perm.iter().enumerate() {
        inv[v] = k;
    }
    let mut col_ptr = Vec::with_capacity(n + 1);
    let mut row = Vec::new();
    col_ptr.push(0);
    for c in cols {
        let s = row.len();
        row.extend(c.iter().map(|&u| inv[u]));
        row[s..].sort_unstable();
        col_ptr.push(row.len());
    }
    Symbolic { perm, col_ptr, row }
}

/// The symbolic factorisation of `a`'s block graph ([`minimum_degree`]).
pub fn analyse(a: &BlockSym) -> Symbolic {
    minimum_degree(a.graph())
}

/// LDLᵀ of a [`BlockSym`] in minimum-degree order ([`analyse`]), L unit lower triangular
/// and D diagonal (scalar pivots).
#[derive(Debug, Clone)]
pub struct BlockLdlt {
    sym: Symbolic,
    /// Off-diagonal blocks of L, in the order of `sym.row`.
    l: Vec<Blk>,
    /// Unit lower triangle of each diagonal block of L (strictly lower part used).
    ld: Vec<Blk>,
    /// Pivots, 6 per block.
    d: Vec<[f64; B]>,
    negatives: usize,
}

#[inline]
fn sub_mul(w: &mut Blk, l: &Blk, f: &Blk) {
    // w −= l · f
    for r in 0..B {
        let lr: [f64; B] = l[B * r..B * r + B].try_into().unwrap();
        for c in 0..B {
            let mut s = 0.0;
            for m in 0..B {
                s += lr[m] * f[B * m + c];
            }
            w[B * r + c] -= s;
        }
    }
}

/// The blocks of A (lower and upper triangle as stored in `a`) in elimination numbering,
/// grouped by the column they fall in of the lower triangle: for column k the entries
/// `aent[acount[k]..acount[k + 1]]`, each (row, index of the block in `a.val`, whether the
/// block is to be transposed).
#[allow(clippy::type_complexity)]
fn permuted_columns(sym: &Symbolic, a: &BlockSym) -> (Vec<usize>, Vec<(usize, usize, bool)>) {
    let n = a.nb;
    let mut inv = vec![0; n];
    for (k, &v) in sym.perm.iter().enumerate() {
        inv[v] = k;
    }
    let mut acount = vec![0usize; n + 1];
    for j in 0..n {
        for p in a.col_ptr[j]..a.col_ptr[j + 1] {
            let (pi, pj) = (inv[a.row[p]], inv[j]);
            acount[pi.min(pj) + 1] += 1;
        }
    }
    for k in 0..n {
        acount[k + 1] += acount[k];
    }
    let mut fillp = acount.clone();
    let mut aent = vec![(0usize, 0usize, false); acount[n]];
    for j in 0..n {
        for p in a.col_ptr[j]..a.col_ptr[j + 1] {
            let (pi, pj) = (inv[a.row[p]], inv[j]);
            let c = pi.min(pj);
            aent[fillp[c]] = (pi.max(pj), p, pi < pj);
            fillp[c] += 1;
        }
    }
    (acount, aent)
}

/// Dense LDLᵀ of a diagonal block (its lower triangle): the unit lower factor, the six
/// pivots and how many of them are negative. `None` on a zero or non-finite pivot.
#[inline]
fn dense_ldlt(a0: &Blk) -> Option<(Blk, [f64; B], usize)> {
    let mut lk = [0.0; 36];
    let mut dk = [0.0; B];
    let mut negatives = 0;
    for c in 0..B {
        let mut v = a0[7 * c];
        for m in 0..c {
            v -= lk[B * c + m] * lk[B * c + m] * dk[m];
        }
        if !v.is_finite() || v == 0.0 {
            return None;
        }
        if v < 0.0 {
            negatives += 1;
        }
        dk[c] = v;
        lk[7 * c] = 1.0;
        for r in c + 1..B {
            let mut g = a0[B * r + c];
            for m in 0..c {
                g -= lk[B * r + m] * lk[B * c + m] * dk[m];
            }
            lk[B * r + c] = g / v;
        }
    }
    Some((lk, dk, negatives))
}

/// One off-diagonal block of L: `out` = W_i Ld⁻ᵀ D⁻¹, row by row, with Ld and D the
/// diagonal block's factor ([`dense_ldlt`]).
#[inline]
fn off_diagonal(wi: &Blk, lk: &Blk, dk: &[f64; B], out: &mut Blk) {
    for r in 0..B {
        let mut y = [0.0; B];
        for c in 0..B {
            let mut v = wi[B * r + c];
            for m in 0..c {
                v -= lk[B * c + m] * y[m];
            }
            y[c] = v;
        }
        for c in 0..B {
            out[B * r + c] = y[c] / dk[c];
        }
    }
}

impl BlockLdlt {
    /// Factors `a` − `shift`·diag(`m_diag`) with the given symbolic analysis. `None` on a
    /// zero or non-finite pivot.
    pub fn factor_with(sym: Symbolic, a: &BlockSym, shift: f64, m_diag: &[f64]) -> Option<Self> {
        let n = a.nb;
        let (acount, aent) = permuted_columns(&sym, a);
        let nl = sym.row.len();
        let mut l = vec![[0.0; 36]; nl];
        let mut ld = vec![[0.0; 36]; n];
        let mut d = vec![[0.0; B]; n];
        let mut negatives = 0;
        let mut map = vec![NONE; n];
        let maxc = (0..n)
            .map(|k| sym.col_ptr[k + 1] - sym.col_ptr[k])
            .max()
            .unwrap_or(0);
        let mut w = vec![[0.0; 36]; maxc + 1];
        let mut head = vec![NONE; n];
        let mut next = vec![NONE; n];
        let mut ptr = vec![0usize; n];
        for k in 0..n {
            let (s, e) = (sym.col_ptr[k], sym.col_ptr[k + 1]);
            map[k] = 0;
            for (t, &r) in sym.row[s..e].iter().enumerate() {
                map[r] = t + 1;
            }
            w[..=e - s].iter_mut().for_each(|b| *b = [0.0; 36]);
            for &(r, p, tr) in &aent[acount[k]..acount[k + 1]] {
                let slot = &mut w[map[r]];
                let b = &a.val[p];
                if tr {
                    for x in 0..B {
                        for y in 0..B {
                            slot[B * x + y] += b[B * y + x];
                        }
                    }
                } else {
                    for x in 0..36 {
                        slot[x] += b[x];
                    }
                }
            }
            let node = sym.perm[k];
            for r in 0..B {
                w[0][7 * r] -= shift * m_diag[B * node + r];
            }
            // updates from the columns j < k with L(k, j) ≠ 0
            let mut j = head[k];
            while j != NONE {
                let nextj = next[j];
                let p = ptr[j];
                let ljk = &l[p];
                let dj = &d[j];
                let mut f = [0.0; 36];
                for x in 0..B {
                    for y in 0..B {
                        f[B * x + y] = dj[x] * ljk[B * y + x];
                    }
                }
                for q in p..sym.col_ptr[j + 1] {
                    sub_mul(&mut w[map[sym.row[q]]], &l[q], &f);
                }
                ptr[j] = p + 1;
                if p + 1 < sym.col_ptr[j + 1] {
                    let r = sym.row[p + 1];
                    next[j] = head[r];
                    head[r] = j;
                }
                j = nextj;
            }
            let (lk, dk, neg) = dense_ldlt(&w[0])?;
            negatives += neg;
            // L(i, k) = W_i Ld⁻ᵀ D⁻¹
            for t in 0..e - s {
                off_diagonal(&w[t + 1], &lk, &dk, &mut l[s + t]);
            }
            ld[k] = lk;
            d[k] = dk;
            map[k] = NONE;
            for &r in &sym.row[s..e] {
                map[r] = NONE;
            }
            if s < e {
                ptr[k] = s;
                let r = sym.row[s];
                next[k] = head[r];
                head[r] = k;
            }
        }
        Some(BlockLdlt {
            sym,
            l,
            ld,
            d,
            negatives,
        })
    }

    /// [`BlockLdlt::factor_with`] after [`analyse`].
    pub fn factor(a: &BlockSym, shift: f64, m_diag: &[f64]) -> Option<Self> {
        Self::factor_with(analyse(a), a, shift, m_diag)
    }

    /// Number of negative pivots (the inertia's negative count).
    pub fn negatives(&self) -> usize {
        self.negatives
    }

    /// The symbolic analysis used.
    pub fn symbolic(&self) -> &Symbolic {
        &self.sym
    }

    /// Solves (P L D Lᵀ Pᵀ) x = b in place.
    pub fn solve_in_place(&self, x: &mut [f64]) {
        let n = self.d.len();
        let sym = &self.sym;
        let mut z = vec![[0.0; B]; n];
        for (k, &v) in sym.perm.iter().enumerate() {
            z[k].copy_from_slice(&x[B * v..B * v + B]);
        }
        for k in 0..n {
            let lk = &self.ld[k];
            let mut zk = z[k];
            for r in 1..B {
                for m in 0..r {
                    zk[r] -= lk[B * r + m] * zk[m];
                }
            }
            z[k] = zk;
            for q in sym.col_ptr[k]..sym.col_ptr[k + 1] {
                let b = &self.l[q];
                let zi = &mut z[sym.row[q]];
                for r in 0..B {
                    let mut s = 0.0;
                    for c in 0..B {
                        s += b[B * r + c] * zk[c];
                    }
                    zi[r] -= s;
                }
            }
        }
        for (zk, dk) in z.iter_mut().zip(&self.d) {
            for r in 0..B {
                zk[r] /= dk[r];
            }
        }
        for k in (0..n).rev() {
            let mut zk = z[k];
            for q in sym.col_ptr[k]..sym.col_ptr[k + 1] {
                let b = &self.l[q];
                let zi = &z[sym.row[q]];
                for r in 0..B {
                    for c in 0..B {
                        zk[c] -= b[B * r + c] * zi[r];
                    }
                }
            }
            let lk = &self.ld[k];
            for r in (0..B).rev() {
                for m in r + 1..B {
                    zk[r] -= lk[B * m + r] * zk[m];
                }
            }
            z[k] = zk;
        }
        for (k, &v) in sym.perm.iter().enumerate() {
            x[B * v..B * v + B].copy_from_slice(&z[k]);
        }
    }
}
