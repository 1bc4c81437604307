#!/usr/bin/env python3
"""Writes Pinocchio reference results for rodyn's kinematics: frames,
Jacobians and centroidal quantities.

Regenerate (from the repository root, after make_fixtures.py):

    python3 tools/pinocchio/make_kinematics_fixtures.py   # host-tests/fixtures/kinematics/*.json

For UR5, Panda, Solo12 (free-flyer root) and the branched tree, the model is
loaded as make_fixtures.py loads it, and the states (q, v, a) are read back
from its fixture `host-tests/fixtures/<name>.json`, so both files describe
the same states. Frames are added on a few bodies with seeded random
placements (a rotation and an offset from the joint frame, Pinocchio's
`OP_FRAME`). Per state the file holds

* `joint_jacobians`, `joint_jacobians_dot`: `computeJointJacobians` and
  `computeJointJacobiansTimeVariation` (world frame, 6 x nv, [linear; angular]);
* per frame: its world placement, `getFrameJacobian` in LOCAL, WORLD and
  LOCAL_WORLD_ALIGNED, `getFrameJacobianTimeVariation` in the same three,
  `getFrameVelocity` and `getFrameClassicalAcceleration` in the three frames
  (at the state's a and at a = 0, the latter being J-dot v);
* `com`, `com_velocity`, `com_acceleration` (`centerOfMass(q, v, a)`),
  `com_jacobian` (`jacobianCenterOfMass`, 3 x nv);
* `ag` (`computeCentroidalMap`, 6 x nv), `ig` (`ccrba`'s `Ig`, 6 x 6), `hg`
  (`ccrba`'s `hg`), `dag` (`dccrba`'s dAg, 6 x nv), `dag_v` (dAg times v), `dhg`
  (`computeCentroidalMomentumTimeVariation(q, v, a)`).

Floats are written with Python's `repr`, so they round-trip exactly.
"""

from __future__ import annotations

import json
import zlib

import numpy as np
import pinocchio as pin

from make_fixtures import OUT, REPO, SPECS, floats, load, write_states_fixture

MODELS = ("ur5", "panda", "solo12", "branched_tree")
OUT_KIN = OUT / "kinematics"
FRAMES_PER_MODEL = 3
RF = {
    "local": pin.ReferenceFrame.LOCAL,
    "world": pin.ReferenceFrame.WORLD,
    "local_world_aligned": pin.ReferenceFrame.LOCAL_WORLD_ALIGNED,
}


def frame_bodies(model: pin.Model) -> list[int]:
    """The last body, one in the middle and the first (rodyn body indices)."""
    nb = model.njoints - 1
    return [nb - 1, nb // 2, 0][:FRAMES_PER_MODEL]


def random_placement(rng: np.random.Generator) -> pin.SE3:
    quat = rng.normal(size=4)
    quat /= np.linalg.norm(quat)
    rot = pin.Quaternion(quat[3], quat[0], quat[1], quat[2]).toRotationMatrix()
    return pin.SE3(rot, rng.uniform(-0.2, 0.2, 3))


def se3(m: pin.SE3) -> dict:
    return {"rotation": floats(m.rotation), "translation": floats(m.translation)}


def state_results(model, data, frame_ids, q, v, a) -> dict:
    nv = model.nv
    pin.computeJointJacobians(model, data, q)
    pin.updateFramePlacements(model, data)
    out = {"joint_jacobians": floats(data.J)}
    frames = []
    for fid in frame_ids:
        entry = {"placement": se3(data.oMf[fid])}
        for name, rf in RF.items():
            entry[f"jacobian_{name}"] = floats(pin.getFrameJacobian(model, data, fid, rf))
        frames.append(entry)
    pin.computeJointJacobiansTimeVariation(model, data, q, v)
    pin.updateFramePlacements(model, data)
    out["joint_jacobians_dot"] = floats(data.dJ)
    for entry, fid in zip(frames, frame_ids):
        for name, rf in RF.items():
            entry[f"jacobian_dot_{name}"] = floats(pin.getFrameJacobianTimeVariation(model, data, fid, rf))
    pin.forwardKinematics(model, data, q, v, a)
    pin.updateFramePlacements(model, data)
    for entry, fid in zip(frames, frame_ids):
        for name, rf in RF.items():
            entry[f"velocity_{name}"] = floats(pin.getFrameVelocity(model, data, fid, rf).vector)
            entry[f"classical_acceleration_{name}"] = floats(
                pin.getFrameClassicalAcceleration(model, data, fid, rf).vector
            )
    pin.forwardKinematics(model, data, q, v, np.zeros(nv))
    for entry, fid in zip(frames, frame_ids):
        for name, rf in RF.items():
            entry[f"jdot_v_{name}"] = floats(pin.getFrameClassicalAcceleration(model, data, fid, rf).vector)
    out["frames"] = frames

    com = pin.centerOfMass(model, data, q, v, a)
    out["com"] = floats(com)
    out["com_velocity"] = floats(data.vcom[0])
    out["com_acceleration"] = floats(data.acom[0])
    out["com_jacobian"] = floats(pin.jacobianCenterOfMass(model, data, q))
    out["ag"] = floats(pin.computeCentroidalMap(model, data, q))
    pin.ccrba(model, data, q, v)
    out["ig"] = floats(data.Ig.matrix())
    out["hg"] = floats(data.hg.vector)
    dag = pin.dccrba(model, data, q, v)
    out["dag"] = floats(dag)
    out["dag_v"] = floats(dag @ v)
    pin.computeCentroidalMomentumTimeVariation(model, data, q, v, a)
    out["dhg"] = floats(data.dhg.vector)
    return out


def main() -> None:
    OUT_KIN.mkdir(parents=True, exist_ok=True)
    specs = {s.name: s for s in SPECS}
    for name in MODELS:
        model = load(specs[name])
        rng = np.random.default_rng(zlib.crc32(f"kinematics {name}".encode()))
        frames = []
        frame_ids = []
        for k, body in enumerate(frame_bodies(model)):
            placement = random_placement(rng)
            fid = model.addFrame(pin.Frame(f"frame_{k}", body + 1, placement, pin.FrameType.OP_FRAME))
            frame_ids.append(fid)
            frames.append({"body": body, "placement": se3(placement)})
        data = model.createData()
        base = json.loads((OUT / f"{name}.json").read_text())
        states = []
        for s in base["states"]:
            q, v, a = (np.array(s[k]) for k in ("q", "v", "a"))
            states.append(state_results(model, data, frame_ids, q, v, a))
        fixture = {
            "generator": "tools/pinocchio/make_kinematics_fixtures.py",
            "pinocchio_version": pin.__version__,
            "model_fixture": f"{name}.json",
            "conventions": (
                "states (q, v, a) are those of model_fixture, in order; spatial vectors and "
                "Jacobian rows [linear; angular]; frame placements body-from-frame (iMf); "
                "rotations row-major; SI units"
            ),
            "frames": frames,
            "states": states,
        }
        write_states_fixture(OUT_KIN / f"{name}.json", fixture)


if __name__ == "__main__":
    main()
