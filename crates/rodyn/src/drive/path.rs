//! Paths: polygons through endpoints, along which springs, dampers and
//! muscles pull.
//!
//! A path of `K ≥ 2` points `p₀ … p_{K-1}` (each an [`Endpoint`] on a body or
//! in the world) has length `L = Σ |p_{k+1} - p_k|` and lengthening velocity
//! `L̇ = Σ e_k · (ṗ_{k+1} - ṗ_k)`, with `e_k` the unit vector from `p_k` to
//! `p_{k+1}`.
//!
//! **Sign convention.** A tension `T > 0` pulls: it draws every point toward
//! its neighbours on the path, so it acts to shorten the path. Point `k`
//! receives the force `T (e_k - e_{k-1})` (with `e_{-1} = e_{K-1} = 0`), and
//! the power these forces deliver to the bodies is
//! `P = Σ f_k · ṗ_k = -T L̇`: a tension does positive work while the path
//! shortens. The map from `T` to body forces is linear in `T`; it depends
//! on the state only through the directions `e_k` and the points.
//!
//! A segment shorter than [`MIN_SEGMENT_LENGTH`] has no direction: it
//! contributes neither force nor lengthening velocity (as MuJoCo treats
//! coincident tendon sites), so coincident points never produce NaN.

use crate::drive::geometry::PointGeometry;
use crate::endpoint::Endpoint;
use crate::error::{DriveProblem, Error, Quantity, Result};
use crate::space::{RigidTransform, Space};
use crate::{Data, Scalar};

/// Segments shorter than this (m) carry no force and no velocity.
pub const MIN_SEGMENT_LENGTH: f64 = 1e-9;

/// A polygon through `K ≥ 2` endpoints.
#[derive(Clone, Copy, Debug)]
pub struct Path<S: Scalar, G: Space, const K: usize> {
    /// The points in order, from origin to insertion.
    pub points: [Endpoint<S, G>; K],
}

/// A path's length, lengthening velocity and force directions at one state,
/// all in the world frame.
#[derive(Clone, Copy, Debug)]
pub struct PathKinematics<S: Scalar, G: Space, const K: usize> {
    /// Length `L` (m).
    pub length: S,
    /// Lengthening velocity `L̇` (m/s), positive when the path grows.
    pub lengthening_velocity: S,
    /// World positions of the points (m).
    pub points: [G::Point<S>; K],
    /// Force on each point per unit tension, `e_k - e_{k-1}` (world frame).
    pub unit_forces: [G::Point<S>; K],
}

impl<S: Scalar, G: PointGeometry, const K: usize> Path<S, G, K> {
    /// A path through `points`; fewer than two points is a compile error.
    #[must_use]
    pub const fn new(points: [Endpoint<S, G>; K]) -> Self {
        const { assert!(K >= 2, "a path needs at least two points") };
        Self { points }
    }

    /// Checks that every endpoint's body exists in a model of `nb` bodies.
    ///
    /// # Errors
    /// [`Error::InvalidDrive`] naming the first body out of range.
    pub fn check(&self, nb: usize) -> Result<()> {
        for p in &self.points {
            if let Some(body) = p.body {
                if body >= nb {
                    return Err(body_out_of_range(body));
                }
            }
        }
        Ok(())
    }

    /// Length, lengthening velocity and unit forces at the state stored in
    /// `data`: it reads `o_m_i` and `v`, as
    /// [`forward_kinematics_velocity`](crate::algorithm::kinematics::forward_kinematics_velocity)
    /// (or ABA, RNEA) leave them.
    ///
    /// # Errors
    /// [`Error::InvalidDrive`] when an endpoint names a body out of range;
    /// [`Error::NonFinite`] with [`Quantity::PathPoint`] naming a point
    /// whose position is not finite, [`Error::NonFiniteResult`] with it
    /// when the length or its rate overflows.
    pub fn kinematics<const NB: usize, const NV: usize>(
        &self,
        data: &Data<S, NB, NV, G>,
    ) -> Result<PathKinematics<S, G, K>> {
        let kin = self.kinematics_in_element(data)?;
        // Non-finite points make the length (and so the unit forces) so.
        // The rate is not tested: every point that enters it enters the
        // length too, and only an overflow of finite numbers could spoil it
        // alone.
        if !kin.length.is_finite() {
            return Err(self.non_finite_length());
        }
        Ok(kin)
    }

