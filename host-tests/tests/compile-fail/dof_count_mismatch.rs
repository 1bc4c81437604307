// A free-flyer and a revolute joint have 7 + 1 configuration coordinates, not 7.
use rodyn::prelude::*;

const BODY: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(0.1, 0.0, 0.0));
const BAD: Model<f64, 2, 7, 7> = Model::new(
    [None, Some(0)],
    [Joint::free_flyer(), Joint::revolute(Axis::X)],
    [Transform::IDENTITY, Transform::IDENTITY],
    [BODY, BODY],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
);

fn main() {
    let _ = BAD.topology();
}
