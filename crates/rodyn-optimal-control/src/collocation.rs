//! Trapezoidal direct collocation (Betts, *Practical Methods for Optimal
//! Control*, 2010, §4.5; von Stryk's DIRCOL, the paper's tool, offers it
//! beside Hermite-Simpson).
//!
//! The time grid `t_k = t_0 + k h`, `k = 0 … N`, carries the state `x_k`
//! and the control `u_k` at every node; controls are linear between nodes.
//! The variables are `z = [x_0, u_0, x_1, u_1, …, x_N, u_N]` and the
//! constraints the `N` defects
//!
//! ```text
//! c_k = x_{k+1} − x_k − h/2 (f(t_k, x_k, u_k) + f(t_{k+1}, x_{k+1}, u_{k+1})) = 0,
//! ```
//!
//! each depending on two nodes only, so the Jacobian is block-banded with
//! the blocks `−I − h/2 A_k`, `−h/2 B_k`, `I − h/2 A_{k+1}`, `−h/2 B_{k+1}`
//! from the state Jacobians `A = ∂f/∂x` and `B = ∂f/∂u`. The objective is
//!
//! ```text
//! J = ∫ (Σᵢ sᵢ xᵢ² + Σᵢ wᵢ uᵢ²) dt + Σᵢ rᵢ ∫ u̇ᵢ² dt
//! ```
//!
//! with the first integral by the trapezoidal rule and the control-rate
//! term as `Σ_k (u_{k+1} − u_k)² / h` (exact for controls linear between
//! nodes): quadratic weights on states, controls and control rates
//! ([`Weights`]).

use crate::ipopt::Nlp;

/// Relative step of the central differences of the Jacobians that form
/// [`Hessian::JacobianDifferences`].
const HESSIAN_STEP: f64 = 1e-6;

/// A controlled system `ẋ = f(t, x, u)` with its state Jacobians.
pub trait Dynamics<const NX: usize, const NU: usize> {
    /// `f(t, x, u)`, or `None` where it cannot be evaluated (a non-finite
    /// state, a singular model: the solver then shortens its step).
    fn rate(&mut self, t: f64, x: &[f64; NX], u: &[f64; NU]) -> Option<[f64; NX]>;

    /// `f` with `A = ∂f/∂x` (`a[i][j] = ∂fᵢ/∂xⱼ`) and `B = ∂f/∂u`.
    fn rate_and_jacobians(
        &mut self,
        t: f64,
        x: &[f64; NX],
        u: &[f64; NU],
        a: &mut [[f64; NX]; NX],
        b: &mut [[f64; NU]; NX],
    ) -> Option<[f64; NX]>;

    /// The exact second derivatives `∇²(μᵀ f)` with respect to `(x, u)`
    /// (a square matrix of side `NX + NU`, rows and columns in `(x, u)`
    /// order) for the weights `μ`: what [`Hessian::Exact`] asks for.
    /// `None` where they cannot be evaluated. The default has none, so a
    /// system without it fails at IPOPT's first Hessian evaluation under
    /// [`Hessian::Exact`].
    fn weighted_second_derivatives(
        &mut self,
        _t: f64,
        _x: &[f64; NX],
        _u: &[f64; NU],
        _mu: &[f64; NX],
    ) -> Option<Vec<Vec<f64>>> {
        None
    }
}

/// Bounds of one node's state and control; `±f64::INFINITY` for none,
/// equal bounds to fix a value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NodeBounds<const NX: usize, const NU: usize> {
    /// Lower bounds of `x`.
    pub x_lower: [f64; NX],
    /// Upper bounds of `x`.
    pub x_upper: [f64; NX],
    /// Lower bounds of `u`.
    pub u_lower: [f64; NU],
    /// Upper bounds of `u`.
    pub u_upper: [f64; NU],
}

/// One node's state and control.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node<const NX: usize, const NU: usize> {
    /// Time, s.
    pub t: f64,
    /// State.
    pub x: [f64; NX],
    /// Control.
    pub u: [f64; NU],
}

/// The objective's weights (see the module's documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Weights<const NX: usize, const NU: usize> {
    /// `sᵢ`, on the squared states.
    pub state: [f64; NX],
    /// `wᵢ`, on the squared controls.
    pub control: [f64; NU],
    /// `rᵢ`, on the squared control rates.
    pub control_rate: [f64; NU],
}

