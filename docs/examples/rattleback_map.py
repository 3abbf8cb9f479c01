#!/usr/bin/env python3
"""Draws the rattleback study (data/studies/rattleback-map.toml): per law, over the contact's
stiffness (x: lambda, with the static compression on top) and the initial spin (y), whether the
spin reversed, and how the run ended. Reads the study's runs.csv (docs/ensembles.md §3).

    frictionlab ensemble data/studies/rattleback-map.toml --out results/ensembles/rattleback-map
    python3 docs/examples/rattleback_map.py results/ensembles/rattleback-map/runs.csv \\
        docs/figures/rattleback/rattleback-map.png

Markers read in grayscale: a filled circle, one reversal (its time in s beside it); a filled
triangle, two or more; without reversal, an open circle (rest), an open diamond (rocks on without
slip and spin: "rolling"), a grey square (undecided: the step budget or t_end ended it), a star
(the law's pole); a cross, the two replicas of the cell disagree (the chaos floor decides the cell). Also prints the table docs/rattleback.md carries.
"""
import csv
import math
import sys
from collections import defaultdict


class Cells(defaultdict):
    key = "contact.lambda"


def varied_key(fieldnames):
    """The study's varied key beside initial.omega3: runs.csv lists the varied keys between `law`
    and `reason` (contact.lambda for rattleback-map, body.misalignment for
    rattleback-misalignment)."""
    keys = fieldnames[fieldnames.index("law") + 1:fieldnames.index("reason")]
    others = [k for k in keys if k != "initial.omega3"]
    if len(others) != 1 or "initial.omega3" not in keys:
        raise SystemExit(f"rattleback_map.py: error: expected initial.omega3 and one other varied key, got {keys}")
    return others[0]


def load(path):
    cells = Cells(list)  # (law, x, omega3) -> rows
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        key = varied_key(reader.fieldnames)
        for r in reader:
            cells[(r["law"], float(r[key]), float(r["initial.omega3"]))].append(r)
    cells.key = key
    return cells


def reversals(r):
    return int(r["spin_reversals"])


def table(cells, laws):
    lams = sorted({k[1] for k in cells})
    spins = sorted({k[2] for k in cells})
    out = []
    for law in laws:
        out.append(f"\n{law}: first reversal time (s), or how the run ended; `|` separates replicas that differ\n")
        out.append(f"| omega3 (1/s) \\ {getattr(cells, 'key', 'contact.lambda')} | " + " | ".join(f"{l:.3g}" for l in lams) + " |")
        out.append("|---" * (len(lams) + 1) + "|")
        for w in spins:
            row = []
            for l in lams:
                texts = []
                for r in cells.get((law, l, w), []):
                    n = reversals(r)
                    texts.append(f"{n}x at {float(r['t_first_reversal']):.2f}" if n else r["reason"])
                row.append(" \\| ".join(sorted(set(texts))))
            out.append(f"| {w:+g} | " + " | ".join(row) + " |")
    return "\n".join(out)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: rattleback_map.py RUNS_CSV OUT_PNG\n")
        return 2
    cells = load(argv[1])
    laws = list(dict.fromkeys(k[0] for k in cells))
    print(table(cells, laws))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lams = sorted({k[1] for k in cells})
    spins = sorted({k[2] for k in cells})
    log_x = cells.key == "contact.lambda"
    fig, axes = plt.subplots(1, len(laws), figsize=(3.2 * len(laws), 3.6), sharey=True)
    for ax, law in zip(axes, laws):
        for (lw, l, w), rows in cells.items():
            if lw != law:
                continue
            ns = {reversals(r) for r in rows}
            x, y = (math.log10(l) if log_x else l), spins.index(w)
            if len(ns) > 1:
                ax.plot(x, y, "kx", ms=9)
            else:
                n = ns.pop()
                if n == 0:
                    # How a run without reversal ended: stopped (rest), rocking on without slip and
                    # spin (rolling), undecided within the step budget or t_end (grey square), or at
                    # the printed law's pole (star).
                    reason = rows[0]["reason"]
                    style = {"rest": ("o", "white"), "rolling": ("D", "white"), "law-pole": ("*", "white")}
                    marker, face = style.get(reason, ("s", "0.7"))
                    ax.plot(x, y, marker, mfc=face, mec="k", ms=8)
                else:
                    ax.plot(x, y, "o" if n == 1 else "^", color="k", ms=8)
                    ax.annotate(f"{float(rows[0]['t_first_reversal']):.1f}", (x, y), textcoords="offset points",
                                xytext=(0, 7), ha="center", fontsize=7)
        ax.set_title(law, fontsize=9)
        if log_x:
            ax.set_xlabel("log10 lambda (N/m^1.5)")
            ax.set_xticks([math.log10(l) for l in lams[::2]])
            ax.set_xticklabels([f"{math.log10(l):.1f}" for l in lams[::2]])
        else:
            ax.set_xlabel(cells.key + (" (rad)" if cells.key == "body.misalignment" else ""))
        ax.set_ylim(-0.6, len(spins) - 0.4)
        ax.grid(alpha=0.3)
    axes[0].set_yticks(range(len(spins)))
    axes[0].set_yticklabels([f"{w:+g}" for w in spins])
    axes[0].set_ylabel("initial spin omega3 (1/s; + counter-clockwise)")
    fig.suptitle("Kane & Levinson rattleback, k = 0.3. Reversed: filled circle (first time, s), triangle 2+.\n"
                 "Not reversed: circle rest, diamond rocks on (rolling), grey square undecided (step budget, "
                 "t_end or chatter), star law pole; x replicas differ", fontsize=7)
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
