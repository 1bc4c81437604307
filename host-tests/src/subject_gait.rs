//! Inverse dynamics of OpenSim's subject01 walk (`data/gait/`) with
//! the planar model `models/gait_subject01.toml`: reading the inputs, the
//! change between OpenSim's coordinates and the model's, the ground
//! reactions as external forces, and the load at a transfemoral socket.
//!
//! OpenSim's coordinates, as in the data: `pelvis_tilt`, `pelvis_tx`,
//! `pelvis_ty` (the pelvis origin in ground and its angle), then the joint
//! angles. The model's pelvis is a planar floating joint whose velocity
//! coordinates are the pelvis' own-frame velocity `(vx, vy, ω)`: with
//! `R(θ)` the pelvis rotation and `p` its origin,
//!
//! ```text
//! v_b = Rᵀ ṗ,   v̇_b = Rᵀ p̈ + ω (v_b,y, −v_b,x),
//! ```
//!
//! and its generalised forces `(F_b, M)` map back to OpenSim's residuals
//! by virtual power: `(τ_tx, τ_ty) = R F_b`, `τ_tilt = M`.

pub use crate::gait_subject01::{body, endpoint, q as qi, v as vi, NB, NQ, NV};
use crate::gait_subject01::{ENDPOINTS_F64, MODEL_F32, MODEL_F64};
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::algorithm::rnea::rnea;
use rodyn::planar::{Planar, PlanarForce, PlanarTransform, Vec2};
use rodyn::space::RigidTransform;
use rodyn::{Data, Model, Scalar};
use std::fmt;
use std::path::{Path, PathBuf};

/// The model in scalar `S`.
pub type SubjectModel<S> = Model<S, NB, NQ, NV, Planar>;

/// The subject's model in `f64` and `f32`.
pub const MODEL: (SubjectModel<f64>, SubjectModel<f32>) = (MODEL_F64, MODEL_F32);

/// OpenSim's coordinate names in the data's order (the `q_`, `qd_`, `qdd_`
/// columns).
pub const COORDINATES: [&str; 10] = [
    "pelvis_tilt",
    "pelvis_tx",
    "pelvis_ty",
    "hip_flexion_r",
    "knee_angle_r",
    "ankle_angle_r",
    "hip_flexion_l",
    "knee_angle_l",
    "ankle_angle_l",
    "lumbar_extension",
];

/// The joint-load columns of `joint_loads.csv`, in the data README's
/// convention (the generalised force on the child body in the positive
/// coordinate direction; the pelvis columns are the residuals).
pub const LOAD_COLUMNS: [&str; 10] = [
    "tau_pelvis_tilt_Nm",
    "tau_pelvis_tx_N",
    "tau_pelvis_ty_N",
    "tau_hip_flexion_r_Nm",
    "tau_knee_angle_r_Nm",
    "tau_ankle_angle_r_Nm",
    "tau_hip_flexion_l_Nm",
    "tau_knee_angle_l_Nm",
    "tau_ankle_angle_l_Nm",
    "tau_lumbar_extension_Nm",
];

/// Standard gravity, as the data and the model use it (m/s²).
pub const GRAVITY: f64 = 9.80665;

/// One foot's ground reaction, in ground: the force of the ground on the
/// foot (N), its point of application (m) and the free moment about z
/// (N m).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Reaction {
    /// `(Fx, Fy)`, N.
    pub force: [f64; 2],
    /// `(CoPx, CoPy)`, m.
    pub cop: [f64; 2],
    /// `Tz`, N m.
    pub free_moment: f64,
}

/// One 60 Hz instant of `inverse_dynamics_inputs_60hz.csv`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Time, s.
    pub time: f64,
    /// Coordinates in [`COORDINATES`] order (rad, m).
    pub q: [f64; 10],
    /// Their rates.
    pub qd: [f64; 10],
    /// Their second derivatives.
    pub qdd: [f64; 10],
    /// Right foot.
    pub right: Reaction,
    /// Left foot.
    pub left: Reaction,
}

