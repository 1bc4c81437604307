//! The gait input files in `host-tests/data/gait/`: joint trajectories as
//! Fourier series and ground reaction forces per foot.
//!
//! * `joint_fourier.csv`: one row per configuration coordinate of the model,
//!   in the model's `q` order, `coordinate,period_s,mean,slope,cos1,sin1,...`.
//!   Angles in rad (model convention: counter-clockwise about z with x
//!   forward and y up, so hip flexion and ankle dorsiflexion are positive and
//!   knee flexion is negative); pelvis position in m relative to the pelvis
//!   joint's placement, slope in m/s.
//! * `ground_reaction.csv`: one row per percent of the cycle,
//!   `percent,time_s,r_fx,r_fy,r_cop,l_fx,l_fy,l_cop`. Forces in N in the
//!   world frame (x forward, y up), exerted by the ground on the foot; `cop`
//!   is the centre of pressure's x in the foot's frame (m), on the sole line.

use super::fourier::FourierSeries;
use super::gait_planar::{NQ, NV};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Names of the configuration coordinates, in the model's `q` order.
pub const COORDINATES: [&str; NQ] = [
    "pelvis_x",
    "pelvis_y",
    "pelvis_pitch",
    "sacroiliac",
    "l_hip",
    "l_knee",
    "l_ankle",
    "r_hip",
    "r_knee",
    "r_ankle",
];

/// The directory of the gait input files.
#[must_use]
pub fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("data/gait")
}

/// One gait cycle: every configuration coordinate as a Fourier series.
#[derive(Clone, Debug, PartialEq)]
pub struct GaitCycle {
    /// Coordinate trajectories in the model's `q` order.
    pub coordinates: Vec<FourierSeries>,
}

/// A model state `(q, v, a)` with the floating base's velocity and
/// acceleration in the pelvis frame, as the planar floating joint expects.
pub type State = ([f64; NQ], [f64; NV], [f64; NV]);

impl GaitCycle {
    /// The cycle's period (s).
    #[must_use]
    pub fn period(&self) -> f64 {
        self.coordinates[0].period
    }

    /// The model state at time `t` (s).
    ///
    /// The pelvis coordinates are world `x, y, θ`; the planar floating joint
    /// takes its velocity `[vx vy ω]` in the pelvis frame, so
    /// `v_lin = Rᵀ ṗ` and its derivative `a_lin = Rᵀ p̈ − ω × v_lin`
    /// (the spatial acceleration in body coordinates).
    #[must_use]
    pub fn state(&self, t: f64) -> State {
        let (mut q, mut qd, mut qdd) = ([0.0; NQ], [0.0; NV], [0.0; NV]);
        for (k, series) in self.coordinates.iter().enumerate() {
            [q[k], qd[k], qdd[k]] = series.evaluate(t);
        }
        let (sin, cos) = q[2].sin_cos();
        let to_pelvis = |x: f64, y: f64| [cos * x + sin * y, -sin * x + cos * y];
        let omega = qd[2];
        let v_lin = to_pelvis(qd[0], qd[1]);
        let a_lin = to_pelvis(qdd[0], qdd[1]);
        let mut v = qd;
        let mut a = qdd;
        v[..2].copy_from_slice(&v_lin);
        a[0] = a_lin[0] + omega * v_lin[1];
        a[1] = a_lin[1] - omega * v_lin[0];
        (q, v, a)
    }

