//! A safe interface to IPOPT (Wächter & Biegler 2006), the interior-point
//! solver for sparse nonlinear programs
//!
//! ```text
//! minimise f(x)  subject to  x_L ≤ x ≤ x_U,  g_L ≤ g(x) ≤ g_U,
//! ```
//!
//! through IPOPT's C interface (`IpStdCInterface.h`), which has been stable
//! since IPOPT 3.9 and is what Debian's `coinor-libipopt-dev` ships.
//!
//! Why not the `ipopt` crate: its `ipopt-sys` (0.5) generates bindings to
//! its own C++ shim at build time, which needs libclang, CMake and static
//! LAPACK libraries; against Debian's IPOPT it stopped at "could not find
//! native static library `lapack`". The C interface is eight functions, so
//! they are declared here, and everything unsafe stays in this file.
//!
//! A problem supplies the Hessian of the Lagrangian or leaves it to IPOPT's
//! limited-memory quasi-Newton (L-BFGS) approximation.

use std::ffi::{c_char, c_int, c_void, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Mutex;
use std::time::Instant;

/// One solve at a time per process: the sequential MUMPS that Debian's
/// IPOPT uses keeps global state and aborts the process when two solves
/// run at once (as parallel tests do).
static ONE_SOLVE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// A nonlinear program for IPOPT, with the constraint Jacobian in
/// coordinate (triplet) form.
pub trait Nlp {
    /// Number of variables `n`.
    fn variables(&self) -> usize;
    /// Number of constraints `m`.
    fn constraints(&self) -> usize;
    /// Bounds on the variables; `±f64::INFINITY` for none.
    fn variable_bounds(&self, lower: &mut [f64], upper: &mut [f64]);
    /// Bounds on the constraints; equal bounds for an equality.
    fn constraint_bounds(&self, lower: &mut [f64], upper: &mut [f64]);
    /// The starting point.
    fn initial_point(&self, x: &mut [f64]);
    /// `f(x)`, or `None` when it cannot be evaluated at `x` (IPOPT then
    /// shortens its step).
    fn objective(&mut self, x: &[f64]) -> Option<f64>;
    /// `∇f(x)`; `false` when it cannot be evaluated.
    fn objective_gradient(&mut self, x: &[f64], gradient: &mut [f64]) -> bool;
    /// `g(x)`; `false` when it cannot be evaluated.
    fn constraint_values(&mut self, x: &[f64], g: &mut [f64]) -> bool;
    /// The Jacobian's structurally non-zero entries as `(row, column)`,
    /// in the order [`Nlp::jacobian_values`] writes them.
    fn jacobian_structure(&self) -> Vec<(usize, usize)>;
    /// The Jacobian's entries at `x`, in [`Nlp::jacobian_structure`]'s
    /// order; `false` when it cannot be evaluated.
    fn jacobian_values(&mut self, x: &[f64], values: &mut [f64]) -> bool;

    /// The lower triangle's (`row ≥ column`) structurally non-zero entries
    /// of the Hessian of the Lagrangian `σ ∇²f + Σᵢ λᵢ ∇²gᵢ`, or `None` to
    /// let IPOPT approximate it by limited-memory quasi-Newton updates
    /// (L-BFGS), the default.
    fn hessian_structure(&self) -> Option<Vec<(usize, usize)>> {
        None
    }

    /// The Hessian of the Lagrangian at `x` for the objective factor `σ`
    /// and the constraint multipliers `λ`, in
    /// [`Nlp::hessian_structure`]'s order; `false` when it cannot be
    /// evaluated. Called only when that structure is `Some`.
    fn hessian_values(
        &mut self,
        _x: &[f64],
        _sigma: f64,
        _lambda: &[f64],
        _values: &mut [f64],
    ) -> bool {
        false
    }
}

/// IPOPT's return status (`ApplicationReturnStatus`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Converged to the requested tolerances.
    Solved,
    /// Converged to the "acceptable" tolerances only.
    SolvedToAcceptableLevel,
    /// The constraints look locally infeasible.
    Infeasible,
    /// Any other outcome, with IPOPT's code.
    Failed(i32),
}

