#!/usr/bin/python3
"""Charts of issue 16: the brick wall's drift and the Brazilian disc's
centre stress with each time integrator.

Runs two scenes of prm/ as they are, with only `Control/Time integrator`
replaced (and, per series, extra entries of subsection Contact), and draws
from what ndda writes:

- brick_wall.png: the top corners' displacements (the scene's two measure
  points, u_x and u_y in mm) and the kinetic energy against time;
- brazilian_disc.png: the centre's sigma_xx and sigma_yy (measure point 0,
  MPa) and the cracked edges against time.

It also writes a markdown fragment with the figures each run ends with
(exit code and message, steps, step cuts, open-close cuts, largest energy
gain, end values of the charted quantities, wall time).

A series is INTEGRATOR or INTEGRATOR+ENTRY=VALUE for an entry of
subsection Contact (e.g. 'generalized-alpha+Open-close iterations=40').

Run it with Debian's Python (python3-numpy, python3-matplotlib):

    /usr/bin/python3 scripts/integrator_charts.py --ndda build/ndda \\
        --prm-dir prm --out-dir doc/integrators \\
        --markdown doc/integrators/integrators.md
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ndda_output import read_table  # noqa: E402

DEFAULT_SERIES = (
    "DDA",
    "generalized-alpha",
    "generalized-alpha+Open-close iterations=40",
)
SCENES = ("brick_wall", "brazilian_disc")


def parse_series(text):
    """'generalized-alpha+Open-close iterations=40' -> (integrator, {entry: value})."""
    parts = text.split("+")
    contact = {}
    for part in parts[1:]:
        if "=" not in part:
            raise SystemExit(f"--series: '{part}' is not ENTRY=VALUE")
        entry, value = part.split("=", 1)
        contact[entry.strip()] = value.strip()
    return parts[0].strip(), contact


def scene_text(prm_path, integrator, contact, directory):
    """The scene's text with the integrator, the contact entries and the
    output directory replaced."""
    with open(prm_path) as stream:
        text = stream.read()
    text, n = re.subn(r"(?m)^(\s*set Time integrator\s*=).*$",
                      rf"\g<1> {integrator}", text)
    if n != 1:
        raise SystemExit(f"{prm_path}: expected one 'set Time integrator' line")
    lines = [f"  set {entry} = {value}" for entry, value in contact.items()]
    if lines:
        text, n = re.subn(r"(?m)^subsection Contact\s*$",
                          "subsection Contact\n" + "\n".join(lines), text, count=1)
        if n != 1:
            raise SystemExit(f"{prm_path}: no 'subsection Contact'")
    text, n = re.subn(r"(?m)^subsection Output\s*$",
                      f"subsection Output\n  set Directory = {directory}", text, count=1)
    if n != 1:
        raise SystemExit(f"{prm_path}: no 'subsection Output'")
    return text


def run(ndda, prm_dir, scene, series, work_dir, timeout):
    """Run one scene with one series; its output directory and a summary."""
    integrator, contact = parse_series(series)
    tag = re.sub(r"[^A-Za-z0-9]+", "_", series).strip("_")
    directory = os.path.join(work_dir, f"{scene}_{tag}")
    prm = os.path.join(work_dir, f"{scene}_{tag}.prm")
    with open(prm, "w") as stream:
        stream.write(scene_text(os.path.join(prm_dir, scene + ".prm"),
                                integrator, contact, directory))
    start = time.perf_counter()
    try:
        result = subprocess.run([ndda, prm], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, timeout=timeout)
        code, output = result.returncode, result.stdout
    except subprocess.TimeoutExpired as expired:
        code, output = None, (expired.stdout or b"").decode(errors="replace")
    wall = time.perf_counter() - start
    message = ""
    for line in output.splitlines():
        if "error:" in line:
            message = line.split("error:", 1)[1].strip()
    if code is None:
        message = f"stopped after {timeout} s"
    return dict(series=series, directory=directory, code=code, message=message, wall=wall)


def statistics_summary(directory):
    stats = read_table(os.path.join(directory, "statistics"))
    summary = dict(
        end_time=stats["Time (s)"][-1],
        steps=len(stats["Time (s)"]),
        step_cuts=int(stats["Step cuts"].sum()),
        open_close_cuts=int(stats["Open-close cuts"].sum()) if "Open-close cuts" in stats else 0,
        largest_gain=stats["Energy gain (J)"].max(),
        supplied=np.abs(stats["Work of loads (J)"]).max(),
    )
    return stats, summary


def figure(n_rows, height):
    """A figure of n_rows panels over a shared time axis."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt.subplots(n_rows, 1, figsize=(7.5, height), sharex=True)


def finish(fig, axes, title, png):
    """Legend on the first panel, title, grids; save and close."""
    import matplotlib.pyplot as plt

    axes[-1].set_xlabel("time (ms)")
    axes[0].legend(fontsize=7)
    axes[0].set_title(title)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def plot_brick_wall(runs, png):
    fig, axes = figure(3, 8)
    for k, r in enumerate(runs):
        points = read_table(os.path.join(r["directory"], "measure_points.txt"))
        t = points["time"] * 1e3
        for p, style in ((0, "-"), (1, "--")):
            axes[0].plot(t, points[f"point {p} u_x"] * 1e3, style, color=f"C{k}",
                         label=f"{r['series']}, point {p}")
            axes[1].plot(t, points[f"point {p} u_y"] * 1e3, style, color=f"C{k}")
        axes[2].semilogy(r["stats"]["Time (s)"] * 1e3,
                         np.maximum(r["stats"]["Kinetic energy (J)"], 1e-12),
                         color=f"C{k}", label=r["series"])
    axes[0].set_ylabel("top corner u_x (mm)")
    axes[1].set_ylabel("top corner u_y (mm)")
    axes[2].set_ylabel("kinetic energy (J)")
    finish(fig, axes, "Brick wall: drift of the top corners (measure points 0 and 1)", png)