    /// [`kinematics`](Self::kinematics) without the test of the length:
    /// for the springs and muscles, which test the length they read (a
    /// spring's tension, a muscle's state) and whose forces
    /// [`drive_forces`](crate::drive::drive_forces) tests. A test here too
    /// grew the pendulum's image by half a kilobyte.
    pub(crate) fn kinematics_in_element<const NB: usize, const NV: usize>(
        &self,
        data: &Data<S, NB, NV, G>,
    ) -> Result<PathKinematics<S, G, K>> {
        self.check(NB)?;
        let mut points = [G::point_zero::<S>(); K];
        let mut velocities = [G::point_zero::<S>(); K];
        for (k, endpoint) in self.points.iter().enumerate() {
            let Some(b) = endpoint.body else {
                points[k] = endpoint.position;
                continue;
            };
            // `get`, not indexing: `check` has vetted `b`, and a bounds-check
            // panic would link core's number formatting into firmware images.
            let (Some(pose), Some(twist)) = (data.o_m_i.get(b), data.v.get(b)) else {
                return Err(body_out_of_range(b));
            };
            points[k] = pose.act_point(&endpoint.position);
            // The body's velocity seen in the world frame is the velocity
            // of the body point at the world origin, so the point's
            // velocity follows from its world position.
            let v_world = pose.act_motion(twist);
            velocities[k] = G::point_velocity(&v_world, &points[k]);
        }
        let min_length = S::from_f64(MIN_SEGMENT_LENGTH);
        let mut length = S::ZERO;
        let mut lengthening_velocity = S::ZERO;
        let mut unit_forces = [G::point_zero::<S>(); K];
        for k in 0..K - 1 {
            let d = G::point_sub(&points[k + 1], &points[k]);
            let l_squared = G::point_dot(&d, &d);
            if l_squared <= min_length * min_length {
                continue;
            }
            let l = l_squared.sqrt();
            let e = G::point_scale(&d, S::ONE / l);
            length += l;
            lengthening_velocity +=
                G::point_dot(&e, &G::point_sub(&velocities[k + 1], &velocities[k]));
            unit_forces[k] = G::point_add(&unit_forces[k], &e);
            unit_forces[k + 1] = G::point_sub(&unit_forces[k + 1], &e);
        }
        Ok(PathKinematics {
            length,
            lengthening_velocity,
            points,
            unit_forces,
        })
    }

    /// Adds the forces of `tension` (N, positive pulls) along the path to
    /// `f_ext`, one spatial force per body in that body's frame (the external
    /// force convention of the algorithms). Points in the world receive
    /// nothing.
    ///
    /// # Errors
    /// [`Error::InvalidDrive`] when an endpoint names a body out of range;
    /// [`Error::NonFinite`] with [`Quantity::ExternalForce`] naming the
    /// first body on the path for a non-finite `tension`.
    pub fn add_tension<const NB: usize, const NV: usize>(
        &self,
        kinematics: &PathKinematics<S, G, K>,
        tension: S,
        data: &Data<S, NB, NV, G>,
        f_ext: &mut [G::Force<S>; NB],
    ) -> Result<()> {
        // The unit forces come from `kinematics`, checked there: a finite
        // tension gives finite forces.
        if !tension.is_finite() {
            return Err(self.non_finite_tension());
        }
        self.add_tension_in_element(kinematics, tension, data, f_ext)
    }

    /// [`add_tension`](Self::add_tension) without the test of the tension:
    /// for the springs and muscles, which test the tension they compute
    /// and whose forces [`drive_forces`](crate::drive::drive_forces)
    /// tests.
    pub(crate) fn add_tension_in_element<const NB: usize, const NV: usize>(
        &self,
        kinematics: &PathKinematics<S, G, K>,
        tension: S,
        data: &Data<S, NB, NV, G>,
        f_ext: &mut [G::Force<S>; NB],
    ) -> Result<()> {
        self.check(NB)?;
        for (k, endpoint) in self.points.iter().enumerate() {
            if let Some(b) = endpoint.body {
                let f = G::point_scale(&kinematics.unit_forces[k], tension);
                let f_world = G::force_at_point(&f, &kinematics.points[k]);
                // `get` for the reason given in `kinematics`.
                let (Some(pose), Some(f_body)) = (data.o_m_i.get(b), f_ext.get_mut(b)) else {
                    return Err(body_out_of_range(b));
                };
                *f_body += pose.act_inv_force(&f_world);
            }
        }
        Ok(())
    }

    /// The error of a path whose length came out non-finite: the first
    /// point given as not finite (the body poses are: forward kinematics
    /// checks them), otherwise an overflow.
    // Out of line, and reading the points rather than the caller's world
    // positions, which it then kept alive: inlined, or handed those, the
    // search grew the pendulum's image by half a kilobyte.
    #[cold]
    #[inline(never)]
    fn non_finite_length(&self) -> Error {
        non_finite_path::<S, G>(self.points.iter().map(|p| p.position))
    }

    /// The error of a non-finite tension: the force on the path's first
    /// body.
    #[cold]
    #[inline(never)]
    fn non_finite_tension(&self) -> Error {
        Error::NonFinite {
            quantity: Quantity::ExternalForce,
            index: self.points.iter().find_map(|p| p.body).unwrap_or(0),
        }
    }

    /// The same path in another scalar type.
    #[must_use]
    pub fn cast<T: Scalar>(&self) -> Path<T, G, K> {
        Path {
            points: core::array::from_fn(|k| Endpoint {
                body: self.points[k].body,
                position: G::cast_point(&self.points[k].position),
            }),
        }
    }
}

/// The error of a path whose length or rate came out non-finite, from
/// the points' world positions: the first that is not finite, otherwise
/// an overflow.
#[inline]
pub(crate) fn non_finite_path<S: Scalar, G: PointGeometry>(
    mut points: impl Iterator<Item = G::Point<S>>,
) -> Error {
    // `p − p` is zero exactly when every entry of `p` is finite.
    let finite = |p: &G::Point<S>| {
        let zero = G::point_sub(p, p);
        G::point_dot(&zero, &zero) == S::ZERO
    };
    match points.position(|p| !finite(&p)) {
        Some(index) => Error::NonFinite {
            quantity: Quantity::PathPoint,
            index,
        },
        None => Error::NonFiniteResult {
            quantity: Quantity::PathPoint,
            index: 0,
        },
    }
}

/// The error of an endpoint on a body the model does not have.
pub(crate) fn body_out_of_range(body: usize) -> Error {
    Error::InvalidDrive {
        problem: DriveProblem::BodyOutOfRange { body },
    }
}
