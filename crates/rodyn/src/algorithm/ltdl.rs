//! Sparse `Lᵀ D L` factorisation of the mass matrix (Featherstone §6.5, Table 6.3).
//!
//! `M = Lᵀ D L` with `L` unit lower triangular. Because `M[k][i]` is zero
//! unless coordinate i supports coordinate k, `L` has the same sparsity and
//! no fill-in is created.
//!
//! The factors are formed a column of `L` at a time, leaves to root (the
//! order of Pinocchio's `cholesky::decompose`, not the row updates of
//! Table 6.3): `L[k][i]` for every i supporting k is one dot product over
//! the coordinates that k supports, which follow k in a
//! [`depth_first`](crate::topology::TopologyTables::depth_first) tree. `L` is
//! therefore stored transposed, `ltdl[i][k] = L[k][i]`, so that these dot
//! products and the solves run along rows.
//!
//! On long chains most of those dot products are short next to the number
//! of them, and gathering each one's partial sums costs as much as its
//! terms. There a row of `L` is formed instead as a combination of the
//! rows below it, eight rows per pass over the entries, with `L` kept
//! untransposed below the diagonal too (fewer instructions on long chains;
//! figures in docs/sections/performance_notebook.md, "CRBA forward
//! dynamics and the factorisation").

use crate::data::Data;
use crate::error::{Error, Quantity, Result};
use crate::model::{check_finite, check_result, Model};
use crate::space::Space;
use crate::topology::Topology;
use crate::Scalar;

// Also re-exported for `crba.rs` until CRBA moves to `algorithm/crba/`
// (issue 23, item 1).
pub(crate) use super::common::supporting_ranges;

/// A pivot `D[k]` below this fraction of its own diagonal entry `M[k][k]`,
/// in units of the scalar's epsilon, means `M` is not numerically positive
/// definite.
///
/// Each pivot is compared with its own row's diagonal rather than with the
/// largest one: the test is then that of `S M S` with `S` the diagonal that
/// makes `M`'s diagonal all ones, so it does not depend on the units of the
/// coordinates (metres against radians) nor on the spread of the inertias
/// (a trunk's 10 kg m² against a finger's 1e-5 kg m²). `D[k] / M[k][k]` is
/// the fraction of coordinate k's inertia that the coordinates below it do
/// not already account for: near zero only when its column is (nearly) a
/// combination of theirs, whatever its size.
const PIVOT_TOLERANCE_EPS: f64 = 64.0;

// Out of order, the value that each step of a recurrence has just formed
// enters that step's sums last, and in the solve by `L` the next
// coordinate is updated on its own (the Panda's factor and solve take less
// time on hosts); in order, the plain order. A choice of the tuning
// profile; figures: the performance notebook, "CRBA forward dynamics and
// the factorisation".
use crate::tuning::HOST_ORDER;

/// `y -= a x`, element by element. Slices of equal length, so the loop
/// carries no bounds checks and vectorises.
#[inline]
fn sub_scaled<S: Scalar>(y: &mut [S], a: S, x: &[S]) {
    let x = &x[..y.len()];
    for j in 0..y.len() {
        y[j] -= a * x[j];
    }
}

/// `x · y` over slices of equal length, in four interleaved partial sums:
/// independent additions that the host runs two lanes at a time.
#[inline]
fn dot<S: Scalar>(x: &[S], y: &[S]) -> S {
    let y = &y[..x.len()];
    let (x4, y4) = (x.chunks_exact(4), y.chunks_exact(4));
    let (x_rest, y_rest) = (x4.remainder(), y4.remainder());
    let mut sums = [S::ZERO; 4];
    for (x, y) in x4.zip(y4) {
        for j in 0..4 {
            sums[j] += x[j] * y[j];
        }
    }
    let mut sum = (sums[0] + sums[2]) + (sums[1] + sums[3]);
    for (x, y) in x_rest.iter().zip(y_rest) {
        sum += *x * *y;
    }
    sum
}

/// A coordinate's row of `L` is formed as a combination of the rows below
/// it (see [`row_by_combination`]) when it has at least this many rows
/// below and this many entries in a stretch; otherwise each entry is one
/// dot product along the transposed rows.
const ROWS_PER_COMBINATION: usize = 4;

