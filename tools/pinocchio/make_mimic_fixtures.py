#!/usr/bin/env python3
"""Writes Pinocchio's dynamics of a robot with mimic joints for rodyn-model's
generated `*_mimic` maps.

Regenerate (from the repository root):

    python3 tools/pinocchio/make_mimic_fixtures.py   # host-tests/fixtures/mimic/gripper.json

`crates/rodyn-model/generated-tests/urdf/gripper.urdf` is loaded with
`buildModelFromUrdf(..., mimic=True)`: the followers (a finger mimicking
the other, a thumb mimicking the wrist, with multipliers and offsets) have
no coordinates of their own. Per seeded random state (q, v, a in that
reduced layout) the file holds `rnea`, the mass matrix (`crba`,
symmetrised) and `oMf` of every link's BODY frame.

Floats are written with Python's `repr`, so they round-trip exactly.
"""

from __future__ import annotations

import zlib

import numpy as np
import pinocchio as pin

from make_fixtures import OUT, REPO, floats, write_states_fixture

URDF = "crates/rodyn-model/generated-tests/urdf/gripper.urdf"
STATES = 8


def main() -> None:
    out = OUT / "mimic"
    out.mkdir(parents=True, exist_ok=True)
    model = pin.buildModelFromUrdf(str(REPO / URDF), mimic=True)
    data = model.createData()
    ids = [fid for fid, f in enumerate(model.frames) if f.type == pin.FrameType.BODY and f.parentJoint > 0]
    rng = np.random.default_rng(zlib.crc32(b"mimic gripper"))
    states = []
    for _ in range(STATES):
        q = np.array([rng.uniform(-2.0, 2.0), rng.uniform(0.0, 0.04)])
        v = rng.uniform(-2.0, 2.0, model.nv)
        a = rng.uniform(-3.0, 3.0, model.nv)
        tau = pin.rnea(model, data, q, v, a).copy()
        upper = pin.crba(model, data, q).copy()
        mass_matrix = np.triu(upper) + np.triu(upper, 1).T
        pin.framesForwardKinematics(model, data, q)
        states.append(
            {
                "q": floats(q),
                "v": floats(v),
                "a": floats(a),
                "rnea": floats(tau),
                "mass_matrix": floats(mass_matrix),
                "o_m_f": [
                    {"rotation": floats(data.oMf[f].rotation), "translation": floats(data.oMf[f].translation)}
                    for f in ids
                ],
            }
        )
    fixture = {
        "generator": "tools/pinocchio/make_mimic_fixtures.py",
        "pinocchio_version": pin.__version__,
        "urdf": URDF,
        "nq": model.nq,
        "nv": model.nv,
        "joints": [[model.names[i], model.joints[i].shortname()] for i in range(1, model.njoints)],
        "frames": [model.frames[f].name for f in ids],
        "conventions": "q, v, a in the mimic=True layout (leaders only); rotations row-major; SI units",
        "states": states,
    }
    write_states_fixture(out / "gripper.json", fixture)


if __name__ == "__main__":
    main()
