//! The index layout of a tree, computed and checked at compile time.
//!
//! Bodies are numbered so that a parent comes before its children
//! (`parent[i] < i`); every pass of every algorithm is then a plain index
//! loop, forwards or backwards, with no recursion.

/// Where each body's coordinates start, and the tree over velocity coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Topology<const NB: usize, const NV: usize> {
    /// Parent body of each body; `None` for a body attached to the world.
    pub parents: [Option<usize>; NB],
    /// First configuration coordinate of each body's joint.
    pub idx_q: [usize; NB],
    /// Number of configuration coordinates of each body's joint.
    pub nq: [usize; NB],
    /// First velocity coordinate of each body's joint.
    pub idx_v: [usize; NB],
    /// Number of velocity coordinates of each body's joint.
    pub nv: [usize; NB],
    /// Featherstone's λ over velocity coordinates: the nearest coordinate
    /// that moves a supporting body, `None` at a root. `lambda_v[k] < k`.
    pub lambda_v: [Option<usize>; NV],
    /// The body each velocity coordinate belongs to.
    pub body_of_v: [usize; NV],
    /// Where the unbroken stretch of λ ending at coordinate k starts:
    /// `lambda_v[m] = Some(m - 1)` for every m in `chain_start_v[k] + 1 ..= k`.
    /// The coordinates that support k (k included) are therefore the
    /// contiguous range `chain_start_v[k] ..= k`, then those supporting
    /// `lambda_v[chain_start_v[k]]`: a chain is one range, a branched tree
    /// a few. The sparse factorisation walks these ranges as slices.
    pub chain_start_v: [usize; NV],
}

impl<const NB: usize, const NV: usize> Topology<NB, NV> {
    /// Lays out the coordinates of a tree and checks it; a `const` evaluation
    /// of an inconsistent tree fails to compile with the panic's message.
    ///
    /// # Panics
    /// When a parent index is not smaller than its child's, when the joints'
    /// coordinate counts do not add up to `nq_total` and `NV`, or when a
    /// joint has more than six degrees of freedom.
    #[must_use]
    pub const fn new(
        parents: [Option<usize>; NB],
        nq: [usize; NB],
        nv: [usize; NB],
        nq_total: usize,
    ) -> Self {
        let mut idx_q = [0; NB];
        let mut idx_v = [0; NB];
        let mut lambda_v = [None; NV];
        let mut body_of_v = [0; NV];
        // The last velocity coordinate that moves body i or one of its ancestors.
        let mut last_v: [Option<usize>; NB] = [None; NB];
        let (mut q, mut v) = (0, 0);
        let mut i = 0;
        while i < NB {
            if let Some(p) = parents[i] {
                if p >= i {
                    panic!("rodyn model: every body's parent must come before it (parent[i] < i); reorder the bodies");
                }
            }
            if nv[i] > crate::joint::MAX_JOINT_NV {
                panic!("rodyn model: a joint has more than 6 degrees of freedom");
            }
            idx_q[i] = q;
            idx_v[i] = v;
            let inherited = match parents[i] {
                Some(p) => last_v[p],
                None => None,
            };
            let mut k = 0;
            while k < nv[i] {
                if v + k >= NV {
                    panic!("rodyn model: the joints have more velocity coordinates than NV");
                }
                lambda_v[v + k] = if k == 0 { inherited } else { Some(v + k - 1) };
                body_of_v[v + k] = i;
                k += 1;
            }
            last_v[i] = if nv[i] > 0 {
                Some(v + nv[i] - 1)
            } else {
                inherited
            };
            q += nq[i];
            v += nv[i];
            i += 1;
        }
        if q != nq_total {
            panic!("rodyn model: the joints' configuration coordinates do not add up to NQ");
        }
        if v != NV {
            panic!("rodyn model: the joints' velocity coordinates do not add up to NV");
        }
        let mut chain_start_v = [0; NV];
        let mut k = 0;
        while k < NV {
            chain_start_v[k] = match lambda_v[k] {
                Some(l) if l + 1 == k => chain_start_v[l],
                _ => k,
            };
            k += 1;
        }
        Self {
            parents,
            idx_q,
            nq,
            idx_v,
            nv,
            lambda_v,
            body_of_v,
            chain_start_v,
        }
    }

    /// `true` when body `ancestor` is `body` or supports it.
    #[must_use]
    pub fn supports(&self, ancestor: usize, body: usize) -> bool {
        let mut b = Some(body);
        while let Some(i) = b {
            if i == ancestor {
                return true;
            }
            if i < ancestor {
                return false;
            }
            b = self.parents[i];
        }
        false
    }
}