/// Whether the factorisation forms rows of `L` by combination: on hosts
/// (the combination fills SIMD lanes the Cortex-M4 does not have), on
/// trees whose coordinates sit below at least `MIN_DEPTH` moving bodies
/// on average (chains of 31 links or more; never an arm or a legged
/// robot): on shorter chains the dots alone run fewer instructions, on
/// longer ones the combination (x86-64, f64; the counts per chain length
/// are in the performance notebook, "CRBA forward dynamics and the
/// factorisation"). The condition on `NV` is known at compile time, so
/// small models carry no second copy.
#[inline(always)]
fn combination_pays<const NB: usize, const NV: usize>(t: &Topology<NB, NV>) -> bool {
    const MIN_DEPTH: usize = 15;
    HOST_ORDER && NV > 2 * MIN_DEPTH && t.mean_support_depth >= MIN_DEPTH
}

/// `l = m - Σ_s d_l[s] rows[s][first..]`: a stretch of a row of `L`, before
/// its division by the pivot, from the rows below it (`L` stored
/// untransposed below the diagonal). Eight rows at a time, then four,
/// then one, so that each entry is loaded and stored once per eight rows
/// and no sum is gathered across lanes (eight rather than four: fewer
/// instructions on the 60-link chain); farthest first, so that the nearest
/// row, formed just before, enters last.
#[inline(never)]
fn row_by_combination<S: Scalar, const NV: usize>(
    l: &mut [S],
    m: &[S],
    rows: &[[S; NV]],
    d_l: &[S],
    first: usize,
) {
    let n = l.len();
    l.copy_from_slice(m);
    let (rows8, d_l8) = (rows.rchunks_exact(8), d_l.rchunks_exact(8));
    let (rows, d_l) = (rows8.remainder(), d_l8.remainder());
    for (rows, a) in rows8.zip(d_l8) {
        let x: [&[S]; 8] = core::array::from_fn(|r| &rows[r][first..first + n]);
        for j in 0..n {
            l[j] -= ((a[7] * x[7][j] + a[6] * x[6][j]) + (a[5] * x[5][j] + a[4] * x[4][j]))
                + ((a[3] * x[3][j] + a[2] * x[2][j]) + (a[1] * x[1][j] + a[0] * x[0][j]));
        }
    }
    if let Some((rows, a)) = rows.rchunks_exact(4).zip(d_l.rchunks_exact(4)).next() {
        let x: [&[S]; 4] = core::array::from_fn(|r| &rows[r][first..first + n]);
        for j in 0..n {
            l[j] -= (a[3] * x[3][j] + a[2] * x[2][j]) + (a[1] * x[1][j] + a[0] * x[0][j]);
        }
    }
    let rest = rows.len() % 4;
    for (row, a) in rows[..rest].iter().zip(&d_l[..rest]).rev() {
        sub_scaled(l, *a, &row[first..first + n]);
    }
}

/// Factors `data.mass_matrix` into `data.ltdl`: `D` on the diagonal, `L`
/// transposed above it (`ltdl[i][k] = L[k][i]` for i < k).
///
/// Inputs: the lower triangle of `data.mass_matrix` (diagonal included), as
/// [`crba`](crate::algorithm::crba::crba) leaves it. Leaves valid: the
/// diagonal and upper triangle of `ltdl`; the lower one is working storage
/// (on long chains it holds `L` untransposed). Entries of `L` that the
/// sparsity makes zero are not written either, except in a tree that is
/// not [`depth_first`](crate::topology::TopologyTables::depth_first), where the
/// factorisation and the solves read them.
///
/// Pivots are formed and tested leaves to root, so the coordinate reported
/// is the highest-numbered one whose pivot fails.
///
/// # Errors
/// [`Error::MassMatrixNotPositiveDefinite`] when a pivot is not safely positive.
pub fn ltdl_factor<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &mut Data<S, NB, NV, G>,
) -> Result<()> {
    let topology = model.topology();
    let pivots = Pivots {
        // Compared in S, like ABA's pivots: no f64 on the hot path.
        tolerance: S::from_f64(PIVOT_TOLERANCE_EPS * S::EPSILON),
        d: [S::ZERO; NV],
    };
    if combination_pays(topology) {
        factor_by_rows(topology, &data.mass_matrix, &mut data.ltdl, pivots)
    } else {
        factor_by_dots(topology, &data.mass_matrix, &mut data.ltdl, pivots)
    }
}

/// The pivots `D` as they are formed, and what they are tested against.
struct Pivots<S, const NV: usize> {
    /// The smallest pivot accepted, as a fraction of its diagonal entry of
    /// `M` ([`PIVOT_TOLERANCE_EPS`] ε).
    tolerance: S,
    /// `D[s]` for the coordinates s formed so far (those after k).
    d: [S; NV],
}

