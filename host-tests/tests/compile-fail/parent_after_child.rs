// A body whose parent comes after it: rejected while compiling the const.
use rodyn::prelude::*;

const LINK: Inertia<f64> = Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0));
const BAD: Model<f64, 2, 2, 2> = Model::new(
    [Some(1), None],
    [Joint::revolute(Axis::Z), Joint::revolute(Axis::Z)],
    [Transform::IDENTITY, Transform::IDENTITY],
    [LINK, LINK],
    Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81)),
);

fn main() {
    let _ = BAD.topology();
}