/// How IPOPT gets the Hessian of the Lagrangian.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hessian {
    /// IPOPT's limited-memory quasi-Newton (L-BFGS) approximation.
    QuasiNewton,
    /// The objective's exact Hessian plus the constraints' second
    /// derivatives by central differences of the state Jacobians `A`, `B`
    /// (each node's 12 × 12 block from `2 (NX + NU)` Jacobian evaluations):
    /// second-order information at first-order cost per entry.
    JacobianDifferences,
    /// The objective's exact Hessian plus the constraints' exact second
    /// derivatives from [`Dynamics::weighted_second_derivatives`].
    Exact,
}

/// The transcription of one optimal-control problem: `nodes` nodes
/// (`N = nodes − 1` intervals) on `[t0, t1]`, the bounds and the initial
/// guess of each node, and the objective's [`Weights`].
pub struct Trapezoidal<D, const NX: usize, const NU: usize> {
    /// The system.
    pub dynamics: D,
    /// Node times (uniform).
    pub times: Vec<f64>,
    /// Per-node bounds.
    pub bounds: Vec<NodeBounds<NX, NU>>,
    /// Per-node initial guess.
    pub guess: Vec<Node<NX, NU>>,
    /// The objective's weights.
    pub weights: Weights<NX, NU>,
    /// How the Hessian of the Lagrangian is formed.
    pub hessian: Hessian,
    /// `f`, `A`, `B` at each node for the last `z` evaluated, so that the
    /// constraints and their Jacobian at one iterate share one pass.
    cache: Cache<NX, NU>,
}

struct Cache<const NX: usize, const NU: usize> {
    z: Vec<f64>,
    with_jacobians: bool,
    f: Vec<[f64; NX]>,
    a: Vec<[[f64; NX]; NX]>,
    b: Vec<[[f64; NU]; NX]>,
}

impl<D: Dynamics<NX, NU>, const NX: usize, const NU: usize> Trapezoidal<D, NX, NU> {
    /// Width of one node's block of variables.
    pub const BLOCK: usize = NX + NU;

    /// A problem on `nodes` uniform nodes over `[t0, t1]`; `bounds` and
    /// `guess` give each node's bounds and initial guess from its time.
    ///
    /// # Panics
    /// With fewer than two nodes or `t1 ≤ t0` (a programming error of the
    /// caller, not a data error).
    pub fn new(
        dynamics: D,
        t0: f64,
        t1: f64,
        nodes: usize,
        bounds: impl Fn(f64) -> NodeBounds<NX, NU>,
        guess: impl Fn(f64) -> Node<NX, NU>,
        weights: Weights<NX, NU>,
    ) -> Self {
        assert!(
            nodes >= 2 && t1 > t0,
            "collocation needs two nodes on a non-empty interval"
        );
        let h = (t1 - t0) / (nodes - 1) as f64;
        let times: Vec<f64> = (0..nodes).map(|k| t0 + h * k as f64).collect();
        Self {
            dynamics,
            bounds: times.iter().map(|&t| bounds(t)).collect(),
            guess: times.iter().map(|&t| guess(t)).collect(),
            times,
            weights,
            hessian: Hessian::QuasiNewton,
            cache: Cache {
                z: Vec::new(),
                with_jacobians: false,
                f: vec![[0.0; NX]; nodes],
                a: vec![[[0.0; NX]; NX]; nodes],
                b: vec![[[0.0; NU]; NX]; nodes],
            },
        }
    }

    /// Number of nodes.
    #[must_use]
    pub fn nodes(&self) -> usize {
        self.times.len()
    }