impl<S: Scalar, const NV: usize> Pivots<S, NV> {
    /// `D[k] = M[k][k] - Σ D[s] L[s][k]²` over the coordinates s in
    /// `below`, with `l_k[s] = L[s][k]`; fills `d_l[s] = D[s] L[s][k]` on
    /// the way and records and returns `D[k]`.
    ///
    /// # Errors
    /// [`Error::MassMatrixNotPositiveDefinite`] when `D[k]` is not safely
    /// positive.
    #[inline(always)]
    fn form(
        &mut self,
        k: usize,
        m_kk: S,
        l_k: &[S; NV],
        below: core::ops::Range<usize>,
        d_l: &mut [S; NV],
    ) -> Result<S> {
        let mut d = m_kk;
        if HOST_ORDER {
            // Slices zipped, with no bounds checks (fewer instructions in
            // the 60-link chain's factorisation), and `L[k + 1][k]`, the
            // entry formed just before, ends the chain of subtractions
            // instead of starting it.
            let (l_k, d_s) = (&l_k[below.clone()], &self.d[below.clone()]);
            for ((l, d_s), dl) in l_k.iter().zip(d_s).zip(&mut d_l[below]).rev() {
                *dl = *d_s * *l;
                d -= *l * *dl;
            }
        } else {
            // Indexed: slicing three ranges per pivot costs the Cortex-M4
            // more than the bounds checks (measured on the Panda).
            for s in below {
                let dl = self.d[s] * l_k[s];
                d_l[s] = dl;
                d -= l_k[s] * dl;
            }
        }
        // A non-positive or NaN `M[k][k]` fails too: `D[k] ≤ M[k][k]`
        // once the pivots below are positive.
        if !(d.is_finite() && d > self.tolerance * m_kk) {
            // Divided in S: an f64 division is a software routine on an
            // FPU without double precision.
            return Err(Error::MassMatrixNotPositiveDefinite {
                dof: k,
                relative_pivot: if m_kk > S::ZERO {
                    (d / m_kk).to_f64()
                } else {
                    0.0
                },
            });
        }
        self.d[k] = d;
        Ok(d)
    }
}

/// [`ltdl_factor`] with every entry of `L` one dot product along the
/// transposed rows: `L[k][i]` for every i supporting k over the
/// coordinates below k.
#[inline(always)]
fn factor_by_dots<S: Scalar, const NB: usize, const NV: usize>(
    topology: &Topology<NB, NV>,
    m: &[[S; NV]; NV],
    h: &mut [[S; NV]; NV],
    mut pivots: Pivots<S, NV>,
) -> Result<()> {
    let mut d_l = [S::ZERO; NV];
    for k in (0..NV).rev() {
        let below = k + 1..topology.last_supported(k) + 1;
        let d = pivots.form(k, m[k][k], &h[k], below, &mut d_l)?;
        h[k][k] = d;
        if !topology.depth_first {
            // The rows that do not support k read this column as zeros.
            for row in &mut h[..k] {
                row[k] = S::ZERO;
            }
        }
        column_by_dots(topology, &m[k], h, &d_l, k, S::ONE / d);
    }
    Ok(())
}

/// `L[k][i] = (M[k][i] - Σ D[s] L[s][k] L[s][i]) / D[k]` over the
/// coordinates s below k, for every i supporting k, into `h[i][k]`.
///
/// Out of line: inlined, its slices became a dozen pointers that the loop
/// over k carried and spilled. Called once per coordinate, it costs a
/// call and saves more (CRBA forward dynamics on x86-64 and the Cortex-M4;
/// only the one-link pendulum pays for the call). Figures: the performance
/// notebook, "CRBA forward dynamics and the factorisation".
#[inline(never)]
fn column_by_dots<S: Scalar, const NB: usize, const NV: usize>(
    topology: &Topology<NB, NV>,
    m_k: &[S; NV],
    h: &mut [[S; NV]; NV],
    d_l: &[S; NV],
    k: usize,
    inverse: S,
) {
    // Sliced here, where `last_supported` states the range in bounds.
    let below = k + 1..topology.last_supported(k) + 1;
    let d_l = &d_l[below.clone()];
    for (first, last) in supporting_ranges(topology, topology.lambda(k)) {
        let rows = h[first..=last].iter_mut().zip(&m_k[first..=last]);
        if d_l.is_empty() {
            for (row, m_ki) in rows {
                row[k] = *m_ki * inverse;
            }
        } else {
            for (row, m_ki) in rows {
                row[k] = (*m_ki - dot(&row[below.clone()], d_l)) * inverse;
            }
        }
    }
}