/// A problem with an input file, with its place.
#[derive(Debug)]
pub struct InputError {
    /// The file.
    pub file: PathBuf,
    /// Line, from 1 (0 for the file as a whole).
    pub line: u64,
    /// The column's name, when one is at fault.
    pub column: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file.display())?;
        // Line 0 is the file as a whole.
        if self.line > 0 {
            write!(f, ":{}", self.line)?;
        }
        if let Some(column) = &self.column {
            write!(f, ": column `{column}`")?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for InputError {}

/// Reads `inverse_dynamics_inputs_60hz.csv`.
///
/// # Errors
/// A missing file or column, a row with too few fields, a field that is
/// not a finite number, and a foot force with no finite centre of
/// pressure: each named by file, line and column.
pub fn read_inputs(path: &Path) -> Result<Vec<Sample>, InputError> {
    let error = |line: u64, column: Option<&str>, message: String| InputError {
        file: path.to_path_buf(),
        line,
        column: column.map(str::to_owned),
        message,
    };
    let mut reader = csv::Reader::from_path(path).map_err(|e| error(0, None, e.to_string()))?;
    let headers = reader
        .headers()
        .map_err(|e| error(1, None, e.to_string()))?
        .clone();
    let column = |name: &str| {
        headers
            .iter()
            .position(|h| h == name)
            .ok_or_else(|| error(1, Some(name), "missing column".to_owned()))
    };
    let kinematic = |prefix: &str, unit: &dyn Fn(&str) -> &'static str| {
        COORDINATES
            .iter()
            .map(|c| column(&format!("{prefix}_{c}_{}", unit(c))))
            .collect::<Result<Vec<_>, _>>()
    };
    let angular = |c: &str| c.ends_with("_tx") || c.ends_with("_ty");
    let q_columns = kinematic("q", &|c| if angular(c) { "m" } else { "rad" })?;
    let qd_columns = kinematic("qd", &|c| if angular(c) { "m_per_s" } else { "rad_per_s" })?;
    let qdd_columns = kinematic("qdd", &|c| {
        if angular(c) {
            "m_per_s2"
        } else {
            "rad_per_s2"
        }
    })?;
    let foot = |side: &str| {
        ["Fx_N", "Fy_N", "CoPx_m", "CoPy_m", "Tz_Nm"].map(|name| column(&format!("{side}_{name}")))
    };
    let time = column("time_s")?;
    let [r_fx, r_fy, r_cx, r_cy, r_tz] = foot("r");
    let [l_fx, l_fy, l_cx, l_cy, l_tz] = foot("l");
    let (r, l) = (
        [r_fx?, r_fy?, r_cx?, r_cy?, r_tz?],
        [l_fx?, l_fy?, l_cx?, l_cy?, l_tz?],
    );

    let mut samples = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| {
            let line = e.position().map_or(0, csv::Position::line);
            error(line, None, e.to_string())
        })?;
        let line = record.position().map_or(0, csv::Position::line);
        let field = |k: usize| -> Result<f64, InputError> {
            let name = &headers[k];
            let text = record
                .get(k)
                .ok_or_else(|| error(line, Some(name), "missing field".to_owned()))?;
            match text.trim().parse::<f64>() {
                Ok(x) if x.is_finite() => Ok(x),
                Ok(x) => Err(error(
                    line,
                    Some(name),
                    format!("{x} is not a finite number"),
                )),
                Err(_) => Err(error(line, Some(name), format!("`{text}` is not a number"))),
            }
        };
        let array = |columns: &[usize]| -> Result<[f64; 10], InputError> {
            let mut out = [0.0; 10];
            for (o, &k) in out.iter_mut().zip(columns) {
                *o = field(k)?;
            }
            Ok(out)
        };
        let reaction = |c: [usize; 5]| -> Result<Reaction, InputError> {
            let force = [field(c[0])?, field(c[1])?];
            let cop = [c[2], c[3]].map(&field);
            let cop = match cop {
                [Ok(x), Ok(y)] => [x, y],
                [Err(e), _] | [_, Err(e)] if force != [0.0, 0.0] => {
                    return Err(InputError {
                        message: format!(
                            "{}; the foot carries a force, so it needs a centre of pressure",
                            e.message
                        ),
                        ..e
                    })
                }
                // No force: the centre of pressure does not matter.
                _ => [0.0, 0.0],
            };
            Ok(Reaction {
                force,
                cop,
                free_moment: field(c[4])?,
            })
        };
        samples.push(Sample {
            time: field(time)?,
            q: array(&q_columns)?,
            qd: array(&qd_columns)?,
            qdd: array(&qdd_columns)?,
            right: reaction(r)?,
            left: reaction(l)?,
        });
    }
    if samples.is_empty() {
        return Err(error(0, None, "no data rows".to_owned()));
    }
    Ok(samples)
}

