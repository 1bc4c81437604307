//! A batch of parameter changes that applies whole or not at all.

use super::ParameterChange;
use crate::error::Result;
use crate::model::Model;
use crate::space::Space;
use crate::spatial::Spatial;
use crate::Scalar;

/// `N` parameter changes, applied in order as one transaction: each is
/// checked as its setter checks it, against the model the earlier changes
/// left (two payloads on one body add up, and the sum is checked too).
///
/// # Example
///
/// ```
/// use rodyn::frame::Frame;
/// use rodyn::update::{ModelUpdate, ParameterChange};
/// # use rodyn::prelude::*;
/// # // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
/// # const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
/// #     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
/// #     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
/// #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut model = PENDULUM;
/// // A tool frame at the link's tip, and a 0.5 kg payload 10 cm beyond it.
/// let tip = Frame::new(0, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)));
/// let grasp = ModelUpdate::new([
///     ParameterChange::Payload { frame: tip, inertia: Inertia::point_mass(0.5, Vec3::new(0.1, 0.0, 0.0)) },
///     ParameterChange::Armature { dof: 0, armature: 0.05 },
/// ]);
/// grasp.apply(&mut model)?;
/// assert!((model.inertia(0).mass - 1.5).abs() < 1e-12);
/// assert!((model.inertia(0).com.x - 1.55 / 1.5).abs() < 1e-12); // (1·1 + 0.5·1.1) / 1.5 m
/// // A batch with one bad change changes nothing and names it.
/// let bad = ModelUpdate::new([
///     ParameterChange::Armature { dof: 0, armature: 0.1 },
///     ParameterChange::Payload { frame: tip, inertia: Inertia::point_mass(-0.5, Vec3::ZERO) },
/// ]);
/// assert_eq!(
///     bad.apply(&mut model),
///     Err(Error::InvalidModel { body: 0, problem: rodyn::error::ModelProblem::InvalidMass })
/// );
/// assert_eq!(model.armature()[0], 0.05);
/// # Ok::<(), rodyn::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct ModelUpdate<S: Scalar, const N: usize, G: Space = Spatial> {
    changes: [ParameterChange<S, G>; N],
}

impl<S: Scalar, const N: usize, G: Space> ModelUpdate<S, N, G> {
    /// The batch of `changes`, applied in this order.
    #[must_use]
    pub const fn new(changes: [ParameterChange<S, G>; N]) -> Self {
        Self { changes }
    }

    /// The changes, in order.
    #[must_use]
    pub const fn changes(&self) -> &[ParameterChange<S, G>; N] {
        &self.changes
    }

    /// Applies every change to `model`, or none.
    ///
    /// The changes are written into a copy of `model`, which replaces it
    /// only when all have passed, so a batch that fails leaves `model`
    /// unchanged, bit for bit. To update a model that a control tick is
    /// reading, stage the batch in a [`DoubleBuffered`](super::DoubleBuffered)
    /// instead ([`Writer::stage_update`](super::Writer::stage_update)),
    /// which writes it into the staging copy without a second copy.
    ///
    /// # Errors
    /// The first change's error that fails ([`ParameterChange::apply_to`]):
    /// it names the body, velocity coordinate or parameter.
    pub fn apply<const NB: usize, const NQ: usize, const NV: usize>(
        &self,
        model: &mut Model<S, NB, NQ, NV, G>,
    ) -> Result<()> {
        let mut next = *model;
        self.write_into(&mut next)?;
        *model = next;
        Ok(())
    }