/// [`ltdl_factor`] with `L` also stored untransposed below the diagonal,
/// so that a row of it with enough rows below and entries in a stretch
/// can be formed as a combination of the rows below ([`row_by_combination`]).
#[inline(never)]
fn factor_by_rows<S: Scalar, const NB: usize, const NV: usize>(
    topology: &Topology<NB, NV>,
    m: &[[S; NV]; NV],
    h: &mut [[S; NV]; NV],
    mut pivots: Pivots<S, NV>,
) -> Result<()> {
    let mut d_l = [S::ZERO; NV];
    for k in (0..NV).rev() {
        let end = topology.last_supported(k) + 1;
        let (to_k, below_k) = h.split_at_mut(k + 1);
        let (above_k, row_k) = to_k.split_at_mut(k);
        let row_k = &mut row_k[0];
        let d = pivots.form(k, m[k][k], row_k, k + 1..end, &mut d_l)?;
        row_k[k] = d;
        if !topology.depth_first {
            // The coordinates that k does not support read L[k][·] as
            // zeros, in both triangles.
            for row in above_k.iter_mut() {
                row[k] = S::ZERO;
            }
            row_k[..k].fill(S::ZERO);
        }
        let inverse = S::ONE / d;
        let rows_below = &below_k[..end - k - 1];
        let d_l = &d_l[k + 1..end];
        for (first, last) in supporting_ranges(topology, topology.lambda(k)) {
            let (l_k, l_k_transposed) = (&mut row_k[first..=last], &mut above_k[first..=last]);
            let m_k = &m[k][first..=last];
            if rows_below.len() >= ROWS_PER_COMBINATION && l_k.len() >= ROWS_PER_COMBINATION {
                row_by_combination(l_k, m_k, rows_below, d_l, first);
                for (l, row) in l_k.iter_mut().zip(l_k_transposed) {
                    *l *= inverse;
                    row[k] = *l;
                }
            } else {
                for ((l, row), m_ki) in l_k.iter_mut().zip(l_k_transposed).zip(m_k) {
                    *l = (*m_ki - dot(&row[k + 1..end], d_l)) * inverse;
                    row[k] = *l;
                }
            }
        }
    }
    Ok(())
}

/// Solves `M x = b` in place with the factors from [`ltdl_factor`].
///
/// Inputs: `b` (NV); `data.ltdl` valid. On return `b` holds `x`.
///
/// # Errors
/// [`Error::NonFinite`] for a non-finite `b`
/// (left unchanged), and
/// [`Error::NonFiniteResult`] when the
/// solution overflows (`b` then holds it).
///
/// # Example
///
/// ```
/// use rodyn::algorithm::{crba::crba, ltdl::{ltdl_factor, ltdl_solve}};
/// # use rodyn::prelude::*;
/// # // Two 1 m links about z, 1 kg point masses at the tips, gravity -y.
/// # const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
/// # const DOUBLE: Model<f64, 2, 2, 2> = Model::new(
/// #     [None, Some(0)], [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
/// #     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
/// #     [LINK, LINK], Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// let q2 = 0.5;
/// crba(&DOUBLE, &mut data, &[0.1, q2])?;
/// ltdl_factor(&DOUBLE, &mut data)?;
/// let b = [1.0, -2.0];
/// let mut x = b;
/// ltdl_solve(&DOUBLE, &data, &mut x)?;
/// // M = [[3 + 2 cos q₂, 1 + cos q₂], [1 + cos q₂, 1]] for this arm: check M x = b.
/// let (m00, m10, m11) = (3.0 + 2.0 * f64::cos(q2), 1.0 + f64::cos(q2), 1.0);
/// assert!((m00 * x[0] + m10 * x[1] - b[0]).abs() < 1e-12);
/// assert!((m10 * x[0] + m11 * x[1] - b[1]).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
pub fn ltdl_solve<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    b: &mut [S; NV],
) -> Result<()> {
    check_finite(b, Quantity::Acceleration)?;
    solve_transposed(model, data, b);
    // D z = y.
    for (k, bk) in b.iter_mut().enumerate() {
        *bk /= data.ltdl[k][k];
    }
    solve_lower(model, data, b);
    check_result(b, Quantity::Acceleration)
}

