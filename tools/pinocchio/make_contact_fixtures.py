"""Pinocchio 4.1 reference for rodyn's constrained forward dynamics.

Solo12 (floating base) at the states of host-tests/fixtures/solo12.json,
with 1 to 4 feet held as 3-D point contacts (RigidConstraintModel
CONTACT_3D in LOCAL_WORLD_ALIGNED) and one foot held as a 6-D frame
contact (CONTACT_6D in LOCAL), solved by `constraintDynamics`:
- anchors at the feet's current placements, no Baumgarte gains (the exact
  KKT solution);
- anchors moved by a few millimetres (and, for frames, turned by a few
  milliradians) with Baumgarte gains Kp = 40 1/s², Kd = 9 1/s.

Talos (example-robot-data's talos_reduced.urdf, free flyer, 38 velocity
coordinates) at random states, with both soles held as 6-D frame
contacts, one sole alone, and one sole as a frame with the other as a
point, with and without gains.

Two larger humanoids for the pivot tests in single precision, each at
random states with both soles held as 6-D frame contacts (no gains) and
one sole alone: Talos with its grippers (talos_full_v2.urdf, 50 velocity
coordinates, gripper joints whose inertia is a millionth of the trunk's)
and Unitree's G1 (g1_29dof_rev_1_0.urdf, 35 velocity coordinates; its
ankle-roll links stand for the soles). They write talos_full.json and
g1.json in the form of talos.json.

Also `impulseDynamics` for the same contacts at the state's velocity,
with restitution 0 and 0.5; and, for Solo12 under "redundant", a
rank-deficient contact set per state (a foot held twice beside another)
solved by Pinocchio's proximal solver (mu 1e-4, 200 iterations).

Writes host-tests/fixtures/contacts/solo12.json and talos.json: per state
and case, the contacts (kind "point" or "frame"; rodyn body index =
Pinocchio joint index - 1; the frame's placement in its body; the anchor:
a world point for a point, a world placement for a frame), the gains, q̈
and λ (three entries per point, six per frame: Pinocchio's order, linear
first), and the impacts' v⁺ and impulses. talos.json also holds the
model in the form of make_fixtures.py (with no states of its own).

    pip install pin example-robot-data
    python3 tools/pinocchio/make_contact_fixtures.py
"""

import json
import sys
from pathlib import Path

import numpy as np
import pinocchio as pin

sys.path.insert(0, str(Path(__file__).resolve().parent))
import make_fixtures as mf  # noqa: E402
from make_models import example_robot_data_dir  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
OFFSET = pin.SE3(pin.exp3(np.array([0.002, -0.004, 0.003])), np.array([0.004, -0.003, 0.002]))
POINT, FRAME = "point", "frame"

#: (contacts as (frame, kind), Kp, Kd, anchors moved by OFFSET)
SOLO_CASES = [
    ([("FL_FOOT", POINT)], 0.0, 0.0, False),
    ([("FL_FOOT", POINT), ("HR_FOOT", POINT)], 0.0, 0.0, False),
    ([("FL_FOOT", POINT), ("FR_FOOT", POINT), ("HL_FOOT", POINT)], 0.0, 0.0, False),
    ([("FL_FOOT", POINT), ("FR_FOOT", POINT), ("HL_FOOT", POINT), ("HR_FOOT", POINT)], 0.0, 0.0, False),
    ([("FR_FOOT", POINT), ("HL_FOOT", POINT)], 40.0, 9.0, True),
    ([("HL_FOOT", FRAME)], 0.0, 0.0, False),
    ([("HL_FOOT", FRAME), ("FR_FOOT", POINT)], 40.0, 9.0, True),
]
TALOS_CASES = [
    ([("left_sole_link", FRAME), ("right_sole_link", FRAME)], 0.0, 0.0, False),
    ([("left_sole_link", FRAME), ("right_sole_link", FRAME)], 40.0, 9.0, True),
    ([("right_sole_link", FRAME)], 0.0, 0.0, False),
    ([("left_sole_link", FRAME), ("right_sole_link", POINT)], 40.0, 9.0, True),
]
TALOS_STATES = 6