impl Status {
    fn from_code(code: c_int) -> Self {
        match code {
            0 => Self::Solved,
            1 => Self::SolvedToAcceptableLevel,
            2 => Self::Infeasible,
            other => Self::Failed(other),
        }
    }

    /// Whether IPOPT reports convergence to its full tolerances.
    #[must_use]
    pub fn converged(self) -> bool {
        self == Self::Solved
    }
}

/// What [`solve`] found.
#[derive(Clone, Debug)]
pub struct Solution {
    /// IPOPT's verdict.
    pub status: Status,
    /// The final iterate.
    pub x: Vec<f64>,
    /// `f` at it.
    pub objective: f64,
    /// IPOPT's iteration count.
    pub iterations: usize,
    /// The (scaled) dual infeasibility of the last iteration: how far the
    /// final point is from first-order optimality.
    pub dual_infeasibility: f64,
    /// Wall time of the solve, s.
    pub seconds: f64,
}

/// Options of one solve.
#[derive(Clone, Debug)]
pub struct Options {
    /// IPOPT's `tol` (relative KKT error).
    pub tolerance: f64,
    /// IPOPT's `constr_viol_tol` (largest absolute constraint violation).
    pub constraint_tolerance: f64,
    /// IPOPT's `max_iter`.
    pub max_iterations: usize,
    /// When set, the "acceptable" stop for problems whose functions have
    /// kinks, where the dual infeasibility cannot fall to `tolerance`: the
    /// constraints within `acceptable_constraint_tolerance` and the
    /// objective's relative change below this value for 10 iterations in a
    /// row (IPOPT's `acceptable_obj_change_tol`; `acceptable_tol` is opened
    /// to 1).
    pub stationary_objective: Option<f64>,
    /// IPOPT's `acceptable_constr_viol_tol`, used with
    /// `stationary_objective`.
    pub acceptable_constraint_tolerance: f64,
    /// IPOPT's own `print_level` (0 silences it).
    pub print_level: i32,
    /// Called after every iteration with `(iteration, objective, primal
    /// infeasibility, dual infeasibility)`: the progress report of long
    /// runs.
    pub progress: Option<fn(usize, f64, f64, f64)>,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            tolerance: 1e-8,
            constraint_tolerance: 1e-8,
            max_iterations: 3000,
            stationary_objective: None,
            acceptable_constraint_tolerance: 1e-7,
            print_level: 0,
            progress: None,
        }
    }
}

/// Errors from setting up IPOPT (a solve that does not converge is a
/// [`Solution`] with its [`Status`], not an error).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SetupError {
    /// The problem is larger than IPOPT's 32-bit indices.
    TooLarge,
    /// IPOPT refused the problem's sizes or bounds.
    Rejected,
    /// IPOPT refused an option (name).
    Option(String),
}

impl std::fmt::Display for SetupError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::TooLarge => write!(f, "the problem exceeds IPOPT's 32-bit indices"),
            Self::Rejected => write!(f, "IPOPT rejected the problem's sizes or bounds"),
            Self::Option(name) => write!(f, "IPOPT rejected the option `{name}`"),
        }
    }
}

impl std::error::Error for SetupError {}

type Bool = c_int;
type Index = c_int;
type Problem = *mut c_void;

type EvalF = extern "C" fn(Index, *mut f64, Bool, *mut f64, *mut c_void) -> Bool;
type EvalGradF = extern "C" fn(Index, *mut f64, Bool, *mut f64, *mut c_void) -> Bool;
type EvalG = extern "C" fn(Index, *mut f64, Bool, Index, *mut f64, *mut c_void) -> Bool;
type EvalJacG = extern "C" fn(
    Index,
    *mut f64,
    Bool,
    Index,
    Index,
    *mut Index,
    *mut Index,
    *mut f64,
    *mut c_void,
) -> Bool;
type EvalH = extern "C" fn(
    Index,
    *mut f64,
    Bool,
    f64,
    Index,
    *mut f64,
    Bool,
    Index,
    *mut Index,
    *mut Index,
    *mut f64,
    *mut c_void,
) -> Bool;
type Intermediate =
    extern "C" fn(Index, Index, f64, f64, f64, f64, f64, f64, f64, f64, Index, *mut c_void) -> Bool;

