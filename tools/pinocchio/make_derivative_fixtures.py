#!/usr/bin/env python3
"""Writes Pinocchio reference results for rodyn's analytic derivatives.

Regenerate (from the repository root, after make_fixtures.py):

    python3 tools/pinocchio/make_derivative_fixtures.py   # host-tests/fixtures/derivatives/*.json

Every model of make_fixtures.py is loaded as it loads it, and the states
(q, v, a, tau, fext) are read back from `host-tests/fixtures/<name>.json`,
so both files describe the same states. Per state the file holds

* `rnea_dq`, `rnea_dv`, `rnea_da`: `computeRNEADerivatives(q, v, a)`
  (nv x nv each, rows = tau; `rnea_da` = M, symmetrised from its upper
  triangle), and `rnea_fext_dq`, `rnea_fext_dv` with the external forces;
* `aba_dq`, `aba_dv`, `aba_dtau`: `computeABADerivatives(q, v, tau)`
  (`aba_dtau` = M^-1, symmetrised), and `aba_fext_dq`, `aba_fext_dv` with
  the external forces.

Derivatives with respect to q are in Pinocchio's tangent space (a free
flyer's six columns are body-frame [linear; angular] increments). To keep
the files small, models with more than 7 velocity coordinates keep three
states, and those with more than 20 one state without the external-force
matrices; floats are written to 15 significant digits (a relative rounding
of 1e-15, far below the tests' 1e-9).
"""

from __future__ import annotations

import json

import numpy as np
import pinocchio as pin

from make_fixtures import OUT, REPO, SPECS, floats, load, write_states_fixture

OUT_DERIV = OUT / "derivatives"
#: Models with more velocity coordinates than these keep fewer states.
MEDIUM_NV = 7
LONG_NV = 20


def rounded(x) -> list:
    """Nested lists of floats at 15 significant digits."""
    return json.loads(json.dumps(floats(x), allow_nan=False), parse_float=lambda t: float(f"{float(t):.15g}"))


def symmetric(upper: np.ndarray) -> np.ndarray:
    return np.triu(upper) + np.triu(upper, 1).T


def state_results(model: pin.Model, data: pin.Data, state: dict, with_fext: bool) -> dict:
    q, v, a, tau = (np.array(state[k]) for k in ("q", "v", "a", "tau"))
    fext = [pin.Force.Zero()] + [pin.Force(np.array(f)) for f in state["fext"]]
    out = {}
    dq, dv, da = pin.computeRNEADerivatives(model, data, q, v, a)
    out["rnea_dq"], out["rnea_dv"], out["rnea_da"] = dq.copy(), dv.copy(), symmetric(da)
    dq, dv, dtau = pin.computeABADerivatives(model, data, q, v, tau)
    out["aba_dq"], out["aba_dv"], out["aba_dtau"] = dq.copy(), dv.copy(), symmetric(dtau)
    if with_fext:
        dq, dv, _ = pin.computeRNEADerivatives(model, data, q, v, a, fext)
        out["rnea_fext_dq"], out["rnea_fext_dv"] = dq.copy(), dv.copy()
        dq, dv, _ = pin.computeABADerivatives(model, data, q, v, tau, fext)
        out["aba_fext_dq"], out["aba_fext_dv"] = dq.copy(), dv.copy()
    return {k: rounded(x) for k, x in out.items()}


def main() -> None:
    OUT_DERIV.mkdir(parents=True, exist_ok=True)
    for spec in SPECS:
        model = load(spec)
        data = model.createData()
        base = json.loads((OUT / f"{spec.name}.json").read_text())
        keep = 1 if model.nv > LONG_NV else 3 if model.nv > MEDIUM_NV else None
        states = base["states"][:keep]
        fixture = {
            "generator": "tools/pinocchio/make_derivative_fixtures.py",
            "pinocchio_version": pin.__version__,
            "model_fixture": f"{spec.name}.json",
            "conventions": (
                "states (q, v, a, tau, fext) are the first states of model_fixture, in order "
                "(without the fext matrices above 20 coordinates); "
                "matrices row-major, rows and columns in v's order; derivatives with respect "
                "to q in the tangent space; SI units"
            ),
            "states": [state_results(model, data, s, model.nv <= LONG_NV) for s in states],
        }
        write_states_fixture(OUT_DERIV / f"{spec.name}.json", fixture)


if __name__ == "__main__":
    main()
