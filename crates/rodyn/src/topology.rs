//! The index layout of a tree, computed and checked at compile time.
//!
//! Bodies are numbered so that a parent comes before its children
//! (`parent[i] < i`); every pass of every algorithm is then a plain index
//! loop, forwards or backwards, with no recursion.

#[cfg(feature = "std")]
extern crate std;

/// What is inconsistent in a tree's layout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum TopologyError {
    /// A body's parent does not come before it (`parent[i] < i` fails).
    ParentAfterChild {
        /// The body.
        body: usize,
    },
    /// A joint with more than [`MAX_JOINT_NV`](crate::joint::MAX_JOINT_NV)
    /// degrees of freedom.
    TooManyJointDofs {
        /// The body the joint moves.
        body: usize,
    },
    /// The joints' configuration coordinates do not add up to `NQ`.
    ConfigurationCount {
        /// The declared `NQ`.
        declared: usize,
        /// The joints' sum.
        found: usize,
    },
    /// The joints' velocity coordinates do not add up to `NV`.
    VelocityCount {
        /// The declared `NV`.
        declared: usize,
        /// The joints' sum.
        found: usize,
    },
}

impl TopologyError {
    /// Which check failed, without the counts (for
    /// [`ModelProblem::Topology`](crate::error::ModelProblem::Topology)).
    #[must_use]
    pub const fn problem(&self) -> crate::error::TopologyProblem {
        use crate::error::TopologyProblem as P;
        match self {
            Self::ParentAfterChild { .. } => P::ParentAfterChild,
            Self::TooManyJointDofs { .. } => P::TooManyJointDofs,
            Self::ConfigurationCount { .. } => P::ConfigurationCount,
            Self::VelocityCount { .. } => P::VelocityCount,
        }
    }

    /// A one-sentence explanation; also the compile error of a `const` model.
    #[must_use]
    pub const fn message(&self) -> &'static str {
        match self {
            Self::ParentAfterChild { .. } => {
                "rodyn model: every body's parent must come before it (parent[i] < i); reorder the bodies"
            }
            Self::TooManyJointDofs { .. } => {
                "rodyn model: a joint has more than 6 degrees of freedom"
            }
            Self::ConfigurationCount { .. } => {
                "rodyn model: the joints' configuration coordinates do not add up to NQ"
            }
            Self::VelocityCount { .. } => {
                "rodyn model: the joints' velocity coordinates do not add up to NV"
            }
        }
    }
}

impl core::fmt::Display for TopologyError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::ParentAfterChild { body } | Self::TooManyJointDofs { body } => {
                write!(f, "{} (body {body})", self.message())
            }
            Self::ConfigurationCount { declared, found }
            | Self::VelocityCount { declared, found } => {
                write!(
                    f,
                    "{} (declared {declared}, joints give {found})",
                    self.message()
                )
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for TopologyError {}

/// A checked tree: where each body's coordinates start, and the tree over
/// velocity coordinates.
///
/// Built only by [`Topology::try_new`] (or [`Topology::new`]), and never
/// changed afterwards: its tables are read through
/// [`Deref`](core::ops::Deref) to [`TopologyTables`], which gives no way
/// to write them. Every `Topology` therefore keeps what `try_new` checked,
/// and the index accessors ([`Self::velocity_range`], [`Self::parent`], ...)
/// tell the optimiser so; the algorithms then index the model's vectors
/// without bounds checks that it could not otherwise remove.
///
/// ```compile_fail
/// use rodyn::topology::Topology;
/// let mut t = Topology::<2, 2>::new([None, Some(0)], [1; 2], [1; 2], 2);
/// t.idx_v[1] = 5; // the tables cannot be written
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Topology<const NB: usize, const NV: usize> {
    tables: TopologyTables<NB, NV>,
}

/// The index tables of a [`Topology`], read through it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TopologyTables<const NB: usize, const NV: usize> {
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
    /// The last coordinate that coordinate k supports (k itself at a leaf).
    /// In a [`depth_first`](Self::depth_first) tree the coordinates k
    /// supports are exactly `k ..= last_supported_v[k]`.
    pub last_supported_v: [usize; NV],
    /// Whether every coordinate's descendants follow it without a gap, as
    /// they do when the bodies are numbered depth first (URDF order).
    /// Otherwise `k ..= last_supported_v[k]` also holds coordinates on
    /// other branches.
    pub depth_first: bool,
    /// One past the last coordinate of body i's subtree (its own and its
    /// descendants'). When [`subtrees_contiguous`](Self::subtrees_contiguous),
    /// the subtree's coordinates are `idx_v[i]..subtree_end_v[i]`.
    pub subtree_end_v: [usize; NB],
    /// Whether every body's subtree holds a contiguous range of
    /// coordinates, as when the bodies are numbered depth first (URDF
    /// order). CRBA walks such ranges as slices.
    pub subtrees_contiguous: bool,
    /// The mean number of moving bodies (bodies with coordinates) that
    /// support a coordinate's body, over the coordinates, rounded down: 0
    /// for a single joint, `(n - 1) / 2` for a chain of n links. CRBA
    /// chooses its backward pass by it.
    pub mean_support_depth: usize,
    /// The configuration coordinates of all joints (the model's `NQ`).
    pub nq_total: usize,
}

