//! Reading the frame-chain fixtures of
//! `tools/pinocchio/make_frame_chain_fixtures.py`
//! (`fixtures/frame_chain/*.json`): a branched robot on a free flyer, the
//! frames a controller asks for (feet, hands, grippers), and Pinocchio's
//! `computeFrameJacobian` for them at random states.

use crate::contact_fixture::{array, numbers, transform};
use crate::fixture::{fixtures_dir, Fixture};
use rodyn::spatial::Transform;
use rodyn::{Frame, Model};
use serde_json::Value;

/// ANYmal (`anymal_b_simple`): 13 bodies, a free flyer.
pub const ANYMAL: (usize, usize, usize) = (13, 19, 18);
/// Unitree G1 (29 joints): 30 bodies, a free flyer.
pub const G1: (usize, usize, usize) = (30, 36, 35);
/// Talos (`talos_reduced`): 33 bodies, a free flyer.
pub const TALOS: (usize, usize, usize) = (33, 39, 38);

/// One robot's fixture: the model, its named frames and the states.
pub struct FrameChainFixture<const NB: usize, const NQ: usize, const NV: usize> {
    /// The robot.
    pub model: Model<f64, NB, NQ, NV>,
    /// `(name, frame)`, in the file's order (four per robot).
    pub frames: Vec<(String, Frame<f64>)>,
    /// The states.
    pub states: Vec<FrameChainState<NQ, NV>>,
}

/// One state and Pinocchio's results at it, per frame.
pub struct FrameChainState<const NQ: usize, const NV: usize> {
    /// Configuration.
    pub q: [f64; NQ],
    /// Velocity.
    pub v: [f64; NV],
    /// Per frame: `ᵒMf`.
    pub placements: Vec<Transform<f64>>,
    /// Per frame, per reference frame (`local`, `world`,
    /// `local_world_aligned`): the 6 x NV Jacobian, rows linear first.
    pub jacobians: Vec<[Vec<f64>; 3]>,
}

/// `fixtures/frame_chain/<name>.json`.
///
/// # Panics
/// When the fixture is missing, malformed, or not of these sizes.
#[must_use]
pub fn load<const NB: usize, const NQ: usize, const NV: usize>(
    name: &str,
) -> FrameChainFixture<NB, NQ, NV> {
    let path = fixtures_dir().join(format!("frame_chain/{name}.json"));
    let model = Fixture::load(&path).unwrap().model::<NB, NQ, NV>().unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let value: Value = serde_json::from_str(&text).unwrap();
    let frames = value["frames"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            let body = usize::try_from(f["body"].as_u64().unwrap()).unwrap();
            (
                f["name"].as_str().unwrap().to_owned(),
                Frame::new(body, transform(&f["placement"])),
            )
        })
        .collect();
    let states = value["frame_states"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            let per_frame = s["frames"].as_array().unwrap();
            FrameChainState {
                q: array(&s["q"]),
                v: array(&s["v"]),
                placements: per_frame
                    .iter()
                    .map(|f| transform(&f["placement"]))
                    .collect(),
                jacobians: per_frame
                    .iter()
                    .map(|f| ["local", "world", "local_world_aligned"].map(|r| numbers(&f[r])))
                    .collect(),
            }
        })
        .collect();
    FrameChainFixture {
        model,
        frames,
        states,
    }
}