    /// The step `h`, s.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.times[1] - self.times[0]
    }

    /// The nodes held in a variable vector `z`.
    #[must_use]
    pub fn unpack(&self, z: &[f64]) -> Vec<Node<NX, NU>> {
        self.times
            .iter()
            .zip(z.chunks_exact(Self::BLOCK))
            .map(|(&t, block)| Node {
                t,
                x: core::array::from_fn(|i| block[i]),
                u: core::array::from_fn(|i| block[NX + i]),
            })
            .collect()
    }

    /// Trapezoidal quadrature weight of node `k`, times `h`.
    fn weight(&self, k: usize) -> f64 {
        let ends = k == 0 || k + 1 == self.nodes();
        self.step() * if ends { 0.5 } else { 1.0 }
    }

    /// Evaluates `f` (and `A`, `B` when asked) at every node of `z`, unless
    /// the cache already holds them.
    fn evaluate(&mut self, z: &[f64], with_jacobians: bool) -> bool {
        if self.cache.z == z && (self.cache.with_jacobians || !with_jacobians) {
            return true;
        }
        let nodes = self.unpack(z);
        for (k, node) in nodes.iter().enumerate() {
            let rate = if with_jacobians {
                self.dynamics.rate_and_jacobians(
                    node.t,
                    &node.x,
                    &node.u,
                    &mut self.cache.a[k],
                    &mut self.cache.b[k],
                )
            } else {
                self.dynamics.rate(node.t, &node.x, &node.u)
            };
            match rate {
                Some(f) if f.iter().all(|v| v.is_finite()) => self.cache.f[k] = f,
                _ => {
                    self.cache.z.clear();
                    return false;
                }
            }
        }
        self.cache.z.clear();
        self.cache.z.extend_from_slice(z);
        self.cache.with_jacobians = with_jacobians;
        true
    }

    /// `∇²(μᵀ f)` at node `k`'s variables `block = (x, u)`, by central
    /// differences of `[A B]ᵀ μ`; `None` where the dynamics fail.
    fn second_derivatives(
        &mut self,
        k: usize,
        block: &[f64],
        mu: &[f64; NX],
    ) -> Option<Vec<Vec<f64>>> {
        let t = self.times[k];
        let mut gradient = |point: &[f64]| -> Option<Vec<f64>> {
            let x: [f64; NX] = core::array::from_fn(|i| point[i]);
            let u: [f64; NU] = core::array::from_fn(|i| point[NX + i]);
            let (mut a, mut b) = ([[0.0; NX]; NX], [[0.0; NU]; NX]);
            self.dynamics
                .rate_and_jacobians(t, &x, &u, &mut a, &mut b)?;
            Some(
                (0..Self::BLOCK)
                    .map(|j| {
                        (0..NX)
                            .map(|i| mu[i] * if j < NX { a[i][j] } else { b[i][j - NX] })
                            .sum()
                    })
                    .collect(),
            )
        };
        let mut columns = Vec::with_capacity(Self::BLOCK);
        for m in 0..Self::BLOCK {
            let step = HESSIAN_STEP * block[m].abs().max(1.0);
            let (mut plus, mut minus) = (block.to_vec(), block.to_vec());
            plus[m] += step;
            minus[m] -= step;
            let (g_plus, g_minus) = (gradient(&plus)?, gradient(&minus)?);
            columns.push(
                g_plus
                    .iter()
                    .zip(&g_minus)
                    .map(|(p, q)| (p - q) / (2.0 * step))
                    .collect::<Vec<f64>>(),
            );
        }
        // columns[m][j] = ∂²/∂z_j∂z_m; returned as [row][column].
        Some(
            (0..Self::BLOCK)
                .map(|r| (0..Self::BLOCK).map(|c| columns[c][r]).collect())
                .collect(),
        )
    }

    /// The largest absolute defect `|c_k|∞` at `z`, or `None` where the
    /// dynamics cannot be evaluated.
    pub fn max_defect(&mut self, z: &[f64]) -> Option<f64> {
        let mut g = vec![0.0; self.constraints()];
        self.constraint_values(z, &mut g)
            .then(|| g.iter().fold(0.0_f64, |m, v| m.max(v.abs())))
    }
}

impl<D: Dynamics<NX, NU>, const NX: usize, const NU: usize> Nlp for Trapezoidal<D, NX, NU> {
    fn variables(&self) -> usize {
        self.nodes() * Self::BLOCK
    }

    fn constraints(&self) -> usize {
        (self.nodes() - 1) * NX
    }