impl<const NB: usize, const NV: usize> core::ops::Deref for Topology<NB, NV> {
    type Target = TopologyTables<NB, NV>;
    #[inline(always)]
    fn deref(&self) -> &TopologyTables<NB, NV> {
        &self.tables
    }
}

impl<const NB: usize, const NV: usize> Topology<NB, NV> {
    /// Lays out the coordinates of a tree and checks it; a `const` evaluation
    /// of an inconsistent tree fails to compile with the panic's message.
    /// For trees built at run time (from a file, say), use [`Self::try_new`].
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
        match Self::try_new(parents, nq, nv, nq_total) {
            Ok(topology) => topology,
            Err(error) => panic!("{}", error.message()),
        }
    }

    /// Lays out the coordinates of a tree, or says what is inconsistent.
    ///
    /// `parents[i]` is body i's parent (`None`: the world), `nq[i]` and
    /// `nv[i]` its joint's coordinate counts, `nq_total` the model's `NQ`.
    ///
    /// # Errors
    /// The first [`TopologyError`] found, naming the body where it applies.
    pub const fn try_new(
        parents: [Option<usize>; NB],
        nq: [usize; NB],
        nv: [usize; NB],
        nq_total: usize,
    ) -> Result<Self, TopologyError> {
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
                    return Err(TopologyError::ParentAfterChild { body: i });
                }
            }
            if nv[i] > crate::joint::MAX_JOINT_NV {
                return Err(TopologyError::TooManyJointDofs { body: i });
            }
            // Checked before the sum, which must not wrap: `idx_q[i] +
            // nq[i] <= nq_total` is what the accessors promise.
            if nq[i] > nq_total - q {
                return Err(TopologyError::ConfigurationCount {
                    declared: nq_total,
                    found: configuration_count(&nq),
                });
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
                    return Err(TopologyError::VelocityCount {
                        declared: NV,
                        found: velocity_count(&nv),
                    });
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
            return Err(TopologyError::ConfigurationCount {
                declared: nq_total,
                found: q,
            });
        }
        if v != NV {
            return Err(TopologyError::VelocityCount {
                declared: NV,
                found: v,
            });
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
        // Leaves to root: a coordinate's λ has already received everything
        // its own descendants pass up.
        let mut last_supported_v = [0; NV];
        let mut supported_count = [1; NV];
        let mut k = NV;
        while k > 0 {
            k -= 1;
            if last_supported_v[k] < k {
                last_supported_v[k] = k;
            }
            if let Some(l) = lambda_v[k] {
                if last_supported_v[l] < last_supported_v[k] {
                    last_supported_v[l] = last_supported_v[k];
                }
                supported_count[l] += supported_count[k];
            }
        }
        let mut depth_first = true;
        let mut k = 0;
        while k < NV {
            depth_first &= last_supported_v[k] - k + 1 == supported_count[k];
            k += 1;
        }
        // Leaves to root again, over bodies: each subtree's last coordinate
        // and its count of coordinates, which a contiguous range matches.
        let mut subtree_end_v = [0; NB];
        let mut subtree_count = [0; NB];
        let mut i = 0;
        while i < NB {
            subtree_end_v[i] = idx_v[i] + nv[i];
            subtree_count[i] = nv[i];
            i += 1;
        }
        let mut subtrees_contiguous = true;
        let mut i = NB;
        while i > 0 {
            i -= 1;
            subtrees_contiguous &= subtree_end_v[i] - idx_v[i] == subtree_count[i];
            if let Some(p) = parents[i] {
                if subtree_end_v[p] < subtree_end_v[i] {
                    subtree_end_v[p] = subtree_end_v[i];
                }
                subtree_count[p] += subtree_count[i];
            }
        }
        // Moving bodies strictly above each body, summed over coordinates.
        let mut moving_ancestors = [0; NB];
        let mut depth_sum = 0;
        let mut i = 0;
        while i < NB {
            if let Some(p) = parents[i] {
                moving_ancestors[i] = moving_ancestors[p] + if nv[p] > 0 { 1 } else { 0 };
            }
            depth_sum += nv[i] * moving_ancestors[i];
            i += 1;
        }
        Ok(Self {
            tables: TopologyTables {
                parents,
                idx_q,
                nq,
                idx_v,
                nv,
                lambda_v,
                body_of_v,
                chain_start_v,
                last_supported_v,
                depth_first,
                subtree_end_v,
                subtrees_contiguous,
                mean_support_depth: match depth_sum.checked_div(NV) {
                    Some(mean) => mean,
                    None => 0,
                },
                nq_total,
            },
        })
    }

    /// The tables, for `const` code (which cannot go through `Deref`).
    #[must_use]
    pub const fn tables(&self) -> &TopologyTables<NB, NV> {
        &self.tables
    }

    /// Body `i`'s first velocity coordinate and their count, `(idx_v[i],
    /// nv[i])`, with `idx_v[i] + nv[i] <= NV` known to the optimiser.
    #[must_use]
    #[inline(always)]
    pub const fn velocity_range(&self, i: usize) -> (usize, usize) {
        let (iv, nv) = (self.tables.idx_v[i], self.tables.nv[i]);
        // SAFETY: `try_new`, the only constructor, stops with an error
        // unless `v + nv[i] <= NV` for every joint, `idx_v[i] = v` the sum
        // of the joints before it (no wrap); the tables cannot be changed
        // afterwards. Tested in `every_small_tree_keeps_its_promises`.
        unsafe {
            core::hint::assert_unchecked(iv <= NV && nv <= NV - iv && iv.unchecked_add(nv) <= NV);
        }
        (iv, nv)
    }

    /// Body `i`'s velocity coordinates, `idx_v[i]..idx_v[i] + nv[i]`, with
    /// the end known to the optimiser to be at most `NV`.
    #[must_use]
    #[inline(always)]
    pub const fn velocity_coordinates(&self, i: usize) -> core::ops::Range<usize> {
        let (iv, nv) = self.velocity_range(i);
        let end = iv + nv;
        // SAFETY: as in `velocity_range`, of which this is the sum.
        unsafe { core::hint::assert_unchecked(iv <= end && end <= NV) };
        iv..end
    }

    /// [`Self::velocity_range`], with `nv[i] <= MAX_JOINT_NV` also known to
    /// the optimiser, for code that keeps a joint's rows in buffers of
    /// that length. (Not in `velocity_range` itself: the bound lets loops
    /// over a joint's coordinates unroll, which cost some callers
    /// instructions on the Cortex-M4.)
    #[must_use]
    #[inline(always)]
    pub const fn joint_velocity_range(&self, i: usize) -> (usize, usize) {
        let (iv, nv) = self.velocity_range(i);
        // SAFETY: `try_new` refuses a joint with more than `MAX_JOINT_NV`
        // velocity coordinates; the tables cannot be changed afterwards.
        unsafe { core::hint::assert_unchecked(nv <= crate::joint::MAX_JOINT_NV) };
        (iv, nv)
    }

    /// Body `i`'s first configuration coordinate and their count,
    /// `(idx_q[i], nq[i])`, with `idx_q[i] + nq[i] <= nq_total` known to
    /// the optimiser.
    #[must_use]
    #[inline(always)]
    pub const fn configuration_range(&self, i: usize) -> (usize, usize) {
        let (iq, nq) = (self.tables.idx_q[i], self.tables.nq[i]);
        // SAFETY: `try_new` refuses a joint with `nq[i] > nq_total - q`,
        // `q = idx_q[i]` the sum of the joints before it, and `q` never
        // exceeds `nq_total`; the tables cannot be changed afterwards.
        unsafe {
            core::hint::assert_unchecked(
                iq <= self.tables.nq_total && nq <= self.tables.nq_total - iq,
            );
        }
        (iq, nq)
    }

    /// Featherstone's λ of velocity coordinate `k`, known to the optimiser
    /// to come before `k`.
    #[must_use]
    #[inline(always)]
    pub const fn lambda(&self, k: usize) -> Option<usize> {
        let lambda = self.tables.lambda_v[k];
        if let Some(l) = lambda {
            // SAFETY: `try_new` sets `lambda_v[k]` to `None`, to `k - 1`, or
            // to the last coordinate of a body before k's (all smaller than
            // k); the tables cannot be changed afterwards.
            unsafe { core::hint::assert_unchecked(l < k) };
        }
        lambda
    }

    /// Where the unbroken stretch of λ ending at coordinate `k` starts
    /// (`chain_start_v[k]`), known to the optimiser to be at most `k`.
    #[must_use]
    #[inline(always)]
    pub const fn chain_start(&self, k: usize) -> usize {
        let start = self.tables.chain_start_v[k];
        // SAFETY: `try_new` sets `chain_start_v[k]` to `k` or to the chain
        // start of `lambda_v[k] = k - 1`, by induction at most `k`; the
        // tables cannot be changed afterwards.
        unsafe { core::hint::assert_unchecked(start <= k) };
        start
    }

    /// The last coordinate that coordinate `k` supports
    /// (`last_supported_v[k]`), known to the optimiser to lie in `k..NV`.
    #[must_use]
    #[inline(always)]
    pub const fn last_supported(&self, k: usize) -> usize {
        let last = self.tables.last_supported_v[k];
        // SAFETY: `try_new` starts every entry at least at its own
        // coordinate and raises it only to coordinates (below `NV`); the
        // tables cannot be changed afterwards.
        unsafe { core::hint::assert_unchecked(k <= last && last < NV) };
        last
    }

    /// One past the last coordinate of body `i`'s subtree
    /// (`subtree_end_v[i]`), known to the optimiser to lie in
    /// `idx_v[i] + nv[i] ..= NV`.
    #[must_use]
    #[inline(always)]
    pub const fn subtree_end(&self, i: usize) -> usize {
        let end = self.tables.subtree_end_v[i];
        let (iv, nv) = self.velocity_range(i);
        // SAFETY: `try_new` starts `subtree_end_v[i]` at `idx_v[i] + nv[i]`
        // and raises it only to children's ends (at most `NV`); the tables
        // cannot be changed afterwards.
        unsafe { core::hint::assert_unchecked(iv + nv <= end && end <= NV) };
        end
    }

    /// Body `i`'s parent, known to the optimiser to come before it.
    #[must_use]
    #[inline(always)]
    pub const fn parent(&self, i: usize) -> Option<usize> {
        let parent = self.tables.parents[i];
        if let Some(p) = parent {
            // SAFETY: `try_new` refuses a parent that is not smaller than
            // its child; the tables cannot be changed afterwards.
            unsafe { core::hint::assert_unchecked(p < i) };
        }
        parent
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
            // A body past the end has no parents (a caller's index).
            b = self.parents.get(i).copied().flatten();
        }
        false
    }
}

