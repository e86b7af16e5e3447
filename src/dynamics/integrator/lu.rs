//! Dense LU factorisation with partial pivoting, for the Newton iteration matrix
//! `I - h*gamma*J` of the SDIRK stepper (on the stack for a size known at compile time).
//!
//! Algorithm: Gaussian elimination with row partial pivoting, `P A = L U`
//! (Golub & Van Loan, *Matrix Computations*, 4th ed., Alg. 3.4.1), column-oriented loops
//! because nalgebra stores matrices column-major.
//!
//! The SDIRK stepper applies the *inverse* built from this factorisation: the two
//! triangular solves are a chain of dependent operations (~340 ns for N = 16 measured),
//! while a dense matrix-vector product parallelises (~65 ns), and the matrix is reused
//! for thousands of Newton iterations per factorisation.
//!
//! Why not `nalgebra::linalg::LU`: for a *generic* dimension it needs the bound
//! `D: DimMin<D, Output = D>`, which would leak into every generic caller. This 60-line
//! version needs none, allocates nothing but the pivot list and is checked against
//! nalgebra's LU for a concrete size in the tests below.
//!
//! When the Jacobian has the block form of a second-order system,
//! [`second_order_inverse`] gets the inverse from a half-size Schur complement instead
//! (the gear model's: 8 x 8 instead of 16 x 16; it allocates the small dynamic blocks),
//! and from [`BLOCKS_FROM_COORDINATES`] coordinates on (trains, planetary sets) the
//! stepper keeps the blocks themselves and applies them ([`IterationInverse`]).

use nalgebra::allocator::Allocator;
use nalgebra::{DMatrix, DefaultAllocator, Dim};

use super::{Matrix, Vector};

/// `P A = L U` of an `N x N` matrix, stored in place (unit lower `L` below the diagonal,
/// `U` on and above it) plus the row interchanges.
#[derive(Debug, Clone)]
pub(crate) struct StaticLu<D: Dim>
where
    DefaultAllocator: Allocator<D, D>,
{
    lu: Matrix<D>,
    /// Row `k` was swapped with row `perm[k]` at elimination step `k`.
    perm: Vec<usize>,
}

impl<D: Dim> StaticLu<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// Factorises `a`. Returns `None` when a pivot is zero or not finite (singular matrix
    /// or NaN/inf entries), so that callers can report an error instead of dividing by zero.
    pub(crate) fn factor(a: &Matrix<D>) -> Option<Self> {
        let n = a.nrows();
        let mut lu = a.clone();
        let mut perm = vec![0usize; n];
        for k in 0..n {
            // Pivot: the largest magnitude in column k on or below the diagonal.
            let mut p = k;
            let mut pivot_abs = lu[(k, k)].abs();
            for i in k + 1..n {
                let v = lu[(i, k)].abs();
                if v > pivot_abs {
                    p = i;
                    pivot_abs = v;
                }
            }
            if !(pivot_abs > 0.0 && pivot_abs.is_finite()) {
                return None;
            }
            perm[k] = p;
            if p != k {
                lu.swap_rows(k, p);
            }
            let inv_pivot = 1.0 / lu[(k, k)];
            for i in k + 1..n {
                lu[(i, k)] *= inv_pivot;
            }
            // Rank-one update of the trailing block, column by column (contiguous inner loop).
            for j in k + 1..n {
                let ukj = lu[(k, j)];
                if ukj != 0.0 {
                    for i in k + 1..n {
                        lu[(i, j)] -= lu[(i, k)] * ukj;
                    }
                }
            }
        }
        Some(Self { lu, perm })
    }

    /// The inverse `A^{-1}`, column by column from `A x_j = e_j` (`N` solves).
    pub(crate) fn inverse(&self) -> Matrix<D> {
        let (dim, _) = self.lu.shape_generic();
        let mut inv = Matrix::<D>::identity_generic(dim, dim);
        for mut col in inv.column_iter_mut() {
            let mut x: Vector<D> = col.clone_owned();
            self.solve_in_place(&mut x);
            col.copy_from(&x);
        }
        inv
    }

    /// Solves `A x = b` in place (`b` becomes `x`). Works on the column-major slices so
    /// that the inner loops are contiguous and free of bounds checks.
    pub(crate) fn solve_in_place(&self, b: &mut Vector<D>) {
        let n = self.perm.len();
        for k in 0..n {
            let p = self.perm[k];
            if p != k {
                b.swap_rows(k, p);
            }
        }
        let a = self.lu.as_slice();
        let x = b.as_mut_slice();
        // Forward substitution with unit lower L, column by column.
        for j in 0..n {
            let xj = x[j];
            let col = &a[j * n..(j + 1) * n];
            for (xi, lij) in x[j + 1..].iter_mut().zip(&col[j + 1..]) {
                *xi -= lij * xj;
            }
        }
        // Back substitution with U, column by column.
        for j in (0..n).rev() {
            let col = &a[j * n..(j + 1) * n];
            x[j] /= col[j];
            let xj = x[j];
            for (xi, uij) in x[..j].iter_mut().zip(&col[..j]) {
                *xi -= uij * xj;
            }
        }
    }
}