/// `Lᵀ y = b` in place, leaves to root: `b[k] -= Σ L[s][k] b[s]` over the
/// `s` below `k` (the first sweep of [`ltdl_solve`]).
pub(crate) fn solve_transposed<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    b: &mut [S; NV],
) {
    let topology = model.topology();
    let h = &data.ltdl;
    for k in (0..NV).rev() {
        let (b_to_k, b_below) = b.split_at_mut(k + 1);
        let end = topology.last_supported(k) + 1;
        let (l, b_below) = (&h[k][k + 1..end], &b_below[..end - k - 1]);
        match (l, b_below) {
            // `b[k + 1]`, final only just now, enters last.
            ([l_next, l_rest @ ..], [b_next, b_rest @ ..]) if HOST_ORDER => {
                b_to_k[k] = (b_to_k[k] - dot(l_rest, b_rest)) - *l_next * *b_next;
            }
            _ => b_to_k[k] -= dot(l, b_below),
        }
    }
}

/// `L x = z` in place, root to leaves: once `b[k]` is final, `b[s] -=
/// L[s][k] b[k]` over the `s` below `k` (the last sweep of [`ltdl_solve`]).
pub(crate) fn solve_lower<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    b: &mut [S; NV],
) {
    let topology = model.topology();
    let h = &data.ltdl;
    for k in 0..NV {
        let b_k = b[k];
        let end = topology.last_supported(k) + 1;
        match (&mut b[k + 1..end], &h[k][k + 1..end]) {
            // `b[k + 1]`, final after this update, on its own; the rest
            // then starts at `k + 2`, where the next pass's reads start.
            ([b_next, b_rest @ ..], [l_next, l_rest @ ..]) if HOST_ORDER => {
                *b_next -= *l_next * b_k;
                sub_scaled(b_rest, b_k, l_rest);
            }
            (b_below, l) => sub_scaled(b_below, b_k, l),
        }
    }
}

/// `Lᵀ y = b` for each row `b` of `rows`, each zero outside the
/// coordinates of `body` and its ancestors (the rows of one contact's
/// Jacobian): each `y` is zero there too, and only that path is swept, once
/// for all the rows: `y[k] = b[k] − Σ L[s][k] y[s]` over the path's
/// coordinates `s` below `k`. Reads only entries of `L` the sparsity keeps,
/// so it holds for any tree numbering.
pub(crate) fn solve_transposed_on_path<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    body: usize,
    rows: &mut [[S; NV]],
) {
    let t = model.topology();
    let h = &data.ltdl;
    // The path's coordinates, leaves first (a parent's precede its child's).
    let mut path = [0usize; NV];
    let mut len = 0;
    let mut i = Some(body);
    while let Some(j) = i {
        // `body` is the caller's; the parents are in range.
        if j >= NB {
            break;
        }
        for k in t.velocity_coordinates(j).rev() {
            // A path holds each coordinate once, so it fits (`get_mut`: no
            // panic path).
            if let Some(slot) = path.get_mut(len) {
                *slot = k;
                len += 1;
            }
        }
        i = t.parent(j);
    }
    for (n, &k) in path.iter().take(len).enumerate() {
        // The coordinates read back are in range: tests, not panic paths
        // (one per entry, where indexing `l` and `b` checked twice).
        let Some(l) = h.get(k) else {
            continue;
        };
        for b in rows.iter_mut() {
            let below =
                path.iter().take(n).fold(
                    S::ZERO,
                    |acc, &s| {
                        if s < NV {
                            acc + l[s] * b[s]
                        } else {
                            acc
                        }
                    },
                );
            b[k] -= below;
        }
    }
}