/// The bodies that support a body, root first and the body itself last
/// (Featherstone's κ⁻¹ path, the bodies whose joints move it): from
/// [`Topology::support_path`]. Held in a fixed array of `NB` (a path has
/// at most `NB` bodies), so that finding it allocates nothing and a
/// `const` evaluation can store it for a frame known when compiling.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SupportPath<const NB: usize> {
    /// `bodies[..len]`: increasing, each the parent of the next.
    bodies: [usize; NB],
    len: usize,
}

impl<const NB: usize> SupportPath<NB> {
    /// The path's bodies, root first; each below `NB` and the parent of the
    /// next.
    #[must_use]
    #[inline(always)]
    pub const fn bodies(&self) -> &[usize] {
        // `len <= NB` (`support_path`, the only constructor): the split
        // never fails.
        match self.bodies.split_at_checked(self.len) {
            Some((path, _)) => path,
            None => &[],
        }
    }

    /// The number of bodies on the path (at least 1: the body itself).
    #[must_use]
    #[inline(always)]
    pub const fn len(&self) -> usize {
        self.len
    }

    /// Always `false`: a path holds at least its own body.
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The body the path leads to (its last), known to the optimiser to
    /// be below `NB`.
    #[must_use]
    #[inline(always)]
    pub fn body(&self) -> usize {
        // A path is never empty (`support_path`); 0 is never returned.
        self.get(self.len.wrapping_sub(1)).unwrap_or(0)
    }