/// Checks that `samples`, read from `path`, are enough for an analysis:
/// at least `min_rows` rows (`why` says what needs them), and times that
/// reach from `span.0` to `span.1` seconds. A file that passes
/// [`read_inputs`] can still be too short for an analysis that averages
/// over its inner frames or follows a gait cycle: without this check such
/// a file gives NaN averages or an index out of range.
///
/// # Errors
/// The file, how many rows it has or which times they cover, and what is
/// missing.
pub fn check_coverage(
    path: &Path,
    samples: &[Sample],
    min_rows: usize,
    why: &str,
    span: (f64, f64),
) -> Result<(), InputError> {
    let error = |message: String| InputError {
        file: path.to_path_buf(),
        line: 0,
        column: None,
        message,
    };
    if samples.len() < min_rows {
        return Err(error(format!(
            "{} data rows, too few: at least {min_rows} are needed ({why})",
            samples.len()
        )));
    }
    let (first, last) = match (samples.first(), samples.last()) {
        (Some(first), Some(last)) => (first.time, last.time),
        _ => return Err(error("no data rows".to_owned())),
    };
    // A thousandth of a 60 Hz frame: the times are printed to 1e-8 s.
    let slack = 1e-5;
    if first > span.0 + slack || last < span.1 - slack {
        return Err(error(format!(
            "the rows cover {first:.3}-{last:.3} s, but {:.3}-{:.3} s is needed",
            span.0, span.1
        )));
    }
    Ok(())
}

/// The model's `(q, v, v̇)` from OpenSim's coordinates, rates and
/// accelerations (see the module documentation).
#[must_use]
pub fn model_state(s: &Sample) -> ([f64; NQ], [f64; NV], [f64; NV]) {
    let (tilt, tilt_rate, tilt_acc) = (s.q[0], s.qd[0], s.qdd[0]);
    let (c, sn) = (tilt.cos(), tilt.sin());
    // Rᵀ x for a ground vector x.
    let to_pelvis = |x: f64, y: f64| [c * x + sn * y, -sn * x + c * y];
    let v_b = to_pelvis(s.qd[1], s.qd[2]);
    let a_rot = to_pelvis(s.qdd[1], s.qdd[2]);
    let a_b = [a_rot[0] + tilt_rate * v_b[1], a_rot[1] - tilt_rate * v_b[0]];
    let mut q = [0.0; NQ];
    let mut v = [0.0; NV];
    let mut a = [0.0; NV];
    q[qi::PELVIS..qi::PELVIS + 3].copy_from_slice(&[s.q[1], s.q[2], tilt]);
    v[vi::PELVIS..vi::PELVIS + 3].copy_from_slice(&[v_b[0], v_b[1], tilt_rate]);
    a[vi::PELVIS..vi::PELVIS + 3].copy_from_slice(&[a_b[0], a_b[1], tilt_acc]);
    for (k, (qk, vk)) in JOINTS.iter().enumerate() {
        let source = 3 + k;
        q[*qk] = s.q[source];
        v[*vk] = s.qd[source];
        a[*vk] = s.qdd[source];
    }
    (q, v, a)
}

/// The model's `(q, v)` index of each OpenSim joint coordinate after the
/// pelvis, in [`COORDINATES`] order.
const JOINTS: [(usize, usize); 7] = [
    (qi::HIP_FLEXION_R, vi::HIP_FLEXION_R),
    (qi::KNEE_ANGLE_R, vi::KNEE_ANGLE_R),
    (qi::ANKLE_ANGLE_R, vi::ANKLE_ANGLE_R),
    (qi::HIP_FLEXION_L, vi::HIP_FLEXION_L),
    (qi::KNEE_ANGLE_L, vi::KNEE_ANGLE_L),
    (qi::ANKLE_ANGLE_L, vi::ANKLE_ANGLE_L),
    (qi::LUMBAR_EXTENSION, vi::LUMBAR_EXTENSION),
];

/// OpenSim's generalised forces in [`LOAD_COLUMNS`] order from the model's
/// `τ` at pelvis angle `tilt`.
#[must_use]
pub fn opensim_loads(tau: &[f64; NV], tilt: f64) -> [f64; 10] {
    let (c, s) = (tilt.cos(), tilt.sin());
    let (fx, fy) = (tau[vi::PELVIS], tau[vi::PELVIS + 1]);
    let mut out = [0.0; 10];
    out[0] = tau[vi::PELVIS + 2];
    out[1] = c * fx - s * fy;
    out[2] = s * fx + c * fy;
    for (k, (_, vk)) in JOINTS.iter().enumerate() {
        out[3 + k] = tau[*vk];
    }
    out
}