/// `(I - c J)^{-1}` for the Jacobian of a second-order system written in first-order
/// form, `J = [[0, I], [A_q, A_v]]` (`N` even, blocks `N/2` square), through the Schur
/// complement of its first block: with `S = I - c A_v - c^2 A_q`,
/// `(I - c J)^{-1} = [[I + c^2 S^{-1} A_q, c S^{-1}], [c S^{-1} A_q, S^{-1}]]`
/// (solve `x - c v = a`, `-c A_q x + (I - c A_v) v = b` for `v` first). One inverse of
/// half the size instead of the full one: about a quarter of the work (Golub & Van Loan,
/// *Matrix Computations*, Sect. 3.2.11 on block elimination). Returns `None` when `J`
/// lacks that structure or `S` is singular (the caller then takes the full LU).
pub(crate) fn second_order_inverse<D: Dim>(jac: &Matrix<D>, c: f64) -> Option<Matrix<D>>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let (a_q, s) = schur_blocks(jac, c)?;
    let s_inv = s.try_inverse()?;
    let n = a_q.nrows();
    let p = &s_inv * &a_q;
    let (dim, _) = jac.shape_generic();
    let mut out = Matrix::<D>::zeros_generic(dim, dim);
    for i in 0..n {
        for j in 0..n {
            out[(i, j)] = f64::from(u8::from(i == j)) + c * c * p[(i, j)];
            out[(i, n + j)] = c * s_inv[(i, j)];
            out[(n + i, j)] = c * p[(i, j)];
            out[(n + i, n + j)] = s_inv[(i, j)];
        }
    }
    out.iter().all(|v| v.is_finite()).then_some(out)
}

/// `A_q` and `S = I - c A_v - c^2 A_q` of [`second_order_inverse`], or `None` when `J`
/// lacks the block structure.
fn schur_blocks<D: Dim>(jac: &Matrix<D>, c: f64) -> Option<(DMatrix<f64>, DMatrix<f64>)>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let full = jac.nrows();
    if !full.is_multiple_of(2) || full == 0 {
        return None;
    }
    let n = full / 2;
    for i in 0..n {
        for j in 0..n {
            if jac[(i, j)] != 0.0 || jac[(i, n + j)] != f64::from(u8::from(i == j)) {
                return None;
            }
        }
    }
    let a_q = DMatrix::from_fn(n, n, |i, j| jac[(n + i, j)]);
    let s = DMatrix::from_fn(n, n, |i, j| {
        f64::from(u8::from(i == j)) - c * jac[(n + i, n + j)] - c * c * a_q[(i, j)]
    });
    Some((a_q, s))
}

/// Fewest coordinates (half the state) from which the stepper keeps `(I - c J)^{-1}` of
/// a second-order system as its blocks ([`IterationInverse::Blocks`]) instead of the
/// explicit inverse: the trains (14 and more) and planetary sets (18 and more). The
/// paper's pair (8) keeps the explicit inverse, so that its results stay bit for bit
/// those of before (the blocks change the order of the round-off).
pub(crate) const BLOCKS_FROM_COORDINATES: usize = 9;

/// `(I - c J)^{-1}` as the SDIRK stepper applies it to the Newton residuals and the
/// error estimate.
#[derive(Debug, Clone)]
pub(crate) enum IterationInverse<D: Dim>
where
    DefaultAllocator: Allocator<D, D>,
{
    /// The explicit inverse: one product of `N^2` multiplications per application.
    Full(Matrix<D>),
    /// A second-order system's blocks (see [`second_order_inverse`]): `[a; b]` maps to
    /// `v = S^{-1} (b + c A_q a)`, `x = a + c v`, two products of `(N/2)^2`
    /// multiplications, half the explicit inverse's, and no `S^{-1} A_q` to form (`N^3 / 8`
    /// multiplications per factorisation saved).
    Blocks {
        /// `A_q`, the stiffness block of `J`.
        a_q: DMatrix<f64>,
        /// `S^{-1}`.
        s_inv: DMatrix<f64>,
        /// `c = h gamma`.
        c: f64,
    },
}