    /// The `k`-th body from the root (`None` past the path's end), known
    /// to the optimiser to be below `NB`.
    #[must_use]
    #[inline(always)]
    pub fn get(&self, k: usize) -> Option<usize> {
        let b = *self.bodies().get(k)?;
        // SAFETY: `support_path`, the only constructor, stores body indices
        // below `NB` only (it starts at a body below `NB` and follows
        // parents, which come before their children); the fields cannot
        // be changed afterwards.
        unsafe { core::hint::assert_unchecked(b < NB) };
        Some(b)
    }

    /// The path's bodies, root first, each known to the optimiser to be
    /// below `NB` (so that indexing `NB`-long arrays by them needs no
    /// check).
    #[inline(always)]
    pub fn iter(&self) -> impl Iterator<Item = usize> + '_ {
        self.bodies().iter().map(|&b| {
            // SAFETY: as in `get`.
            unsafe { core::hint::assert_unchecked(b < NB) };
            b
        })
    }
}

impl<const NB: usize, const NV: usize> Topology<NB, NV> {
    /// The bodies that support `body`, root first, `body` last (see
    /// [`SupportPath`]); `None` when `body` is not below `NB`. `const`, so
    /// that a frame known when compiling can keep its path in a constant.
    #[must_use]
    pub const fn support_path(&self, body: usize) -> Option<SupportPath<NB>> {
        if body >= NB {
            return None;
        }
        // Parents come before children: the walk ends within NB steps
        // (the tests on `i` and `k`, always true, keep the walk free of
        // bounds checks).
        let mut len = 0;
        let mut b = Some(body);
        while let Some(i) = b {
            if i >= NB || len >= NB {
                return None;
            }
            len += 1;
            b = self.tables.parents[i];
        }
        let mut bodies = [0; NB];
        let mut k = len;
        let mut b = Some(body);
        while let Some(i) = b {
            if i >= NB || k == 0 {
                break;
            }
            k -= 1;
            if k < NB {
                bodies[k] = i;
            }
            b = self.tables.parents[i];
        }
        Some(SupportPath { bodies, len })
    }
}