#: (fixture name, URDF under example-robot-data's robots/, left and right
#: sole frames, states)
HUMANOIDS = [
    ("talos_full", "talos_data/robots/talos_full_v2.urdf", "left_sole_link", "right_sole_link", 4),
    ("g1", "g1_description/urdf/g1_29dof_rev_1_0.urdf", "left_ankle_roll_link", "right_ankle_roll_link", 4),
]

#: A redundant contact set (a rank-deficient J_c), solved by Pinocchio's
#: proximal solver (mu, iterations): the same foot held twice beside
#: another foot (Solo12).
SOLO_REDUNDANT = ([("FL_FOOT", POINT), ("FL_FOOT", POINT), ("HR_FOOT", POINT)], 0.0, 0.0, False)
PROXIMAL = (1e-4, 200)


def placement(m):
    return {"rotation": m.rotation.flatten().tolist(), "translation": m.translation.tolist()}


def solve_case(model, data, q, v, tau, feet, kp, kd, moved, proximal=(0.0, 1)):
    """constraintDynamics and impulseDynamics for one contact set; `proximal`
    is (mu, iterations) of Pinocchio's proximal solver (mu = 0: the exact
    KKT solve)."""
    pin.framesForwardKinematics(model, data, q)
    models = pin.StdVec_RigidConstraintModel()
    contacts = []
    for name, kind in feet:
        fid = model.getFrameId(name)
        frame = model.frames[fid]
        anchor = data.oMf[fid].copy()
        if moved:
            anchor = anchor * OFFSET if kind == FRAME else pin.SE3(anchor.rotation, anchor.translation + OFFSET.translation)
        if kind == FRAME:
            cm = pin.RigidConstraintModel(pin.ContactType.CONTACT_6D, model, frame.parentJoint,
                                          frame.placement, 0, anchor, pin.ReferenceFrame.LOCAL)
        else:
            cm = pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, model, frame.parentJoint,
                                          frame.placement, 0, anchor, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)
        cm.m_baumgarte_parameters.Kp = kp
        cm.m_baumgarte_parameters.Kd = kd
        models.append(cm)
        contacts.append({"name": name, "kind": kind, "body": frame.parentJoint - 1,
                         "placement": placement(frame.placement),
                         "anchor": placement(anchor) if kind == FRAME else anchor.translation.tolist()})
    datas = pin.StdVec_RigidConstraintData()
    for cm in models:
        datas.append(cm.createData())
    pin.initConstraintDynamics(model, data, models, datas)
    mu, iterations = proximal
    ddq = pin.constraintDynamics(model, data, q, v, tau, models, datas,
                                 pin.ProximalSettings(1e-14, mu, iterations))
    lam = np.array(data.lambda_c).tolist()
    # The impact of the same contacts at this state's velocity: plastic,
    # and with restitution 0.5. The stacked Jacobian's rows are those of
    # the contacts above (points: world-aligned linear rows; frames: local
    # 6-D rows).
    pin.computeJointJacobians(model, data, q)
    pin.framesForwardKinematics(model, data, q)
    rows = []
    for name, kind in feet:
        fid = model.getFrameId(name)
        if kind == FRAME:
            rows.append(pin.getFrameJacobian(model, data, fid, pin.ReferenceFrame.LOCAL))
        else:
            rows.append(pin.getFrameJacobian(model, data, fid, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)[:3])
    jc = np.vstack(rows)
    impacts = []
    for e in ((0.0, 0.5) if proximal[0] == 0.0 else ()):
        v_after = pin.impulseDynamics(model, data, q, v, jc, e, 0.0)
        impacts.append({"restitution": e, "v_after": np.array(v_after).tolist(),
                        "impulse": np.array(data.impulse_c).tolist()})
    out = {"contacts": contacts, "kp": kp, "kd": kd, "ddq": np.array(ddq).tolist(), "lambda": lam,
           "impacts": impacts}
    if mu > 0.0:
        out["proximal_mu"] = mu
        out["proximal_iterations"] = iterations
        del out["impacts"]  # impulseDynamics has no proximal form here
    return out


