#!/usr/bin/env python3
"""Writes host-tests/fixtures/frame_chain/{anymal,g1,talos}.json: three
branched robots of example-robot-data on a free flyer, with the frames a
controller asks for every tick (feet, hands, grippers) and Pinocchio's
`computeFrameJacobian` for them at random states.

Regenerate (from the repository root):

    pip install pin example-robot-data
    python3 tools/pinocchio/make_frame_chain_fixtures.py

Robots (URDFs from example-robot-data):

* ANYmal (`anymal_b_simple_description/robots/anymal.urdf`), frames
  LF_FOOT, RF_FOOT, LH_FOOT, RH_FOOT;
* Unitree G1 (`g1_description/urdf/g1_29dof_rev_1_0.urdf`), frames
  left_rubber_hand, right_rubber_hand, left_ankle_roll_link,
  right_ankle_roll_link;
* Talos (`talos_data/robots/talos_reduced.urdf`), frames
  gripper_left_base_link, gripper_right_base_link, left_sole_link,
  right_sole_link.

Each file holds the model (as make_fixtures.py describes one), the frames
(`body`: the index of the frame's parent joint less one, rodyn's body;
`placement`: the frame in that body), and per state `q`, `v` and per frame
its placement `oMf` and its Jacobian in LOCAL, WORLD and
LOCAL_WORLD_ALIGNED (6 x nv, rows linear first). The rodyn benchmark
(`kinematics_timing`) reads the robots and frames from here; Pinocchio's
side (`bench_kinematics.cpp`) reads the same URDFs and frame names.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pinocchio as pin

sys.path.insert(0, str(Path(__file__).resolve().parent))
import make_fixtures as mf  # noqa: E402
from make_models import example_robot_data_dir  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "host-tests" / "fixtures" / "frame_chain"
STATES = 6

ROBOTS = {
    "anymal": (
        "anymal_b_simple_description/robots/anymal.urdf",
        ["LF_FOOT", "RF_FOOT", "LH_FOOT", "RH_FOOT"],
    ),
    "g1": (
        "g1_description/urdf/g1_29dof_rev_1_0.urdf",
        ["left_rubber_hand", "right_rubber_hand", "left_ankle_roll_link", "right_ankle_roll_link"],
    ),
    "talos": (
        "talos_data/robots/talos_reduced.urdf",
        ["gripper_left_base_link", "gripper_right_base_link", "left_sole_link", "right_sole_link"],
    ),
}

REFERENCES = {
    "local": pin.ReferenceFrame.LOCAL,
    "world": pin.ReferenceFrame.WORLD,
    "local_world_aligned": pin.ReferenceFrame.LOCAL_WORLD_ALIGNED,
}


def placement(m: pin.SE3) -> dict:
    return {"rotation": mf.floats(m.rotation), "translation": mf.floats(m.translation)}


def write(name: str, urdf_rel: str, frame_names: list[str]) -> None:
    urdf = example_robot_data_dir() / urdf_rel
    model = pin.buildModelFromUrdf(str(urdf), pin.JointModelFreeFlyer())
    data = model.createData()
    spec = mf.ModelSpec(name, floating=True)
    description = mf.describe(spec, model)
    description["urdf"] = f"example-robot-data: {urdf_rel}"
    frames = []
    ids = []
    for frame_name in frame_names:
        fid = model.getFrameId(frame_name)
        frame = model.frames[fid]
        ids.append(fid)
        frames.append({"name": frame_name, "body": int(frame.parentJoint) - 1, "placement": placement(frame.placement)})
    rng = np.random.default_rng(2026)
    states = []
    for _ in range(STATES):
        q = mf.random_configuration(model, rng)
        v = rng.uniform(-1.0, 1.0, model.nv)
        per_frame = []
        for fid in ids:
            entry = {}
            for key, reference in REFERENCES.items():
                j = pin.computeFrameJacobian(model, data, q, fid, reference)
                entry[key] = mf.floats(j)
            pin.framesForwardKinematics(model, data, q)
            entry["placement"] = placement(data.oMf[fid])
            per_frame.append(entry)
        states.append({"q": mf.floats(q), "v": mf.floats(v), "frames": per_frame})
    fixture = {
        "generator": "tools/pinocchio/make_frame_chain_fixtures.py",
        "pinocchio_version": pin.__version__,
        "model": description,
        "frames": frames,
        "states": [],
        "frame_states": states,
    }
    OUT.mkdir(parents=True, exist_ok=True)
    path = OUT / f"{name}.json"
    path.write_text(json.dumps(fixture) + "\n")
    print(f"wrote {path.relative_to(ROOT)} ({model.nv} velocity coordinates, {len(states)} states)")


def main() -> None:
    for name, (urdf, frames) in ROBOTS.items():
        write(name, urdf, frames)


if __name__ == "__main__":
    main()
