"""Inverse kinematics: rodyn's solution puts the frame where it was asked,
by Pinocchio's forward kinematics (Pinocchio has no IK function to compare
with; its example runs the same damped least squares)."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from conftest import assert_close, get_pair

IK_CASES = [
    ("panda", "panda_hand"),
    ("ur5", "tool0"),
    ("kinova", "j2s6s200_end_effector"),  # continuous joints: (cos, sin) in and out
    ("solo12", "FL_FOOT"),
]


@pytest.mark.parametrize("robot, frame", IK_CASES)
def test_inverse_kinematics_reaches_a_reachable_target(robot, frame):
    pair = get_pair(robot)
    m, pm, pd = pair.model, pair.pin_model, pair.pin_data
    fid = pm.getFrameId(frame)
    # A target the robot reaches: the frame's placement at a nearby
    # configuration, the search starting from another one.
    goal = pin.integrate(pm, pin.neutral(pm), np.linspace(0.2, 0.4, m.nv))
    pin.framesForwardKinematics(pm, pd, goal)
    target = pd.oMf[fid].homogeneous.copy()
    q = m.inverse_kinematics(frame, target, pin.neutral(pm), tolerance=1e-11)
    assert q.shape == (m.nq,)
    assert pin.isNormalized(pm, q, 1e-12)
    pin.framesForwardKinematics(pm, pd, q)
    assert_close(f"inverse_kinematics {robot} {frame}", pd.oMf[fid].homogeneous, target)


def test_unreachable_target_raises(panda):
    target = np.eye(4)
    target[:3, 3] = [10.0, 0.0, 0.0]
    with pytest.raises(ArithmeticError):
        panda.model.inverse_kinematics("panda_hand", target, panda.model.neutral(), max_iterations=20)


def test_bad_target_is_named(panda):
    with pytest.raises(ValueError, match="target"):
        panda.model.inverse_kinematics("panda_hand", np.eye(3), panda.model.neutral())
    with pytest.raises(ValueError, match="unknown frame"):
        panda.model.inverse_kinematics("no_such_frame", np.eye(4), panda.model.neutral())
