"""Impulse dynamics against Pinocchio's impulseDynamics with rigid
constraint models (no proximal damping), on the contact sets of the
constrained-dynamics tests, with and without restitution."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from conftest import assert_close, get_pair, pinocchio_contact_models, random_states

IMPACT_CASES = [
    ("panda", [("panda_hand", "frame")]),
    ("solo12", ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"]),
    ("solo12", [("HL_FOOT", "frame"), "FR_FOOT"]),
    ("anymal", ["LF_FOOT", "RH_FOOT"]),
    ("talos_reduced", [("left_sole_link", "frame"), "right_sole_link"]),
    ("g1", [("left_ankle_roll_link", "frame"), ("right_ankle_roll_link", "frame")]),
]


def pinocchio_impulse(pair, q, v, contacts, restitution):
    pm, pd = pair.pin_model, pair.pin_data
    models, datas = pinocchio_contact_models(pair, q, contacts)
    pin.initConstraintDynamics(pm, pd, models, datas)
    v_after = pin.impulseDynamics(pm, pd, q, v, models, datas, restitution, pin.ProximalSettings(1e-14, 0.0, 1))
    return np.array(v_after), np.array(pd.impulse_c)


@pytest.mark.parametrize("restitution", [0.0, 0.5])
@pytest.mark.parametrize("robot, contacts", IMPACT_CASES, ids=[f"{r}-{i}" for i, (r, _) in enumerate(IMPACT_CASES)])
def test_impulse_dynamics(robot, contacts, restitution):
    pair = get_pair(robot)
    for s in random_states(pair):
        v_after, impulses = pair.model.impulse_dynamics(s.q, s.v, contacts, restitution)
        ref_v, ref_impulses = pinocchio_impulse(pair, s.q, s.v, contacts, restitution)
        assert_close("impulse_dynamics v_after", v_after, ref_v)
        assert_close("impulse_dynamics impulses", impulses, ref_impulses)


def test_restitution_out_of_range_is_named(panda):
    s = random_states(panda, count=1)[0]
    with pytest.raises(ValueError, match="restitution"):
        panda.model.impulse_dynamics(s.q, s.v, ["panda_hand"], 1.5)