#[link(name = "ipopt")]
extern "C" {
    fn CreateIpoptProblem(
        n: Index,
        x_l: *mut f64,
        x_u: *mut f64,
        m: Index,
        g_l: *mut f64,
        g_u: *mut f64,
        nele_jac: Index,
        nele_hess: Index,
        index_style: Index,
        eval_f: EvalF,
        eval_g: EvalG,
        eval_grad_f: EvalGradF,
        eval_jac_g: EvalJacG,
        eval_h: EvalH,
    ) -> Problem;
    fn FreeIpoptProblem(problem: Problem);
    fn AddIpoptStrOption(problem: Problem, keyword: *mut c_char, value: *mut c_char) -> Bool;
    fn AddIpoptNumOption(problem: Problem, keyword: *mut c_char, value: f64) -> Bool;
    fn AddIpoptIntOption(problem: Problem, keyword: *mut c_char, value: c_int) -> Bool;
    fn SetIntermediateCallback(problem: Problem, callback: Intermediate) -> Bool;
    fn IpoptSolve(
        problem: Problem,
        x: *mut f64,
        g: *mut f64,
        obj_val: *mut f64,
        mult_g: *mut f64,
        mult_x_l: *mut f64,
        mult_x_u: *mut f64,
        user_data: *mut c_void,
    ) -> c_int;
}

/// What the callbacks see through IPOPT's `user_data` pointer.
struct Context<'p, P> {
    problem: &'p mut P,
    structure: Vec<(usize, usize)>,
    hessian_structure: Option<Vec<(usize, usize)>>,
    iterations: usize,
    dual_infeasibility: f64,
    progress: Option<fn(usize, f64, f64, f64)>,
}