    /// Reads `joint_fourier.csv`.
    ///
    /// # Errors
    /// A message naming the file and line for an unreadable file, a missing
    /// or misplaced coordinate, or a number that does not parse.
    pub fn read(path: &Path) -> Result<Self, String> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
        let mut coordinates = Vec::new();
        for (line_no, line) in text.lines().enumerate().skip(1) {
            let at = || format!("{}:{}", path.display(), line_no + 1);
            let mut fields = line.split(',');
            let name = fields.next().unwrap_or_default();
            let expected = COORDINATES.get(coordinates.len()).copied();
            if Some(name) != expected {
                return Err(format!(
                    "{}: expected coordinate {expected:?}, found {name:?}",
                    at()
                ));
            }
            let numbers = fields
                .map(|x| {
                    x.trim()
                        .parse::<f64>()
                        .map_err(|e| format!("{}: {x:?}: {e}", at()))
                })
                .collect::<Result<Vec<_>, _>>()?;
            if numbers.len() < 3 || numbers.len() % 2 == 0 {
                return Err(format!(
                    "{}: expected period, mean, slope and cos/sin pairs",
                    at()
                ));
            }
            let pairs = &numbers[3..];
            coordinates.push(FourierSeries {
                period: numbers[0],
                mean: numbers[1],
                slope: numbers[2],
                cos: pairs.iter().step_by(2).copied().collect(),
                sin: pairs.iter().skip(1).step_by(2).copied().collect(),
            });
        }
        if coordinates.len() != NQ {
            return Err(format!(
                "{}: {} coordinates, expected {NQ}",
                path.display(),
                coordinates.len()
            ));
        }
        Ok(Self { coordinates })
    }

    /// The text of `joint_fourier.csv`.
    #[must_use]
    pub fn to_csv(&self) -> String {
        let harmonics = self
            .coordinates
            .iter()
            .map(|c| c.cos.len())
            .max()
            .unwrap_or(0);
        let mut out = String::from("coordinate,period_s,mean,slope");
        for k in 1..=harmonics {
            let _ = write!(out, ",cos{k},sin{k}");
        }
        out.push('\n');
        for (name, c) in COORDINATES.iter().zip(&self.coordinates) {
            let _ = write!(out, "{name},{},{:.9},{:.9}", c.period, c.mean, c.slope);
            for (cos, sin) in c.cos.iter().zip(&c.sin) {
                let _ = write!(out, ",{cos:.9},{sin:.9}");
            }
            out.push('\n');
        }
        out
    }
}

/// The ground reaction on one foot.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FootLoad {
    /// Force of the ground on the foot in the world frame `[fx, fy]` (N).
    pub force: [f64; 2],
    /// Centre of pressure: x in the foot's frame on the sole line (m).
    pub cop: f64,
}

/// The ground reactions at one instant of the cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GroundReaction {
    /// Percent of the gait cycle (0 = right heel strike).
    pub percent: f64,
    /// Time since right heel strike (s).
    pub time: f64,
    /// Right foot (the prosthetic side).
    pub right: FootLoad,
    /// Left foot.
    pub left: FootLoad,
}

/// The header of `ground_reaction.csv`.
pub const GROUND_REACTION_HEADER: &str = "percent,time_s,r_fx,r_fy,r_cop,l_fx,l_fy,l_cop";

impl GroundReaction {
    /// Reads `ground_reaction.csv`.
    ///
    /// # Errors
    /// A message naming the file and line for an unreadable file, a wrong
    /// header, a missing field or a number that does not parse.
    pub fn read_all(path: &Path) -> Result<Vec<Self>, String> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
        let mut lines = text.lines().enumerate();
        match lines.next() {
            Some((_, h)) if h == GROUND_REACTION_HEADER => {}
            _ => {
                return Err(format!(
                    "{}:1: expected header {GROUND_REACTION_HEADER}",
                    path.display()
                ))
            }
        }
        lines
            .map(|(line_no, line)| {
                let at = || format!("{}:{}", path.display(), line_no + 1);
                let x = line
                    .split(',')
                    .map(|x| {
                        x.trim()
                            .parse::<f64>()
                            .map_err(|e| format!("{}: {x:?}: {e}", at()))
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                if x.len() != 8 {
                    return Err(format!("{}: expected 8 fields, found {}", at(), x.len()));
                }
                Ok(Self {
                    percent: x[0],
                    time: x[1],
                    right: FootLoad {
                        force: [x[2], x[3]],
                        cop: x[4],
                    },
                    left: FootLoad {
                        force: [x[5], x[6]],
                        cop: x[7],
                    },
                })
            })
            .collect()
    }

    /// One line of `ground_reaction.csv`.
    #[must_use]
    pub fn to_csv_line(self) -> String {
        let (r, l) = (self.right, self.left);
        format!(
            "{},{:.4},{:.4},{:.4},{:.5},{:.4},{:.4},{:.5}",
            self.percent, self.time, r.force[0], r.force[1], r.cop, l.force[0], l.force[1], l.cop
        )
    }
}
