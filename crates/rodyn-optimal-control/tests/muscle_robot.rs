//! The muscle robot's optimal-control problem (Thelen muscles) on a coarse grid (26 nodes, at most
//! 1,000 iterations, so that it runs in seconds unoptimised): the solution
//! holds the desired angles and the bounds, its defects are below 1e-6,
//! its controls replayed by RK4 follow the desired motion, and the
//! extensors m2 and m4 stay idle while the arm is lifted and lowered
//! against gravity.
//!
//! It solves with the finite-difference route, the one IPOPT settles with:
//! with exact derivatives the muscle model's kinks keep the dual
//! infeasibility jumping and the iterate where the iteration limit stops
//! it is feasible only to about 1e-4 (see the optimal-control section).

use rodyn_optimal_control::collocation::Node;
use rodyn_optimal_control::ipopt::{solve, Options};
use rodyn_optimal_control::muscle_robot::{resimulate, Derivatives, Task, NX};
use rodyn_scenarios::muscle_robot::{NU, NV};

#[test]
fn coarse_solution_is_feasible_and_tracks() {
    let task = Task {
        nodes: 26,
        ..Task::default()
    };
    let mut problem = task.transcribe(Derivatives::FiniteDifference).unwrap();
    let options = Options {
        max_iterations: 1000,
        ..Options::default()
    };
    let solution = solve(&mut problem, &options).unwrap();
    let nodes: Vec<Node<NX, NU>> = problem.unpack(&solution.x);

    let defect = problem.max_defect(&solution.x).unwrap();
    assert!(defect < 1e-6, "largest defect {defect:e}");
    for node in &nodes {
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

    let (rms, worst) = resimulate(&task, &nodes, 1e-4).unwrap();
    eprintln!("objective {:.6e}, defect {defect:.1e}, iterations {}, tracking RMS {rms:.3e} rad, worst {worst:.3e} rad", solution.objective, solution.iterations);
    assert!(rms < 0.05, "re-simulated tracking RMS {rms} rad");

    let peak = |i: usize| nodes.iter().fold(0.0_f64, |m, n| m.max(n.x[2 * NV + i]));
    eprintln!(
        "peak activations {:?}",
        [peak(0), peak(1), peak(2), peak(3)]
    );
    assert!(peak(1) < 1e-3 && peak(3) < 1e-3, "extensors active");
    assert!(peak(0) > 0.3, "the shoulder flexor m1 lifts the arm");
}
