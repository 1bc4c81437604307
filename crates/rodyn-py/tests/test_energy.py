"""Kinetic and potential energy against Pinocchio's computeKineticEnergy and
computePotentialEnergy, within 1e-9 of each energy's scale."""

from __future__ import annotations

import pinocchio as pin

from conftest import assert_close, random_states


def test_kinetic_energy(pair):
    for s in random_states(pair):
        reference = pin.computeKineticEnergy(pair.pin_model, pair.pin_data, s.q, s.v)
        assert_close("kinetic_energy", pair.model.kinetic_energy(s.q, s.v), reference)


def test_potential_energy(pair):
    for s in random_states(pair):
        reference = pin.computePotentialEnergy(pair.pin_model, pair.pin_data, s.q)
        assert_close("potential_energy", pair.model.potential_energy(s.q), reference)


def test_energies_are_floats(panda):
    q = panda.model.neutral()
    assert isinstance(panda.model.kinetic_energy(q, [0.0] * panda.model.nv), float)
    assert isinstance(panda.model.potential_energy(q), float)
