#!/usr/bin/env python3
"""The contact model's effect on the paper's cases beside the law's, from two ensemble reports per
case: the contact study (contact-egg-*: exact@section vs exact@hertz) and the law study (egg-*:
exact vs the approximate laws, docs/ensembles/egg-*.md). Prints the markdown tables of
docs/ensembles/contact-model.md. Both reports are read as `frictionlab ensemble` wrote them.

  python3 dynamics/ensemble/contact_model_page.py --contact results/ensembles --laws docs/ensembles
"""
import argparse
import re
import sys
from pathlib import Path

CASES = [f"egg-{egg}-{c}" for egg in ("printed", "homogeneous") for c in "abc"]
FEATURES = ["t_vertical", "plateau_tilt_deg", "t_rest", "final_gamma3", "liftoffs", "work_slide", "work_spin"]
LAWS = ["pade-reconstructed", "moller-ellipsoidal"]


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def read_report(path):
    """{feature: {law: row}}, {law: class row}, {law: divergence row}, header line."""
    features, classes, divergence = {}, {}, {}
    feature = None
    section = None
    header = None
    for line in Path(path).read_text().splitlines():
        if line.startswith("## "):
            section = line
            feature = None
        m = re.match(r"### .*\(`([a-z_0-9]+)`", line)
        if m:
            feature = m.group(1)
            features[feature] = {}
            continue
        if not line.startswith("|") or line.startswith("|---"):
            continue
        c = cells(line)
        if c[0] in ("law", "", "feature"):
            header = c
            continue
        if feature and section and section.startswith("## Does"):
            features[feature][c[0]] = dict(zip(header, c))
        elif section and section.startswith("## Where the runs end"):
            classes[c[0]] = dict(zip(header, c))
        elif section and section.startswith("## Divergence"):
            divergence[c[0].split(" ")[0]] = dict(zip(header, c))
    return features, classes, divergence


def verdict(row):
    return row.get("verdict", "–").replace("**", "") if row else "–"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--contact", default="results/ensembles", help="folder of the contact-egg-* study outputs")
    ap.add_argument("--laws", default="docs/ensembles", help="folder of the law studies' reports (egg-*.md)")
    a = ap.parse_args()
    out = sys.stdout
    done = []
    for case in CASES:
        report = Path(a.contact) / f"contact-{case}" / "report.md"
        if report.exists():
            done.append(case)
    out.write("### Verdicts: the contact model beside the law\n\n")
    out.write("Per case and feature: *contact* = `exact@hertz` against `exact@section` (contact study), "
              "*law* = the approximate law against `exact` under `section` (law study). **C**: changes, "
              "c: within chaos, u: unclear, n: negligible.\n\n")
    short = {"changes": "**C**", "within chaos": "c", "unclear": "u", "negligible": "n", "n/a": "–", "–": "–"}
    out.write("| feature |" + "".join(f" {c.removeprefix('egg-')}: contact / pade-rec / moller |" for c in done) + "\n")
    out.write("|---|" + "---|" * len(done) + "\n")
    data = {}
    for case in done:
        data[case] = (read_report(Path(a.contact) / f"contact-{case}" / "report.md"),
                      read_report(Path(a.laws) / f"{case}.md"))
    rows = [("outcome class", None)] + [(f, f) for f in FEATURES]
    for name, f in rows:
        out.write(f"| {name} |")
        for case in done:
            (cf, cc, _), (lf, lc, _) = data[case]
            if f is None:
                v = [verdict(cc.get("exact@hertz"))] + [verdict(lc.get(law)) for law in LAWS]
            else:
                v = [verdict(cf.get(f, {}).get("exact@hertz"))] + [verdict(lf.get(f, {}).get(law)) for law in LAWS]
            out.write(" " + " / ".join(short.get(x, x) for x in v) + " |")
        out.write("\n")
    out.write("\n### Sizes: medians and W1 against the floor\n\n")
    out.write("| case | feature | median section | median Hertz | W1 contact (floor) | median pade-rec | W1 pade-rec (floor) "
              "| median moller | W1 moller (floor) |\n|---|---|---|---|---|---|---|---|---|\n")
    for case in done:
        (cf, cc, cd), (lf, lc, ld) = data[case]
        for f in ("t_vertical", "t_rest", "final_gamma3", "work_spin"):
            s = cf.get(f, {}).get("exact@section", {})
            h = cf.get(f, {}).get("exact@hertz", {})
            out.write(f"| {case.removeprefix('egg-')} | {f} | {s.get('median', '–')} | {h.get('median', '–')} | "
                      f"{h.get('W1', '–')} ({h.get('floor W1', '–')}) |")
            for law in LAWS:
                r = lf.get(f, {}).get(law, {})
                out.write(f" {r.get('median', '–')} | {r.get('W1', '–')} ({r.get('floor W1', '–')}) |")
            out.write("\n")
    out.write("\n### Outcome classes and divergence times\n\n")
    out.write("| case | classes section | classes Hertz | TV contact (floor) | TV pade-rec (floor) | TV moller (floor) "
              "| median parting Hertz vs section (s) | median parting floor (s) | D, p vs floor |\n|---|---|---|---|---|---|---|---|---|\n")
    for case in done:
        (cf, cc, cd), (lf, lc, ld) = data[case]
        def counts(row):
            return ", ".join(f"{k} {v}" for k, v in row.items() if k not in ("law", "TV", "p", "floor TV", "floor p", "verdict") and v != "0")
        h = cc.get("exact@hertz", {})
        out.write(f"| {case.removeprefix('egg-')} | {counts(cc.get('exact@section', {}))} | {counts(h)} | "
                  f"{h.get('TV', '–')} ({h.get('floor TV', '–')}) |")
        for law in LAWS:
            r = lc.get(law, {})
            out.write(f" {r.get('TV', '–')} ({r.get('floor TV', '–')}) |")
        d = cd.get('exact@hertz', {})
        out.write(f" {d.get('median', '–')} | {cd.get('floor', {}).get('median', '–')} | "
                  f"{d.get('D vs floor', '–')}, {d.get('p', '–')} |\n")
    missing = [c for c in CASES if c not in done]
    if missing:
        out.write("\nNot run: " + ", ".join(missing) + "\n")


if __name__ == "__main__":
    main()
