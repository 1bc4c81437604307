#!/usr/bin/env python3
"""Writes Pinocchio reference results for rodyn's host tests.

Regenerate (from the repository root):

    pip install pin example-robot-data
    python3 tools/pinocchio/make_models.py      # models/urdf/*.urdf
    python3 tools/pinocchio/make_fixtures.py    # host-tests/fixtures/*.json

Each URDF in models/urdf/ is loaded with `pinocchio.buildModelFromUrdf`
(Solo12 with a `JointModelFreeFlyer` root). One JSON file per model holds

* the model exactly as Pinocchio built it: Pinocchio merges every fixed
  joint into its parent body, so a body here is a Pinocchio joint, with its
  parent, type (`RZ`, `RevoluteUnaligned`, `PY`, `FreeFlyer`, ...), axis,
  `jointPlacement` (rotation, row-major, and translation: the joint frame at
  q = 0 in the parent's joint frame) and `inertia` (mass, `lever` = centre of
  mass, `inertia` = rotational inertia about the centre of mass, all in the
  joint frame); the gravity; and what was merged, for the record;
* several seeded random states (q, v, a, tau, one external force per body in
  that body's own frame, Pinocchio's `fext` convention, `[linear; angular]`)
  with Pinocchio's results: RNEA with and without the external forces, the
  mass matrix (CRBA, symmetrised from its upper triangle), ABA with and
  without the external forces, nonlinear effects, generalised gravity,
  kinetic and potential energy and the centre of mass.

Floats are written with Python's `repr`, so they round-trip exactly.
The output is deterministic for a given Pinocchio version.
"""

from __future__ import annotations

import json
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pinocchio as pin

REPO = Path(__file__).resolve().parents[2]
URDF_DIR = REPO / "models" / "urdf"
OUT = REPO / "host-tests" / "fixtures"

#: The planar chains move in the x-y plane, so gravity lies in it.
PLANAR_GRAVITY = (0.0, -9.81, 0.0)


@dataclass(frozen=True)
class ModelSpec:
    name: str
    floating: bool = False
    gravity: tuple | None = None  # None: Pinocchio's default (0, 0, -9.81)
    states: int = 8


SPECS = (
    [ModelSpec("ur5"), ModelSpec("panda"), ModelSpec("solo12", floating=True), ModelSpec("branched_tree")]
    + [ModelSpec(f"planar_chain_{n}", gravity=PLANAR_GRAVITY, states=8 if n <= 20 else 5) for n in (1, 2, 3, 5, 10, 20, 40, 60)]
    + [ModelSpec(f"spatial_chain_{n}", states=8 if n <= 20 else 5) for n in (5, 12, 40)]
)


def load(spec: ModelSpec) -> pin.Model:
    path = str(URDF_DIR / f"{spec.name}.urdf")
    model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer()) if spec.floating else pin.buildModelFromUrdf(path)
    if spec.gravity is not None:
        model.gravity = pin.Motion(np.array(spec.gravity), np.zeros(3))
    return model


def floats(x) -> list:
    """A numpy array (any shape) as nested lists of Python floats."""
    return np.asarray(x, dtype=float).tolist()


def joint_type(joint) -> str:
    name = joint.shortname()
    prefix = "JointModel"
    return name[len(prefix):] if name.startswith(prefix) else name


def describe(spec: ModelSpec, model: pin.Model) -> dict:
    joints = []
    for i in range(1, model.njoints):
        joint = model.joints[i]
        kind = joint_type(joint)
        entry = {
            "name": model.names[i],
            "parent": None if model.parents[i] == 0 else int(model.parents[i]) - 1,
            "type": kind,
            "nq": joint.nq,
            "nv": joint.nv,
            "idx_q": joint.idx_q,
            "idx_v": joint.idx_v,
        }
        if kind in ("RevoluteUnaligned", "PrismaticUnaligned"):
            entry["axis"] = floats(joint.extract().axis)
        placement = model.jointPlacements[i]
        entry["placement"] = {"rotation": floats(placement.rotation), "translation": floats(placement.translation)}
        inertia = model.inertias[i]
        entry["inertia"] = {"mass": float(inertia.mass), "lever": floats(inertia.lever), "inertia": floats(inertia.inertia)}
        joints.append(entry)
    merged = [f.name for f in model.frames if f.type == pin.FrameType.FIXED_JOINT]
    return {
        "name": spec.name,
        "urdf": f"models/urdf/{spec.name}.urdf",
        "root_joint": "FreeFlyer" if spec.floating else None,
        "nq": model.nq,
        "nv": model.nv,
        "gravity": floats(model.gravity.linear),
        # Links welded to the world by fixed joints: Pinocchio keeps their
        # inertia on the universe, where it never moves and enters no result.
        "world_fixed_mass": float(model.inertias[0].mass),
        "merged_fixed_joints": merged,
        "joints": joints,
    }


