#!/usr/bin/env python3
"""Writes Pinocchio's link frames and their world placements (`data.oMf`)
for the frames rodyn-model writes into a generated module.

Regenerate (from the repository root):

    python3 tools/pinocchio/make_frame_fixtures.py   # host-tests/fixtures/frames/*.json

The Panda (fixed base: its flange `panda_link8`, the hand turned by -45°
about z, the tool centre point) and Solo12 (free-flyer root: the feet) are
loaded as make_fixtures.py loads them. For every `BODY` frame (one per
URDF link) on a moving joint the file holds its name, its rodyn body (the
Pinocchio parent joint minus one) and its placement in that body (`iMf`);
links welded to the world are left out, as the generated module leaves
them out. Per seeded random configuration (make_fixtures.py's rule) it
holds `oMf` of each of those frames after `framesForwardKinematics`.

The same for a test robot with continuous joints,
`crates/rodyn-model/generated-tests/urdf/wheeled_arm.urdf` on a
free-flyer: Pinocchio keeps each continuous joint's angle as
`(cos θ, sin θ)` (`JointModelRUBY`, `RevoluteUnboundedUnaligned`, ...),
so each state also holds the configuration in rodyn's layout (`q_rodyn`,
`θ = atan2(sin, cos)`), which the generated `q_from_pinocchio` must give.

Rotations row-major; floats written with Python's `repr`, so they
round-trip exactly.
"""

from __future__ import annotations

import zlib

import numpy as np
import pinocchio as pin

from make_fixtures import OUT, REPO, SPECS, floats, joint_type, load, random_configuration, write_states_fixture

MODELS = ("panda", "solo12")
CONTINUOUS_URDF = "crates/rodyn-model/generated-tests/urdf/wheeled_arm.urdf"
OUT_FRAMES = OUT / "frames"
STATES = 8


def se3(m: pin.SE3) -> dict:
    return {"rotation": floats(m.rotation), "translation": floats(m.translation)}


def body_frames(model: pin.Model) -> tuple[list[int], list[dict]]:
    """Pinocchio's BODY frames on moving joints: their ids, and each one's
    name, rodyn body and placement."""
    ids = [fid for fid, f in enumerate(model.frames) if f.type == pin.FrameType.BODY and f.parentJoint > 0]
    frames = [
        {
            "name": model.frames[fid].name,
            "body": int(model.frames[fid].parentJoint) - 1,
            "placement": se3(model.frames[fid].placement),
        }
        for fid in ids
    ]
    return ids, frames


def continuous_state(model: pin.Model, data: pin.Data, ids: list[int], rng: np.random.Generator) -> dict:
    """A random configuration in Pinocchio's layout and in rodyn's (one
    angle per continuous joint), with oMf of the frames."""
    q, q_rodyn = [], []
    for joint in model.joints[1:]:
        kind = joint_type(joint)
        if kind == "FreeFlyer":
            quat = rng.normal(size=4)
            part = list(rng.uniform(-1.0, 1.0, 3)) + list(quat / np.linalg.norm(quat))
            q += part
            q_rodyn += part
        elif joint.nq == 2 and joint.nv == 1:  # continuous: (cos θ, sin θ)
            theta = rng.uniform(-np.pi, np.pi)
            c, s = np.cos(theta), np.sin(theta)
            q += [c, s]
            q_rodyn.append(float(np.arctan2(s, c)))
        elif joint.nq == 1:
            x = rng.uniform(-np.pi, np.pi)
            q.append(x)
            q_rodyn.append(x)
        else:
            raise SystemExit(f"{kind}: no random configuration rule")
    q = np.array(q)
    pin.framesForwardKinematics(model, data, q)
    return {"q": floats(q), "q_rodyn": floats(q_rodyn), "o_m_f": [se3(data.oMf[fid]) for fid in ids]}


def continuous_fixture() -> None:
    model = pin.buildModelFromUrdf(str(REPO / CONTINUOUS_URDF), pin.JointModelFreeFlyer())
    data = model.createData()
    ids, frames = body_frames(model)
    rng = np.random.default_rng(zlib.crc32(b"frames wheeled_arm"))
    fixture = {
        "generator": "tools/pinocchio/make_frame_fixtures.py",
        "pinocchio_version": pin.__version__,
        "urdf": CONTINUOUS_URDF,
        "root_joint": "FreeFlyer",
        "nq": model.nq,
        "nv": model.nv,
        "joints": [[model.names[i], joint_type(model.joints[i]), model.joints[i].idx_q] for i in range(1, model.njoints)],
        "conventions": (
            "q in Pinocchio's layout ((cos θ, sin θ) per continuous joint), q_rodyn in rodyn's "
            "(θ = atan2(sin, cos)); frames and o_m_f as in panda.json"
        ),
        "frames": frames,
        "states": [continuous_state(model, data, ids, rng) for _ in range(STATES)],
    }
    write_states_fixture(OUT_FRAMES / "wheeled_arm.json", fixture)


def main() -> None:
    OUT_FRAMES.mkdir(parents=True, exist_ok=True)
    continuous_fixture()
    specs = {s.name: s for s in SPECS}
    for name in MODELS:
        model = load(specs[name])
        data = model.createData()
        ids, frames = body_frames(model)
        rng = np.random.default_rng(zlib.crc32(f"frames {name}".encode()))
        states = []
        for _ in range(STATES):
            q = random_configuration(model, rng)
            pin.framesForwardKinematics(model, data, q)
            states.append({"q": floats(q), "o_m_f": [se3(data.oMf[fid]) for fid in ids]})
        fixture = {
            "generator": "tools/pinocchio/make_frame_fixtures.py",
            "pinocchio_version": pin.__version__,
            "urdf": f"models/urdf/{name}.urdf",
            "root_joint": "FreeFlyer" if specs[name].floating else None,
            "conventions": (
                "frames: Pinocchio's BODY frames on moving joints, in Pinocchio's order, body = "
                "parentJoint - 1, placement iMf; states: q (Pinocchio's layout), o_m_f per frame; "
                "rotations row-major; SI units"
            ),
            "frames": frames,
            "states": states,
        }
        write_states_fixture(OUT_FRAMES / f"{name}.json", fixture)


if __name__ == "__main__":
    main()
