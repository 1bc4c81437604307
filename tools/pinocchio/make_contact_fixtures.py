"""Pinocchio 4.1 reference for rodyn's constrained forward dynamics.

Solo12 (floating base) at the states of host-tests/fixtures/solo12.json,
with 1 to 4 feet held as 3-D point contacts (RigidConstraintModel
CONTACT_3D in LOCAL_WORLD_ALIGNED), solved by `constraintDynamics`:
- anchors at the feet's current positions, no Baumgarte gains (the exact
  KKT solution);
- two feet with anchors moved by a few millimetres and Baumgarte gains
  Kp = 40 1/s², Kd = 9 1/s.

Also `impulseDynamics` for the same contacts at the state's velocity,
with restitution 0 and 0.5.

Writes host-tests/fixtures/contacts/solo12.json: per state and case, the
contacts (rodyn body index = Pinocchio joint index - 1, the foot frame's
placement in it, the anchor), the gains, q̈ and λ (three per contact), and
the impacts' v⁺ and impulses.

    python3 tools/pinocchio/make_contact_fixtures.py
"""

import json
import sys
from pathlib import Path

import numpy as np
import pinocchio as pin

sys.path.insert(0, str(Path(__file__).resolve().parent))
import make_fixtures as mf  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CASES = [
    (["FL_FOOT"], 0.0, 0.0, None),
    (["FL_FOOT", "HR_FOOT"], 0.0, 0.0, None),
    (["FL_FOOT", "FR_FOOT", "HL_FOOT"], 0.0, 0.0, None),
    (["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"], 0.0, 0.0, None),
    (["FR_FOOT", "HL_FOOT"], 40.0, 9.0, np.array([0.004, -0.003, 0.002])),
]


def placement(m):
    return {"rotation": m.rotation.flatten().tolist(), "translation": m.translation.tolist()}


def main():
    model = mf.load(mf.ModelSpec("solo12", floating=True))
    data = model.createData()
    states = json.loads((ROOT / "host-tests" / "fixtures" / "solo12.json").read_text())["states"]
    out = []
    for state in states:
        q, v, tau = (np.array(state[k]) for k in ("q", "v", "tau"))
        pin.framesForwardKinematics(model, data, q)
        cases = []
        for feet, kp, kd, offset in CASES:
            models = pin.StdVec_RigidConstraintModel()
            contacts = []
            for name in feet:
                fid = model.getFrameId(name)
                frame = model.frames[fid]
                anchor = data.oMf[fid].copy()
                if offset is not None:
                    anchor.translation = anchor.translation + offset
                cm = pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, model, frame.parentJoint,
                                              frame.placement, 0, anchor, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)
                cm.m_baumgarte_parameters.Kp = kp
                cm.m_baumgarte_parameters.Kd = kd
                models.append(cm)
                contacts.append({"name": name, "body": frame.parentJoint - 1,
                                 "placement": placement(frame.placement),
                                 "anchor": anchor.translation.tolist()})
            datas = pin.StdVec_RigidConstraintData()
            for cm in models:
                datas.append(cm.createData())
            pin.initConstraintDynamics(model, data, models, datas)
            ddq = pin.constraintDynamics(model, data, q, v, tau, models, datas, pin.ProximalSettings(1e-14, 0.0, 1))
            lam = np.array(data.lambda_c).tolist()
            # The impact of the same contacts at this state's velocity:
            # plastic, and with restitution 0.5.
            pin.computeJointJacobians(model, data, q)
            pin.framesForwardKinematics(model, data, q)
            jc = np.vstack([pin.getFrameJacobian(model, data, model.getFrameId(c["name"]),
                                                 pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)[:3] for c in contacts])
            impacts = []
            for e in (0.0, 0.5):
                v_after = pin.impulseDynamics(model, data, q, v, jc, e, 0.0)
                impacts.append({"restitution": e, "v_after": np.array(v_after).tolist(),
                                "impulse": np.array(data.impulse_c).tolist()})
            cases.append({"contacts": contacts, "kp": kp, "kd": kd, "ddq": ddq.tolist(),
                          "lambda": lam, "impacts": impacts})
        out.append({"q": q.tolist(), "v": v.tolist(), "tau": tau.tolist(), "cases": cases})
    path = ROOT / "host-tests" / "fixtures" / "contacts" / "solo12.json"
    path.write_text(json.dumps({"generator": f"pinocchio {pin.__version__}", "states": out}) + "\n")
    print(f"wrote {path} ({len(out)} states x {len(CASES)} cases)")


if __name__ == "__main__":
    main()
