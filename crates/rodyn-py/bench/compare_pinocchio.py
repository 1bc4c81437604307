#!/usr/bin/env python3
"""Time of one Python call of rodyn's and of Pinocchio's bindings.

    python crates/rodyn-py/bench/compare_pinocchio.py [--rounds N] [--calls N]

Run in the venv of `cargo xtask python-env` after `pip install
./crates/rodyn-py`. For the Panda (fixed base) and Solo12 (free-flyer) of
example-robot-data, both libraries load the same URDF and are called from
Python at the same random state: `aba`, `rnea`, `crba` and the Jacobian of
the end-effector frame in LOCAL_WORLD_ALIGNED (`computeFrameJacobian`,
which runs the forward kinematics as rodyn's `frame_jacobian` does). rodyn
is timed twice: returning a new array, and writing into an `out=` buffer.

Each round times a batch of calls of every variant in turn (interleaved,
so that a slow moment of the machine falls on all of them alike); the
table gives each variant's best round, in microseconds per call, Python's
call overhead included, and rodyn's time over Pinocchio's. The best round
rather than the median, as `timeit` advises: on a shared machine the other
rounds measure the other processes (a median moved by 10-20x between two
runs on a machine with a load of 11 on two cores). The last column is the
median over rounds of the ratio within each round: rodyn's and
Pinocchio's batches of one round run a few milliseconds apart, so a slow
moment of the machine moves both sides of that ratio alike.
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import sys
import sysconfig
import time
from pathlib import Path

import numpy as np
import pinocchio as pin

import rodyn

ROBOTS = [
    # (name, URDF under example-robot-data's robots/, floating base, end-effector frame)
    ("Panda", "panda_description/urdf/panda.urdf", False, "panda_hand"),
    ("Solo12", "solo_description/robots/solo12.urdf", True, "FL_FOOT"),
]


def robots_dir() -> Path:
    return Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix" / "share" / "example-robot-data" / "robots"


def positive(text: str) -> int:
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, not {value}")
    return value


def variants(name: str, urdf: Path, floating: bool, frame: str):
    """The calls to time: {function: {variant: callable}}."""
    m = rodyn.Model.from_urdf(str(urdf), floating_base=floating)
    pm = pin.buildModelFromUrdf(str(urdf), pin.JointModelFreeFlyer()) if floating else pin.buildModelFromUrdf(str(urdf))
    pd = pm.createData()
    if not pm.existFrame(frame) or frame not in m.frame_names:
        sys.exit(f"compare_pinocchio: {name} has no frame {frame}")
    fid = pm.getFrameId(frame)
    rng = np.random.default_rng(1)
    pin.seed(1)
    q = pin.randomConfiguration(pm, -np.ones(pm.nq), np.ones(pm.nq))
    v, a, tau = (rng.uniform(-1, 1, pm.nv) for _ in range(3))
    vec, mat, jac = np.empty(m.nv), np.empty((m.nv, m.nv)), np.empty((6, m.nv))
    lwa = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
    return {
        "aba": {
            "pinocchio": lambda: pin.aba(pm, pd, q, v, tau),
            "rodyn": lambda: m.aba(q, v, tau),
            "rodyn out=": lambda: m.aba(q, v, tau, out=vec),
        },
        "rnea": {
            "pinocchio": lambda: pin.rnea(pm, pd, q, v, a),
            "rodyn": lambda: m.rnea(q, v, a),
            "rodyn out=": lambda: m.rnea(q, v, a, out=vec),
        },
        "crba": {
            "pinocchio": lambda: pin.crba(pm, pd, q),
            "rodyn": lambda: m.crba(q),
            "rodyn out=": lambda: m.crba(q, out=mat),
        },
        "frame_jacobian": {
            "pinocchio": lambda: pin.computeFrameJacobian(pm, pd, q, fid, lwa),
            "rodyn": lambda: m.frame_jacobian(q, frame),
            "rodyn out=": lambda: m.frame_jacobian(q, frame, out=jac),
        },
    }


def time_batch(call, calls: int) -> float:
    """Microseconds per call over one batch."""
    start = time.perf_counter_ns()
    for _ in range(calls):
        call()
    return (time.perf_counter_ns() - start) / calls / 1e3


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{cpu}; Python {platform.python_version()}; Pinocchio {pin.__version__}; numpy {np.__version__}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=positive, default=101, help="interleaved rounds (the best is taken)")
    parser.add_argument("--calls", type=positive, default=300, help="calls per variant per round")
    args = parser.parse_args()

    tables = {}
    for name, urdf, floating, frame in ROBOTS:
        path = robots_dir() / urdf
        if not path.exists():
            sys.exit(f"compare_pinocchio: {path} is missing (pip install example-robot-data)")
        tables[name] = variants(name, path, floating, frame)
    samples = {(r, f, v): [] for r, table in tables.items() for f, calls in table.items() for v in calls}
    for key in samples:  # warm-up
        r, f, v = key
        time_batch(tables[r][f][v], args.calls // 10 + 1)
    # Every variant of every robot in each round.
    for _ in range(args.rounds):
        for key in samples:
            r, f, v = key
            samples[key].append(time_batch(tables[r][f][v], args.calls))
    rows = []
    for r, table in tables.items():
        for f in table:
            pin_rounds = samples[(r, f, "pinocchio")]
            ours_rounds = samples[(r, f, "rodyn")]
            pin_us, ours = min(pin_rounds), min(ours_rounds)
            ours_out = min(samples[(r, f, "rodyn out=")])
            median_ratio = float(np.median(np.array(ours_rounds) / np.array(pin_rounds)))
            rows.append((r, f, pin_us, ours, ours_out, median_ratio))

    print(f"{datetime.date.today().isoformat()}; {machine()}; "
          f"best of {args.rounds} interleaved rounds of {args.calls} calls; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs")
    print()
    print("| robot | function | Pinocchio (µs) | rodyn (µs) | rodyn / Pinocchio | rodyn `out=` (µs) | `out=` / Pinocchio | median of rounds' rodyn / Pinocchio |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for name, f, pin_us, ours, ours_out, median_ratio in rows:
        print(f"| {name} | `{f}` | {pin_us:.2f} | {ours:.2f} | {ours / pin_us:.2f} | {ours_out:.2f} | {ours_out / pin_us:.2f} "
              f"| {median_ratio:.2f} |")


if __name__ == "__main__":
    main()
