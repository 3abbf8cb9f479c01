"""Evaluate every fast friction law over a range of slip ratios and plot them against `exact`.

    MPLBACKEND=Agg python3 docs/examples/plot_laws.py     # writes laws_F1_M.png, laws_F2.png

A circle would hide F2 (it vanishes by symmetry), so the patch is an ellipse, b/a = 0.5, its
major axis at psi = pi/4 from the slip. F1 and F2 are shown per kN, M per kNa, against the slip
ratio s = U/(a|Omega|) (docs/model.md: the laws depend on s, b/a, psi and sign(Omega) only).
"""

import matplotlib.pyplot as plt
import numpy as np

import frictionlab

a, b, psi = 0.01, 0.005, np.pi / 4   # m, m, rad
N, k, Omega = 10.0, 0.3, 20.0        # N, -, 1/s
s = np.logspace(-2, 2, 400)          # slip ratio U/(a|Omega|)
U = s * a * abs(Omega)               # m/s

laws = [info["name"] for info in frictionlab.laws() if not info["slow"]]
fig1, (ax_f1, ax_m) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
fig2, ax_f2 = plt.subplots(figsize=(5, 4), constrained_layout=True)
for name in laws:
    F1, F2, M = frictionlab.Law(name)(U, Omega, a, b, psi, N, k)   # all elements at once
    style = dict(lw=2.5, color="k") if name == "exact" else dict(lw=1.2)
    ax_f1.semilogx(s, F1 / (k * N), label=name, **style)
    ax_m.semilogx(s, M / (k * N * a), label=name, **style)
    ax_f2.semilogx(s, F2 / (k * N), label=name, **style)
ax_f1.set(xlabel="s = U / (a |Omega|)", ylabel="F1 / (k N)", title="sliding force")
ax_m.set(xlabel="s = U / (a |Omega|)", ylabel="M / (k N a)", title="spinning moment")
ax_f2.set(xlabel="s = U / (a |Omega|)", ylabel="F2 / (k N)", title=f"lateral force, b/a = {b / a}, psi = pi/4")
ax_m.legend(fontsize=8)
ax_f2.legend(fontsize=8)
fig1.savefig("laws_F1_M.png", dpi=120)
fig2.savefig("laws_F2.png", dpi=120)
print("wrote laws_F1_M.png, laws_F2.png")