/// Solves `M X = B` in place for `C` right-hand sides at once, with the
/// factors from [`ltdl_factor`]: row k of `b` holds coordinate k's entries
/// of every column (so `b = I` gives `M⁻¹`). The same sweeps as
/// [`ltdl_solve`], each step a row update across all columns, which
/// vectorises and saves a sweep per column.
///
/// # Errors
/// As [`ltdl_solve`], the index being the flattened `row · C + column`.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::{crba::crba, ltdl::{ltdl_factor, ltdl_solve_columns}};
/// # use rodyn::prelude::*;
/// # // Two 1 m links about z, 1 kg point masses at the tips, gravity -y.
/// # const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
/// # const DOUBLE: Model<f64, 2, 2, 2> = Model::new(
/// #     [None, Some(0)], [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
/// #     [Transform::IDENTITY, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0))],
/// #     [LINK, LINK], Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut data = Data::new();
/// let m = *crba(&DOUBLE, &mut data, &[0.1, 0.5])?;
/// ltdl_factor(&DOUBLE, &mut data)?;
/// let mut inverse = [[1.0, 0.0], [0.0, 1.0]];
/// ltdl_solve_columns(&DOUBLE, &data, &mut inverse)?;
/// // M M⁻¹ = I (CRBA fills M's lower triangle).
/// let m01 = m[1][0];
/// assert!((m[0][0] * inverse[0][0] + m01 * inverse[1][0] - 1.0).abs() < 1e-12);
/// assert!((m01 * inverse[0][1] + m[1][1] * inverse[1][1] - 1.0).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
pub fn ltdl_solve_columns<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const C: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    b: &mut [[S; C]; NV],
) -> Result<()> {
    check_finite(b.as_flattened(), Quantity::Acceleration)?;
    let topology = model.topology();
    let h = &data.ltdl;
    // Lᵀ Y = B, leaves to root.
    for k in (0..NV).rev() {
        let end = topology.last_supported(k) + 1;
        let (head, below) = b.split_at_mut(k + 1);
        let row_k = &mut head[k];
        for (row_s, l) in below.iter().zip(&h[k][k + 1..end]) {
            for (x, y) in row_k.iter_mut().zip(row_s) {
                *x -= *l * *y;
            }
        }
    }
    // D Z = Y.
    for (k, row) in b.iter_mut().enumerate() {
        let inverse = S::ONE / h[k][k];
        for x in row.iter_mut() {
            *x *= inverse;
        }
    }
    // L X = Z, root to leaves.
    for k in 0..NV {
        let end = topology.last_supported(k) + 1;
        let (head, below) = b.split_at_mut(k + 1);
        let row_k = &head[k];
        for (row_s, l) in below.iter_mut().zip(&h[k][k + 1..end]) {
            for (x, y) in row_s.iter_mut().zip(row_k) {
                *x -= *l * *y;
            }
        }
    }
    check_result(b.as_flattened(), Quantity::Acceleration)
}

/// `X = M⁻¹ B` from the factors, `B` given as `sign · b` or, without `b`,
/// the identity (then `X = M⁻¹`, and `C` must be `NV`); no checks of the
/// input or the result (for callers whose inputs are finite by
/// construction and who check what they return).
///
/// Each sweep forms one row of `X` at a time as a combination of rows
/// already final (`Y_k = B_k − Σ L[s][k] Y_s` over the s that k supports,
/// then `X_s = D⁻¹[s] Y_s − Σ L[s][k] X_k` over the k supporting s), the
/// row accumulated in a local copy: a row of a small model then stays in
/// registers across the combination instead of being loaded and stored
/// once per term, as [`ltdl_solve_columns`] does. The second sweep reads
/// only entries of `L` the sparsity keeps and the first reads zeros where
/// it has none, so this holds for any tree numbering.
///
/// Returns, for rows of at most [`SUMMED_ROW_MAX`] columns, the sum of
/// `X`'s entries, each row summed while it is still in registers: finite
/// only when every entry is (the test of `check_matrix_result`, which this
/// spares the caller a pass over `X` for); a sum that overflows is not
/// finite either, and the caller then searches `X`. Longer rows are not in
/// registers, and summed there they cost more than the caller's test: `None`.
pub(crate) fn solve_columns_by_rows<
    S: Scalar,
    const NB: usize,
    const NQ: usize,
    const NV: usize,
    const C: usize,
    G: Space,
>(
    model: &Model<S, NB, NQ, NV, G>,
    data: &Data<S, NB, NV, G>,
    b: Option<(S, &[[S; C]; NV])>,
    x: &mut [[S; C]; NV],
) -> Option<S> {
    let topology = model.topology();
    let h = &data.ltdl;
    // Lᵀ Y = B, leaves to root.
    for k in (0..NV).rev() {
        let mut acc = match b {
            Some((sign, b)) => b[k].map(|v| sign * v),
            None => {
                let mut unit = [S::ZERO; C];
                if let Some(one) = unit.get_mut(k) {
                    *one = S::ONE;
                }
                unit
            }
        };
        // Through `get`: no bounds checks in firmware images.
        let end = topology.last_supported(k) + 1;
        let (head, below) = x.split_at_mut(k + 1);
        for (row_s, l) in below.iter().zip(h[k].get(k + 1..end).unwrap_or_default()) {
            for (a, y) in acc.iter_mut().zip(row_s) {
                *a -= *l * *y;
            }
        }
        if let Some(row_k) = head.last_mut() {
            *row_k = acc;
        }
    }
    // L X = D⁻¹ Y, root to leaves.
    let mut total = S::ZERO;
    for s in 0..NV {
        let (above, from_s) = x.split_at_mut(s);
        let Some(row_s) = from_s.first_mut() else {
            break;
        };
        let inverse = S::ONE / h[s][s];
        let mut acc = row_s.map(|v| v * inverse);
        // The coordinates supporting s, a chain of them at a time (as
        // `supporting_ranges` walks them, but through `get`: no bounds
        // checks in firmware images).
        let mut support = topology.lambda(s);
        while let Some(end) = support {
            let first = topology.chain_start_v.get(end).copied().unwrap_or(end);
            let (above, h) = (above.get(first..=end), h.get(first..=end));
            for (row_k, h_k) in above.unwrap_or_default().iter().zip(h.unwrap_or_default()) {
                let l = h_k[s];
                for (a, y) in acc.iter_mut().zip(row_k) {
                    *a -= l * *y;
                }
            }
            support = topology.lambda_v.get(first).copied().flatten();
        }
        *row_s = acc;
        if C <= SUMMED_ROW_MAX {
            total += row_sum(&acc);
        }
    }
    (C <= SUMMED_ROW_MAX).then_some(total)
}

