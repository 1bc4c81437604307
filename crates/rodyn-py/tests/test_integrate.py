"""`integrate` against Pinocchio's integrate: free-flyers on SE(3), the
continuous joints' (cos, sin) pairs on the circle."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from conftest import assert_close, random_states


def test_integrate(pair):
    for s in random_states(pair):
        reference = pin.integrate(pair.pin_model, s.q, s.v)
        ours = pair.model.integrate(s.q, s.v)
        assert_close("integrate", ours, reference)
        assert pin.isNormalized(pair.pin_model, ours, 1e-12)


def test_integrate_rejects_a_wrong_velocity(panda):
    with pytest.raises(ValueError, match="v has"):
        panda.model.integrate(panda.model.neutral(), np.zeros(panda.model.nv + 1))
