"""Sweep of every URDF of example-robot-data: does rodyn load what Pinocchio
loads, and agree with it?

For each URDF under the pip wheel's cmeel.prefix/share/example-robot-data/
robots (a free-flyer root, as `rodyn-model check --floating-base`):
Pinocchio 4.1 loads it (or not), checks that its mass matrix is positive
definite at the neutral configuration and at 3 random states, and computes
RNEA (with a random acceleration), the mass matrix and ABA; rodyn's model
compiler loads the same file at run time (the `model_sweep` example) and
computes the same. Continuous joints are converted (Pinocchio: cos, sin;
rodyn: one angle). Errors are max |x - x_ref| / max(1, max |x_ref|) over the
states.

Writes docs/sections/model_sweep.md (the table) and prints the counts.

    python3 tools/pinocchio/sweep_example_robot_data.py
"""

import glob
import json
import math
import os
import site
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import pinocchio as pin

ROOT = Path(__file__).resolve().parents[2]
TOLERANCE = 1e-9


def robots_dir():
    for p in site.getsitepackages():
        g = glob.glob(os.path.join(p, "cmeel.prefix/share/example-robot-data/robots"))
        if g:
            return Path(g[0])
    raise SystemExit("example-robot-data is not installed: pip install example-robot-data")


def rodyn_q(model, q):
    out = []
    for j in model.joints[1:]:
        i, nq, nv = j.idx_q, j.nq, j.nv
        if nq == 2 and nv == 1:  # continuous: cos, sin
            out.append(math.atan2(q[i + 1], q[i]))
        else:
            out.extend(q[i:i + nq].tolist())
    return out


def states(model, rng):
    data = model.createData()
    out = []
    for k in range(3):
        q = pin.integrate(model, pin.neutral(model), rng.uniform(-0.6, 0.6, model.nv))
        v = rng.uniform(-1.0, 1.0, model.nv)
        a = rng.uniform(-1.0, 1.0, model.nv)
        tau = rng.uniform(-1.0, 1.0, model.nv)
        m = pin.crba(model, data, q)
        m = np.triu(m) + np.triu(m, 1).T
        pd = bool(np.all(np.linalg.eigvalsh(m) > 0.0))
        ref = {"rnea": pin.rnea(model, data, q, v, a).tolist(), "mass_matrix": m.tolist(),
               "forward_dynamics": pin.aba(model, data, q, v, tau).tolist() if pd else None}
        out.append(({"q": rodyn_q(model, q), "v": v.tolist(), "a": a.tolist(), "tau": tau.tolist()}, ref, pd))
    return out


def error(x, ref):
    x, ref = np.array(x, dtype=float), np.array(ref, dtype=float)
    if x.shape != ref.shape:
        return math.inf
    return float(np.max(np.abs(x - ref)) / max(1.0, float(np.max(np.abs(ref)))))


def main():
    rng = np.random.default_rng(1)
    base = robots_dir()
    urdfs = sorted(base.rglob("*.urdf"))
    rows, jobs = [], []
    for path in urdfs:
        name = str(path.relative_to(base))
        try:
            model = pin.buildModelFromUrdf(str(path), pin.JointModelFreeFlyer())
        except Exception as e:  # noqa: BLE001 - any failure means "Pinocchio does not load it"
            rows.append({"name": name, "pin": False, "why": str(e).splitlines()[0][:80]})
            continue
        sts = states(model, rng)
        rows.append({"name": name, "pin": True, "nq": model.nq, "nv": model.nv,
                     "pd": all(s[2] for s in sts), "refs": [s[1] for s in sts]})
        jobs.append({"urdf": str(path), "floating_base": True, "states": [s[0] for s in sts], "row": len(rows) - 1})
    with tempfile.TemporaryDirectory() as tmp:
        inp, out = Path(tmp) / "in.json", Path(tmp) / "out.json"
        inp.write_text(json.dumps(jobs))
        subprocess.run(["cargo", "run", "--quiet", "--release", "-p", "rodyn-host-tests", "--example", "model_sweep",
                        "--", str(inp), str(out)], check=True, cwd=ROOT)
        results = json.loads(out.read_text())
    for job, res in zip(jobs, results):
        row = rows[job["row"]]
        row["rodyn"] = res["loaded"]
        if not res["loaded"]:
            row["why"] = res["error"].split("error: ")[-1][:100]
            continue
        row["rodyn_nq"], row["rodyn_nv"], row["warnings"] = res["nq"], res["nv"], res["warnings"]
        worst = 0.0
        for st, ref in zip(res["states"], row["refs"]):
            if "error" in st:
                worst = math.inf
                row["why"] = st["error"][:100]
                continue
            worst = max(worst, error(st["rnea"], ref["rnea"]), error(st["mass_matrix"], ref["mass_matrix"]))
            if ref["forward_dynamics"] is not None and st["forward_dynamics"] is not None:
                worst = max(worst, error(st["forward_dynamics"], ref["forward_dynamics"]))
        row["error"] = worst

    pin_pd = [r for r in rows if r["pin"] and r["pd"]]
    ok = [r for r in pin_pd if r.get("rodyn") and r.get("error", math.inf) <= TOLERANCE]
    lines = ["# Model files: example-robot-data against Pinocchio", "",
             "Every URDF of `example-robot-data` " + "(pip package, " + f"{len(urdfs)} files) with a free-flyer root, loaded by "
             "Pinocchio 4.1 and by rodyn's model compiler (at run time), compared on RNEA (random q, v, a), the "
             "mass matrix and forward dynamics (ABA; rodyn: `M⁻¹ (τ − h)` from its CRBA) at 3 random states. "
             "Error: max |x − x_ref| / max(1, max |x_ref|) over the states. Continuous joints: Pinocchio's (cos, sin) "
             "pair is one angle in rodyn (nq differs by one per such joint).", "",
             "Regenerate: `python3 tools/pinocchio/sweep_example_robot_data.py`.", "",
             f"**{len(ok)} of the {len(pin_pd)} URDFs that Pinocchio loads with a positive-definite mass matrix "
             f"load in rodyn and agree within {TOLERANCE:g}** ({sum(r['pin'] for r in rows)} of {len(rows)} load in Pinocchio).", "",
             "| robot | Pinocchio nq / nv | rodyn nq / nv | M positive definite | rodyn loads | warnings | worst relative error |",
             "|---|---|---|---|---|---:|---:|"]
    for r in rows:
        if not r["pin"]:
            lines.append(f"| `{r['name']}` | not loaded ({r['why']}) | | | | | |")
            continue
        loaded = "yes" if r.get("rodyn") else f"no: {r.get('why', '')}"
        rn = f"{r.get('rodyn_nq', '')} / {r.get('rodyn_nv', '')}" if r.get("rodyn") else ""
        err = f"{r['error']:.1e}" if "error" in r and math.isfinite(r["error"]) else ("-" if not r.get("rodyn") else r.get("why", "inf"))
        lines.append(f"| `{r['name']}` | {r['nq']} / {r['nv']} | {rn} | {'yes' if r['pd'] else 'no'} | {loaded} | "
                     f"{r.get('warnings', '')} | {err} |")
    (ROOT / "docs" / "sections" / "model_sweep.md").write_text("\n".join(lines) + "\n")
    print(f"{len(ok)} of {len(pin_pd)} Pinocchio-loadable (positive-definite) URDFs load in rodyn within {TOLERANCE:g}")
    for r in pin_pd:
        if r not in ok:
            print("  not within:", r["name"], r.get("why", ""), r.get("error"))


if __name__ == "__main__":
    main()