    fn variable_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
        let blocks = lower
            .chunks_exact_mut(Self::BLOCK)
            .zip(upper.chunks_exact_mut(Self::BLOCK));
        for ((lower, upper), bounds) in blocks.zip(&self.bounds) {
            lower[..NX].copy_from_slice(&bounds.x_lower);
            lower[NX..].copy_from_slice(&bounds.u_lower);
            upper[..NX].copy_from_slice(&bounds.x_upper);
            upper[NX..].copy_from_slice(&bounds.u_upper);
        }
    }

    fn constraint_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
        lower.fill(0.0);
        upper.fill(0.0);
    }

    fn initial_point(&self, z: &mut [f64]) {
        for (block, node) in z.chunks_exact_mut(Self::BLOCK).zip(&self.guess) {
            block[..NX].copy_from_slice(&node.x);
            block[NX..].copy_from_slice(&node.u);
        }
    }

    fn objective(&mut self, z: &[f64]) -> Option<f64> {
        let w = &self.weights;
        let h = self.step();
        let blocks: Vec<&[f64]> = z.chunks_exact(Self::BLOCK).collect();
        let mut value = 0.0;
        for (k, block) in blocks.iter().enumerate() {
            let squares = |values: &[f64], weights: &[f64]| -> f64 {
                values.iter().zip(weights).map(|(v, w)| w * v * v).sum()
            };
            value += self.weight(k)
                * (squares(&block[..NX], &w.state) + squares(&block[NX..], &w.control));
            if let Some(next) = blocks.get(k + 1) {
                let rates: Vec<f64> = next[NX..]
                    .iter()
                    .zip(&block[NX..])
                    .map(|(b, a)| b - a)
                    .collect();
                value += squares(&rates, &w.control_rate) / h;
            }
        }
        Some(value)
    }

    fn objective_gradient(&mut self, z: &[f64], gradient: &mut [f64]) -> bool {
        let w = self.weights;
        let h = self.step();
        gradient.fill(0.0);
        for k in 0..self.nodes() {
            let weight = self.weight(k);
            let at = k * Self::BLOCK;
            for i in 0..NX {
                gradient[at + i] = 2.0 * weight * w.state[i] * z[at + i];
            }
            for i in 0..NU {
                gradient[at + NX + i] += 2.0 * weight * w.control[i] * z[at + NX + i];
                if k + 1 < self.nodes() {
                    let next = at + Self::BLOCK + NX + i;
                    let rate = 2.0 * w.control_rate[i] * (z[next] - z[at + NX + i]) / h;
                    gradient[next] += rate;
                    gradient[at + NX + i] -= rate;
                }
            }
        }
        true
    }

    fn constraint_values(&mut self, z: &[f64], g: &mut [f64]) -> bool {
        if !self.evaluate(z, false) {
            return false;
        }
        let half_h = 0.5 * self.step();
        let blocks: Vec<&[f64]> = z.chunks_exact(Self::BLOCK).collect();
        for (k, defect) in g.chunks_exact_mut(NX).enumerate() {
            let (x0, x1) = (&blocks[k][..NX], &blocks[k + 1][..NX]);
            let (f0, f1) = (&self.cache.f[k], &self.cache.f[k + 1]);
            for i in 0..NX {
                defect[i] = x1[i] - x0[i] - half_h * (f0[i] + f1[i]);
            }
        }
        true
    }

    fn jacobian_structure(&self) -> Vec<(usize, usize)> {
        // Interval k's rows against the two nodes' blocks, dense: row-major
        // over the 2 × (NX + NU) columns.
        let mut entries = Vec::with_capacity((self.nodes() - 1) * NX * 2 * Self::BLOCK);
        for k in 0..self.nodes() - 1 {
            for i in 0..NX {
                for j in 0..2 * Self::BLOCK {
                    entries.push((k * NX + i, k * Self::BLOCK + j));
                }
            }
        }
        entries
    }

    fn jacobian_values(&mut self, z: &[f64], values: &mut [f64]) -> bool {
        if !self.evaluate(z, true) {
            return false;
        }
        let half_h = 0.5 * self.step();
        let row_length = 2 * Self::BLOCK;
        for (k, rows) in values.chunks_exact_mut(NX * row_length).enumerate() {
            for (i, row) in rows.chunks_exact_mut(row_length).enumerate() {
                for (node, side) in [(k, -1.0), (k + 1, 1.0)] {
                    let offset = if node == k { 0 } else { Self::BLOCK };
                    let (a, b) = (&self.cache.a[node][i], &self.cache.b[node][i]);
                    for j in 0..NX {
                        let identity = if i == j { side } else { 0.0 };
                        row[offset + j] = identity - half_h * a[j];
                    }
                    for j in 0..NU {
                        row[offset + NX + j] = -half_h * b[j];
                    }
                }
            }
        }
        true
    }

    fn hessian_structure(&self) -> Option<Vec<(usize, usize)>> {
        if self.hessian == Hessian::QuasiNewton {
            return None;
        }
        // Each node's block (lower triangle), then the control-rate term's
        // coupling of u_{k+1, i} with u_{k, i}.
        let mut entries = Vec::new();
        for k in 0..self.nodes() {
            let at = k * Self::BLOCK;
            for r in 0..Self::BLOCK {
                for c in 0..=r {
                    entries.push((at + r, at + c));
                }
            }
        }
        for k in 0..self.nodes() - 1 {
            for i in 0..NU {
                let at = k * Self::BLOCK + NX + i;
                entries.push((at + Self::BLOCK, at));
            }
        }
        Some(entries)
    }

    // The block's entries read `second[r][c]` and `second[c][r]` to
    // symmetrise, which an iterator over one of them cannot express.
    #[allow(clippy::needless_range_loop)]
    fn hessian_values(
        &mut self,
        z: &[f64],
        sigma: f64,
        lambda: &[f64],
        values: &mut [f64],
    ) -> bool {
        let (w, h, nodes) = (self.weights, self.step(), self.nodes());
        let triangle = Self::BLOCK * (Self::BLOCK + 1) / 2;
        let (blocks, coupling) = values.split_at_mut(nodes * triangle);
        for (k, block) in blocks.chunks_exact_mut(triangle).enumerate() {
            // μ_k: the multipliers of the defects in which f at node k appears.
            let mut mu = [0.0; NX];
            for interval in [k.checked_sub(1), (k + 1 < nodes).then_some(k)]
                .into_iter()
                .flatten()
            {
                for (m, l) in mu
                    .iter_mut()
                    .zip(&lambda[interval * NX..(interval + 1) * NX])
                {
                    *m += l;
                }
            }
            let block_z = &z[k * Self::BLOCK..(k + 1) * Self::BLOCK];
            let second = if self.hessian == Hessian::Exact {
                let x: [f64; NX] = core::array::from_fn(|i| block_z[i]);
                let u: [f64; NU] = core::array::from_fn(|i| block_z[NX + i]);
                self.dynamics
                    .weighted_second_derivatives(self.times[k], &x, &u, &mu)
            } else {
                self.second_derivatives(k, block_z, &mu)
            };
            let Some(second) = second else {
                return false;
            };
            let mut entry = block.iter_mut();
            for r in 0..Self::BLOCK {
                for c in 0..=r {
                    let mut value = -0.5 * h * 0.5 * (second[r][c] + second[c][r]);
                    if r == c {
                        let weight = 2.0 * self.weight(k);
                        value += sigma
                            * if r < NX {
                                weight * w.state[r]
                            } else {
                                let i = r - NX;
                                let pairs = f64::from(u8::from(k > 0) + u8::from(k + 1 < nodes));
                                weight * w.control[i] + pairs * 2.0 * w.control_rate[i] / h
                            };
                    }
                    if let Some(slot) = entry.next() {
                        *slot = value;
                    }
                }
            }
        }
        for (slot, i) in coupling.iter_mut().zip((0..NU).cycle()) {
            *slot = -sigma * 2.0 * w.control_rate[i] / h;
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ipopt::{solve, Options};

    /// A double integrator `ẍ = u` driven from rest at 0 to rest at 1 in
    /// 1 s with the least `∫ u² dt`: the optimum is `u = 6 − 12 t`, cost 12.
    struct DoubleIntegrator;

    impl Dynamics<2, 1> for DoubleIntegrator {
        fn rate(&mut self, _: f64, x: &[f64; 2], u: &[f64; 1]) -> Option<[f64; 2]> {
            Some([x[1], u[0]])
        }
        fn rate_and_jacobians(
            &mut self,
            t: f64,
            x: &[f64; 2],
            u: &[f64; 1],
            a: &mut [[f64; 2]; 2],
            b: &mut [[f64; 1]; 2],
        ) -> Option<[f64; 2]> {
            *a = [[0.0, 1.0], [0.0, 0.0]];
            *b = [[0.0], [1.0]];
            self.rate(t, x, u)
        }
    }

    #[test]
    fn minimum_effort_double_integrator() {
        let free = NodeBounds {
            x_lower: [f64::NEG_INFINITY; 2],
            x_upper: [f64::INFINITY; 2],
            u_lower: [f64::NEG_INFINITY],
            u_upper: [f64::INFINITY],
        };
        let nodes = 41;
        let mut problem = Trapezoidal::new(
            DoubleIntegrator,
            0.0,
            1.0,
            nodes,
            |t| {
                let fixed = |x: [f64; 2]| NodeBounds {
                    x_lower: x,
                    x_upper: x,
                    ..free
                };
                if t == 0.0 {
                    fixed([0.0, 0.0])
                } else if (t - 1.0).abs() < 1e-12 {
                    fixed([1.0, 0.0])
                } else {
                    free
                }
            },
            |t| Node {
                t,
                x: [t, 0.0],
                u: [0.0],
            },
            Weights {
                state: [0.0; 2],
                control: [1.0],
                control_rate: [0.0],
            },
        );
        let solution = solve(&mut problem, &Options::default()).unwrap();
        assert!(solution.status.converged(), "{:?}", solution.status);
        assert!(problem.max_defect(&solution.x).unwrap() < 1e-9);
        // The discrete optimum's control is off by O(h²) inside the
        // interval (1.4e-2 at most, h = 0.025 s); the two end nodes, which
        // one defect each constrains, carry an O(h) error (0.14).
        let nodes = problem.unpack(&solution.x);
        for (k, node) in nodes.iter().enumerate() {
            let exact = 6.0 - 12.0 * node.t;
            let bound = if k == 0 || k + 1 == nodes.len() {
                0.2
            } else {
                2e-2
            };
            let error = (node.u[0] - exact).abs();
            assert!(
                error < bound,
                "u({}) = {} against {exact}",
                node.t,
                node.u[0]
            );
        }
        // The discrete cost is 12.03 (the end nodes' O(h) error).
        assert!(
            (solution.objective - 12.0).abs() < 5e-2,
            "cost {}",
            solution.objective
        );
    }

    /// The objective's gradient against central differences, every weight
    /// non-zero.
    #[test]
    fn objective_gradient_matches_differences() {
        let mut problem = Trapezoidal::new(
            DoubleIntegrator,
            0.0,
            1.0,
            6,
            |_| NodeBounds {
                x_lower: [f64::NEG_INFINITY; 2],
                x_upper: [f64::INFINITY; 2],
                u_lower: [f64::NEG_INFINITY],
                u_upper: [f64::INFINITY],
            },
            |t| Node {
                t,
                x: [t.sin(), t.cos()],
                u: [3.0 * t * t - 1.0],
            },
            Weights {
                state: [0.7, 1.3],
                control: [2.0],
                control_rate: [0.4],
            },
        );
        let mut z = vec![0.0; problem.variables()];
        problem.initial_point(&mut z);
        let mut gradient = vec![0.0; z.len()];
        assert!(problem.objective_gradient(&z, &mut gradient));
        for j in 0..z.len() {
            let (mut plus, mut minus) = (z.clone(), z.clone());
            plus[j] += 1e-6;
            minus[j] -= 1e-6;
            let difference =
                (problem.objective(&plus).unwrap() - problem.objective(&minus).unwrap()) / 2e-6;
            assert!(
                (gradient[j] - difference).abs() < 1e-7,
                "{j}: {} against {difference}",
                gradient[j]
            );
        }
    }

    /// A pendulum `θ̈ = −sin θ + u`: nonlinear, so the constraints have
    /// second derivatives.
    struct Pendulum;

    impl Dynamics<2, 1> for Pendulum {
        fn rate(&mut self, _: f64, x: &[f64; 2], u: &[f64; 1]) -> Option<[f64; 2]> {
            Some([x[1], -x[0].sin() + u[0]])
        }
        fn rate_and_jacobians(
            &mut self,
            t: f64,
            x: &[f64; 2],
            u: &[f64; 1],
            a: &mut [[f64; 2]; 2],
            b: &mut [[f64; 1]; 2],
        ) -> Option<[f64; 2]> {
            *a = [[0.0, 1.0], [-x[0].cos(), 0.0]];
            *b = [[0.0], [1.0]];
            self.rate(t, x, u)
        }
    }

    fn pendulum_swing(hessian: Hessian) -> Trapezoidal<Pendulum, 2, 1> {
        let free = NodeBounds {
            x_lower: [f64::NEG_INFINITY; 2],
            x_upper: [f64::INFINITY; 2],
            u_lower: [-2.0],
            u_upper: [2.0],
        };
        let mut problem = Trapezoidal::new(
            Pendulum,
            0.0,
            3.0,
            31,
            |t| {
                let fixed = |x: [f64; 2]| NodeBounds {
                    x_lower: x,
                    x_upper: x,
                    ..free
                };
                if t == 0.0 {
                    fixed([0.0, 0.0])
                } else if (t - 3.0).abs() < 1e-12 {
                    fixed([2.0, 0.0])
                } else {
                    free
                }
            },
            |t| Node {
                t,
                x: [2.0 * t / 3.0, 0.0],
                u: [0.5],
            },
            Weights {
                state: [0.1, 0.0],
                control: [1.0],
                control_rate: [0.05],
            },
        );
        problem.hessian = hessian;
        problem
    }

    /// The Hessian of the Lagrangian against central differences of its
    /// gradient `σ ∇f + Jᵀ λ`, at a point and multipliers off the optimum.
    #[test]
    fn hessian_matches_differences_of_the_gradient() {
        let mut problem = pendulum_swing(Hessian::JacobianDifferences);
        let (n, m) = (problem.variables(), problem.constraints());
        let z: Vec<f64> = (0..n).map(|i| 0.3 * (i as f64 * 0.7).sin()).collect();
        let lambda: Vec<f64> = (0..m).map(|i| (i as f64 * 1.3).cos()).collect();
        let sigma = 0.8;
        let structure = problem.jacobian_structure();
        let mut lagrangian_gradient = |z: &[f64]| -> Vec<f64> {
            let mut g = vec![0.0; n];
            assert!(problem.objective_gradient(z, &mut g));
            g.iter_mut().for_each(|v| *v *= sigma);
            let mut values = vec![0.0; structure.len()];
            assert!(problem.jacobian_values(z, &mut values));
            for (&(i, j), v) in structure.iter().zip(&values) {
                g[j] += lambda[i] * v;
            }
            g
        };
        let mut expected = vec![vec![0.0; n]; n];
        for j in 0..n {
            let (mut plus, mut minus) = (z.clone(), z.clone());
            plus[j] += 1e-6;
            minus[j] -= 1e-6;
            let (gp, gm) = (lagrangian_gradient(&plus), lagrangian_gradient(&minus));
            for i in 0..n {
                expected[i][j] = (gp[i] - gm[i]) / 2e-6;
            }
        }
        let mut problem = pendulum_swing(Hessian::JacobianDifferences);
        let entries = problem.hessian_structure().unwrap();
        let mut values = vec![0.0; entries.len()];
        assert!(problem.hessian_values(&z, sigma, &lambda, &mut values));
        let mut dense = vec![vec![0.0; n]; n];
        for (&(i, j), v) in entries.iter().zip(&values) {
            dense[i][j] += v;
            if i != j {
                dense[j][i] += v;
            }
        }
        for i in 0..n {
            for j in 0..n {
                assert!(
                    (dense[i][j] - expected[i][j]).abs() < 1e-6,
                    "({i}, {j}): {} against {}",
                    dense[i][j],
                    expected[i][j]
                );
            }
        }
    }

    /// With the Hessian, IPOPT solves the smooth swing in a few dozen
    /// iterations, and both Hessians reach the same optimum.
    #[test]
    fn pendulum_swing_converges_with_either_hessian() {
        let mut exact = pendulum_swing(Hessian::JacobianDifferences);
        let newton = solve(&mut exact, &Options::default()).unwrap();
        let mut lbfgs = pendulum_swing(Hessian::QuasiNewton);
        let quasi = solve(&mut lbfgs, &Options::default()).unwrap();
        assert!(
            newton.status.converged() && quasi.status.converged(),
            "{:?} {:?}",
            newton.status,
            quasi.status
        );
        assert!(
            newton.iterations < 60,
            "{} iterations with the Hessian",
            newton.iterations
        );
        assert!((newton.objective - quasi.objective).abs() < 1e-6 * newton.objective);
        eprintln!(
            "iterations: Hessian {}, L-BFGS {}",
            newton.iterations, quasi.iterations
        );
    }
}
