"""Shared set-up of the tests: example-robot-data's robots, loaded by rodyn
and by Pinocchio 4.1 (the reference), and seeded random states.

The robots come from the `example-robot-data` wheel installed beside the
tests (`cargo xtask python-env`); `RODYN_ROBOTS` names another folder of
the same layout.
"""

from __future__ import annotations

import os
import sysconfig
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

import rodyn


def robots_dir() -> Path:
    override = os.environ.get("RODYN_ROBOTS")
    if override:
        return Path(override)
    purelib = Path(sysconfig.get_paths()["purelib"])
    return purelib / "cmeel.prefix" / "share" / "example-robot-data" / "robots"


@dataclass(frozen=True)
class Robot:
    name: str
    urdf: str  # under robots_dir()
    floating: bool

    @property
    def path(self) -> Path:
        return robots_dir() / self.urdf


#: Fixed and floating bases, small and large, and the continuous joints
#: Pinocchio keeps as (cos, sin) (Kinova's first joint, the pendulum's two).
ROBOTS = [
    Robot("panda", "panda_description/urdf/panda.urdf", False),
    Robot("ur5", "ur_description/urdf/ur5_robot.urdf", False),
    Robot("kinova", "kinova_description/robots/kinova.urdf", False),
    Robot("double_pendulum_continuous", "double_pendulum_description/urdf/double_pendulum_continuous.urdf", False),
    Robot("solo12", "solo_description/robots/solo12.urdf", True),
    Robot("anymal", "anymal_b_simple_description/robots/anymal.urdf", True),
    Robot("talos_reduced", "talos_data/robots/talos_reduced.urdf", True),
    Robot("g1", "g1_description/urdf/g1_29dof_rev_1_0.urdf", True),
]

ROBOT_BY_NAME = {robot.name: robot for robot in ROBOTS}


@dataclass
class Pair:
    """One robot as rodyn and as Pinocchio see it."""

    robot: Robot
    model: rodyn.Model
    pin_model: pin.Model
    pin_data: pin.Data


def load_pair(robot: Robot) -> Pair:
    path = str(robot.path)
    model = rodyn.Model.from_urdf(path, floating_base=robot.floating)
    if robot.floating:
        pin_model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    else:
        pin_model = pin.buildModelFromUrdf(path)
    return Pair(robot, model, pin_model, pin_model.createData())


_PAIRS: dict[str, Pair] = {}


def get_pair(name: str) -> Pair:
    """The robot `name`, loaded once per test session."""
    if name not in _PAIRS:
        _PAIRS[name] = load_pair(ROBOT_BY_NAME[name])
    return _PAIRS[name]


@pytest.fixture(params=[robot.name for robot in ROBOTS])
def pair(request) -> Pair:
    return get_pair(request.param)


@pytest.fixture
def panda() -> Pair:
    return get_pair("panda")


@dataclass
class State:
    q: np.ndarray
    v: np.ndarray
    a: np.ndarray
    tau: np.ndarray


def random_states(pair: Pair, count: int = 3, seed: int = 7) -> list[State]:
    """Pinocchio's random configurations (joints in [-1, 1] rad or m, any
    orientation of a floating base, any angle of a continuous joint) with
    uniform velocities, accelerations and torques."""
    rng = np.random.default_rng(seed)
    nq, nv = pair.pin_model.nq, pair.pin_model.nv
    pin.seed(seed)
    states = []
    for _ in range(count):
        q = pin.randomConfiguration(pair.pin_model, -np.ones(nq), np.ones(nq))
        states.append(State(q, rng.uniform(-1, 1, nv), rng.uniform(-1, 1, nv), rng.uniform(-5, 5, nv)))
    return states


#: The agreement asked of every function: 1e-9 of the result's own scale
#: (its largest entry, at least 1), which absorbs rounding in results whose
#: entries reach 1e5 (the inverse mass matrix of a light gripper).
TOLERANCE = 1e-9


def assert_close(what: str, ours, reference) -> None:
    ours = np.asarray(ours)
    reference = np.asarray(reference)
    assert ours.shape == reference.shape, f"{what}: shape {ours.shape}, Pinocchio's {reference.shape}"
    scale = max(1.0, float(np.max(np.abs(reference)))) if reference.size else 1.0
    error = float(np.max(np.abs(ours - reference))) if reference.size else 0.0
    assert error <= TOLERANCE * scale, f"{what}: differs from Pinocchio by {error:.3e} (scale {scale:.3e})"


def symmetric_from_upper(matrix: np.ndarray) -> np.ndarray:
    """Pinocchio fills only the upper triangle of M and M⁻¹."""
    upper = np.triu(matrix)
    return upper + np.triu(upper, 1).T


def pinocchio_contact_models(pair: Pair, q: np.ndarray, contacts):
    """Pinocchio's rigid constraint models (and their datas) for rodyn's
    `contacts`, anchored where the frames are at `q`: a frame name is a
    point contact (CONTACT_3D in LOCAL_WORLD_ALIGNED), a `(name, "frame")`
    pair holds the whole frame (CONTACT_6D in LOCAL)."""
    pm, pd = pair.pin_model, pair.pin_data
    pin.framesForwardKinematics(pm, pd, q)
    models = pin.StdVec_RigidConstraintModel()
    for contact in contacts:
        name, kind = (contact, "point") if isinstance(contact, str) else contact
        fid = pm.getFrameId(name)
        frame = pm.frames[fid]
        if kind == "frame":
            cm = pin.RigidConstraintModel(pin.ContactType.CONTACT_6D, pm, frame.parentJoint, frame.placement,
                                          0, pd.oMf[fid], pin.ReferenceFrame.LOCAL)
        else:
            cm = pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, pm, frame.parentJoint, frame.placement,
                                          0, pd.oMf[fid], pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)
        models.append(cm)
    datas = pin.StdVec_RigidConstraintData()
    for cm in models:
        datas.append(cm.createData())
    return models, datas
