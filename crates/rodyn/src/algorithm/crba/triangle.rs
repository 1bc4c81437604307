//! The parts of `M` that no column writes: the mirror above the diagonal
//! and the zeros between unrelated limbs.
//!
//! Why it exists: the passes fill the lower triangle and only the entries
//! a column reaches; where a pass does not write the rest as it goes
//! (`crate::tuning::ENTRIES_IN_PASS`), these two loops
//! complete `M` afterwards.

use crate::topology::Topology;
use crate::Scalar;

/// Copies the lower triangle of `m` onto the upper. Out of order two rows
/// by two columns at a time, so that each row above takes its entries in
/// adjacent pairs (faster on the 60-link chain's CRBA on hosts); in order,
/// paying per instruction, one entry at a time (on the Cortex-M4 the
/// blocked form ran more instructions on the quadruped's CRBA). The
/// profile: `crate::tuning::MIRROR_IN_BLOCKS`; figures: the performance
/// notebook, "CRBA".
#[inline]
pub(super) fn mirror_lower<S: Scalar, const NV: usize>(m: &mut [[S; NV]; NV]) {
    if !crate::tuning::MIRROR_IN_BLOCKS {
        for r in 1..NV {
            for c in 0..r {
                m[c][r] = m[r][c];
            }
        }
        return;
    }
    let mut r = 1;
    while r + 1 < NV {
        // Rows r and r + 1, their common columns in 2 x 2 blocks.
        let mut c = 0;
        while c + 1 < r {
            let (a0, a1, b0, b1) = (m[r][c], m[r][c + 1], m[r + 1][c], m[r + 1][c + 1]);
            m[c][r] = a0;
            m[c][r + 1] = b0;
            m[c + 1][r] = a1;
            m[c + 1][r + 1] = b1;
            c += 2;
        }
        // The rest: at most one column of row r, two of row r + 1.
        for k in c..=r {
            if k < r {
                m[k][r] = m[r][k];
            }
            m[k][r + 1] = m[r + 1][k];
        }
        r += 2;
    }
    if r < NV {
        for k in 0..r {
            m[k][r] = m[r][k];
        }
    }
}

/// Zeroes the entries below the diagonal that no column reaches: those
/// left of each coordinate's unbroken stretch of supporting coordinates
/// (see [`TopologyTables::chain_start_v`](crate::topology::TopologyTables::chain_start_v)) that do not support it. A chain has
/// none. With `mirrored`, their mirrors above the diagonal too. The local
/// pass on a tree with contiguous subtrees writes its zeros itself
/// ([`backward_body`]).
#[inline]
pub(super) fn clear_lower<S: Scalar, const NB: usize, const NV: usize>(
    t: &Topology<NB, NV>,
    m: &mut [[S; NV]; NV],
    mirrored: bool,
) {
    for (k, row) in m.iter_mut().enumerate() {
        // Most rows have nothing to clear (every row of a chain): they
        // skip the fill, which can become a call into `memset` (fewer
        // instructions on the M4's Panda CRBA; see the notebook, "CRBA").
        let start = t.chain_start(k);
        if start > 0 {
            row[..start].fill(S::ZERO);
        }
    }
    if mirrored {
        for k in 0..NV {
            for row in &mut m[..t.chain_start(k)] {
                row[k] = S::ZERO;
            }
        }
    }
}