impl<D: Dim> IterationInverse<D>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// `(I - c J)^{-1}` of `jac`: the blocks of a second-order system of at least
    /// [`BLOCKS_FROM_COORDINATES`] coordinates, else the explicit inverse through the
    /// Schur complement ([`second_order_inverse`]) or the full LU; `None` when singular or
    /// not finite.
    pub(crate) fn of(jac: &Matrix<D>, c: f64) -> Option<Self> {
        if jac.nrows() >= 2 * BLOCKS_FROM_COORDINATES {
            if let Some((a_q, s)) = schur_blocks(jac, c) {
                // nalgebra's inverse: fewer instructions than the LU above here (1.30 G
                // against 1.39 G for the four-planet set's `dynamics`, callgrind).
                let s_inv = s.try_inverse()?;
                let finite = s_inv.iter().all(|v| v.is_finite());
                return finite.then_some(Self::Blocks { a_q, s_inv, c });
            }
        }
        let inv = match second_order_inverse(jac, c) {
            Some(inv) => inv,
            None => {
                let (dim, _) = jac.shape_generic();
                StaticLu::factor(&(Matrix::<D>::identity_generic(dim, dim) - jac * c))?.inverse()
            }
        };
        inv.iter().all(|v| v.is_finite()).then_some(Self::Full(inv))
    }

    /// The identity (no factorisation yet).
    pub(crate) fn identity(dim: D) -> Self {
        Self::Full(Matrix::<D>::identity_generic(dim, dim))
    }

    /// `(I - c J)^{-1} r`.
    pub(crate) fn apply(&self, r: &Vector<D>) -> Vector<D> {
        match self {
            Self::Full(m) => m * r,
            Self::Blocks { a_q, s_inv, c } => {
                let n = a_q.nrows();
                let mut out = r.clone();
                let (top, bottom) = out.as_mut_slice().split_at_mut(n);
                let (a, b) = r.as_slice().split_at(n);
                // w = b + c A_q a (in the top half until x is formed), then v = S^{-1} w,
                // each a sum of columns (column-major storage: contiguous, vectorised).
                top.copy_from_slice(b);
                axpy_columns(top, a_q.as_slice(), a, *c);
                bottom.fill(0.0);
                axpy_columns(bottom, s_inv.as_slice(), top, 1.0);
                for ((x, ai), vi) in top.iter_mut().zip(a).zip(bottom.iter()) {
                    *x = ai + c * vi;
                }
                out
            }
        }
    }
}

