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

Rotations row-major; floats written with Python's `repr`, so they
round-trip exactly.
"""

from __future__ import annotations

import zlib

import numpy as np
import pinocchio as pin

from make_fixtures import OUT, SPECS, floats, load, random_configuration, write_states_fixture

MODELS = ("panda", "solo12")
OUT_FRAMES = OUT / "frames"
STATES = 8


def se3(m: pin.SE3) -> dict:
    return {"rotation": floats(m.rotation), "translation": floats(m.translation)}


def main() -> None:
    OUT_FRAMES.mkdir(parents=True, exist_ok=True)
    specs = {s.name: s for s in SPECS}
    for name in MODELS:
        model = load(specs[name])
        data = model.createData()
        ids = [
            fid
            for fid, f in enumerate(model.frames)
            if f.type == pin.FrameType.BODY and f.parentJoint > 0
        ]
        frames = [
            {
                "name": model.frames[fid].name,
                "body": int(model.frames[fid].parentJoint) - 1,
                "placement": se3(model.frames[fid].placement),
            }
            for fid in ids
        ]
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
