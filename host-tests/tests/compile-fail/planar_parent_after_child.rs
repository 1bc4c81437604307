// A planar model whose first body hangs from the second: parents must come first.
use rodyn::planar::{Planar, PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
use rodyn::Model;

const BODY: PlanarInertia<f64> = PlanarInertia::new(1.0, Vec2::new(0.5, 0.0), 0.01);
const ORIGIN: PlanarTransform<f64> = PlanarTransform::from_translation(Vec2::new(0.0, 0.0));
const BAD: Model<f64, 2, 2, 2, Planar> = Model::new_planar(
    [Some(1), None],
    [PlanarJoint::Revolute, PlanarJoint::Revolute],
    [ORIGIN, ORIGIN],
    [BODY, BODY],
    PlanarMotion::new(0.0, Vec2::new(0.0, -9.81)),
);

fn main() {
    let _ = BAD.topology();
}
