//! Reproducible random models and states for property tests.
//!
//! A tiny SplitMix64 generator keeps the tests deterministic and free of
//! dependencies; every test names its seed, so a failure can be replayed.

use rodyn::joint::{Axis, Joint};
use rodyn::planar::Planar;
use rodyn::planar::{PlanarInertia, PlanarJoint, PlanarMotion, PlanarTransform, Vec2};
use rodyn::spatial::{Force, Inertia, Mat3, Motion, Sym3, Transform, Vec3};
use rodyn::topology::Topology;
use rodyn::Model;

/// SplitMix64: small, fast, and good enough for test inputs.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
    /// Uniform integer in `0..n`.
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }
    /// A random unit vector.
    pub fn unit_vector(&mut self) -> Vec3<f64> {
        loop {
            let v = Vec3::new(
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
            );
            let n = v.norm();
            if n > 0.2 && n <= 1.0 {
                return v.scale(1.0 / n);
            }
        }
    }
    /// A random rotation matrix.
    pub fn rotation(&mut self) -> Mat3<f64> {
        let axis = self.unit_vector();
        Mat3::from_axis_angle(&axis, self.uniform(-3.0, 3.0))
    }
    /// A random physical rigid-body inertia (positive principal moments that
    /// satisfy the triangle inequality, random orientation).
    pub fn inertia(&mut self) -> Inertia<f64> {
        let mass = self.uniform(0.2, 3.0);
        let com = Vec3::new(
            self.uniform(-0.3, 0.3),
            self.uniform(-0.3, 0.3),
            self.uniform(-0.3, 0.3),
        );
        let (a, b) = (self.uniform(0.01, 0.1), self.uniform(0.01, 0.1));
        let c = self.uniform((a - b).abs() + 0.001, a + b);
        let principal = Sym3::diagonal(a, b, c);
        Inertia::new(mass, com, principal.rotate(&self.rotation()))
    }
    /// A random placement: rotation and a translation up to 0.5 m.
    pub fn placement(&mut self) -> Transform<f64> {
        Transform::new(
            self.rotation(),
            Vec3::new(
                self.uniform(-0.5, 0.5),
                self.uniform(-0.5, 0.5),
                self.uniform(-0.5, 0.5),
            ),
        )
    }
    /// A random one-degree-of-freedom joint: revolute or prismatic, about a
    /// coordinate axis or a general one.
    pub fn one_dof_joint(&mut self) -> Joint<f64> {
        let axis = match self.below(4) {
            0 => Axis::X,
            1 => Axis::Y,
            2 => Axis::Z,
            _ => Axis::Unit(self.unit_vector()),
        };
        if self.below(5) == 0 {
            Joint::prismatic(axis)
        } else {
            Joint::revolute(axis)
        }
    }
    /// A random spatial force of moderate size.
    pub fn force(&mut self) -> Force<f64> {
        Force::new(
            self.unit_vector().scale(self.uniform(0.0, 3.0)),
            self.unit_vector().scale(self.uniform(0.0, 10.0)),
        )
    }
    /// `n` values uniform in `[-r, r]`.
    pub fn vector<const N: usize>(&mut self, r: f64) -> [f64; N] {
        core::array::from_fn(|_| self.uniform(-r, r))
    }
}

/// Gravity along -z, 9.81 m/s².
pub fn gravity() -> Motion<f64> {
    Motion::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -9.81))
}

/// A random tree of one-degree-of-freedom joints (random parents, axes,
/// placements and inertias).
pub fn random_tree<const N: usize>(rng: &mut Rng) -> Model<f64, N, N, N> {
    let parents: [Option<usize>; N] =
        core::array::from_fn(|i| if i == 0 { None } else { Some(rng.below(i)) });
    let joints: [Joint<f64>; N] = core::array::from_fn(|_| rng.one_dof_joint());
    let topology = Topology::new(parents, [1; N], [1; N], N);
    Model::from_parts(
        topology,
        joints,
        core::array::from_fn(|_| rng.placement()),
        core::array::from_fn(|_| rng.inertia()),
        gravity(),
    )
}