/// The longest row that [`solve_columns_by_rows`] sums as it forms it:
/// twelve SSE2 registers of `f64`, beside which the sum's lanes and the
/// combination's operands still fit x86-64's sixteen (the 60-link chain's
/// rows, summed, took more instructions than a separate test).
const SUMMED_ROW_MAX: usize = 24;

/// The sum of a row's entries in four interleaved partial sums: vector
/// lanes on hosts, and no chain of dependent additions along the row.
#[inline(always)]
fn row_sum<S: Scalar>(row: &[S]) -> S {
    let chunks = row.chunks_exact(4);
    let rest = chunks.remainder();
    let mut sums = [S::ZERO; 4];
    for chunk in chunks {
        for (sum, x) in sums.iter_mut().zip(chunk) {
            *sum += *x;
        }
    }
    for (sum, x) in sums.iter_mut().zip(rest) {
        *sum += *x;
    }
    (sums[0] + sums[2]) + (sums[1] + sums[3])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Uniform numbers in `[lo, hi)` from a fixed seed (a 64-bit LCG).
    struct Numbers(u64);

    impl Numbers {
        fn next(&mut self, lo: f64, hi: f64) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
        }
    }

    /// Whether coordinate i supports coordinate k (i on k's λ chain, k included).
    fn supports<const NB: usize, const NV: usize>(
        t: &Topology<NB, NV>,
        i: usize,
        k: usize,
    ) -> bool {
        let mut c = Some(k);
        while let Some(j) = c {
            if j == i {
                return true;
            }
            c = t.lambda_v[j];
        }
        false
    }

    /// `D`, `L` with the tree's sparsity, and `M = Lᵀ D L` from them.
    #[allow(clippy::type_complexity)]
    fn factors_and_mass_matrix<const NB: usize, const NV: usize>(
        t: &Topology<NB, NV>,
        seed: u64,
    ) -> ([f64; NV], [[f64; NV]; NV], [[f64; NV]; NV]) {
        let mut numbers = Numbers(seed);
        let d: [f64; NV] = core::array::from_fn(|_| numbers.next(0.5, 2.0));
        let l: [[f64; NV]; NV] = core::array::from_fn(|k| {
            core::array::from_fn(|i| match i.cmp(&k) {
                core::cmp::Ordering::Equal => 1.0,
                core::cmp::Ordering::Less if supports(t, i, k) => numbers.next(-0.2, 0.2),
                _ => 0.0,
            })
        });
        let m = core::array::from_fn(|a| {
            // `l[k][a]` is zero for `k < a`: the sum starts where both may not be.
            core::array::from_fn(|b| (a.max(b)..NV).map(|k| l[k][a] * d[k] * l[k][b]).sum())
        });
        (d, l, m)
    }

    /// Factors `M = Lᵀ D L` both ways, into storage full of NaN (so that
    /// a read of an entry not written shows), and holds each to `D` and `L`.
    fn assert_both_recover<const NB: usize, const NV: usize>(t: &Topology<NB, NV>, seed: u64) {
        let (d, l, m) = factors_and_mass_matrix(t, seed);
        let pivots = || Pivots {
            tolerance: 1e-12,
            d: [0.0; NV],
        };
        let mut by_dots = [[f64::NAN; NV]; NV];
        factor_by_dots(t, &m, &mut by_dots, pivots()).unwrap();
        let mut by_rows = [[f64::NAN; NV]; NV];
        factor_by_rows(t, &m, &mut by_rows, pivots()).unwrap();
        for k in 0..NV {
            for i in (0..k).filter(|&i| supports(t, i, k)) {
                for (what, got) in [
                    ("by dots, above", by_dots[i][k]),
                    ("by rows, above", by_rows[i][k]),
                    ("by rows, below", by_rows[k][i]),
                ] {
                    assert!(
                        (got - l[k][i]).abs() < 1e-12,
                        "{what}: L[{k}][{i}] = {got}, not {}",
                        l[k][i]
                    );
                }
            }
            for got in [by_dots[k][k], by_rows[k][k]] {
                assert!(
                    (got - d[k]).abs() < 1e-12 * d[k],
                    "D[{k}] = {got}, not {}",
                    d[k]
                );
            }
        }
    }

    /// The sum that the row solve returns is the sum of its result's
    /// entries, and not finite when an entry overflows.
    #[test]
    fn the_row_solve_sums_its_result() {
        use crate::prelude::*;
        // Two 1 m links about z, 1 kg point masses at the tips, gravity -y.
        const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
        const DOUBLE: Model<f64, 2, 2, 2> = Model::new(
            [None, Some(0)],
            [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
            [
                Transform::IDENTITY,
                Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)),
            ],
            [LINK, LINK],
            Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
        );
        let mut data = Data::new();
        crate::algorithm::crba::crba(&DOUBLE, &mut data, &[0.1, 0.5]).unwrap();
        ltdl_factor(&DOUBLE, &mut data).unwrap();
        let b = [[1.0, -2.0], [0.5, 3.0]];
        let mut x = [[0.0; 2]; 2];
        let sum = solve_columns_by_rows(&DOUBLE, &data, Some((-1.0, &b)), &mut x).unwrap();
        let mut by_solve = b.map(|row| row.map(|v| -v));
        ltdl_solve_columns(&DOUBLE, &data, &mut by_solve).unwrap();
        let expected: f64 = by_solve.iter().flatten().sum();
        assert!((sum - expected).abs() < 1e-12 * expected.abs().max(1.0));
        let huge = [[f64::MAX, 0.0], [0.0, f64::MAX]];
        let sum = solve_columns_by_rows(&DOUBLE, &data, Some((1.0, &huge)), &mut x).unwrap();
        assert!(!sum.is_finite());
        assert!(x.iter().flatten().any(|v| !v.is_finite()));
    }

    #[test]
    fn a_long_chain_factors_the_same_by_rows_and_by_dots() {
        let t = Topology::<40, 40>::new(
            core::array::from_fn(|i| i.checked_sub(1)),
            [1; 40],
            [1; 40],
            40,
        );
        // Only the out-of-order profile takes the combination; both
        // factorisations run here in either.
        assert_eq!(combination_pays(&t), HOST_ORDER);
        assert_both_recover(&t, 1);
    }

    #[test]
    fn a_branched_tree_with_a_free_root_factors_the_same_both_ways() {
        // A free-flying root, a trunk of 9 links and two branches of 12,
        // numbered depth first: the rows' stretches break at the branch.
        let parents = core::array::from_fn(|i| match i {
            0 => None,
            10 => Some(6),
            _ => Some(i - 1),
        });
        let nv = core::array::from_fn(|i| if i == 0 { 6 } else { 1 });
        let nq = core::array::from_fn(|i| if i == 0 { 7 } else { 1 });
        let t = Topology::<34, 39>::new(parents, nq, nv, 40);
        assert!(t.depth_first);
        assert_both_recover(&t, 2);
    }

    #[test]
    fn a_tree_numbered_out_of_depth_first_order_factors_the_same_both_ways() {
        // A trunk of 4 links; a branch of 8 on it; a second branch of 8 on
        // the trunk; then 8 more links on the end of the first branch. The
        // second branch sits below the first one's coordinates without
        // being supported by them, so both factors read the zeros that the
        // sparsity leaves, in stretches long enough to be combined.
        let parents = core::array::from_fn(|i| match i {
            0 => None,
            12 => Some(3),
            20 => Some(11),
            _ => Some(i - 1),
        });
        let t = Topology::<28, 28>::new(parents, [1; 28], [1; 28], 28);
        assert!(!t.depth_first);
        assert_both_recover(&t, 3);
    }

    #[test]
    fn interleaved_chains_factor_the_same_both_ways() {
        // Two chains from one root, their bodies alternating: every
        // stretch is one coordinate long.
        let parents = core::array::from_fn(|i| match i {
            0 => None,
            1 => Some(0),
            _ => Some(i - 2),
        });
        let t = Topology::<36, 36>::new(parents, [1; 36], [1; 36], 36);
        assert!(!t.depth_first);
        assert_both_recover(&t, 4);
    }
}