    /// Writes the changes into `staging` in order, stopping at the first
    /// that fails: `staging` is then partly written, and is meant to be
    /// thrown away (the staging copy of a
    /// [`DoubleBuffered`](super::DoubleBuffered), which is not published).
    ///
    /// # Errors
    /// As [`apply`](Self::apply).
    pub fn write_into<const NB: usize, const NQ: usize, const NV: usize>(
        &self,
        staging: &mut Model<S, NB, NQ, NV, G>,
    ) -> Result<()> {
        for change in &self.changes {
            change.apply_to(staging)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::drive::JointMotor;
    use crate::error::{Error, ModelProblem, Quantity};
    use crate::frame::Frame;
    use crate::joint::{Axis, Joint};
    use crate::space::BodyInertia;
    use crate::spatial::{Inertia, Motion, Sym3, Transform, Vec3};
    extern crate std;
    use std::format;

    type Chain = Model<f64, 3, 3, 3>;

    fn chain() -> Chain {
        let link = Inertia::new(
            2.0,
            Vec3::new(0.2, 0.0, 0.01),
            Sym3::diagonal(0.01, 0.02, 0.025),
        );
        Model::new(
            [None, Some(0), Some(1)],
            [
                Joint::revolute(Axis::Z),
                Joint::revolute(Axis::Y),
                Joint::revolute(Axis::Y),
            ],
            [
                Transform::IDENTITY,
                Transform::from_translation(Vec3::new(0.4, 0.0, 0.0)),
                Transform::from_translation(Vec3::new(0.4, 0.0, 0.0)),
            ],
            [link; 3],
            Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
        )
    }

    /// Every float of the model, bit for bit: `Debug` prints the shortest
    /// decimal that reads back to the same bits, and the sign of a zero.
    fn bits(model: &Chain) -> std::string::String {
        format!("{model:?}")
    }

    fn tool() -> Frame<f64> {
        Frame::new(2, Transform::from_translation(Vec3::new(0.3, 0.0, 0.05)))
    }

    fn good_changes() -> [ParameterChange<f64>; 4] {
        [
            ParameterChange::Payload {
                frame: tool(),
                inertia: Inertia::new(
                    1.5,
                    Vec3::new(0.0, 0.0, 0.04),
                    Sym3::diagonal(2e-3, 2e-3, 1e-3),
                ),
            },
            ParameterChange::Inertia {
                body: 0,
                inertia: Inertia::point_mass(3.0, Vec3::new(0.1, 0.0, 0.0)),
            },
            ParameterChange::Motor(JointMotor::new(1, 0, 100.0, 0.05, 3e-5)),
            ParameterChange::Armature {
                dof: 2,
                armature: 0.02,
            },
        ]
    }

    /// A good batch leaves the model the single setters leave.
    #[test]
    fn a_good_batch_matches_the_single_setters() {
        let mut by_batch = chain();
        ModelUpdate::new(good_changes())
            .apply(&mut by_batch)
            .unwrap();

        let mut by_setters = chain();
        let payload = Inertia::new(
            1.5,
            Vec3::new(0.0, 0.0, 0.04),
            Sym3::diagonal(2e-3, 2e-3, 1e-3),
        );
        let held = by_setters
            .inertia(2)
            .combine(&payload.act(&tool().placement));
        by_setters.set_inertia(2, held).unwrap();
        by_setters
            .set_inertia(0, Inertia::point_mass(3.0, Vec3::new(0.1, 0.0, 0.0)))
            .unwrap();
        by_setters.set_armature(1, 100.0 * 100.0 * 3e-5).unwrap();
        by_setters.set_armature(2, 0.02).unwrap();
        assert_eq!(bits(&by_batch), bits(&by_setters));
        // The payload's numbers: 2 + 1.5 kg; centre of mass (2·0.2 + 1.5·0.3) / 3.5 in x.
        assert!((by_batch.inertia(2).mass - 3.5).abs() < 1e-12);
        assert!((by_batch.inertia(2).com.x - 0.85 / 3.5).abs() < 1e-12);
        assert!((by_batch.inertia(2).com.z - (2.0 * 0.01 + 1.5 * 0.09) / 3.5).abs() < 1e-12);
        assert!((by_batch.armature()[1] - 0.3).abs() < 1e-12);
    }

    /// A batch whose last change is bad changes nothing, bit for bit, and
    /// its error names the body and the problem.
    #[test]
    fn a_bad_batch_changes_nothing() {
        let triangle = Sym3::diagonal(0.01, 0.01, 0.03); // I_zz > I_xx + I_yy
        let cases: [(ParameterChange<f64>, Error); 7] = [
            (
                ParameterChange::Payload {
                    frame: tool(),
                    inertia: Inertia::point_mass(f64::NAN, Vec3::ZERO),
                },
                Error::InvalidModel {
                    body: 2,
                    problem: ModelProblem::NonFiniteParameter,
                },
            ),
            (
                ParameterChange::Payload {
                    frame: tool(),
                    inertia: Inertia::point_mass(-0.5, Vec3::ZERO),
                },
                Error::InvalidModel {
                    body: 2,
                    problem: ModelProblem::InvalidMass,
                },
            ),
            (
                ParameterChange::Payload {
                    frame: tool(),
                    inertia: Inertia::new(1.0, Vec3::ZERO, triangle),
                },
                Error::InvalidModel {
                    body: 2,
                    problem: ModelProblem::InvalidInertia,
                },
            ),
            (
                ParameterChange::Payload {
                    frame: Frame::new(7, Transform::IDENTITY),
                    inertia: Inertia::point_mass(1.0, Vec3::ZERO),
                },
                Error::FrameBodyOutOfRange { body: 7 },
            ),
            (
                ParameterChange::Inertia {
                    body: 1,
                    inertia: Inertia::new(1.0, Vec3::ZERO, triangle),
                },
                Error::InvalidModel {
                    body: 1,
                    problem: ModelProblem::InvalidInertia,
                },
            ),
            (
                ParameterChange::Motor(JointMotor::new(0, 0, 50.0, 0.02, f64::INFINITY)),
                Error::NonFinite {
                    quantity: Quantity::Drive,
                    index: 2,
                },
            ),
            (
                ParameterChange::Armature {
                    dof: 3,
                    armature: 0.1,
                },
                Error::InvalidDrive {
                    problem: crate::error::DriveProblem::DofOutOfRange { dof: 3 },
                },
            ),
        ];
        for (bad, error) in cases {
            let [a, b, c, d] = good_changes();
            let mut model = chain();
            let before = bits(&model);
            let batch = ModelUpdate::new([a, b, c, d, bad]);
            assert_eq!(batch.apply(&mut model), Err(error), "{bad:?}");
            assert_eq!(bits(&model), before, "{bad:?} changed the model");
        }
    }

    /// Through the double buffer: a bad batch is refused at staging, the
    /// active model (what the tick reads) keeps every bit.
    #[test]
    fn a_bad_batch_is_not_published() {
        let mut buffers = super::super::DoubleBuffered::new(chain());
        let before = bits(buffers.active());
        let (mut tick, mut writer) = buffers.split();
        let bad = ModelUpdate::new([
            ParameterChange::Armature {
                dof: 0,
                armature: 0.5,
            },
            ParameterChange::Payload {
                frame: tool(),
                inertia: Inertia::point_mass(-1.0, Vec3::ZERO),
            },
        ]);
        assert!(writer.stage_update(&bad).is_err());
        assert!(!writer.publish());
        assert_eq!(tick.read(bits), before);
        writer
            .stage_update(&ModelUpdate::new(good_changes()))
            .unwrap();
        assert!(writer.publish());
        let mut expected = chain();
        ModelUpdate::new(good_changes())
            .apply(&mut expected)
            .unwrap();
        assert_eq!(tick.read(bits), bits(&expected));
    }
}
