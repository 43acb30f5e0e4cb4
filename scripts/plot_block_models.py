#!/usr/bin/python3
"""Chart of benchmarks/block_models: time per step against the number of
bricks, one line per block kinematics model (rigid, affine, meshed).

Reads the benchmark's standard output (one or more files; a later row for
the same model and wall replaces an earlier one) and draws two log-log
panels: the mean wall time per nominal step (2 ms of simulated time: a
run whose steps were cut takes more steps for it), and that time per
brick, against the number of bricks, with the issue's targets (1.0 ms a step at about 100
bricks; a cost per brick flat within a factor 2, drawn as the band from
the cheapest 102-brick model's cost per brick to twice it).

    /usr/bin/python3 scripts/plot_block_models.py block_models.txt \\
        --out doc/performance/block_models.png

Needs Debian's python3-matplotlib.
"""

import argparse
import collections
import re
import sys

# model, bricks, DoFs, ms/step, median, us/brick, then the counts per step
ROW = re.compile(r"^\s*(meshed|affine|rigid)\s+(\d+)\s+(\d+)\s+([\d.]+)"
                 r"\s+([\d.]+)\s+([\d.]+)(\s+[\d.]+)+\s*$")
# How the runs started (the benchmark's first line), for the title.
STARTS = set()
STYLE = {"meshed": ("o-", "tab:blue"), "affine": ("s-", "tab:orange"),
         "rigid": ("^-", "tab:green")}


def read_rows(paths):
    """{model: {bricks: (ms per step, us per brick)}} from the outputs;
    per nominal step (2 ms of simulated time) where a row has the mean
    accepted step over the nominal one (dt/dt0, the tenth column)."""
    rows = collections.defaultdict(dict)
    for path in paths:
        with open(path) as f:
            for line in f:
                if "gravity was ramped" in line:
                    STARTS.add("settled walls (gravity ramped up)")
                elif "gravity switched on at t = 0" in line:
                    STARTS.add("gravity switched on at t = 0")
                m = ROW.match(line)
                if m:
                    model, bricks = m.group(1), int(m.group(2))
                    fields = line.split()
                    scale = float(fields[9]) if len(fields) >= 11 else 1.
                    rows[model][bricks] = (float(m.group(4)) / scale,
                                           float(m.group(6)) / scale)
    if not rows:
        sys.exit("plot_block_models: no rows of block_models in "
                 + ", ".join(paths))
    return rows


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for model in ("rigid", "affine", "meshed"):
        if model not in rows:
            continue
        bricks = sorted(rows[model])
        marker, colour = STYLE[model]
        left.loglog(bricks, [rows[model][b][0] for b in bricks], marker,
                    color=colour, label=model)
        right.loglog(bricks, [rows[model][b][1] for b in bricks], marker,
                     color=colour, label=model)
    left.axhline(1.0, color="grey", linestyle="--", linewidth=1)
    left.annotate("target at ~100 bricks: 1.0 ms", (110, 1.05),
                  color="grey", fontsize=8)
    smallest = min(min(r) for r in rows.values())
    base = min(r[smallest][1] for r in rows.values() if smallest in r)
    right.axhspan(base, 2 * base, color="grey", alpha=0.2,
                  label="flat within 2x")
    left.set_xlabel("bricks")
    left.set_ylabel("wall time per 2 ms step (ms)")
    right.set_xlabel("bricks")
    right.set_ylabel("wall time per 2 ms step and brick (us)")
    for ax in (left, right):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Staggered brick walls, DDA, dt = 2 ms"
                 + "".join(", " + s for s in sorted(STARTS))
                 + " (benchmarks/block_models.cc)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outputs", nargs="+",
                        help="standard output of benchmarks/block_models")
    parser.add_argument("--out", required=True, help="the PNG to write")
    args = parser.parse_args()
    plot(read_rows(args.outputs), args.out)


if __name__ == "__main__":
    main()
