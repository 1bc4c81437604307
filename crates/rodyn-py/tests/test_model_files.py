"""Models from rodyn's own TOML files (no Pinocchio counterpart): the
pendulum of models/pendulum.toml against its closed form, and what a
model says about itself."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import rodyn
from conftest import get_pair

MODELS = Path(__file__).resolve().parents[3] / "models"


def test_pendulum_from_toml_matches_its_closed_form():
    # A 1 kg rod, centre of mass 0.5 m from the pivot, inertia 0.083333
    # kg m² about its centre, gravity 9.81 m/s² along -y.
    m = rodyn.Model.from_file(MODELS / "pendulum.toml")
    assert (m.nq, m.nv) == (1, 1)
    assert m.joint_names == ["hinge"]
    mass, lever, inertia_centre, g = 1.0, 0.5, 0.083333, 9.81
    for theta in (0.0, 0.4, -1.3, 2.9):
        q = np.array([theta])
        assert m.gravity(q)[0] == pytest.approx(mass * g * lever * math.sin(theta), abs=1e-12)
        assert m.crba(q)[0, 0] == pytest.approx(inertia_centre + mass * lever**2, abs=1e-12)
        # ABA inverts RNEA.
        v, a = np.array([0.7]), np.array([-0.2])
        tau = m.rnea(q, v, a)
        assert m.aba(q, v, tau)[0] == pytest.approx(a[0], abs=1e-12)


def test_repr_and_warnings(panda):
    m = panda.model
    assert repr(m) == f"<rodyn.Model 'panda': nq={m.nq}, nv={m.nv}, {len(m.joint_names)} joints, {len(m.frame_names)} frames>"
    # example-robot-data's Panda has joint limits, which rodyn does not keep.
    assert any("limit" in w for w in m.warnings)
    assert all(":" in w and "warning" in w for w in m.warnings)


def test_random_configuration_without_seed_moves_on():
    m = get_pair("solo12").model
    first, second = m.random_configuration(), m.random_configuration()
    assert not np.array_equal(first, second)
    assert np.linalg.norm(first[3:7]) == pytest.approx(1.0, abs=1e-12)


def _every_urdf():
    from conftest import robots_dir

    return sorted(robots_dir().rglob("*.urdf"))


@pytest.mark.parametrize("path", _every_urdf(), ids=lambda p: p.name)
def test_every_example_robot_data_urdf_loads_or_says_where(path):
    """The issue's one-liner on every URDF of example-robot-data, fixed and
    floating: the compiler refuses a file with a located ModelError, and a
    model it builds runs ABA to finite accelerations."""
    for floating in (False, True):
        try:
            m = rodyn.Model.from_urdf(path, floating_base=floating)
        except rodyn.ModelError as error:
            assert error.file == str(path) and error.line >= 1 and error.column >= 1
            continue
        ddq = m.aba(m.neutral(), [0] * m.nv, [0] * m.nv)
        assert ddq.shape == (m.nv,) and np.all(np.isfinite(ddq))
