//! One size class: a rodyn model of fixed capacity holding a smaller
//! file's model, and its workspace.
//!
//! The file's bodies come first, in the file's order, so its coordinates
//! are the first `nq` and `nv` of the class's and body, joint and frame
//! indices are unchanged. The rest are padding: revolute joints about z
//! hanging from the world, massless, each with a unit armature so that the
//! mass matrix stays positive definite and ABA's pivots stay non-zero.
//! Padding is a separate subtree of the world at rest (`q = 0`, `v = 0`,
//! no torque): it exchanges no force with the file's bodies, so every
//! result on the file's coordinates is the file model's.

use super::skeleton::Skeleton;
use rodyn::algorithm::centroidal::CentroidalData;
use rodyn::algorithm::constrained_dynamics::ConstraintData;
use rodyn::algorithm::crba::CrbaPlan;
use rodyn::algorithm::derivatives::DerivativeData;
use rodyn::algorithm::frame_chain::FrameChain;
use rodyn::algorithm::inverse_kinematics::IkData;
use rodyn::algorithm::jacobian::JacobianData;
use rodyn::joint::{Axis, Joint};
use rodyn::space::VectorOps;
use rodyn::spatial::{Force, Inertia, Motion, Sym3, Transform, Vec3};
use rodyn::{Data, Model};

/// Most constrained rows a run-time call takes: six frame contacts or
/// twelve point contacts.
pub const MAX_CONTACT_ROWS: usize = 36;

/// The armature of a padding coordinate (kg m²): any positive value keeps
/// its row of the mass matrix invertible, and it never moves.
const PADDING_ARMATURE: f64 = 1.0;

/// A file's model in a class of `NB` bodies, `NQ` and `NV` coordinates.
pub(super) struct Padded<const NB: usize, const NQ: usize, const NV: usize> {
    pub model: Model<f64, NB, NQ, NV>,
    /// CRBA's frames, quarter turns recognised at load time as the
    /// compiled model's `CRBA_PLAN_F64` has them.
    pub plan: CrbaPlan<f64, NB>,
    /// Each frame with its body's support path, in the model's frame
    /// order: found once here rather than on every Jacobian call.
    pub chains: Vec<FrameChain<f64, NB>>,
}

impl<const NB: usize, const NQ: usize, const NV: usize> Padded<NB, NQ, NV> {
    /// The class model of `skeleton`, which must fit (checked by the class
    /// choice: `skeleton.nb() <= NB`, and the coordinates left over are
    /// one per padding body).
    ///
    /// # Errors
    /// The core's checked constructor refuses the tree (a parent after its
    /// child: the model compiler orders bodies, so this names a bug there
    /// rather than panicking), or a frame on a body the model does not
    /// have.
    pub fn new(skeleton: &Skeleton) -> rodyn::Result<Box<Self>> {
        let nb = skeleton.nb();
        let mut parents = [None; NB];
        let mut joints = [Joint::revolute(Axis::Z); NB];
        let mut placements = [Transform::IDENTITY; NB];
        let mut inertias = [Inertia::new(0.0, Vec3::ZERO, Sym3::ZERO); NB];
        parents[..nb].copy_from_slice(&skeleton.parents);
        joints[..nb].copy_from_slice(&skeleton.joints);
        placements[..nb].copy_from_slice(&skeleton.placements);
        inertias[..nb].copy_from_slice(&skeleton.inertias);
        let mut model = Model::try_new(parents, joints, placements, inertias, skeleton.gravity)?;
        let nv_file = NV - (NB - nb);
        let mut armature = [0.0; NV];
        armature[nv_file..].fill(PADDING_ARMATURE);
        model = model.with_armature(armature);
        let plan = CrbaPlan::new(&model);
        let chains = skeleton
            .frames
            .iter()
            .map(|(_, frame)| FrameChain::try_new(&model, frame))
            .collect::<rodyn::Result<_>>()?;
        Ok(Box::new(Self {
            model,
            plan,
            chains,
        }))
    }
}

/// A class's workspace: rodyn's `Data` and the algorithms' own
/// workspaces, and the padded inputs (the padding entries stay at rest:
/// calls write only the file's).
pub(super) struct Scratch<const NB: usize, const NQ: usize, const NV: usize> {
    pub data: Box<Data<f64, NB, NV>>,
    pub derivatives: Box<DerivativeData<f64, NB, NV>>,
    pub jacobians: Box<JacobianData<f64, NV>>,
    pub centroidal: Box<CentroidalData<f64, NB, NV>>,
    pub constraint: Box<ConstraintData<f64, NV, MAX_CONTACT_ROWS>>,
    pub ik: Box<IkData<f64, NV>>,
    pub columns: Box<[Motion<f64>; NV]>,
    /// External forces per body (the drives'), zero between calls.
    pub f_ext: Box<[Force<f64>; NB]>,
    pub q: [f64; NQ],
    pub v: [f64; NV],
    pub a: [f64; NV],
}

impl<const NB: usize, const NQ: usize, const NV: usize> Scratch<NB, NQ, NV> {
    pub fn new(padded: &Padded<NB, NQ, NV>) -> Box<Self> {
        Box::new(Self {
            data: Box::default(),
            derivatives: Box::default(),
            jacobians: Box::default(),
            centroidal: Box::default(),
            constraint: Box::default(),
            ik: Box::default(),
            columns: Box::new([Motion::ZERO; NV]),
            f_ext: Box::new([Force::ZERO; NB]),
            q: padded.model.neutral_configuration(),
            v: [0.0; NV],
            a: [0.0; NV],
        })
    }

    /// `q` into the padded configuration (the caller checked its length).
    #[inline(always)]
    pub fn set_q(&mut self, q: &[f64]) {
        self.q[..q.len()].copy_from_slice(q);
    }
    /// `v` into the padded velocity.
    #[inline(always)]
    pub fn set_v(&mut self, v: &[f64]) {
        self.v[..v.len()].copy_from_slice(v);
    }
    /// A call's velocity-sized inputs in order: the first into `v`, the
    /// second (an acceleration or a torque) into `a`.
    #[inline(always)]
    pub fn set_rates(&mut self, rates: &[&[f64]]) {
        if let Some(v) = rates.first() {
            self.set_v(v);
        }
        if let Some(a) = rates.get(1) {
            self.set_a(a);
        }
    }
    /// `a` (an acceleration or a torque) into the second padded vector.
    #[inline(always)]
    pub fn set_a(&mut self, a: &[f64]) {
        self.a[..a.len()].copy_from_slice(a);
    }
}
