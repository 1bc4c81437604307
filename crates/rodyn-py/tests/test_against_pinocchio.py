"""Every function of `rodyn.Model` against Pinocchio 4.1's Python bindings
on example-robot-data's robots, at seeded random states, within 1e-9 of
each result's scale (conftest.TOLERANCE).

Arrays go in and come out in Pinocchio's layout (free-flyer
q = [x y z qx qy qz qw], continuous joints as (cos, sin)), so no test
converts anything.
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from conftest import assert_close, get_pair, pinocchio_contact_models, random_states, symmetric_from_upper

REFERENCES = {
    "local": pin.ReferenceFrame.LOCAL,
    "world": pin.ReferenceFrame.WORLD,
    "local_world_aligned": pin.ReferenceFrame.LOCAL_WORLD_ALIGNED,
}


def test_sizes_and_names(pair):
    m, pm = pair.model, pair.pin_model
    assert (m.nq, m.nv) == (pm.nq, pm.nv)
    assert m.joint_names == list(pm.names)[1:]
    missing = [name for name in m.frame_names if not pm.existFrame(name)]
    assert not missing, f"frames Pinocchio does not have: {missing}"
    assert len(set(m.frame_names)) == len(m.frame_names)


def test_neutral(pair):
    assert_close("neutral", pair.model.neutral(), pin.neutral(pair.pin_model))


def test_random_configuration_is_a_configuration(pair):
    m, pm = pair.model, pair.pin_model
    q = m.random_configuration(seed=3)
    assert q.shape == (m.nq,) and np.all(np.isfinite(q))
    np.testing.assert_array_equal(q, m.random_configuration(seed=3))
    assert not np.array_equal(q, m.random_configuration(seed=4))
    # Pinocchio's own check of unit quaternions and (cos, sin) pairs.
    assert pin.isNormalized(pm, q, 1e-12)
    # Usable by both: RNEA agrees there too.
    v = np.linspace(-1, 1, m.nv)
    assert_close("rnea at random_configuration", m.rnea(q, v, v), pin.rnea(pm, pair.pin_data, q, v, v))


def test_rnea(pair):
    for s in random_states(pair):
        assert_close("rnea", pair.model.rnea(s.q, s.v, s.a), pin.rnea(pair.pin_model, pair.pin_data, s.q, s.v, s.a))


def test_aba(pair):
    for s in random_states(pair):
        assert_close("aba", pair.model.aba(s.q, s.v, s.tau), pin.aba(pair.pin_model, pair.pin_data, s.q, s.v, s.tau))


def test_crba_is_full_and_symmetric(pair):
    for s in random_states(pair):
        ours = pair.model.crba(s.q)
        np.testing.assert_array_equal(ours, ours.T)
        reference = symmetric_from_upper(pin.crba(pair.pin_model, pair.pin_data, s.q))
        assert_close("crba", ours, reference)


def test_gravity(pair):
    for s in random_states(pair):
        reference = pin.computeGeneralizedGravity(pair.pin_model, pair.pin_data, s.q)
        assert_close("gravity", pair.model.gravity(s.q), reference)


def test_nonlinear_effects(pair):
    for s in random_states(pair):
        reference = pin.nonLinearEffects(pair.pin_model, pair.pin_data, s.q, s.v)
        assert_close("nonlinear_effects", pair.model.nonlinear_effects(s.q, s.v), reference)


def test_frame_placement(pair):
    pm, pd = pair.pin_model, pair.pin_data
    for s in random_states(pair, count=2):
        pin.framesForwardKinematics(pm, pd, s.q)
        for name in pair.model.frame_names:
            ours = pair.model.frame_placement(s.q, name)
            assert_close(f"frame_placement {name}", ours, pd.oMf[pm.getFrameId(name)].homogeneous)


@pytest.mark.parametrize("reference", sorted(REFERENCES))
def test_frame_jacobian(pair, reference):
    pm, pd = pair.pin_model, pair.pin_data
    for s in random_states(pair, count=2):
        for name in pair.model.frame_names:
            expected = pin.computeFrameJacobian(pm, pd, s.q, pm.getFrameId(name), REFERENCES[reference])
            ours = pair.model.frame_jacobian(s.q, name, reference)
            assert_close(f"frame_jacobian {name} {reference}", ours, expected)


def test_frame_jacobian_default_reference_is_local_world_aligned(pair):
    q = random_states(pair, count=1)[0].q
    name = pair.model.frame_names[-1]
    np.testing.assert_array_equal(
        pair.model.frame_jacobian(q, name), pair.model.frame_jacobian(q, name, "local_world_aligned")
    )


def test_com(pair):
    for s in random_states(pair):
        assert_close("com", pair.model.com(s.q), pin.centerOfMass(pair.pin_model, pair.pin_data, s.q))


def test_centroidal_map(pair):
    for s in random_states(pair):
        reference = pin.computeCentroidalMap(pair.pin_model, pair.pin_data, s.q)
        assert_close("centroidal_map", pair.model.centroidal_map(s.q), reference)


def test_rnea_derivatives(pair):
    for s in random_states(pair):
        dtau_dq, dtau_dv, mass = pair.model.rnea_derivatives(s.q, s.v, s.a)
        ref_dq, ref_dv, ref_m = pin.computeRNEADerivatives(pair.pin_model, pair.pin_data, s.q, s.v, s.a)
        assert_close("rnea_derivatives dtau_dq", dtau_dq, ref_dq)
        assert_close("rnea_derivatives dtau_dv", dtau_dv, ref_dv)
        assert_close("rnea_derivatives M", mass, symmetric_from_upper(ref_m))


def test_aba_derivatives(pair):
    for s in random_states(pair):
        dddq_dq, dddq_dv, minv = pair.model.aba_derivatives(s.q, s.v, s.tau)
        ref_dq, ref_dv, ref_minv = pin.computeABADerivatives(pair.pin_model, pair.pin_data, s.q, s.v, s.tau)
        assert_close("aba_derivatives dddq_dq", dddq_dq, ref_dq)
        assert_close("aba_derivatives dddq_dv", dddq_dv, ref_dv)
        assert_close("aba_derivatives Minv", minv, symmetric_from_upper(ref_minv))


def test_out_buffers_are_filled_and_returned(pair):
    m = pair.model
    s = random_states(pair, count=1)[0]
    cases = [
        (lambda out: m.rnea(s.q, s.v, s.a, out=out), (m.nv,), m.rnea(s.q, s.v, s.a)),
        (lambda out: m.aba(s.q, s.v, s.tau, out=out), (m.nv,), m.aba(s.q, s.v, s.tau)),
        (lambda out: m.crba(s.q, out=out), (m.nv, m.nv), m.crba(s.q)),
    ]
    name = m.frame_names[-1]
    cases.append((lambda out: m.frame_jacobian(s.q, name, "world", out=out), (6, m.nv), m.frame_jacobian(s.q, name, "world")))
    for call, shape, expected in cases:
        out = np.full(shape, np.nan)
        returned = call(out)
        assert returned is out
        np.testing.assert_array_equal(out, expected)


def test_lists_and_non_contiguous_arrays_are_accepted(pair):
    m = pair.model
    s = random_states(pair, count=1)[0]
    expected = m.aba(s.q, s.v, s.tau)
    np.testing.assert_array_equal(m.aba(list(s.q), tuple(s.v), list(s.tau)), expected)
    strided = np.zeros((m.nv, 2))
    strided[:, 0] = s.tau
    np.testing.assert_array_equal(m.aba(s.q, s.v, strided[:, 0]), expected)
    # The one-liner: zeros as Python ints.
    zero = [0] * m.nv
    assert_close("aba from lists of ints", m.aba(m.neutral(), zero, zero), pin.aba(pair.pin_model, pair.pin_data, pin.neutral(pair.pin_model), np.zeros(m.nv), np.zeros(m.nv)))


#: Contact sets per robot: frame names are point contacts (CONTACT_3D in
#: LOCAL_WORLD_ALIGNED), (name, "frame") pairs hold the whole frame
#: (CONTACT_6D in LOCAL).
CONTACT_CASES = [
    ("panda", [("panda_hand", "frame")]),
    ("solo12", ["FL_FOOT"]),
    ("solo12", ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"]),
    ("solo12", [("HL_FOOT", "frame"), "FR_FOOT"]),
    ("anymal", ["LF_FOOT", "RH_FOOT"]),
    ("talos_reduced", [("left_sole_link", "frame"), ("right_sole_link", "frame")]),
    ("talos_reduced", [("left_sole_link", "frame"), "right_sole_link"]),
    ("g1", [("left_ankle_roll_link", "frame"), ("right_ankle_roll_link", "frame")]),
]


def pinocchio_constraint_dynamics(pair, q, v, tau, contacts):
    """Pinocchio's constraintDynamics for `contacts`, anchored where the
    frames are, without Baumgarte gains: the exact KKT solution."""
    pm, pd = pair.pin_model, pair.pin_data
    models, datas = pinocchio_contact_models(pair, q, contacts)
    pin.initConstraintDynamics(pm, pd, models, datas)
    ddq = pin.constraintDynamics(pm, pd, q, v, tau, models, datas, pin.ProximalSettings(1e-14, 0.0, 1))
    return np.array(ddq), np.array(pd.lambda_c)


@pytest.mark.parametrize("robot, contacts", CONTACT_CASES, ids=[f"{r}-{len(c)}-{i}" for i, (r, c) in enumerate(CONTACT_CASES)])
def test_constrained_dynamics(robot, contacts):
    pair = get_pair(robot)
    for s in random_states(pair):
        ddq, lam = pair.model.constrained_dynamics(s.q, s.v, s.tau, contacts)
        ref_ddq, ref_lam = pinocchio_constraint_dynamics(pair, s.q, s.v, s.tau, contacts)
        assert_close("constrained_dynamics ddq", ddq, ref_ddq)
        assert_close("constrained_dynamics lambda", lam, ref_lam)
