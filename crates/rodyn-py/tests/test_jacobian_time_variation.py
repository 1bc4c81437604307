"""The time variation of frame Jacobians against Pinocchio's
getFrameJacobianTimeVariation (after computeJointJacobiansTimeVariation and
updateFramePlacements), in the three reference frames."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from conftest import assert_close, random_states

REFERENCES = {
    "local": pin.ReferenceFrame.LOCAL,
    "world": pin.ReferenceFrame.WORLD,
    "local_world_aligned": pin.ReferenceFrame.LOCAL_WORLD_ALIGNED,
}


@pytest.mark.parametrize("reference", sorted(REFERENCES))
def test_frame_jacobian_time_variation(pair, reference):
    pm, pd = pair.pin_model, pair.pin_data
    for s in random_states(pair, count=2):
        pin.computeJointJacobiansTimeVariation(pm, pd, s.q, s.v)
        pin.updateFramePlacements(pm, pd)
        for name in pair.model.frame_names:
            expected = pin.getFrameJacobianTimeVariation(pm, pd, pm.getFrameId(name), REFERENCES[reference])
            ours = pair.model.frame_jacobian_time_variation(s.q, s.v, name, reference)
            assert_close(f"frame_jacobian_time_variation {name} {reference}", ours, expected)


def test_default_reference_and_out_buffer(panda):
    m = panda.model
    s = random_states(panda, count=1)[0]
    name = m.frame_names[-1]
    expected = m.frame_jacobian_time_variation(s.q, s.v, name, "local_world_aligned")
    np.testing.assert_array_equal(m.frame_jacobian_time_variation(s.q, s.v, name), expected)
    out = np.full((6, m.nv), np.nan)
    assert m.frame_jacobian_time_variation(s.q, s.v, name, out=out) is out
    np.testing.assert_array_equal(out, expected)


def test_zero_velocity_gives_zero(panda):
    m = panda.model
    q = random_states(panda, count=1)[0].q
    dj = m.frame_jacobian_time_variation(q, np.zeros(m.nv), m.frame_names[-1])
    np.testing.assert_array_equal(dj, np.zeros((6, m.nv)))
