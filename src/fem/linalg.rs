//! Swappable sparse factorisation backends for the shift-invert eigen-solver.
//!
//! [`SpdFactor`] is the one operation the solver needs from a linear-algebra backend:
//! factor K − σM (K symmetric, in the [`Skyline`] the assembly produces, M diagonal) and
//! solve with the factor. Two implementations:
//!
//! * [`SkylineLdlt`] — the crate's own envelope LDLᵀ on the RCM ordering
//!   ([`Skyline::factor_ldlt`]); always built. It reports the inertia (count of negative
//!   pivots), which the Sturm-sequence check uses.
//! * `FaerLlt` (cargo feature `faer`) — faer's sparse Cholesky (AMD fill-reducing ordering,
//!   simplicial or supernodal as faer decides). A successful LLᵀ proves K − σM positive
//!   definite (no negative pivot), but faer's high-level API reports no inertia of an
//!   indefinite matrix: its factorisation simply fails there.
//!
//! The backend is picked at run time by [`Backend`] in
//! [`super::eigen::EigenOptions::backend`]; the solver itself is generic over [`SpdFactor`]
//! ([`super::eigen::lowest_modes_with`]), so its logic is single-source. The faer backend is
//! compiled only with the `faer` feature (off by default — see docs/fem.md, "Sparse
//! factorisation backends", for the measurements behind that choice); selecting
//! [`Backend::Faer`] in a build without it is an [`WingbeatError::InvalidInput`] error.

use super::blocksparse::{BlockLdlt, BlockSym};
use super::sparse::Skyline;
use crate::error::{Result, WingbeatError};
use serde::{Deserialize, Serialize};

/// Which sparse factorisation the eigen-solver uses for K − σM.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Backend {
    /// The built-in node-block sparse LDLᵀ on a minimum-degree ordering (default; no
    /// dependency; [`super::blocksparse`]).
    #[default]
    Sparse,
    /// The built-in envelope LDLᵀ on the RCM ordering (the former default; kept for
    /// cross-checks).
    Skyline,
    /// faer's sparse Cholesky with AMD ordering (needs the `faer` cargo feature).
    Faer,
}

impl Backend {
    /// Whether this build can use the backend.
    pub fn available(self) -> bool {
        match self {
            Backend::Sparse | Backend::Skyline => true,
            Backend::Faer => cfg!(feature = "faer"),
        }
    }

    /// Lower-case name (`sparse`, `skyline`, `faer`), as in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Backend::Sparse => "sparse",
            Backend::Skyline => "skyline",
            Backend::Faer => "faer",
        }
    }
}

/// What the eigen-solver needs of the stiffness matrix itself.
pub trait SymOperator {
    /// Dimension.
    fn dim(&self) -> usize;
    /// Diagonal entry i.
    fn diag_entry(&self, i: usize) -> f64;
    /// y = A x.
    fn mul(&self, x: &[f64], y: &mut [f64]);
}

impl SymOperator for Skyline {
    fn dim(&self) -> usize {
        self.n
    }
    fn diag_entry(&self, i: usize) -> f64 {
        self.diag(i)
    }
    fn mul(&self, x: &[f64], y: &mut [f64]) {
        self.matvec(x, y);
    }
}

impl SymOperator for BlockSym {
    fn dim(&self) -> usize {
        self.n()
    }
    fn diag_entry(&self, i: usize) -> f64 {
        self.diag(i)
    }
    fn mul(&self, x: &[f64], y: &mut [f64]) {
        self.matvec(x, y);
    }
}

/// A factorisation of K − σM (K symmetric, M diagonal) that can solve with it.
pub trait SpdFactor: Sized {
    /// The storage of K this backend factors.
    type Matrix: SymOperator;
    /// Factors K − `shift`·diag(`m_diag`). An error means the backend could not factor it
    /// (a zero or non-finite pivot; for a Cholesky backend also "not positive definite").
    fn factor(k: &Self::Matrix, shift: f64, m_diag: &[f64]) -> Result<Self>;
    /// Factors the same K with another shift, reusing what it can of this factorisation
    /// (the block-sparse LDLᵀ keeps its ordering and symbolic analysis).
    fn refactor(&self, k: &Self::Matrix, shift: f64, m_diag: &[f64]) -> Result<Self> {
        Self::factor(k, shift, m_diag)
    }
    /// Overwrites `x` with (K − σM)⁻¹ x.
    fn solve_in_place(&self, x: &mut [f64]);
    /// Number of negative pivots (the Sturm count: eigenvalues of K φ = λMφ below σ), when
    /// the backend knows it.
    fn negative_pivots(&self) -> Option<usize>;
}

/// The built-in skyline LDLᵀ ([`Skyline::factor_ldlt`]) behind [`SpdFactor`].
#[derive(Debug, Clone)]
pub struct SkylineLdlt {
    fac: Skyline,
    negatives: usize,
}