/// Recovers the context and a slice from IPOPT's raw arguments, and runs
/// `body` without letting a panic unwind into C (undefined behaviour):
/// a panic is reported to IPOPT as a failed evaluation.
fn guarded<P>(user_data: *mut c_void, body: impl FnOnce(&mut Context<'_, P>) -> bool) -> Bool {
    // SAFETY: `user_data` is the `&mut Context<P>` that `solve` passed to
    // `IpoptSolve`, alive and not otherwise borrowed during the solve.
    let context = unsafe { &mut *user_data.cast::<Context<'_, P>>() };
    Bool::from(catch_unwind(AssertUnwindSafe(|| body(context))).unwrap_or(false))
}

/// # Safety
/// `pointer` must point to `length` valid `f64`s (IPOPT's arrays of size
/// `n` or `m`), not aliased for the returned lifetime.
unsafe fn slice<'a>(pointer: *mut f64, length: Index) -> &'a mut [f64] {
    std::slice::from_raw_parts_mut(pointer, usize::try_from(length).unwrap_or(0))
}

extern "C" fn eval_f<P: Nlp>(
    n: Index,
    x: *mut f64,
    _: Bool,
    f: *mut f64,
    data: *mut c_void,
) -> Bool {
    guarded::<P>(data, |c| {
        // SAFETY: IPOPT passes `x` of size n and one output value.
        let (x, f) = unsafe { (slice(x, n), &mut *f) };
        c.problem.objective(x).map(|value| *f = value).is_some()
    })
}

extern "C" fn eval_grad_f<P: Nlp>(
    n: Index,
    x: *mut f64,
    _: Bool,
    gradient: *mut f64,
    data: *mut c_void,
) -> Bool {
    guarded::<P>(data, |c| {
        // SAFETY: IPOPT passes `x` and `grad_f`, both of size n.
        let (x, gradient) = unsafe { (slice(x, n), slice(gradient, n)) };
        c.problem.objective_gradient(x, gradient)
    })
}

extern "C" fn eval_g<P: Nlp>(
    n: Index,
    x: *mut f64,
    _: Bool,
    m: Index,
    g: *mut f64,
    data: *mut c_void,
) -> Bool {
    guarded::<P>(data, |c| {
        // SAFETY: IPOPT passes `x` of size n and `g` of size m.
        let (x, g) = unsafe { (slice(x, n), slice(g, m)) };
        c.problem.constraint_values(x, g)
    })
}

#[allow(clippy::too_many_arguments)]
extern "C" fn eval_jac_g<P: Nlp>(
    n: Index,
    x: *mut f64,
    _: Bool,
    _m: Index,
    entries: Index,
    rows: *mut Index,
    columns: *mut Index,
    values: *mut f64,
    data: *mut c_void,
) -> Bool {
    guarded::<P>(data, |c| {
        if values.is_null() {
            // First call: the structure, into IPOPT's index arrays.
            let length = usize::try_from(entries).unwrap_or(0);
            // SAFETY: IPOPT passes `iRow` and `jCol` of size nele_jac.
            let (rows, columns) = unsafe {
                (
                    std::slice::from_raw_parts_mut(rows, length),
                    std::slice::from_raw_parts_mut(columns, length),
                )
            };
            for ((row, column), &(i, j)) in rows.iter_mut().zip(columns).zip(&c.structure) {
                // The sizes were checked against Index's range by `solve`.
                *row = Index::try_from(i).unwrap_or(Index::MAX);
                *column = Index::try_from(j).unwrap_or(Index::MAX);
            }
            true
        } else {
            // SAFETY: IPOPT passes `x` of size n and `values` of size nele_jac.
            let (x, values) = unsafe { (slice(x, n), slice(values, entries)) };
            c.problem.jacobian_values(x, values)
        }
    })
}

#[allow(clippy::too_many_arguments)]
extern "C" fn eval_h<P: Nlp>(
    n: Index,
    x: *mut f64,
    _: Bool,
    sigma: f64,
    m: Index,
    lambda: *mut f64,
    _: Bool,
    entries: Index,
    rows: *mut Index,
    columns: *mut Index,
    values: *mut f64,
    data: *mut c_void,
) -> Bool {
    guarded::<P>(data, |c| {
        if values.is_null() {
            let Some(structure) = &c.hessian_structure else {
                return false;
            };
            let length = usize::try_from(entries).unwrap_or(0);
            // SAFETY: IPOPT passes `iRow` and `jCol` of size nele_hess.
            let (rows, columns) = unsafe {
                (
                    std::slice::from_raw_parts_mut(rows, length),
                    std::slice::from_raw_parts_mut(columns, length),
                )
            };
            for ((row, column), &(i, j)) in rows.iter_mut().zip(columns).zip(structure) {
                *row = Index::try_from(i).unwrap_or(Index::MAX);
                *column = Index::try_from(j).unwrap_or(Index::MAX);
            }
            true
        } else {
            // SAFETY: IPOPT passes `x` of size n, `lambda` of size m and
            // `values` of size nele_hess.
            let (x, lambda, values) =
                unsafe { (slice(x, n), slice(lambda, m), slice(values, entries)) };
            c.problem.hessian_values(x, sigma, lambda, values)
        }
    })
}

#[allow(clippy::too_many_arguments)]
extern "C" fn intermediate<P: Nlp>(
    _mode: Index,
    iteration: Index,
    objective: f64,
    primal_infeasibility: f64,
    dual_infeasibility: f64,
    _: f64,
    _: f64,
    _: f64,
    _: f64,
    _: f64,
    _: Index,
    data: *mut c_void,
) -> Bool {
    guarded::<P>(data, |c| {
        c.iterations = usize::try_from(iteration).unwrap_or(0);
        c.dual_infeasibility = dual_infeasibility;
        if let Some(progress) = c.progress {
            progress(
                c.iterations,
                objective,
                primal_infeasibility,
                dual_infeasibility,
            );
        }
        true
    })
}

/// Frees the IPOPT problem however `solve` returns.
struct Handle(Problem);

impl Drop for Handle {
    fn drop(&mut self) {
        // SAFETY: the pointer came from `CreateIpoptProblem` and is freed once.
        unsafe { FreeIpoptProblem(self.0) }
    }
}

fn set_option(handle: &Handle, name: &str, value: OptionValue<'_>) -> Result<(), SetupError> {
    let rejected = || SetupError::Option(name.to_owned());
    let key = CString::new(name).map_err(|_| rejected())?;
    // SAFETY: IPOPT copies the NUL-terminated strings; it does not keep or
    // write through the pointers despite their `char*` type.
    let accepted = unsafe {
        match value {
            OptionValue::Int(v) => AddIpoptIntOption(handle.0, key.as_ptr().cast_mut(), v),
            OptionValue::Num(v) => AddIpoptNumOption(handle.0, key.as_ptr().cast_mut(), v),
            OptionValue::Str(v) => {
                let value = CString::new(v).map_err(|_| rejected())?;
                AddIpoptStrOption(handle.0, key.as_ptr().cast_mut(), value.as_ptr().cast_mut())
            }
        }
    };
    if accepted == 0 {
        Err(rejected())
    } else {
        Ok(())
    }
}

enum OptionValue<'a> {
    Int(c_int),
    Num(f64),
    Str(&'a str),
}

/// IPOPT's bound for "no bound" (`nlp_lower_bound_inf` and
/// `nlp_upper_bound_inf` default to ∓1e19).
const NO_BOUND: f64 = 1e19;

/// Solves `problem` with IPOPT (MUMPS for the linear systems; L-BFGS for
/// the Hessian of the Lagrangian unless the problem supplies it). Solves from several threads run one
/// after the other.
///
/// # Errors
/// [`SetupError`] when IPOPT refuses the problem or an option. A solve that
/// stops without converging returns `Ok` with its [`Status`].
pub fn solve<P: Nlp>(problem: &mut P, options: &Options) -> Result<Solution, SetupError> {
    // A poisoned lock only means another solve panicked in Rust code; the
    // solver's state is released by then.
    let _one_at_a_time = ONE_SOLVE_AT_A_TIME
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let (n, m) = (problem.variables(), problem.constraints());
    let structure = problem.jacobian_structure();
    let hessian_structure = problem.hessian_structure();
    let index = |size: usize| Index::try_from(size).map_err(|_| SetupError::TooLarge);
    let hessian_entries = index(hessian_structure.as_ref().map_or(0, Vec::len))?;
    let (n_index, m_index, entries) = (index(n)?, index(m)?, index(structure.len())?);
    let lower_triangle = |&(i, j): &(usize, usize)| i < n && j <= i;
    if structure.iter().any(|&(i, j)| i >= m || j >= n)
        || hessian_structure
            .as_ref()
            .is_some_and(|h| !h.iter().all(lower_triangle))
    {
        return Err(SetupError::Rejected);
    }
    let clamp = |v: &mut f64| *v = v.clamp(-NO_BOUND, NO_BOUND);
    let (mut x_l, mut x_u) = (vec![0.0; n], vec![0.0; n]);
    problem.variable_bounds(&mut x_l, &mut x_u);
    let (mut g_l, mut g_u) = (vec![0.0; m], vec![0.0; m]);
    problem.constraint_bounds(&mut g_l, &mut g_u);
    for v in x_l
        .iter_mut()
        .chain(&mut x_u)
        .chain(&mut g_l)
        .chain(&mut g_u)
    {
        clamp(v);
    }
    // SAFETY: the bound arrays have sizes n and m and are copied by IPOPT;
    // the callbacks match the C interface's signatures.
    let handle = Handle(unsafe {
        CreateIpoptProblem(
            n_index,
            x_l.as_mut_ptr(),
            x_u.as_mut_ptr(),
            m_index,
            g_l.as_mut_ptr(),
            g_u.as_mut_ptr(),
            entries,
            hessian_entries,
            0,
            eval_f::<P>,
            eval_g::<P>,
            eval_grad_f::<P>,
            eval_jac_g::<P>,
            eval_h::<P>,
        )
    });
    if handle.0.is_null() {
        return Err(SetupError::Rejected);
    }
    if hessian_entries == 0 {
        set_option(
            &handle,
            "hessian_approximation",
            OptionValue::Str("limited-memory"),
        )?;
    }
    set_option(&handle, "tol", OptionValue::Num(options.tolerance))?;
    set_option(
        &handle,
        "constr_viol_tol",
        OptionValue::Num(options.constraint_tolerance),
    )?;
    set_option(
        &handle,
        "max_iter",
        OptionValue::Int(c_int::try_from(options.max_iterations).unwrap_or(c_int::MAX)),
    )?;
    set_option(
        &handle,
        "print_level",
        OptionValue::Int(options.print_level),
    )?;
    // Without this IPOPT prints its banner even at print level 0.
    set_option(&handle, "sb", OptionValue::Str("yes"))?;
    // SAFETY: the handle is live; the callback matches the C signature.
    if unsafe { SetIntermediateCallback(handle.0, intermediate::<P>) } == 0 {
        return Err(SetupError::Option("intermediate callback".to_owned()));
    }

    let mut x = vec![0.0; n];
    problem.initial_point(&mut x);
    let mut objective = f64::NAN;
    let mut context = Context {
        problem,
        structure,
        hessian_structure,
        iterations: 0,
        dual_infeasibility: f64::NAN,
        progress: options.progress,
    };
    let start = Instant::now();
    // SAFETY: `x` has size n; the multiplier and `g` outputs may be null in
    // the C interface; `context` outlives the call and is reached only
    // through `user_data` during it.
    let code = unsafe {
        IpoptSolve(
            handle.0,
            x.as_mut_ptr(),
            std::ptr::null_mut(),
            &mut objective,
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::null_mut(),
            std::ptr::from_mut(&mut context).cast(),
        )
    };
    Ok(Solution {
        status: Status::from_code(code),
        x,
        objective,
        iterations: context.iterations,
        dual_infeasibility: context.dual_infeasibility,
        seconds: start.elapsed().as_secs_f64(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hock-Schittkowski problem 71, IPOPT's own example: the known optimum
    /// f* = 17.0140173 at x* = (1, 4.7429994, 3.8211503, 1.3794082).
    struct Hs071;

    impl Nlp for Hs071 {
        fn variables(&self) -> usize {
            4
        }
        fn constraints(&self) -> usize {
            2
        }
        fn variable_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
            lower.fill(1.0);
            upper.fill(5.0);
        }
        fn constraint_bounds(&self, lower: &mut [f64], upper: &mut [f64]) {
            lower.copy_from_slice(&[25.0, 40.0]);
            upper.copy_from_slice(&[f64::INFINITY, 40.0]);
        }
        fn initial_point(&self, x: &mut [f64]) {
            x.copy_from_slice(&[1.0, 5.0, 5.0, 1.0]);
        }
        fn objective(&mut self, x: &[f64]) -> Option<f64> {
            Some(x[0] * x[3] * (x[0] + x[1] + x[2]) + x[2])
        }
        fn objective_gradient(&mut self, x: &[f64], g: &mut [f64]) -> bool {
            g[0] = x[3] * (2.0 * x[0] + x[1] + x[2]);
            g[1] = x[0] * x[3];
            g[2] = x[0] * x[3] + 1.0;
            g[3] = x[0] * (x[0] + x[1] + x[2]);
            true
        }
        fn constraint_values(&mut self, x: &[f64], g: &mut [f64]) -> bool {
            g[0] = x.iter().product();
            g[1] = x.iter().map(|v| v * v).sum();
            true
        }
        fn jacobian_structure(&self) -> Vec<(usize, usize)> {
            (0..2).flat_map(|i| (0..4).map(move |j| (i, j))).collect()
        }
        fn jacobian_values(&mut self, x: &[f64], values: &mut [f64]) -> bool {
            let product: f64 = x.iter().product();
            for j in 0..4 {
                values[j] = product / x[j];
                values[4 + j] = 2.0 * x[j];
            }
            true
        }
    }

    #[test]
    fn solves_hock_schittkowski_71() {
        let solution = solve(&mut Hs071, &Options::default()).unwrap();
        assert!(solution.status.converged(), "{:?}", solution.status);
        let expected = [1.0, 4.742_999_4, 3.821_150_3, 1.379_408_2];
        for (x, e) in solution.x.iter().zip(expected) {
            assert!((x - e).abs() < 1e-5, "{x} against {e}");
        }
        assert!((solution.objective - 17.014_017_3).abs() < 1e-6);
        assert!(solution.iterations > 0);
    }
}
