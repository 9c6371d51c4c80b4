//! Symmetric skyline (variable-band / envelope) matrix with an in-place LDLᵀ factorisation,
//! and the reverse Cuthill–McKee node ordering that keeps the envelope small.
//!
//! Pure Rust and single-threaded. For the planar shell meshes used here (≤ 20 000 nodes)
//! the RCM envelope of a 2-D mesh grows like N^1.5, which is affordable, and the envelope
//! factorisation needs no pivoting because it is only applied to positive-definite
//! matrices K − σM with σ < 0 (or used as a Sturm-sequence count).

use std::collections::VecDeque;

/// Reverse Cuthill–McKee ordering of a graph given as adjacency lists. Returns `order`
/// where `order[k]` is the original index of the k-th vertex in the new numbering.
pub fn rcm_order(adj: &[Vec<usize>]) -> Vec<usize> {
    let n = adj.len();
    let mut visited = vec![false; n];
    let mut order = Vec::with_capacity(n);
    let bfs_last = |start: usize, visited: &[bool]| -> (usize, usize) {
        // returns (last vertex reached, eccentricity)
        let mut dist = vec![usize::MAX; n];
        let mut q = VecDeque::new();
        dist[start] = 0;
        q.push_back(start);
        let mut last = start;
        while let Some(v) = q.pop_front() {
            last = v;
            for &w in &adj[v] {
                if !visited[w] && dist[w] == usize::MAX {
                    dist[w] = dist[v] + 1;
                    q.push_back(w);
                }
            }
        }
        (last, dist[last])
    };
    for seed in 0..n {
        if visited[seed] {
            continue;
        }
        // pseudo-peripheral start: repeat BFS from the farthest vertex a few times
        let mut start = seed;
        let mut ecc = 0;
        for _ in 0..4 {
            let (far, e) = bfs_last(start, &visited);
            if e <= ecc {
                break;
            }
            ecc = e;
            start = far;
        }
        let first = order.len();
        visited[start] = true;
        order.push(start);
        let mut head = first;
        while head < order.len() {
            let v = order[head];
            head += 1;
            let mut nb: Vec<usize> = adj[v].iter().copied().filter(|&w| !visited[w]).collect();
            nb.sort_by_key(|&w| adj[w].len());
            for w in nb {
                visited[w] = true;
                order.push(w);
            }
        }
    }
    order.reverse();
    order
}

/// Symmetric matrix in skyline storage: row i holds columns `first[i] ..= i`.
#[derive(Debug, Clone)]
pub struct Skyline {
    /// Dimension.
    pub n: usize,
    /// First stored column of each row.
    pub first: Vec<usize>,
    /// Offset of each row's first stored entry in `data` (length n + 1).
    pub start: Vec<usize>,
    /// Row-wise lower envelope entries.
    pub data: Vec<f64>,
}

impl Skyline {
    /// An all-zero matrix with the given first columns.
    pub fn new(first: Vec<usize>) -> Skyline {
        let n = first.len();
        let mut start = Vec::with_capacity(n + 1);
        let mut s = 0;
        for (i, &f) in first.iter().enumerate() {
            start.push(s);
            s += i - f + 1;
        }
        start.push(s);
        Skyline {
            n,
            first,
            start,
            data: vec![0.0; s],
        }
    }

    /// Number of stored entries (the envelope size).
    pub fn stored(&self) -> usize {
        self.data.len()
    }

    /// Adds `v` to entry (i, j) (and so to (j, i)); entries outside the envelope are ignored
    /// (they never occur for a correctly built envelope).
    #[inline]
    pub fn add(&mut self, i: usize, j: usize, v: f64) {
        let (r, c) = if i >= j { (i, j) } else { (j, i) };
        debug_assert!(c >= self.first[r]);
        self.data[self.start[r] + c - self.first[r]] += v;
    }

    /// Diagonal entry i.
    #[inline]
    pub fn diag(&self, i: usize) -> f64 {
        self.data[self.start[i + 1] - 1]
    }

    /// Adds `v` to diagonal entry i.
    #[inline]
    pub fn add_diag(&mut self, i: usize, v: f64) {
        self.data[self.start[i + 1] - 1] += v;
    }

    /// y = A x.
    pub fn matvec(&self, x: &[f64], y: &mut [f64]) {
        y.iter_mut().for_each(|v| *v = 0.0);
        for i in 0..self.n {
            let f = self.first[i];
            let row = &self.data[self.start[i]..self.start[i + 1]];
            let (off, d) = row.split_at(row.len() - 1);
            let mut s = d[0] * x[i];
            let xi = x[i];
            for (k, &a) in off.iter().enumerate() {
                s += a * x[f + k];
                y[f + k] += a * xi;
            }
            y[i] += s;
        }
    }

    /// In-place LDLᵀ factorisation (no pivoting). Afterwards the strictly lower entries hold
    /// L and the diagonal slots hold D. Returns the number of negative pivots (Sturm count)
    /// or `None` if a pivot is zero or non-finite.
    pub fn factor_ldlt(&mut self) -> Option<usize> {
        let mut negatives = 0;
        for i in 0..self.n {
            let fi = self.first[i];
            let si = self.start[i];
            // g_ij = a_ij − Σ_k g_ik L_jk for j in fi..i
            for j in fi..i {
                let fj = self.first[j];
                let k0 = fi.max(fj);
                let sj = self.start[j];
                let row_j = sj + (k0 - fj);
                let len = j - k0;
                let mut s = 0.0;
                if len > 0 {
                    let (lo, hi) = self.data.split_at(si);
                    let a = &hi[(k0 - fi)..(k0 - fi) + len];
                    let b = &lo[row_j..row_j + len];
                    s = dot(a, b);
                }
                self.data[si + (j - fi)] -= s;
            }
            // L_ij = g_ij / D_j ; D_i = a_ii − Σ g_ij L_ij
            let mut dsum = 0.0;
            for j in fi..i {
                let dj = self.diag(j);
                let g = self.data[si + (j - fi)];
                let l = g / dj;
                dsum += g * l;
                self.data[si + (j - fi)] = l;
            }
            let di = self.data[si + (i - fi)] - dsum;
            if !di.is_finite() || di == 0.0 {
                return None;
            }
            if di < 0.0 {
                negatives += 1;
            }
            self.data[si + (i - fi)] = di;
        }
        Some(negatives)
    }

    /// Solves (L D Lᵀ) x = b in place (after [`Skyline::factor_ldlt`]).
    pub fn solve_in_place(&self, x: &mut [f64]) {
        for i in 0..self.n {
            let f = self.first[i];
            let row = &self.data[self.start[i]..self.start[i + 1] - 1];
            x[i] -= dot(row, &x[f..i]);
        }
        for (i, xi) in x.iter_mut().enumerate() {
            *xi /= self.diag(i);
        }
        for i in (0..self.n).rev() {
            let f = self.first[i];
            let xi = x[i];
            let row = &self.data[self.start[i]..self.start[i + 1] - 1];
            for (k, &l) in row.iter().enumerate() {
                x[f + k] -= l * xi;
            }
        }
    }
}

/// Dot product with four independent accumulators.
#[inline]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut s = [0.0; 4];
    let chunks = n / 4;
    for c in 0..chunks {
        let k = 4 * c;
        s[0] += a[k] * b[k];
        s[1] += a[k + 1] * b[k + 1];
        s[2] += a[k + 2] * b[k + 2];
        s[3] += a[k + 3] * b[k + 3];
    }
    for k in 4 * chunks..n {
        s[0] += a[k] * b[k];
    }
    (s[0] + s[1]) + (s[2] + s[3])
}