/// `y += s M x` for the square matrix `M` stored column-major in `m` (`y.len()` rows).
fn axpy_columns(y: &mut [f64], m: &[f64], x: &[f64], s: f64) {
    let n = y.len();
    for (col, xj) in m.chunks_exact(n).zip(x) {
        let f = s * xj;
        for (yi, mij) in y.iter_mut().zip(col) {
            *yi += mij * f;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix5, SMatrix, Vector5};

    /// A deterministic, non-symmetric, well-conditioned 5x5 matrix whose (0,0) entry is zero,
    /// so that the factorisation must pivot.
    fn test_matrix() -> Matrix5<f64> {
        Matrix5::from_fn(|i, j| {
            if i == 0 && j == 0 {
                0.0
            } else {
                ((3 * i + 7 * j) % 11) as f64 - 5.0 + if i == j { 12.0 } else { 0.0 }
            }
        })
    }

    #[test]
    fn solves_like_nalgebra_lu() {
        let a = test_matrix();
        let b = Vector5::new(1.0, -2.0, 3.0, 0.5, -4.0);
        let mut x = b;
        StaticLu::factor(&a)
            .expect("regular")
            .solve_in_place(&mut x);
        let x_ref = a.lu().solve(&b).expect("regular");
        // Both are backward-stable solutions of a matrix with condition number ~10:
        // they agree to a few ulps of |x| ~ 1.
        assert!((x - x_ref).amax() < 1e-13, "{x} vs {x_ref}");
        // And the residual is at round-off level relative to |A||x| ~ 20.
        assert!((a * x - b).amax() < 1e-13);
    }

    #[test]
    fn inverse_times_matrix_is_identity() {
        let a = test_matrix();
        let inv = StaticLu::factor(&a).expect("regular").inverse();
        // Condition number ~10, entries ~10: round-off of a few ulps per entry.
        assert!((inv * a - Matrix5::identity()).amax() < 1e-13);
    }

    #[test]
    fn singular_and_non_finite_matrices_are_rejected() {
        // Two identical rows: they receive identical elimination updates, so one of them
        // becomes an exact zero row and its pivot is exactly zero.
        let mut s = test_matrix();
        let row0 = s.row(0).into_owned();
        s.set_row(3, &row0);
        assert!(StaticLu::factor(&s).is_none());
        let mut n = test_matrix();
        n[(2, 2)] = f64::NAN;
        assert!(StaticLu::factor(&n).is_none());
        assert!(StaticLu::factor(&Matrix5::<f64>::zeros()).is_none());
    }

    #[test]
    fn second_order_inverse_matches_the_full_lu() {
        // A damped chain of 4 masses in first-order form, stiff (k/m up to 1e9 1/s^2,
        // c/m up to 1e6 1/s), at step coefficients from 1e-8 to 1e-3 s.
        let (k, d) = ([2e8, 5e7, 1e9, 3e6], [1e4, 4e5, 2e2, 1e3]);
        let mut jac = SMatrix::<f64, 8, 8>::zeros();
        for i in 0..4 {
            jac[(i, 4 + i)] = 1.0;
            jac[(4 + i, i)] = -k[i];
            jac[(4 + i, 4 + i)] = -d[i];
            if i > 0 {
                jac[(4 + i, i - 1)] = 0.5 * k[i];
                jac[(4 + i - 1, i)] = 0.3 * k[i - 1];
            }
        }
        for c in [1e-8, 1e-6, 1e-5, 1e-4, 1e-3] {
            let m = SMatrix::<f64, 8, 8>::identity() - jac * c;
            let full = StaticLu::factor(&m).unwrap().inverse();
            let schur = second_order_inverse(&jac, c).unwrap();
            // Both are backward-stable inverses of a matrix of condition ~ c^2 k ~ 1e3:
            // agreement to ~1e-12 of the largest entry.
            let scale = full.amax();
            assert!((full - schur).amax() < 1e-12 * scale, "c = {c}");
            assert!((schur * m - SMatrix::<f64, 8, 8>::identity()).amax() < 1e-10);
        }
        // Without the structure: declined.
        let mut other = jac;
        other[(0, 0)] = 1.0;
        assert!(second_order_inverse(&other, 1e-5).is_none());
    }

    #[test]
    fn the_blocks_apply_the_inverse_of_the_full_lu() {
        // A damped chain of 10 masses (at least BLOCKS_FROM_COORDINATES), stiff and
        // non-symmetric as above, in first-order form of dimension 20 (`Dyn`).
        let n = 10;
        let dim = nalgebra::Dyn(2 * n);
        let mut jac = Matrix::<nalgebra::Dyn>::zeros_generic(dim, dim);
        for i in 0..n {
            let k = 1e6 * (1.0 + (7 * i % 5) as f64) * 10f64.powi(i as i32 % 4);
            jac[(i, n + i)] = 1.0;
            jac[(n + i, i)] = -k;
            jac[(n + i, n + i)] = -1e2 * (1.0 + i as f64);
            if i > 0 {
                jac[(n + i, i - 1)] = 0.4 * k;
                jac[(n + i - 1, i)] = 0.2 * k;
            }
        }
        let r = Vector::<nalgebra::Dyn>::from_fn_generic(dim, nalgebra::U1, |i, _| {
            ((5 * i) % 7) as f64 - 3.0
        });
        for c in [1e-8, 1e-6, 1e-4, 1e-3] {
            let inv = IterationInverse::of(&jac, c).unwrap();
            assert!(matches!(inv, IterationInverse::Blocks { .. }), "c = {c}");
            let m = Matrix::<nalgebra::Dyn>::identity_generic(dim, dim) - &jac * c;
            let x = StaticLu::factor(&m).unwrap().inverse() * &r;
            let y = inv.apply(&r);
            // A system of condition ~ c^2 k <= 1e4: agreement with the full LU to ~1e-11
            // of the largest component. The blocks are not backward-stable row by row
            // (x = a + c v cancels, and c A_q carries x's error into the lower rows), so
            // the residual is bounded against |M| |y| rather than |r|: an emulation in
            // IEEE doubles gave 38 ulps of it at c = 1e-4; 1e-12 (about 4500 ulps) is
            // far from both that and a wrong solve (order one).
            assert!((&y - &x).amax() < 1e-11 * x.amax(), "c = {c}");
            let size = (m.abs() * y.abs()).amax();
            assert!((&m * &y - &r).amax() < 1e-12 * size, "c = {c}");
        }
        // The paper's size keeps the explicit inverse (its results bit for bit).
        let small = Matrix::<nalgebra::Dyn>::from_fn_generic(
            nalgebra::Dyn(16),
            nalgebra::Dyn(16),
            |i, j| jac[(if i < 8 { i } else { i + 2 }, if j < 8 { j } else { j + 2 })],
        );
        assert!(matches!(
            IterationInverse::of(&small, 1e-5),
            Some(IterationInverse::Full(_))
        ));
    }
}