/// A random floating-base tree: a free-flyer root, `NB - 2` one-degree-of-
/// freedom joints and one fixed joint somewhere below the root.
/// Sizes: `NQ = NB + 5`, `NV = NB + 4`.
pub fn random_floating_tree<const NB: usize, const NQ: usize, const NV: usize>(
    rng: &mut Rng,
) -> Model<f64, NB, NQ, NV> {
    assert!(NB >= 3 && NQ == NB + 5 && NV == NB + 4, "sizes must match");
    let fixed = 1 + rng.below(NB - 1);
    let parents: [Option<usize>; NB] =
        core::array::from_fn(|i| if i == 0 { None } else { Some(rng.below(i)) });
    let joints: [Joint<f64>; NB] = core::array::from_fn(|i| match i {
        0 => Joint::free_flyer(),
        i if i == fixed => Joint::Fixed,
        _ => rng.one_dof_joint(),
    });
    let nq: [usize; NB] = core::array::from_fn(|i| joints[i].const_nq());
    let nv: [usize; NB] = core::array::from_fn(|i| joints[i].const_nv());
    Model::from_parts(
        Topology::new(parents, nq, nv, NQ),
        joints,
        core::array::from_fn(|_| rng.placement()),
        core::array::from_fn(|_| rng.inertia()),
        gravity(),
    )
}

/// A random configuration of `model` (unit quaternions for free flyers).
pub fn random_configuration<const NB: usize, const NQ: usize, const NV: usize>(
    model: &Model<f64, NB, NQ, NV>,
    rng: &mut Rng,
) -> [f64; NQ] {
    let mut q: [f64; NQ] = rng.vector(2.0);
    model
        .normalize(&mut q)
        .expect("a random quaternion is not zero");
    q
}

/// A random planar chain and its 3-D twin: all joints about z, placements
/// rotate about z and translate in x-y, gravity along -y.
pub fn random_planar_chain<const N: usize>(
    rng: &mut Rng,
) -> (Model<f64, N, N, N, Planar>, Model<f64, N, N, N>) {
    let parents: [Option<usize>; N] =
        core::array::from_fn(|i| if i == 0 { None } else { Some(rng.below(i)) });
    let angles: [f64; N] = rng.vector(3.0);
    let offsets: [(f64, f64); N] =
        core::array::from_fn(|_| (rng.uniform(0.1, 0.6), rng.uniform(-0.2, 0.2)));
    let masses: [(f64, f64, f64, f64); N] = core::array::from_fn(|_| {
        (
            rng.uniform(0.2, 2.0),
            rng.uniform(-0.1, 0.4),
            rng.uniform(-0.1, 0.1),
            rng.uniform(0.005, 0.05),
        )
    });
    let prismatic = rng.below(N);
    let planar_joints: [PlanarJoint<f64>; N] = core::array::from_fn(|i| {
        if i == prismatic && N > 1 {
            PlanarJoint::Prismatic(Vec2::new(0.6, 0.8))
        } else {
            PlanarJoint::Revolute
        }
    });
    let joints3: [Joint<f64>; N] = core::array::from_fn(|i| match planar_joints[i] {
        PlanarJoint::Prismatic(a) => Joint::prismatic(Axis::Unit(Vec3::new(a.x, a.y, 0.0))),
        _ => Joint::revolute(Axis::Z),
    });
    let planar = Model::from_parts(
        Topology::new(parents, [1; N], [1; N], N),
        planar_joints,
        core::array::from_fn(|i| {
            PlanarTransform::from_angle(angles[i], Vec2::new(offsets[i].0, offsets[i].1))
        }),
        core::array::from_fn(|i| {
            let (m, cx, cy, izz) = masses[i];
            PlanarInertia::new(m, Vec2::new(cx, cy), izz)
        }),
        PlanarMotion::new(0.0, Vec2::new(0.0, -9.81)),
    );
    let spatial = Model::from_parts(
        Topology::new(parents, [1; N], [1; N], N),
        joints3,
        core::array::from_fn(|i| {
            Transform::new(
                Mat3::from_axis_angle(&Vec3::new(0.0, 0.0, 1.0), angles[i]),
                Vec3::new(offsets[i].0, offsets[i].1, 0.0),
            )
        }),
        core::array::from_fn(|i| {
            let (m, cx, cy, izz) = masses[i];
            // Out-of-plane moments are arbitrary but valid; they never act.
            Inertia::new(
                m,
                Vec3::new(cx, cy, 0.0),
                Sym3::diagonal(izz * 0.7, izz * 0.6, izz),
            )
        }),
        Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
    );
    (planar, spatial)
}