def random_configuration(model: pin.Model, rng: np.random.Generator) -> np.ndarray:
    q = np.zeros(model.nq)
    for joint in model.joints[1:]:
        kind, iq = joint_type(joint), joint.idx_q
        if kind == "FreeFlyer":
            quat = rng.normal(size=4)
            q[iq : iq + 3] = rng.uniform(-1.0, 1.0, size=3)
            q[iq + 3 : iq + 7] = quat / np.linalg.norm(quat)  # [qx qy qz qw]
        elif kind.startswith("P"):
            q[iq] = rng.uniform(-0.3, 0.3)
        elif kind.startswith("R") and joint.nq == 1:
            q[iq] = rng.uniform(-np.pi, np.pi)
        else:
            raise SystemExit(f"{kind}: no random configuration rule")
    return q


def random_state(model: pin.Model, data: pin.Data, rng: np.random.Generator) -> dict:
    q = random_configuration(model, rng)
    v = rng.uniform(-2.0, 2.0, model.nv)
    a = rng.uniform(-3.0, 3.0, model.nv)
    # A torque of the model's own scale: the one that produces another random
    # acceleration. Pinocchio's ABA result below is the reference, not that
    # acceleration.
    tau = pin.rnea(model, data, q, v, rng.uniform(-3.0, 3.0, model.nv)).copy()
    fext_list = [np.concatenate([rng.uniform(-5.0, 5.0, 3), rng.uniform(-1.0, 1.0, 3)]) for _ in range(model.njoints - 1)]
    fext = pin.StdVec_Force()
    fext.append(pin.Force.Zero())  # the universe
    for f in fext_list:
        fext.append(pin.Force(f[:3], f[3:]))

    rnea = pin.rnea(model, data, q, v, a).copy()
    rnea_fext = pin.rnea(model, data, q, v, a, fext).copy()
    upper = pin.crba(model, data, q).copy()
    mass_matrix = np.triu(upper) + np.triu(upper, 1).T
    aba = pin.aba(model, data, q, v, tau).copy()
    aba_fext = pin.aba(model, data, q, v, tau, fext).copy()
    nle = pin.nonLinearEffects(model, data, q, v).copy()
    gravity = pin.computeGeneralizedGravity(model, data, q).copy()
    kinetic = pin.computeKineticEnergy(model, data, q, v)
    potential = pin.computePotentialEnergy(model, data, q)
    com = pin.centerOfMass(model, data, q).copy()
    return {
        "q": floats(q),
        "v": floats(v),
        "a": floats(a),
        "tau": floats(tau),
        "fext": [floats(f) for f in fext_list],
        "rnea": floats(rnea),
        "rnea_fext": floats(rnea_fext),
        "mass_matrix": floats(mass_matrix),
        "aba": floats(aba),
        "aba_fext": floats(aba_fext),
        "nonlinear_effects": floats(nle),
        "gravity_torques": floats(gravity),
        "kinetic_energy": float(kinetic),
        "potential_energy": float(potential),
        "center_of_mass": floats(com),
    }


def dump(obj: dict) -> str:
    """JSON with one joint and one state per line: compact, yet diffs stay readable."""
    head = {k: v for k, v in obj.items() if k not in ("model", "states")}
    model = {k: v for k, v in obj["model"].items() if k != "joints"}
    lines = ["{"]
    for k, v in head.items():
        lines.append(f"{json.dumps(k)}: {json.dumps(v)},")
    lines.append('"model": {')
    for k, v in model.items():
        lines.append(f"  {json.dumps(k)}: {json.dumps(v)},")
    joints = ",\n    ".join(json.dumps(j) for j in obj["model"]["joints"])
    lines.append(f'  "joints": [\n    {joints}\n  ]')
    lines.append("},")
    states = ",\n  ".join(json.dumps(s) for s in obj["states"])
    lines.append(f'"states": [\n  {states}\n]')
    lines.append("}")
    return "\n".join(lines) + "\n"


def write_states_fixture(path: Path, fixture: dict) -> None:
    """Writes `fixture` as JSON with one state per line under "states" (compact,
    yet diffs stay readable), checks that it parses, and says what it wrote."""
    text = "{\n" + ",\n".join(
        f"{json.dumps(k)}: "
        + ("[\n  " + ",\n  ".join(json.dumps(x) for x in v) + "\n]" if k == "states" else json.dumps(v))
        for k, v in fixture.items()
    ) + "\n}\n"
    json.loads(text)
    path.write_text(text)
    print(f"wrote {path.relative_to(REPO)} ({len(text) // 1024} KiB, {len(fixture['states'])} states)")


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for spec in SPECS:
        model = load(spec)
        data = model.createData()
        rng = np.random.default_rng(zlib.crc32(spec.name.encode()))
        fixture = {
            "generator": "tools/pinocchio/make_fixtures.py",
            "pinocchio_version": pin.__version__,
            "conventions": (
                "Pinocchio's: q = [x y z qx qy qz qw] for a free flyer, v in the body frame "
                "[linear; angular]; spatial vectors [linear; angular]; fext per body in its own "
                "joint frame; mass matrix symmetrised; SI units (m, kg, s, N, N m, J)"
            ),
            "model": describe(spec, model),
            "states": [random_state(model, data, rng) for _ in range(spec.states)],
        }
        path = OUT / f"{spec.name}.json"
        text = dump(fixture)
        json.loads(text)  # the writer is hand-rolled: make sure it is valid JSON
        path.write_text(text)
        print(f"wrote {path.relative_to(REPO)} ({len(text) // 1024} KiB, {spec.states} states)")


if __name__ == "__main__":
    main()
