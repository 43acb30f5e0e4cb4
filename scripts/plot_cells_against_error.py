#!/usr/bin/python3
"""Cells against accuracy of Kirsch's hole (tests/kirsch_hole.cc, part 3):
the largest nodal hoop stress error along the hole, relative to 3 S,
against the number of cells, for uniform and graded meshes
(Geometry/Mesh grading), P1 and P2, on log-log axes, with the targets of
issue 18 (1 % for P2, 3 % for P1) as dashed lines.

    /usr/bin/python3 scripts/plot_cells_against_error.py \\
        build/tests/kirsch_hole/cells_against_error.txt --out PNG

The input has one row per mesh: degree, 'uniform' or 'graded', sides of
the hole's polygon per quarter, cells, error (%). Needs
matplotlib (Debian's python3-matplotlib).
"""
import argparse
import collections

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("data")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()

    series = collections.defaultdict(list)
    with open(args.data) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            degree, kind, sides, cells, error = line.split()
            series[(int(degree), kind)].append((int(cells), float(error), int(sides)))

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    colours = {1: "tab:blue", 2: "tab:red"}
    for (degree, kind), points in sorted(series.items()):
        points.sort()
        ax.loglog([p[0] for p in points], [p[1] for p in points],
                  "o-" if kind == "graded" else "s--",
                  color=colours[degree], label=f"P{degree} {kind}",
                  markerfacecolor="white" if kind == "uniform" else colours[degree])
        for cells, error, sides in points:
            ax.annotate(str(sides), (cells, error), textcoords="offset points",
                        xytext=(4, 4), fontsize=7, color=colours[degree])
    for degree, target in ((1, 3.0), (2, 1.0)):
        ax.axhline(target, color=colours[degree], linewidth=0.8, linestyle=":")
        ax.text(ax.get_xlim()[1] / 1.1, target * 1.05, f"P{degree} target {target:g} %",
                color=colours[degree], fontsize=8, ha="right")
    ax.set_xlabel("cells (quarter plate)")
    ax.set_ylabel("largest nodal hoop stress error along the hole (% of 3 S)")
    ax.set_title("Kirsch's hole: cells against accuracy\n"
                 "(numbers: sides of the hole's polygon per quarter)", fontsize=10)
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)


if __name__ == "__main__":
    main()