/// The sum of the joints' configuration coordinates, for error reports
/// (saturating: a count near `usize::MAX` must not wrap).
const fn configuration_count<const NB: usize>(nq: &[usize; NB]) -> usize {
    let (mut sum, mut i) = (0usize, 0);
    while i < NB {
        sum = sum.saturating_add(nq[i]);
        i += 1;
    }
    sum
}

/// The sum of the joints' velocity coordinates, for error reports.
const fn velocity_count<const NB: usize>(nv: &[usize; NB]) -> usize {
    let (mut sum, mut i) = (0, 0);
    while i < NB {
        sum += nv[i];
        i += 1;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::{SupportPath, Topology, TopologyError};
    use crate::joint::MAX_JOINT_NV;

    /// What the algorithms rely on to reach every index without a panic
    /// path (and report `ModelProblem::InconsistentTopology` otherwise):
    /// parents precede children, each joint's coordinates lie within
    /// `q` and `v`, and no joint has more than `MAX_JOINT_NV` of them.
    fn assert_fits<const NB: usize, const NV: usize>(t: &Topology<NB, NV>, nq_total: usize) {
        assert_eq!(t.nq_total, nq_total);
        for i in 0..NB {
            if let Some(p) = t.parents[i] {
                assert!(p < i, "body {i}: parent {p}");
            }
            // What the accessors state to the optimiser, without wrapping.
            assert!(
                t.idx_q[i]
                    .checked_add(t.nq[i])
                    .is_some_and(|end| end <= nq_total),
                "body {i}: q"
            );
            assert!(
                t.idx_v[i].checked_add(t.nv[i]).is_some_and(|end| end <= NV),
                "body {i}: v"
            );
            assert!(t.nv[i] <= MAX_JOINT_NV, "body {i}: nv");
        }
        for i in 0..NB {
            let end = t.subtree_end_v[i];
            assert!(
                t.idx_v[i] + t.nv[i] <= end && end <= NV,
                "body {i}: subtree"
            );
        }
        for k in 0..NV {
            assert!(t.body_of_v[k] < NB);
            assert!(t.chain_start_v[k] <= k);
            assert!(k <= t.last_supported_v[k] && t.last_supported_v[k] < NV);
            if let Some(l) = t.lambda_v[k] {
                assert!(l < k);
            }
        }
    }

    #[test]
    fn try_new_keeps_every_index_in_range() {
        // A chain of revolute joints.
        let chain = Topology::<4, 4>::try_new([None, Some(0), Some(1), Some(2)], [1; 4], [1; 4], 4);
        assert_fits(&chain.unwrap(), 4);
        // A free-flyer trunk with two legs, a fixed sensor at the end (nq ≠ nv, nv = 0).
        let legs = Topology::<6, 10>::try_new(
            [None, Some(0), Some(1), Some(0), Some(3), Some(4)],
            [7, 1, 1, 1, 1, 0],
            [6, 1, 1, 1, 1, 0],
            11,
        );
        assert_fits(&legs.unwrap(), 11);
        // Only fixed joints: no coordinates at all.
        let fixed = Topology::<2, 0>::try_new([None, Some(0)], [0; 2], [0; 2], 0);
        assert_fits(&fixed.unwrap(), 0);
        // And what it refuses.
        assert!(matches!(
            Topology::<2, 2>::try_new([Some(1), None], [1; 2], [1; 2], 2),
            Err(TopologyError::ParentAfterChild { body: 0 })
        ));
        assert!(matches!(
            Topology::<1, 7>::try_new([None], [7], [7], 7),
            Err(TopologyError::TooManyJointDofs { body: 0 })
        ));
        assert!(Topology::<2, 2>::try_new([None, Some(0)], [1; 2], [1; 2], 3).is_err());
        assert!(Topology::<2, 3>::try_new([None, Some(0)], [1; 2], [1; 2], 2).is_err());
    }

    /// Every table `try_new` accepts keeps the promises of
    /// `velocity_range`, `configuration_range` and `parent` (which tell
    /// the optimiser so, in `unsafe`): all trees of three bodies, with
    /// parents before, at and after each body, and coordinate counts
    /// around the limits, including counts that would wrap a sum.
    #[test]
    fn every_small_tree_keeps_its_promises() {
        fn sweep<const NV: usize>() -> usize {
            let parent_choices = [None, Some(0), Some(1), Some(2)];
            let nv_choices = [0, 1, 6, 7];
            let nq_choices = [0, 1, 7, usize::MAX - 1];
            let totals = [0, 2, 8, usize::MAX];
            let mut accepted = 0;
            // Every combination of the four choices (2²⁰ of them); under
            // Miri a sample spread over them all (an odd stride mixes the
            // digits), in which each size still accepts some trees.
            for n in (0..1usize << 20).step_by(crate::test_points(1, 211)) {
                let (p, v, q) = (n & 63, (n >> 6) & 63, (n >> 12) & 63);
                let nq_total = totals[n >> 18];
                let parents = [0, 1, 2].map(|k| parent_choices[(p >> (2 * k)) & 3]);
                let nv = [0, 1, 2].map(|k| nv_choices[(v >> (2 * k)) & 3]);
                let nq = [0, 1, 2].map(|k| nq_choices[(q >> (2 * k)) & 3]);
                if let Ok(t) = Topology::<3, NV>::try_new(parents, nq, nv, nq_total) {
                    assert_fits(&t, nq_total);
                    for i in 0..3 {
                        assert_eq!(t.velocity_range(i), (t.idx_v[i], t.nv[i]));
                        assert_eq!(t.joint_velocity_range(i), t.velocity_range(i));
                        assert_eq!(t.velocity_coordinates(i), t.idx_v[i]..t.idx_v[i] + t.nv[i]);
                        assert_eq!(t.configuration_range(i), (t.idx_q[i], t.nq[i]));
                        assert_eq!(t.parent(i), t.parents[i]);
                        assert_eq!(t.subtree_end(i), t.subtree_end_v[i]);
                    }
                    for k in 0..NV {
                        assert_eq!(t.lambda(k), t.lambda_v[k]);
                        assert_eq!(t.chain_start(k), t.chain_start_v[k]);
                        assert_eq!(t.last_supported(k), t.last_supported_v[k]);
                    }
                    accepted += 1;
                }
            }
            accepted
        }
        // Each size accepts some trees (the sweep is not vacuous).
        assert!(sweep::<0>() > 0);
        assert!(sweep::<2>() > 0);
        assert!(sweep::<7>() > 0);
        assert!(sweep::<13>() > 0);
    }

    /// The support path of every body of a branched tree is its chain of
    /// parents, root first; a body past the end has none.
    #[test]
    fn support_paths_follow_the_parents() {
        let parents = [
            None,
            Some(0),
            Some(1),
            Some(0),
            Some(3),
            Some(4),
            None,
            Some(6),
        ];
        let t = Topology::<8, 8>::new(parents, [1; 8], [1; 8], 8);
        let expected: [&[usize]; 8] = [
            &[0],
            &[0, 1],
            &[0, 1, 2],
            &[0, 3],
            &[0, 3, 4],
            &[0, 3, 4, 5],
            &[6],
            &[6, 7],
        ];
        for (body, path) in expected.iter().enumerate() {
            let p = t.support_path(body).unwrap();
            assert_eq!(p.bodies(), *path, "body {body}");
            assert_eq!((p.len(), p.body(), p.is_empty()), (path.len(), body, false));
            assert_eq!(p.get(p.len()), None);
            for b in p.bodies() {
                assert!(t.supports(*b, body));
            }
        }
        assert_eq!(t.support_path(8), None);
        // Known when compiling.
        const PATH: Option<SupportPath<3>> =
            Topology::<3, 3>::new([None, Some(0), Some(0)], [1; 3], [1; 3], 3).support_path(2);
        assert_eq!(PATH.unwrap().bodies(), &[0, 2]);
    }

    #[test]
    fn last_supported_and_depth_first() {
        // 0 ─ 1 ─ 2, 0 ─ 3: depth first.
        let t = Topology::<4, 4>::new([None, Some(0), Some(1), Some(0)], [1; 4], [1; 4], 4);
        assert_eq!(t.last_supported_v, [3, 2, 2, 3]);
        assert!(t.depth_first);
        // 0 ─ 1 ─ 3, 0 ─ 2: coordinate 2 sits inside 1's range.
        let t = Topology::<4, 4>::new([None, Some(0), Some(0), Some(1)], [1; 4], [1; 4], 4);
        assert_eq!(t.last_supported_v, [3, 3, 2, 3]);
        assert!(!t.depth_first);
        // Two roots, a two-coordinate joint on the second.
        let t = Topology::<3, 4>::new([None, None, Some(1)], [1, 2, 1], [1, 2, 1], 4);
        assert_eq!(t.last_supported_v, [0, 3, 3, 3]);
        assert!(t.depth_first);
    }

    #[test]
    fn subtrees_are_contiguous_when_numbered_depth_first() {
        // 0 ─ 1 ─ 2, 0 ─ 3.
        let t = Topology::<4, 4>::new([None, Some(0), Some(1), Some(0)], [1; 4], [1; 4], 4);
        assert_eq!(t.subtree_end_v, [4, 3, 3, 4]);
        assert!(t.subtrees_contiguous);
        // 0 ─ 1 ─ 3, 0 ─ 2: body 1's subtree holds coordinates 1 and 3.
        let t = Topology::<4, 4>::new([None, Some(0), Some(0), Some(1)], [1; 4], [1; 4], 4);
        assert!(!t.subtrees_contiguous);
        // A fixed body (no coordinate) between two branches of the same
        // parent: its subtree is empty here but the parent's stays whole.
        let t = Topology::<4, 3>::new(
            [None, Some(0), Some(0), Some(0)],
            [1, 1, 0, 1],
            [1, 1, 0, 1],
            3,
        );
        assert_eq!(t.subtree_end_v, [3, 2, 2, 3]);
        assert!(t.subtrees_contiguous);
    }

    #[test]
    fn mean_support_depth_counts_moving_ancestors() {
        // A chain of 7: 0 + 1 + ... + 6 = 21 over 7 coordinates.
        let chain = Topology::<7, 7>::new(
            core::array::from_fn(|i| i.checked_sub(1)),
            [1; 7],
            [1; 7],
            7,
        );
        assert_eq!(chain.mean_support_depth, 3);
        // Fixed bodies on the way are not counted: body 4 has one moving
        // ancestor, not four; depths 0 and 1, a mean of 0.
        let t = Topology::<5, 2>::new(
            [None, Some(0), Some(1), Some(2), Some(3)],
            [1, 0, 0, 0, 1],
            [1, 0, 0, 0, 1],
            2,
        );
        assert_eq!(t.mean_support_depth, 0);
    }
}