impl SpdFactor for SkylineLdlt {
    type Matrix = Skyline;
    fn factor(k: &Skyline, shift: f64, m_diag: &[f64]) -> Result<Self> {
        let mut fac = k.clone();
        for (i, &m) in m_diag.iter().enumerate() {
            fac.add_diag(i, -shift * m);
        }
        match fac.factor_ldlt() {
            Some(negatives) => Ok(SkylineLdlt { fac, negatives }),
            None => Err(WingbeatError::NonFinite {
                what: "skyline LDLᵀ of K − σM".into(),
                detail: format!("zero or non-finite pivot at σ = {shift:e}"),
            }),
        }
    }

    fn solve_in_place(&self, x: &mut [f64]) {
        self.fac.solve_in_place(x);
    }

    fn negative_pivots(&self) -> Option<usize> {
        Some(self.negatives)
    }
}

/// The node-block sparse LDLᵀ ([`BlockLdlt`], minimum-degree order) behind [`SpdFactor`].
#[derive(Debug, Clone)]
pub struct SparseLdlt(pub BlockLdlt);

impl SpdFactor for SparseLdlt {
    type Matrix = BlockSym;
    fn factor(k: &BlockSym, shift: f64, m_diag: &[f64]) -> Result<Self> {
        BlockLdlt::factor(k, shift, m_diag)
            .map(SparseLdlt)
            .ok_or_else(|| WingbeatError::NonFinite {
                what: "sparse LDLᵀ of K − σM".into(),
                detail: format!("zero or non-finite pivot at σ = {shift:e}"),
            })
    }

    fn refactor(&self, k: &BlockSym, shift: f64, m_diag: &[f64]) -> Result<Self> {
        BlockLdlt::factor_with(self.0.symbolic().clone(), k, shift, m_diag)
            .map(SparseLdlt)
            .ok_or_else(|| WingbeatError::NonFinite {
                what: "sparse LDLᵀ of K − σM".into(),
                detail: format!("zero or non-finite pivot at σ = {shift:e}"),
            })
    }

    fn solve_in_place(&self, x: &mut [f64]) {
        self.0.solve_in_place(x);
    }

    fn negative_pivots(&self) -> Option<usize> {
        Some(self.0.negatives())
    }
}

/// faer's sparse Cholesky (LLᵀ with AMD ordering) behind [`SpdFactor`].
#[cfg(feature = "faer")]
#[derive(Debug, Clone)]
pub struct FaerLlt {
    llt: faer::sparse::linalg::solvers::Llt<usize, f64>,
}

#[cfg(feature = "faer")]
impl FaerLlt {
    /// The upper triangle of K − σM in compressed-column form, structural zeros of the
    /// skyline envelope dropped (so that AMD sees the true graph): column i of the upper
    /// triangle is row i of the skyline's lower envelope.
    fn upper_csc(k: &Skyline, shift: f64, m_diag: &[f64]) -> (Vec<usize>, Vec<usize>, Vec<f64>) {
        let mut col_ptr = Vec::with_capacity(k.n + 1);
        let mut row_idx = Vec::new();
        let mut val = Vec::new();
        col_ptr.push(0);
        for i in 0..k.n {
            let f = k.first[i];
            let row = &k.data[k.start[i]..k.start[i + 1]];
            let (off, d) = row.split_at(row.len() - 1);
            for (c, &a) in off.iter().enumerate() {
                if a != 0.0 {
                    row_idx.push(f + c);
                    val.push(a);
                }
            }
            row_idx.push(i);
            val.push(d[0] - shift * m_diag[i]);
            col_ptr.push(row_idx.len());
        }
        (col_ptr, row_idx, val)
    }
}

#[cfg(feature = "faer")]
impl SpdFactor for FaerLlt {
    type Matrix = Skyline;
    fn factor(k: &Skyline, shift: f64, m_diag: &[f64]) -> Result<Self> {
        use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
        let n = k.n;
        let (col_ptr, row_idx, val) = Self::upper_csc(k, shift, m_diag);
        let sym = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
        let a = SparseColMatRef::new(sym, &val);
        match a.sp_cholesky(faer::Side::Upper) {
            Ok(llt) => Ok(FaerLlt { llt }),
            Err(e) => Err(WingbeatError::NonFinite {
                what: "faer sparse Cholesky of K − σM".into(),
                detail: format!("{e} at σ = {shift:e}"),
            }),
        }
    }

    fn solve_in_place(&self, x: &mut [f64]) {
        use faer::linalg::solvers::Solve;
        let n = x.len();
        self.llt
            .solve_in_place(faer::MatMut::from_column_major_slice_mut(x, n, 1));
    }

    fn negative_pivots(&self) -> Option<usize> {
        // a completed LLᵀ has only positive pivots
        Some(0)
    }
}

/// Sturm count of K − μM with the backend's inertia: the number of eigenvalues of
/// K φ = λ M φ below μ, or `None` where the backend cannot tell (faer: any μ above the
/// lowest eigenvalue, where its Cholesky fails).
pub fn sturm_count<F: SpdFactor>(k: &F::Matrix, m_diag: &[f64], mu: f64) -> Option<usize> {
    F::factor(k, mu, m_diag).ok()?.negative_pivots()
}
