"""Simulate the egg of the paper's case (a) with two laws and plot gamma3, the component of the
upward vertical along the egg's symmetry axis (docs/model.md): it starts at 0.97 and |gamma3|
near 1 means the axis is vertical (docs/experiments.md compares the laws on it).

    MPLBACKEND=Agg python3 docs/examples/simulate_egg.py    # writes egg_gamma3.png

The scenario is the shipped data/scenarios/egg-printed-a.toml (or $FRICTIONLAB_DATA_DIR's).
"""

import os

import matplotlib.pyplot as plt

import frictionlab

here = os.path.dirname(os.path.abspath(__file__))
data = os.environ.get("FRICTIONLAB_DATA_DIR", os.path.join(here, "..", "..", "data"))
scenario = os.path.join(data, "scenarios", "egg-printed-a.toml")

fig, ax = plt.subplots(figsize=(7, 4), constrained_layout=True)
for law in ["exact", "moller-ellipsoidal"]:
    run = frictionlab.simulate(scenario, law=law, overrides={"run.t_end": 30.0, "run.output_dt": 0.01})
    print(f"{law}: {run.reason} at t = {run.summary['final_time']:.4g} s, {len(run.t)} samples")
    ax.plot(run.t, run["gamma3"], label=law, lw=1)
ax.set(xlabel="t (s)", ylabel="gamma3", title="egg-printed, case a")
ax.legend()
fig.savefig("egg_gamma3.png", dpi=120)
print("wrote egg_gamma3.png")
