# %% [markdown]
# # rodyn from Python: the Panda against Pinocchio
#
# Loads example-robot-data's Panda with rodyn and with Pinocchio, checks
# that both compute the same dynamics, then lets the arm fall under
# gravity from a bent pose with joint damping, integrated with rodyn's
# forward dynamics (ABA), and plots the joint angles and the hand's height.
#
#     pip install ./crates/rodyn-py pin example-robot-data matplotlib
#     python examples/python/panda_against_pinocchio.py [--out panda_fall.png]
#
# The cells (`# %%`) run one by one in VS Code, Spyder or Jupyter
# (through jupytext) as well as in one go.

# %%
import argparse
import sysconfig
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # writes a file; no window needed
import matplotlib.pyplot as plt
import numpy as np
import pinocchio as pin

import rodyn

parser = argparse.ArgumentParser(description="The Panda falling, rodyn against Pinocchio")
parser.add_argument("--out", type=Path, default=Path("panda_fall.png"), help="the PNG to write")
parser.add_argument("--duration", type=float, default=2.0, help="simulated time, s (default 2)")
args, _ = parser.parse_known_args()  # known only: notebooks pass their own
if not args.duration > 0:
    parser.error(f"--duration must be positive, not {args.duration}")

robots = Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix/share/example-robot-data/robots"
urdf = robots / "panda_description/urdf/panda.urdf"

# %% [markdown]
# ## One URDF, two libraries
# Both read the same file; rodyn takes and returns numpy arrays in
# Pinocchio's layout, so states pass between them unchanged.

# %%
model = rodyn.Model.from_urdf(str(urdf))
pin_model = pin.buildModelFromUrdf(str(urdf))
pin_data = pin_model.createData()
print(f"{urdf.name}: nq = {model.nq}, nv = {model.nv}, joints {model.joint_names}")

hand = pin_model.getFrameId("panda_hand")


def pinocchio_hand(q):
    pin.framesForwardKinematics(pin_model, pin_data, q)
    return pin_data.oMf[hand].homogeneous


rng = np.random.default_rng(0)
worst = {}
for _ in range(20):
    q = pin.randomConfiguration(pin_model, -np.ones(model.nq), np.ones(model.nq))
    v, tau = rng.uniform(-1, 1, model.nv), rng.uniform(-5, 5, model.nv)
    checks = {
        "aba": (model.aba(q, v, tau), pin.aba(pin_model, pin_data, q, v, tau)),
        "rnea": (model.rnea(q, v, tau), pin.rnea(pin_model, pin_data, q, v, tau)),
        # Pinocchio fills the upper triangle of M.
        "crba": (model.crba(q), np.triu(pin.crba(pin_model, pin_data, q)) + np.triu(pin_data.M, 1).T),
        "hand placement": (model.frame_placement(q, "panda_hand"), pinocchio_hand(q)),
    }
    for name, (ours, theirs) in checks.items():
        worst[name] = max(worst.get(name, 0.0), float(np.max(np.abs(ours - theirs))))
for name, difference in worst.items():
    print(f"{name:>15}: largest difference from Pinocchio over 20 states {difference:.1e}")
assert max(worst.values()) < 1e-9, "rodyn and Pinocchio disagree"

# %% [markdown]
# ## A damped fall
# Semi-implicit Euler at 1 ms: q̈ = ABA(q, v, −D v), with D = 2 N·m·s/rad
# on every joint. Pinocchio's ABA is called at the same states for the
# record of their largest difference along the way.

# %%
dt, damping = 1e-3, 2.0
steps = int(round(args.duration / dt))
q = pin.neutral(pin_model)
q[:7] = [0.0, -0.3, 0.0, -2.2, 0.0, 2.0, 0.8]  # a bent pose
v = np.zeros(model.nv)
ddq = np.empty(model.nv)  # reused: rodyn writes into it
times, angles, hand_height = [], [], []
largest_difference = 0.0
for k in range(steps + 1):
    times.append(k * dt)
    angles.append(q[:7].copy())
    hand_height.append(model.frame_placement(q, "panda_hand")[2, 3])
    tau = -damping * v
    model.aba(q, v, tau, out=ddq)
    largest_difference = max(largest_difference, float(np.max(np.abs(ddq - pin.aba(pin_model, pin_data, q, v, tau)))))
    v = v + dt * ddq
    q = pin.integrate(pin_model, q, dt * v)
print(f"fall of {args.duration} s in {steps} steps; largest |q̈ rodyn − q̈ Pinocchio| {largest_difference:.1e} rad/s²")

# %% [markdown]
# ## Plot

# %%
times, angles = np.array(times), np.array(angles)
fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True, height_ratios=[2, 1])
for j in range(7):
    top.plot(times, angles[:, j], label=model.joint_names[j])
top.set_ylabel("joint angle (rad)")
top.set_title(f"Panda falling under gravity with joint damping {damping} N·m·s/rad (rodyn ABA, dt = {dt * 1e3:.0f} ms)")
top.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), fontsize="small")
top.grid(alpha=0.3)
bottom.plot(times, hand_height, color="black", label="panda_hand")
bottom.set_xlabel("time (s)")
bottom.set_ylabel("hand height (m)")
bottom.legend(loc="upper right", fontsize="small")
bottom.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(args.out, dpi=120)
print(f"wrote {args.out}")