/// A ground reaction as a force on a foot in the foot's frame, about its
/// origin (RNEA's `f_ext`), given the foot's pose in ground.
#[must_use]
pub fn foot_force<S: Scalar>(o_m_foot: &PlanarTransform<S>, r: &Reaction) -> PlanarForce<S> {
    let f = |x: f64| S::from_f64(x);
    let force_world = Vec2::new(f(r.force[0]), f(r.force[1]));
    let cop_world = Vec2::new(f(r.cop[0]), f(r.cop[1]));
    let at = o_m_foot.rotate_inv(&(cop_world - o_m_foot.trans));
    let mut force = PlanarForce::at_point(o_m_foot.rotate_inv(&force_world), &at);
    // A pure moment is the same about any point and in any frame of the plane.
    force.ang += f(r.free_moment);
    force
}

/// The load at a transfemoral socket, in the thigh's frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SocketLoad {
    /// τ_p, moment about z on the residual thigh at the socket point (N m),
    /// counter-clockwise positive.
    pub torque: f64,
    /// F_p along the thigh's long axis (its y axis, towards the hip), N:
    /// positive pushes the residual limb up into the socket (compression,
    /// stance), negative pulls it (tension, the limb hanging in swing).
    pub normal: f64,
    /// Shear along the thigh's x axis (anterior), N.
    pub shear: f64,
}

/// The result at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Time, s.
    pub time: f64,
    /// OpenSim's generalised forces, [`LOAD_COLUMNS`] order.
    pub loads: [f64; 10],
    /// The load on the residual thigh at the `socket` point.
    pub socket: SocketLoad,
}

/// Inverse dynamics of one sample in scalar `S`: the model's `τ` (its own
/// coordinates) and, in `f64`, the socket load.
///
/// # Errors
/// Those of RNEA.
pub fn model_torques<S: Scalar>(
    model: &SubjectModel<S>,
    data: &mut Data<S, NB, NV, Planar>,
    sample: &Sample,
) -> rodyn::Result<[S; NV]> {
    let (q, v, a) = model_state(sample);
    let cast = |x: &[f64; NV]| x.map(S::from_f64);
    let q = cast(&q);
    forward_kinematics(model, data, &q)?;
    let mut f_ext = [PlanarForce::new(S::ZERO, Vec2::ZERO); NB];
    f_ext[body::FOOT_R] = foot_force(&data.o_m_i[body::FOOT_R], &sample.right);
    f_ext[body::FOOT_L] = foot_force(&data.o_m_i[body::FOOT_L], &sample.left);
    Ok(*rnea(model, data, &q, &cast(&v), &cast(&a), Some(&f_ext))?)
}

/// Inverse dynamics of one sample in `f64` with the socket load.
///
/// # Errors
/// Those of RNEA.
pub fn inverse_dynamics(
    model: &SubjectModel<f64>,
    data: &mut Data<f64, NB, NV, Planar>,
    sample: &Sample,
) -> rodyn::Result<Frame> {
    let tau = model_torques(model, data, sample)?;
    Ok(Frame {
        time: sample.time,
        loads: opensim_loads(&tau, sample.q[0]),
        socket: socket_load(data),
    })
}

/// The load on the residual thigh at the socket point: the force the
/// shank exerts on the thigh across the knee (RNEA's `f` of the right
/// tibia, negated and moved into the femur frame), reduced to the socket
/// point `S` (`n_S = n_O − p_S × f`). The thigh's own segment between the
/// socket and the knee is counted as thigh. Needs `li_m_i` and `f` from
/// RNEA.
#[must_use]
pub fn socket_load(data: &Data<f64, NB, NV, Planar>) -> SocketLoad {
    let on_shank = data.li_m_i[body::TIBIA_R].act_force(&data.f[body::TIBIA_R]);
    let on_thigh = -on_shank;
    let socket = ENDPOINTS_F64[endpoint::SOCKET].position;
    SocketLoad {
        torque: on_thigh.ang - socket.cross(&on_thigh.lin),
        normal: on_thigh.lin.y,
        shear: on_thigh.lin.x,
    }
}

/// The model with the right shank and foot replaced by a prosthesis of
/// `fraction` of their mass, with the same centres of mass and moments of
/// inertia scaled by the same fraction.
///
/// # Errors
/// None for a positive fraction (the setters' checks).
pub fn with_prosthesis(fraction: f64) -> rodyn::Result<SubjectModel<f64>> {
    let mut model = MODEL_F64;
    for b in [body::TIBIA_R, body::FOOT_R] {
        let i = *model.inertia(b);
        let scaled = rodyn::planar::PlanarInertia::new(i.mass * fraction, i.com, i.izz * fraction);
        model.set_inertia(b, scaled)?;
    }
    Ok(model)
}

/// The data directory: `data/gait/` in the repository.
#[must_use]
pub fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../data/gait")
}