def plot_disc(runs, png):
    fig, axes = figure(2, 6.5)
    for k, r in enumerate(runs):
        points = read_table(os.path.join(r["directory"], "measure_points.txt"))
        t = points["time"] * 1e3
        axes[0].plot(t, points["point 0 sigma_xx"] / 1e6, "-", color=f"C{k}",
                     label=f"{r['series']}: sigma_xx")
        axes[0].plot(t, points["point 0 sigma_yy"] / 1e6, "--", color=f"C{k}",
                     label=f"{r['series']}: sigma_yy")
        axes[1].plot(r["stats"]["Time (s)"] * 1e3, r["stats"]["Cracked edges"],
                     color=f"C{k}", label=r["series"])
    axes[0].set_ylabel("centre stress (MPa)")
    axes[1].set_ylabel("cracked edges")
    finish(fig, axes, "Brazilian disc: stress at the centre (measure point 0)", png)


def end_value(table, column):
    return table[column][-1]


def markdown(runs_by_scene, out_dir, markdown_path, elapsed):
    rel = os.path.relpath(out_dir, os.path.dirname(os.path.abspath(markdown_path)))
    lines = [
        "## Integrators on the brick wall and the Brazilian disc (issue 16)",
        "",
        f"Generated by `scripts/integrator_charts.py` on {time.strftime('%Y-%m-%d')} "
        f"({sum(len(r) for r in runs_by_scene.values())} ndda runs, "
        f"{elapsed / 60:.1f} min): each scene of `prm/` as it is, with "
        "`Control/Time integrator` replaced, and for a series with '+' an entry of "
        "subsection Contact set as named.",
        "",
    ]
    for scene, runs in runs_by_scene.items():
        lines += [f"### {scene}", "", f"![{scene}]({rel}/{scene}.png)", ""]
        if scene == "brick_wall":
            header = "| series | exit | end time (s) | steps | step cuts | open-close cuts | largest energy gain (J) | top corners u_x at the end (mm) | top corners u_y at the end (mm) | wall time (s) |"
        else:
            header = "| series | exit | end time (s) | steps | step cuts | open-close cuts | largest energy gain (J) | centre sigma_xx at the end (MPa) | cracked edges at the end | wall time (s) |"
        lines += [header, "|" + "---|" * (header.count("|") - 1)]
        for r in runs:
            s = r["summary"]
            points = read_table(os.path.join(r["directory"], "measure_points.txt"))
            if scene == "brick_wall":
                extra = (f"{1e3 * end_value(points, 'point 0 u_x'):.3g}, "
                         f"{1e3 * end_value(points, 'point 1 u_x'):.3g} | "
                         f"{1e3 * end_value(points, 'point 0 u_y'):.3g}, "
                         f"{1e3 * end_value(points, 'point 1 u_y'):.3g}")
            else:
                extra = (f"{end_value(points, 'point 0 sigma_xx') / 1e6:.3g} | "
                         f"{int(end_value(r['stats'], 'Cracked edges'))}")
            exit_text = "0" if r["code"] == 0 else f"{r['code']}: {r['message']}"
            lines.append(
                f"| {r['series']} | {exit_text} | {s['end_time']:.4g} | {s['steps']} | "
                f"{s['step_cuts']} | {s['open_close_cuts']} | {s['largest_gain']:.3g} | "
                f"{extra} | {r['wall']:.1f} |")
        lines.append("")
    with open(markdown_path, "w") as stream:
        stream.write("\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ndda", required=True)
    parser.add_argument("--prm-dir", required=True)
    parser.add_argument("--out-dir", required=True)
    parser.add_argument("--markdown", required=True)
    parser.add_argument("--series", default=",".join(DEFAULT_SERIES),
                        help="comma-separated series (default: %(default)s)")
    parser.add_argument("--timeout", type=float, default=600)
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    series = [s.strip() for s in args.series.split(",") if s.strip()]
    ndda = os.path.abspath(args.ndda)
    start = time.perf_counter()
    runs_by_scene = {}
    with tempfile.TemporaryDirectory(prefix="integrator_charts_") as work_dir:
        for scene in SCENES:
            runs = []
            for s in series:
                r = run(ndda, args.prm_dir, scene, s, work_dir, args.timeout)
                r["stats"], r["summary"] = statistics_summary(r["directory"])
                print(f"{scene}, {s}: exit {r['code']}, t = {r['summary']['end_time']:.4g} s, "
                      f"{r['wall']:.1f} s {r['message']}", flush=True)
                runs.append(r)
            runs_by_scene[scene] = runs
        plot_brick_wall(runs_by_scene["brick_wall"], os.path.join(args.out_dir, "brick_wall.png"))
        plot_disc(runs_by_scene["brazilian_disc"], os.path.join(args.out_dir, "brazilian_disc.png"))
        markdown(runs_by_scene, args.out_dir, args.markdown, time.perf_counter() - start)
    print(f"wrote {args.out_dir} and {args.markdown}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
