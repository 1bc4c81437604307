//! Inverse kinematics of one frame: damped least squares on its pose error.

use super::check::Input;
use super::{RuntimeError, RuntimeModel, Workspace};
use rodyn::algorithm::inverse_kinematics::{solve, IkSettings};
use rodyn::spatial::{Mat3, Transform, Vec3};

impl RuntimeModel {
    /// Moves `q` (the start, then the solution) until `frame` reaches the
    /// world placement `target` (4 × 4 homogeneous, row-major) within
    /// `tolerance` on every component of the pose error (rad and m), in
    /// at most `max_iterations` damped least-squares steps. Returns the
    /// steps taken.
    ///
    /// # Errors
    /// An unknown frame, a target that is not a rigid placement, a
    /// non-positive tolerance; the target not reached within the budget
    /// (`q` then holds the last iterate); as [`rnea`](Self::rnea).
    pub fn inverse_kinematics(
        &self,
        ws: &mut Workspace,
        frame: &str,
        target: &[f64; 16],
        tolerance: f64,
        max_iterations: usize,
        q: &mut [f64],
    ) -> Result<usize, RuntimeError> {
        let f = self.frame(frame)?;
        self.check_q(q)?;
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(RuntimeError::invalid_input(format!(
                "tolerance is {tolerance}, it must be positive"
            )));
        }
        let row = |r: usize| [target[4 * r], target[4 * r + 1], target[4 * r + 2]];
        let target = Transform::new(
            Mat3::from_rows([row(0), row(1), row(2)]),
            Vec3::new(target[3], target[7], target[11]),
        );
        let settings = IkSettings::new()
            .with_tolerance(tolerance)
            .with_max_iterations(max_iterations);
        let nq = self.nq;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            let s = &mut **s;
            s.set_q(q);
            let result = solve(
                &m.model,
                &mut s.data,
                &mut s.ik,
                f,
                &target,
                &settings,
                &mut s.q,
            );
            q.copy_from_slice(&s.q[..nq]);
            result.map_err(|e| {
                self.explain(
                    "inverse kinematics",
                    &e,
                    &[Input {
                        name: "q",
                        values: q,
                    }],
                )
            })
        })
    }
}
