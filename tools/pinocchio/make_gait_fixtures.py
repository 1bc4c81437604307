"""Pinocchio 4.1 reference for the measured gait example.

Builds OpenSim's subject01 planar model (data/gait/segments.csv) in
Pinocchio, independently of rodyn's model file: a planar floating pelvis
(JointModelPlanar: q = (x, y, cos, sin), v = own-frame (vx, vy, w)), pins
about z for the lumbar, hips, knees (at their knee_angle = 0 position) and
ankles, and the lumped feet. For every 5th frame of
inverse_dynamics_inputs_60hz.csv it converts OpenSim's coordinates, rates
and accelerations to the joint's, applies each foot's ground reaction
(force at the centre of pressure plus the free moment) and runs RNEA.

Writes host-tests/fixtures/gait/subject01_rnea.json: per frame, the row
index, the time and tau in the model's velocity order (pelvis vx, vy, w,
lumbar, hip r, knee r, ankle r, hip l, knee l, ankle l).

    python3 tools/pinocchio/make_gait_fixtures.py [--data DIR]
"""

import argparse
import csv
import json
import math
from pathlib import Path

import numpy as np
import pinocchio as pin

ROOT = Path(__file__).resolve().parents[2]
GRAVITY = 9.80665


def segments(data_dir):
    rows = {}
    with open(data_dir / "segments.csv", newline="") as f:
        for row in csv.DictReader(f):
            rows[row["body"]] = row
    return rows


def inertia(row):
    mass = float(row["mass_kg"])
    com = np.array([float(row["com_x_m"]), float(row["com_y_m"]), 0.0])
    izz = float(row["Izz_kgm2"])
    # Only the z moment acts in planar motion; x and y are set equal to it.
    return pin.Inertia(mass, com, np.diag([izz, izz, izz]))


def build(data_dir):
    seg = segments(data_dir)
    model = pin.Model()
    model.gravity.linear = np.array([0.0, -GRAVITY, 0.0])

    def add(parent, name, joint, row, placement_row=None):
        if placement_row is None:
            placement_row = row
        xyz = np.array([float(placement_row["joint_in_parent_x_m"]), float(placement_row["joint_in_parent_y_m"]), 0.0])
        jid = model.addJoint(parent, joint, pin.SE3(np.eye(3), xyz), name)
        model.appendBodyToJoint(jid, inertia(row), pin.SE3.Identity())
        return jid

    pelvis = add(0, "pelvis", pin.JointModelPlanar(), seg["pelvis"])
    add(pelvis, "lumbar", pin.JointModelRZ(), seg["torso"])
    for side in "rl":
        femur = add(pelvis, f"hip_{side}", pin.JointModelRZ(), seg[f"femur_{side}"])
        tibia = add(femur, f"knee_{side}", pin.JointModelRZ(), seg[f"tibia_{side}"])
        add(tibia, f"ankle_{side}", pin.JointModelRZ(), seg[f"foot_{side}"])
    return model


COORDS = ["pelvis_tilt", "pelvis_tx", "pelvis_ty", "hip_flexion_r", "knee_angle_r", "ankle_angle_r",
          "hip_flexion_l", "knee_angle_l", "ankle_angle_l", "lumbar_extension"]


def state(row):
    def get(prefix, c, lin, ang):
        return float(row[f"{prefix}_{c}_{lin if c in ('pelvis_tx', 'pelvis_ty') else ang}"])
    q = {c: get("q", c, "m", "rad") for c in COORDS}
    qd = {c: get("qd", c, "m_per_s", "rad_per_s") for c in COORDS}
    qdd = {c: get("qdd", c, "m_per_s2", "rad_per_s2") for c in COORDS}
    th, w = q["pelvis_tilt"], qd["pelvis_tilt"]
    rot = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
    pdot = np.array([qd["pelvis_tx"], qd["pelvis_ty"]])
    pddot = np.array([qdd["pelvis_tx"], qdd["pelvis_ty"]])
    vb = rot.T @ pdot
    # d/dt (R^T pdot) = R^T pddot + (dR^T/dt) pdot, dR^T/dt = -w J R^T, J = [[0,-1],[1,0]].
    jmat = np.array([[0.0, -1.0], [1.0, 0.0]])
    ab = rot.T @ pddot - w * (jmat @ vb)
    joints = ["lumbar_extension", "hip_flexion_r", "knee_angle_r", "ankle_angle_r", "hip_flexion_l",
              "knee_angle_l", "ankle_angle_l"]
    qp = np.array([q["pelvis_tx"], q["pelvis_ty"], math.cos(th), math.sin(th)] + [q[j] for j in joints])
    vp = np.array([vb[0], vb[1], w] + [qd[j] for j in joints])
    ap = np.array([ab[0], ab[1], qdd["pelvis_tilt"]] + [qdd[j] for j in joints])
    return qp, vp, ap


def ground_forces(model, data, qp, row):
    pin.forwardKinematics(model, data, qp)
    fext = [pin.Force.Zero() for _ in range(model.njoints)]
    for side in "rl":
        fx, fy = float(row[f"{side}_Fx_N"]), float(row[f"{side}_Fy_N"])
        cx, cy = float(row[f"{side}_CoPx_m"]), float(row[f"{side}_CoPy_m"])
        tz = float(row[f"{side}_Tz_Nm"])
        force = np.array([fx, fy, 0.0])
        moment = np.cross(np.array([cx, cy, 0.0]), force) + np.array([0.0, 0.0, tz])
        jid = model.getJointId(f"ankle_{side}")
        fext[jid] = data.oMi[jid].actInv(pin.Force(force, moment))
    return fext


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", type=Path, default=ROOT / "data" / "gait")
    args = parser.parse_args()
    model = build(args.data)
    data = model.createData()
    frames = []
    with open(args.data / "inverse_dynamics_inputs_60hz.csv", newline="") as f:
        for index, row in enumerate(csv.DictReader(f)):
            if index % 5:
                continue
            qp, vp, ap = state(row)
            fext = ground_forces(model, data, qp, row)
            tau = pin.rnea(model, data, qp, vp, ap, fext)
            frames.append({"row": index, "time": float(row["time_s"]), "tau": tau.tolist()})
    out = ROOT / "host-tests" / "fixtures" / "gait" / "subject01_rnea.json"
    out.write_text(json.dumps({"generator": f"pinocchio {pin.__version__}", "frames": frames}, indent=1) + "\n")
    print(f"wrote {out} ({len(frames)} frames)")


if __name__ == "__main__":
    main()
