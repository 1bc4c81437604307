//! Frames, Jacobians and their time variation, the centre of mass and the
//! centroidal map.

use super::check::Input;
use super::padded::{Padded, Scratch};
use super::{RuntimeError, RuntimeModel, Workspace};
use rodyn::algorithm::centroidal::centroidal_map;
use rodyn::algorithm::energy::center_of_mass;
use rodyn::algorithm::frame_chain::chain_jacobian;
use rodyn::algorithm::frames::{frame_placement, ReferenceFrame};
use rodyn::algorithm::jacobian::{frame_jacobian_time_variation, joint_jacobians_time_variation};
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::spatial::{Motion, Transform};

/// The frame a Jacobian's rows are expressed in (Pinocchio's
/// `ReferenceFrame`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reference {
    /// The frame's own axes, at its origin (`LOCAL`).
    Local,
    /// The world's axes, at the world's origin (`WORLD`).
    World,
    /// The world's axes, at the frame's origin (`LOCAL_WORLD_ALIGNED`).
    LocalWorldAligned,
}

impl Reference {
    fn rodyn(self) -> ReferenceFrame {
        match self {
            Self::Local => ReferenceFrame::Local,
            Self::World => ReferenceFrame::World,
            Self::LocalWorldAligned => ReferenceFrame::LocalWorldAligned,
        }
    }
}

/// `m` as a 4 × 4 homogeneous matrix, row-major.
fn homogeneous(m: &Transform<f64>, out: &mut [f64; 16]) {
    for r in 0..3 {
        out[4 * r..4 * r + 3].copy_from_slice(&m.rot.m[r]);
    }
    out[3] = m.trans.x;
    out[7] = m.trans.y;
    out[11] = m.trans.z;
    out[12..].copy_from_slice(&[0.0, 0.0, 0.0, 1.0]);
}

/// The first `nv` columns as a `6 × nv` row-major matrix, linear rows first.
fn linear_first_rows(columns: &[Motion<f64>], nv: usize, out: &mut [f64]) {
    for (k, c) in columns[..nv].iter().enumerate() {
        for (r, x) in c.to_linear_first().into_iter().enumerate() {
            out[r * nv + k] = x;
        }
    }
}

impl RuntimeModel {
    /// The world placement `ᵒMf` of `frame` at `q`, a 4 × 4 homogeneous
    /// matrix, row-major.
    ///
    /// # Errors
    /// An unknown frame; as [`rnea`](Self::rnea).
    pub fn frame_placement(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        frame: &str,
        out: &mut [f64; 16],
    ) -> Result<(), RuntimeError> {
        let f = self.frame(frame)?;
        class_call!(self, ws, "frame placement",
            inputs: [q],
            checks: [],
            |m, s| forward_kinematics(&m.model, &mut s.data, &s.q)
                .and_then(|()| frame_placement(&s.data, f))
                .map(|o_m_f| homogeneous(&o_m_f, out)))
    }

    /// The Jacobian of `frame` at `q` in `reference` into `out`: `6 × nv`,
    /// row-major, linear rows first (Pinocchio's `computeFrameJacobian`),
    /// walking only the joints that move the frame.
    ///
    /// # Errors
    /// An unknown frame; as [`rnea`](Self::rnea).
    pub fn frame_jacobian(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        frame: &str,
        reference: Reference,
        out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        let f = self.frame_index(frame)?;
        self.check_q(q)?;
        self.check_matrix("out", out, 6)?;
        dispatch!(&self.class, &mut ws.class, |m, s| {
            class_frame_jacobian(m, s, q, f, reference.rodyn(), out).map_err(|e| {
                self.explain(
                    "frame Jacobian",
                    &e,
                    &[Input {
                        name: "q",
                        values: q,
                    }],
                )
            })
        })
    }

    /// The time variation `J̇(q, v)` of `frame`'s Jacobian in `reference`
    /// into `out` (`6 × nv`, as [`frame_jacobian`](Self::frame_jacobian);
    /// Pinocchio's `getFrameJacobianTimeVariation`).
    ///
    /// # Errors
    /// An unknown frame; as [`rnea`](Self::rnea).
    pub fn frame_jacobian_time_variation(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        frame: &str,
        reference: Reference,
        out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        let f = self.frame(frame)?;
        let nv = self.nv;
        class_call!(self, ws, "frame Jacobian time variation",
            inputs: [q, "v" => v],
            checks: [self.check_matrix("out", out, 6)],
            |m, s| joint_jacobians_time_variation(&m.model, &mut s.data, &mut s.jacobians, &s.q, &s.v)
                .and_then(|()| {
                    frame_jacobian_time_variation(
                        &m.model,
                        &s.data,
                        &s.jacobians,
                        f,
                        reference.rodyn(),
                        &mut s.columns,
                    )
                })
                .map(|()| linear_first_rows(&s.columns[..], nv, out)))
    }

    /// The centre of mass at `q`, world frame (m).
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea); a model without mass.
    pub fn com(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        out: &mut [f64; 3],
    ) -> Result<(), RuntimeError> {
        class_call!(self, ws, "centre of mass",
            inputs: [q],
            checks: [],
            |m, s| center_of_mass(&m.model, &mut s.data, &s.q)
                .map(|(c, _mass)| *out = [c.x, c.y, c.z]))
    }

    /// The centroidal momentum map `A_g(q)` into `out`: `6 × nv`,
    /// row-major, linear momentum rows first (Pinocchio's
    /// `computeCentroidalMap`), about the centre of mass in world axes.
    ///
    /// # Errors
    /// As [`rnea`](Self::rnea).
    pub fn centroidal_map(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        let nv = self.nv;
        class_call!(self, ws, "centroidal map",
        inputs: [q],
        checks: [self.check_matrix("out", out, 6)],
        |m, s| centroidal_map(&m.model, &mut s.data, &mut s.centroidal, &s.q).map(|()| {
            for (k, column) in s.centroidal.ag[..nv].iter().enumerate() {
                for (r, x) in column.to_linear_first().into_iter().enumerate() {
                    out[r * nv + k] = x;
                }
            }
        }))
    }
}

/// One class's frame Jacobian: `q` in, the `6 × nv` rows out (`out` holds
/// `6 nv` entries), along the support path found at load time. A function
/// of its own per class, as `class_crba`: each class's walk is optimised
/// as a unit instead of as one arm of the dispatch.
#[inline(never)]
fn class_frame_jacobian<const NB: usize, const NQ: usize, const NV: usize>(
    m: &Padded<NB, NQ, NV>,
    s: &mut Scratch<NB, NQ, NV>,
    q: &[f64],
    frame: usize,
    reference: ReferenceFrame,
    out: &mut [f64],
) -> rodyn::Result<()> {
    s.set_q(q);
    chain_jacobian(&m.model, &s.q, &m.chains[frame], reference, &mut s.columns)?;
    linear_first_rows(&s.columns[..], out.len() / 6, out);
    Ok(())
}
