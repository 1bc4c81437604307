//! Derivatives of the joint accelerations with respect to model parameters
//! (a body mass, a segment length, a muscle's optimal fibre length and
//! maximum isometric force), by running the same dynamics on `Dual`,
//! against central finite differences within 1e-6 relative (f64).

// Row and column indices mirror the matrix equations being checked.
#![allow(clippy::needless_range_loop)]

use rodyn::drive::DriveForces;
use rodyn::planar::{PlanarInertia, PlanarTransform, Vec2};
use rodyn::prelude::*;
use rodyn_scenarios::muscle_robot::{self as robot, NU, NV};

/// One model parameter, set to a value of any scalar type.
#[derive(Clone, Copy, Debug)]
enum Parameter {
    /// Mass of the lower link (kg), centre of mass and inertia about it kept.
    LowerLinkMass,
    /// Length of the upper link: x of the elbow's placement (m).
    UpperLinkLength,
    /// Optimal fibre length of m3 (m).
    OptimalFiberLength,
    /// Maximum isometric force of m1 (N).
    MaxIsometricForce,
}

impl Parameter {
    fn nominal(self) -> f64 {
        match self {
            Self::LowerLinkMass => 1.0,
            Self::UpperLinkLength => robot::MODEL_F64.placement(1).trans.x,
            Self::OptimalFiberLength => robot::MUSCLES_F64[2].params.optimal_fiber_length,
            Self::MaxIsometricForce => robot::MUSCLES_F64[0].params.max_isometric_force,
        }
    }

    /// The robot with this parameter set to `value`.
    fn robot<S: Scalar>(self, value: S) -> (robot::RobotModel<S>, robot::RobotMuscles<S>) {
        let mut model = robot::model::<S>().unwrap();
        let mut muscles = robot::muscles::<S>();
        match self {
            Self::LowerLinkMass => {
                let i = *model.inertia(1);
                model
                    .set_inertia(1, PlanarInertia::new(value, i.com, i.izz))
                    .unwrap();
            }
            Self::UpperLinkLength => {
                model
                    .set_placement(
                        1,
                        PlanarTransform::from_translation(Vec2::new(value, S::ZERO)),
                    )
                    .unwrap();
            }
            Self::OptimalFiberLength => muscles[2].params.optimal_fiber_length = value,
            Self::MaxIsometricForce => muscles[0].params.max_isometric_force = value,
        }
        (model, muscles)
    }

    fn ddq<S: Scalar>(self, value: S, q: &[f64; NV], v: &[f64; NV], a: &[f64; NU]) -> [S; NV] {
        let (model, muscles) = self.robot(value);
        let c = |x: &[f64; NV]| x.map(S::from_f64);
        *robot::forward_dynamics(
            &model,
            &muscles,
            &mut Data::new(),
            &c(q),
            &c(v),
            &a.map(S::from_f64),
            &mut DriveForces::new(),
        )
        .unwrap()
    }
}

#[test]
fn parameter_derivatives_by_dual_numbers_match_central_differences() {
    let states = [
        ([0.3, 0.6], [0.5, -1.0], [0.3, 0.2, 0.6, 0.4]),
        ([-0.4, 1.1], [-1.5, 0.7], [0.8, 0.1, 0.2, 0.5]),
        ([0.9, 0.2], [0.2, 1.9], [0.15, 0.7, 0.4, 0.25]),
    ];
    for p in [
        Parameter::LowerLinkMass,
        Parameter::UpperLinkLength,
        Parameter::OptimalFiberLength,
        Parameter::MaxIsometricForce,
    ] {
        let x = p.nominal();
        for (q, v, a) in &states {
            let by_dual = p.ddq(Dual::variable(x), q, v, a);
            let h = 1e-5 * x;
            let (plus, minus) = (p.ddq(x + h, q, v, a), p.ddq(x - h, q, v, a));
            for i in 0..NV {
                // Compare the scaled derivatives x ∂q̈/∂x (rad/s²), so that a
                // force in newtons and a length in metres weigh alike.
                let fd = x * (plus[i] - minus[i]) / (2.0 * h);
                let dual = x * by_dual[i].du;
                assert!(
                    (dual - fd).abs() <= 1e-6 * fd.abs().max(1e-3),
                    "{p:?} at q {q:?}: x d qdd[{i}]/dx dual {dual} vs central difference {fd}"
                );
                // A derivative that is zero everywhere would pass trivially.
                assert!(
                    fd.abs() > 1e-2,
                    "{p:?}: qdd[{i}] hardly depends on it ({fd})"
                );
                // The value part is the f64 result.
                let plain = p.ddq(x, q, v, a);
                approx::assert_relative_eq!(by_dual[i].re, plain[i], max_relative = 1e-14);
            }
        }
    }
}
