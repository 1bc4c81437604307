"""Bad input raises ValueError (or its subclass rodyn.ModelError) naming
what is wrong; nothing crashes the interpreter."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rodyn
from conftest import get_pair


def test_model_error_carries_file_line_and_column(tmp_path):
    path = tmp_path / "broken.urdf"
    path.write_text(
        '<robot name="broken">\n'
        '  <link name="base"/>\n'
        '  <joint name="elbow" type="hinge">\n'
        '    <parent link="base"/><child link="arm"/>\n'
        "  </joint>\n"
        '  <link name="arm"/>\n'
        "</robot>\n"
    )
    with pytest.raises(rodyn.ModelError) as caught:
        rodyn.Model.from_urdf(str(path))
    error = caught.value
    assert isinstance(error, ValueError)
    assert error.file == str(path)
    assert error.line == 3
    assert error.column >= 1
    assert f"{path}:3:{error.column}" in str(error)
    assert "hinge" in str(error)


def test_toml_diagnostic_has_its_line(tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text('name = "broken"\n\n[[bodies]]\nname = 3\n')
    with pytest.raises(rodyn.ModelError) as caught:
        rodyn.Model.from_file(str(path))
    assert caught.value.file == str(path)
    assert caught.value.line >= 3


def test_missing_file_is_a_model_error(tmp_path):
    path = tmp_path / "absent.urdf"
    with pytest.raises(rodyn.ModelError, match="cannot read"):
        rodyn.Model.from_urdf(str(path))


def test_wrong_length_names_the_argument_and_the_lengths(panda):
    m = panda.model
    q = m.neutral()
    with pytest.raises(ValueError, match=rf"\bv\b.*{m.nv - 1}.*{m.nv}|\bv\b.*{m.nv}.*{m.nv - 1}"):
        m.rnea(q, np.zeros(m.nv - 1), np.zeros(m.nv))
    with pytest.raises(ValueError, match=r"\bq\b"):
        m.crba(np.zeros(m.nq + 1))


def test_nan_names_the_argument_and_the_entry(panda):
    m = panda.model
    tau = np.zeros(m.nv)
    tau[4] = math.nan
    with pytest.raises(ValueError, match=r"tau.*\b4\b"):
        m.aba(m.neutral(), np.zeros(m.nv), tau)
    q = m.neutral()
    q[2] = math.inf
    with pytest.raises(ValueError, match=r"\bq\b.*\b2\b"):
        m.gravity(q)


def test_wrong_dtype_is_named(panda):
    m = panda.model
    with pytest.raises(ValueError, match="float64"):
        m.rnea(m.neutral(), np.zeros(m.nv, dtype=np.float32), np.zeros(m.nv))
    with pytest.raises(ValueError, match=r"\ba\b"):
        m.rnea(m.neutral(), np.zeros(m.nv), np.zeros(m.nv, dtype=np.int64))
    with pytest.raises(ValueError, match=r"\bq\b"):
        m.crba("not a vector")
    with pytest.raises(ValueError, match=r"\bq\b.*(1-D|one-dimensional|dimension)"):
        m.crba(np.zeros((m.nq, 1)))


def test_unknown_frame_and_reference(panda):
    m = panda.model
    with pytest.raises(ValueError, match="no_such_frame"):
        m.frame_placement(m.neutral(), "no_such_frame")
    with pytest.raises(ValueError, match="no_such_frame"):
        m.frame_jacobian(m.neutral(), "no_such_frame")
    with pytest.raises(ValueError, match="sideways.*local_world_aligned"):
        m.frame_jacobian(m.neutral(), m.frame_names[0], "sideways")


def test_bad_out_buffers(panda):
    m = panda.model
    q, zero = m.neutral(), np.zeros(m.nv)
    with pytest.raises(ValueError, match=r"out.*shape"):
        m.rnea(q, zero, zero, out=np.zeros(m.nv + 1))
    with pytest.raises(ValueError, match=r"out.*float64"):
        m.crba(q, out=np.zeros((m.nv, m.nv), dtype=np.float32))
    with pytest.raises(ValueError, match=r"out.*contiguous"):
        m.crba(q, out=np.zeros((m.nv, 2 * m.nv))[:, ::2])
    read_only = np.zeros(m.nv)
    read_only.flags.writeable = False
    with pytest.raises(ValueError, match=r"out.*writ"):
        m.aba(q, zero, zero, out=read_only)
    # The output may not be one of the inputs.
    tau = np.zeros(m.nv)
    with pytest.raises(ValueError, match=r"out.*tau"):
        m.aba(q, zero, tau, out=tau)


def test_quaternion_not_of_unit_length_is_named():
    m = get_pair("solo12").model
    q = m.neutral()
    q[3:7] = [0.0, 0.0, 0.0, 2.0]
    with pytest.raises(ValueError, match="quaternion|unit"):
        m.aba(q, np.zeros(m.nv), np.zeros(m.nv))


def test_continuous_joint_pair_not_on_the_circle_is_named():
    m = get_pair("double_pendulum_continuous").model
    q = m.neutral()
    q[0:2] = [2.0, 0.0]
    with pytest.raises(ValueError, match=r"\bq\b"):
        m.rnea(q, np.zeros(m.nv), np.zeros(m.nv))


def test_bad_contacts_are_named(panda):
    m = panda.model
    q, zero = m.neutral(), np.zeros(m.nv)
    with pytest.raises(ValueError, match="no_such_frame"):
        m.constrained_dynamics(q, zero, zero, ["no_such_frame"])
    with pytest.raises(ValueError, match=r"contacts\[0\].*'point' or 'frame'"):
        m.constrained_dynamics(q, zero, zero, [("panda_hand", "line")])
    with pytest.raises(ValueError, match="list"):
        m.constrained_dynamics(q, zero, zero, "panda_hand")


def test_redundant_contacts_are_an_arithmetic_error():
    m = get_pair("solo12").model
    q = m.neutral()
    # The same foot held twice: the constraint rows are dependent.
    with pytest.raises(ArithmeticError, match="constrained dynamics"):
        m.constrained_dynamics(q, np.zeros(m.nv), np.zeros(m.nv), ["FL_FOOT", "FL_FOOT"])


def test_frame_name_of_another_type_is_named(panda):
    q = panda.model.neutral()
    with pytest.raises(ValueError, match="name must be a frame's name"):
        panda.model.frame_jacobian(q, 3)
    with pytest.raises(ValueError, match="name must be a frame's name"):
        panda.model.frame_placement(q, None)


def test_frame_names_are_recognised_after_many_others(panda):
    # More names than the bindings keep, then the first again: the
    # answer must not depend on what was kept.
    m = panda.model
    q = m.random_configuration(seed=5)
    first = m.frame_jacobian(q, m.frame_names[0])
    for name in m.frame_names * 2:
        m.frame_jacobian(q, "".join(name))  # a new str object each time
    np.testing.assert_array_equal(m.frame_jacobian(q, m.frame_names[0]), first)
    with pytest.raises(ValueError, match="unknown frame 'nope'"):
        m.frame_jacobian(q, "nope")
