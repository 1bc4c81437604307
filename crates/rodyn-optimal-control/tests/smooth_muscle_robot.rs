//! The muscle robot's optimal-control problem on the smooth (De Groote
//! et al. 2016) muscles, as the example solves it: 101 nodes, rodyn's
//! analytic Jacobian and the exact Hessian. IPOPT must report "Optimal
//! Solution Found" at its default tolerance (1e-8) within 100 iterations,
//! the defects must be below 1e-8, the controls replayed by RK4 at 0.1 ms
//! must follow the desired angles to 1e-2 rad RMS, the objective on the
//! grid twice as fine must agree to 1e-3 relative, and the solution must
//! hold its bounds. (The solve time is a benchmark figure, reported by the
//! example, not asserted.)

use rodyn_optimal_control::collocation::Hessian;
use rodyn_optimal_control::ipopt::{Options, Status};
use rodyn_optimal_control::muscle_robot::Task;
use rodyn_optimal_control::smooth_muscle_robot::{
    effort_shares, solve_smooth, MAX_DEFECT, MAX_TRACKING_RMS,
};
use rodyn_scenarios::muscle_robot::NV;

#[test]
fn smooth_muscles_converge_with_exact_derivatives() {
    let task = Task {
        hessian: Hessian::Exact,
        ..Task::default()
    };
    let run = solve_smooth(&task, &Options::default(), 1e-4).unwrap();
    eprintln!(
        "{:?} after {} iterations, objective {:.9e}, defect {:.1e}, tracking RMS {:.2e} rad",
        run.solution.status,
        run.solution.iterations,
        run.solution.objective,
        run.max_defect,
        run.tracking_rms
    );
    assert_eq!(run.solution.status, Status::Solved);
    assert!(
        run.solution.iterations <= 100,
        "{} iterations",
        run.solution.iterations
    );
    assert!(
        run.max_defect <= MAX_DEFECT,
        "largest defect {:e}",
        run.max_defect
    );
    assert!(
        run.tracking_rms <= MAX_TRACKING_RMS,
        "re-simulated tracking RMS {} rad",
        run.tracking_rms
    );
    for node in &run.nodes {
        let (desired, _) = task.desired(node.t);
        for (q, d) in node.x[..NV].iter().zip(desired) {
            assert!(
                (q - d).abs() < 1e-9,
                "angle {q} against {d} at {} s",
                node.t
            );
        }
        for value in node.u.iter().chain(&node.x[2 * NV..]) {
            assert!(
                (-1e-9..=1.0 + 1e-9).contains(value),
                "{value} outside [0, 1]"
            );
        }
    }
    // Lifting the arm forward against gravity: the shoulder flexor m1
    // does most of the work, the elbow flexor m3 the rest, the extensors
    // m2 and m4 stay idle.
    let shares = effort_shares(&run.nodes);
    assert!(shares[0] > 0.8 && shares[2] > 0.05, "shares {shares:?}");
    assert!(shares[1] < 1e-6 && shares[3] < 1e-6, "shares {shares:?}");

    let fine = Task {
        nodes: 2 * task.nodes - 1,
        ..task
    };
    let refined = solve_smooth(&fine, &Options::default(), 1e-4).unwrap();
    assert_eq!(refined.solution.status, Status::Solved);
    let relative =
        (refined.solution.objective - run.solution.objective).abs() / run.solution.objective;
    assert!(
        relative <= 1e-3,
        "objectives {} and {} on {} and {} nodes",
        run.solution.objective,
        refined.solution.objective,
        task.nodes,
        fine.nodes
    );
}