def solo12():
    model = mf.load(mf.ModelSpec("solo12", floating=True))
    data = model.createData()
    states = json.loads((ROOT / "host-tests" / "fixtures" / "solo12.json").read_text())["states"]
    out = []
    for state in states:
        q, v, tau = (np.array(state[k]) for k in ("q", "v", "tau"))
        cases = [solve_case(model, data, q, v, tau, *case) for case in SOLO_CASES]
        redundant = [solve_case(model, data, q, v, tau, *SOLO_REDUNDANT, proximal=PROXIMAL)]
        out.append({"q": q.tolist(), "v": v.tolist(), "tau": tau.tolist(), "cases": cases,
                    "redundant": redundant})
    path = ROOT / "host-tests" / "fixtures" / "contacts" / "solo12.json"
    path.write_text(json.dumps({"generator": f"pinocchio {pin.__version__}", "states": out}) + "\n")
    print(f"wrote {path} ({len(out)} states x {len(SOLO_CASES)} cases)")


def talos():
    urdf = example_robot_data_dir() / "talos_data" / "robots" / "talos_reduced.urdf"
    model = pin.buildModelFromUrdf(str(urdf), pin.JointModelFreeFlyer())
    data = model.createData()
    spec = mf.ModelSpec("talos_reduced", floating=True)
    rng = np.random.default_rng(2026)
    out = []
    for _ in range(TALOS_STATES):
        q = mf.random_configuration(model, rng)
        v = rng.uniform(-1.0, 1.0, model.nv)
        tau = pin.rnea(model, data, q, v, rng.uniform(-2.0, 2.0, model.nv)).copy()
        cases = [solve_case(model, data, q, v, tau, *case) for case in TALOS_CASES]
        out.append({"q": q.tolist(), "v": v.tolist(), "tau": tau.tolist(), "cases": cases})
    description = mf.describe(spec, model)
    description["urdf"] = "example-robot-data: talos_data/robots/talos_reduced.urdf"
    fixture = {"generator": "tools/pinocchio/make_contact_fixtures.py", "pinocchio_version": pin.__version__,
               "model": description, "states": [], "contact_states": out}
    path = ROOT / "host-tests" / "fixtures" / "contacts" / "talos.json"
    path.write_text(json.dumps(fixture) + "\n")
    print(f"wrote {path} ({len(out)} states x {len(TALOS_CASES)} cases)")


def humanoid(name, urdf_path, left, right, states):
    """A humanoid's model and its states with both soles held, and one."""
    urdf = example_robot_data_dir() / urdf_path
    model = pin.buildModelFromUrdf(str(urdf), pin.JointModelFreeFlyer())
    data = model.createData()
    cases = [([(left, FRAME), (right, FRAME)], 0.0, 0.0, False), ([(right, FRAME)], 0.0, 0.0, False)]
    rng = np.random.default_rng(2027)
    out = []
    for _ in range(states):
        q = mf.random_configuration(model, rng)
        v = rng.uniform(-1.0, 1.0, model.nv)
        tau = pin.rnea(model, data, q, v, rng.uniform(-2.0, 2.0, model.nv)).copy()
        solved = [solve_case(model, data, q, v, tau, *case) for case in cases]
        out.append({"q": q.tolist(), "v": v.tolist(), "tau": tau.tolist(), "cases": solved})
    description = mf.describe(mf.ModelSpec(name, floating=True), model)
    description["urdf"] = f"example-robot-data: {urdf_path}"
    fixture = {"generator": "tools/pinocchio/make_contact_fixtures.py", "pinocchio_version": pin.__version__,
               "model": description, "states": [], "contact_states": out}
    path = ROOT / "host-tests" / "fixtures" / "contacts" / f"{name}.json"
    path.write_text(json.dumps(fixture) + "\n")
    print(f"wrote {path} ({len(out)} states x {len(cases)} cases)")


def main():
    solo12()
    talos()
    for spec in HUMANOIDS:
        humanoid(*spec)


if __name__ == "__main__":
    main()
