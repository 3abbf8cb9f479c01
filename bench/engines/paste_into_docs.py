#!/usr/bin/env python3
"""Pastes a run of engines_side_by_side into docs/engines.md §6: the tables of RUN/engines.md
between the markers <!-- engines table: begin --> and <!-- engines table: end -->, and the figures
RUN/plots/*.png into docs/figures/engines/problem-*.png. Regenerate, do not retype:

    build/bench/engines/engines_side_by_side --out results/engines
    python3 bench/engines/paste_into_docs.py results/engines
"""
import pathlib
import shutil
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]
BEGIN, END = "<!-- engines table: begin -->", "<!-- engines table: end -->"


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: paste_into_docs.py RUN_FOLDER")
    run = pathlib.Path(sys.argv[1])
    table = (run / "engines.md").read_text(encoding="utf-8").strip()
    doc_path = REPO / "docs" / "engines.md"
    doc = doc_path.read_text(encoding="utf-8")
    if doc.count(BEGIN) != 1 or doc.count(END) != 1:
        sys.exit(f"paste_into_docs.py: error: {doc_path} needs one '{BEGIN}' and one '{END}'")
    head, rest = doc.split(BEGIN)
    _, tail = rest.split(END)
    doc_path.write_text(head + BEGIN + "\n" + table + "\n" + END + tail, encoding="utf-8")
    figures = REPO / "docs" / "figures" / "engines"
    for png in sorted((run / "plots").glob("*.png")):
        shutil.copyfile(png, figures / ("problem-" + png.name))
        print("copied", png.name)


if __name__ == "__main__":
    main()
