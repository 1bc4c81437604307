//! Inverse dynamics of the gait model with ground reactions, and the load at
//! the prosthesis' socket interface.

use super::data::FootLoad;
use super::gait_planar::{body, endpoint, ENDPOINTS_F64, NB, NQ, NV};
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::algorithm::rnea::rnea;
use rodyn::planar::{Planar, PlanarForce, PlanarTransform, Vec2};
use rodyn::space::RigidTransform;
use rodyn::{Data, Model, Scalar};

/// The gait model in scalar `S`.
pub type GaitModel<S> = Model<S, NB, NQ, NV, Planar>;
/// Its workspace.
pub type GaitData<S> = Data<S, NB, NV, Planar>;

/// The load the prosthesis (right shank and foot) exerts on the residual
/// thigh, reduced to the `socket` point and expressed in the thigh's frame
/// (y along the thigh's long axis towards the hip, x anterior, z out of the
/// sagittal plane).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InterfaceLoad<S> {
    /// τ_p: moment about z at the socket (N m); positive turns the thigh
    /// counter-clockwise, towards hip flexion.
    pub torque: S,
    /// F_p: force along the thigh's long axis (N); positive pushes the
    /// residual limb into the socket towards the hip (compression).
    pub normal: S,
    /// Shear force along the thigh's x axis (N); positive anterior.
    pub shear: S,
}

/// The result of inverse dynamics at one instant of the cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaitFrame<S> {
    /// Generalised forces `τ` in the model's `v` order: the first three are
    /// the residual at the floating pelvis (`fx, fy` in N in the pelvis
    /// frame, moment in N m about the hip), then the joint torques (N m).
    pub tau: [S; NV],
    /// The load at the socket interface.
    pub interface: InterfaceLoad<S>,
}

/// The sole point under the centre of pressure `cop` (x in the foot frame):
/// on the line through the heel and toe endpoints.
#[must_use]
pub fn sole_point<S: Scalar>(cop: S) -> Vec2<S> {
    let heel = ENDPOINTS_F64[endpoint::R_HEEL].position;
    Vec2::new(cop, S::from_f64(heel.y))
}

/// The ground reaction on a foot as a planar force in the foot's own frame
/// (RNEA's `f_ext` convention), given the foot's pose `o_m_foot`.
#[must_use]
pub fn foot_force<S: Scalar>(o_m_foot: &PlanarTransform<S>, load: &FootLoad) -> PlanarForce<S> {
    let world = Vec2::new(S::from_f64(load.force[0]), S::from_f64(load.force[1]));
    PlanarForce::at_point(
        o_m_foot.rotate_inv(&world),
        &sole_point(S::from_f64(load.cop)),
    )
}

/// Joint torques, floating-base residual and socket load at state
/// `(q, v, a)` with ground reactions on the right and left feet.
///
/// # Errors
/// Those of [`rnea`]: non-finite inputs.
pub fn gait_inverse_dynamics<S: Scalar>(
    model: &GaitModel<S>,
    data: &mut GaitData<S>,
    (q, v, a): (&[S; NQ], &[S; NV], &[S; NV]),
    right: &FootLoad,
    left: &FootLoad,
) -> rodyn::Result<GaitFrame<S>> {
    forward_kinematics(model, data, q)?;
    let mut f_ext = [PlanarForce::new(S::ZERO, Vec2::ZERO); NB];
    f_ext[body::R_FOOT] = foot_force(&data.o_m_i[body::R_FOOT], right);
    f_ext[body::L_FOOT] = foot_force(&data.o_m_i[body::L_FOOT], left);
    let tau = *rnea(model, data, q, v, a, Some(&f_ext))?;
    Ok(GaitFrame {
        tau,
        interface: interface_load(data),
    })
}

/// The socket load from RNEA's joint force at the right knee.
///
/// `data.f[R_SHANK]` is the force the thigh exerts on the prosthesis across
/// the knee, in the shank frame about the knee; its negative, moved into
/// the thigh frame and reduced to the socket point (`n_S = n_O − p_S × f`),
/// is the load on the residual limb. Needs `li_m_i` and `f` from [`rnea`].
#[must_use]
pub fn interface_load<S: Scalar>(data: &GaitData<S>) -> InterfaceLoad<S> {
    let on_prosthesis = data.li_m_i[body::R_SHANK].act_force(&data.f[body::R_SHANK]);
    let on_thigh = -on_prosthesis;
    let socket = ENDPOINTS_F64[endpoint::SOCKET].position.cast::<S>();
    InterfaceLoad {
        torque: on_thigh.ang - socket.cross(&on_thigh.lin),
        normal: on_thigh.lin.y,
        shear: on_thigh.lin.x,
    }
}
