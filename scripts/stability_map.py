#!/usr/bin/python3
"""Stability map: where the contact methods fail, over penalty x step size.

For each scene (block drop, vertex-vertex example 2, jointed grid) the
script runs ndda over

- 'Contact/Penalty factor' (fixed penalty, multiples of E t): 10, 30, 100,
  300, 1000, plus the scene's own factor where it lies inside that range;
- 'Control/Time step': the scene's own x 0.1, 0.3, 1, 3, 10;
- 'Contact/Vertex-vertex method': revised, shortest path;
- 'Control/Time integrator': DDA, Newmark and generalized-alpha at its
  default spectral radius (--integrators names others or fewer);

with a shortened 'End time' per scene (SCENES below says which and why),
and classifies each run by ndda's own checks, the first that applies:

1. diverged: an error exit other than the open-close one (the step size
   fell below 1e-6 of the nominal step, the displacement increment still
   too large after all step cuts, a crash), or NaN/inf in the statistics;
2. open-close not converged: the error exit that says the open-close
   iteration still changes contact states, or a finished run in which
   ndda had to halve steps because the open-close iteration did not
   settle ('Open-close cuts' > 0);
3. energy gained: 'Energy gain (J)' rises above 1 % of the energy supplied
   to the scene, i.e. the largest |work of loads + initial kinetic
   energy| of the run (ndda's gain is kinetic + strain + contact energy -
   work of loads - initial kinetic energy, so the initial kinetic energy
   is read from the first row as kinetic + strain + contact energy - gain
   - work of loads);
4. penetrated: 'Max penetration (m)' beyond the scene's tolerance,
   'Contact/Maximum penetration ratio' x half the scene height (ndda's
   definition, source/simulator.cc: half of the larger of the mesh's
   height and 1e-3 of its width; the height is read from the mesh ndda
   writes at t = 0 in a probe run);
5. stable.

A run that exceeds --timeout (wall seconds) is stopped and classified
from the statistics rows it wrote (open-close cuts, energy gain); if they
show neither, it is 'timed out'. ndda rewrites its statistics file at every
progress line, set here to every 0.5 s, so a stopped run or an error exit
leaves the rows up to then.

Writes into --out-dir one PNG per scene (2 x 2 panels: integrator x
vertex-vertex method; penalty factor against step size, the scene's own
setting outlined), runs.csv (one row per run) and the markdown fragment
--markdown (tables, counts and sentences generated from the results). Text
between the lines '<!-- hand-written begin -->' and '<!-- hand-written
end -->' of an existing markdown file is kept when it is written again.

Run it with Debian's Python (python3-numpy, python3-matplotlib):

    /usr/bin/python3 scripts/stability_map.py --ndda build/ndda \\
        --prm-dir prm --out-dir doc/stability \\
        --markdown doc/stability/stability.md
    /usr/bin/python3 scripts/stability_map.py --ndda build/ndda \\
        --prm-dir prm --out-dir /tmp/stab --markdown /tmp/stab/s.md --quick

Runs one ndda process at a time; each run's output goes to a temporary
directory that is removed after it is read (--keep keeps them).
"""

import argparse
import collections
import csv
import datetime
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ndda_output  # noqa: E402

PENALTIES = (10.0, 30.0, 100.0, 300.0, 1000.0)
STEP_FACTORS = (0.1, 0.3, 1.0, 3.0, 10.0)
METHODS = ("revised", "shortest path")
INTEGRATORS = ("DDA", "Newmark", "generalized-alpha")

QUICK_SCENE = "vertex_vertex_2"
QUICK_PENALTIES = (10.0, 1000.0)
QUICK_STEP_FACTORS = (1.0, 10.0)

# End time of each scene's runs, and why that much is enough.
SCENES = collections.OrderedDict(
    [
        (
            "block_drop",
            dict(
                end_time=0.34,
                why="the block hits at 0.319 s; 0.34 s covers the fall, the "
                "first impact (0.1-1 ms at these penalties) and 20 ms of the "
                "rebound",
            ),
        ),
        (
            "vertex_vertex_2",
            dict(
                end_time=None,
                why="the scene's own end time: the vertex reaches the apex "
                "at 0.14 s and lands on an edge or the other within it",
            ),
        ),
        (
            "jointed_grid",
            dict(
                end_time_steps=15,
                why="15 of the scene's own steps (0.03 s): the grid loads "
                "its contacts under gravity (a wave crosses its 7 m in "
                "about 3 ms) and settles or starts to chatter",
            ),
        ),
    ]
)

CLASSES = collections.OrderedDict(
    [
        ("stable", dict(code="S", colour="#4daf4a")),
        ("penetrated", dict(code="P", colour="#ff7f00")),
        ("energy gained", dict(code="E", colour="#e41a1c")),
        ("open-close not converged", dict(code="OC", colour="#377eb8")),
        ("diverged", dict(code="D", colour="#252525")),
        ("timed out", dict(code="T", colour="#bdbdbd")),
    ]
)

ENERGY_LIMIT = 0.01

CSV_FIELDS = [
    "scene",
    "integrator",
    "method",
    "penalty_factor",
    "dt_factor",
    "dt",
    "end_time",
    "class",
    "class_without_cuts",
    "message",
    "exit_code",
    "steps",
    "time_reached",
    "step_cuts",
    "open_close_cuts",
    "mean_open_close_iterations",
    "max_penetration",
    "penetration_tolerance",
    "max_energy_gain",
    "energy_reference",
    "wall_time",
]


class MapError(Exception):
    """A problem that stops the sweep (bad arguments, unreadable scene)."""


def read_entry(text, subsection, entry):
    """Value of 'set entry = value' inside 'subsection ...' of a prm text.

    Only the last occurrence counts, as in deal.II's ParameterHandler;
    continuation lines and nested subsections are followed.
    """
    path = []
    value = None
    for line in text.replace("\\\n", " ").splitlines():
        line = line.split("#", 1)[0].strip()
        match = re.match(r"subsection\s+(.*\S)", line)
        if match:
            path.append(match.group(1))
            continue
        if line == "end":
            if path:
                path.pop()
            continue
        match = re.match(r"set\s+(.*?)\s*=\s*(.*)", line)
        if match and path == [subsection] and match.group(1) == entry:
            value = match.group(2).strip()
    return value


def override(text, entries):
    """The prm text with a block per subsection appended (the last set wins)."""
    blocks = collections.OrderedDict()
    for (subsection, entry), value in entries.items():
        blocks.setdefault(subsection, []).append(f"  set {entry} = {value}")
    appended = "".join(
        f"\nsubsection {name}\n" + "\n".join(lines) + "\nend\n"
        for name, lines in blocks.items()
    )
    return text.rstrip("\n") + "\n" + appended


def run_ndda(ndda, text, work, timeout):
    """Run ndda on a prm text in 'work'; (exit code, stderr, seconds)."""
    os.makedirs(work, exist_ok=True)
    prm = os.path.join(work, "scene.prm")
    with open(prm, "w") as stream:
        stream.write(text)
    start = time.monotonic()
    try:
        process = subprocess.run(
            [ndda, prm],
            cwd=work,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            text=True,
            timeout=timeout,
        )
        code, stderr = process.returncode, process.stderr
    except subprocess.TimeoutExpired as error:
        stderr = error.stderr or ""
        if isinstance(stderr, bytes):
            stderr = stderr.decode(errors="replace")
        code = None
    return code, stderr, time.monotonic() - start


def error_message(stderr):
    """The text after 'ndda: error:' on one line, else stderr's last line."""
    match = re.search(r"ndda: error:\s*(.*)", stderr, re.S)
    text = match.group(1) if match else (stderr.strip().splitlines() or [""])[-1]
    return " ".join(text.split())


class Scene:
    """One scene: its prm text, own settings and penetration tolerance."""

    def __init__(self, name, prm_dir, settings):
        self.name = name
        path = os.path.join(prm_dir, name + ".prm")
        try:
            with open(path) as stream:
                self.text = stream.read()
        except OSError as error:
            raise MapError(f"{path}: cannot read the scene: {error}")

        def own(subsection, entry, default):
            value = read_entry(self.text, subsection, entry)
            return value if value is not None else default

        self.dt = float(own("Control", "Time step", "1e-3"))
        self.own_end_time = float(own("Control", "End time", "1"))
        self.penalty = float(own("Contact", "Penalty factor", "100"))
        self.penalty_mode = own("Contact", "Penalty", "fixed")
        self.method = own("Contact", "Vertex-vertex method", "revised")
        self.integrator = own("Control", "Time integrator", "Newmark")
        self.penetration_ratio = float(
            own("Contact", "Maximum penetration ratio", "1e-3")
        )
        if "end_time_steps" in settings:
            self.end_time = settings["end_time_steps"] * self.dt
        else:
            self.end_time = settings["end_time"] or self.own_end_time
        self.why = settings["why"]
        self.half_height = None
        self.tolerance = None

    def probe(self, ndda, work, timeout):
        """Half the scene height from the mesh ndda writes at t = 0."""
        text = override(
            self.text,
            {
                ("Control", "End time"): repr(self.dt),
                ("Output", "Directory"): os.path.join(work, "out") + "/",
                ("Output", "Write vtu"): "true",
                ("Output", "Interval"): "0",
            },
        )
        code, stderr, _ = run_ndda(ndda, text, work, timeout)
        if code != 0:
            raise MapError(
                f"{self.name}: the probe run (one step) failed: "
                f"{error_message(stderr)}"
            )
        points = ndda_output.read_vtu(
            os.path.join(work, "out", "solution-00000.vtu")
        ).points
        height = points[:, 1].max() - points[:, 1].min()
        width = points[:, 0].max() - points[:, 0].min()
        self.half_height = 0.5 * max(height, 1e-3 * width)
        self.tolerance = self.penetration_ratio * self.half_height


def read_statistics(path):
    """ndda_output.read_table, after dropping a last row cut short.

    ndda rewrites the file at every progress line; a run stopped by the
    timeout can leave its last row half written.
    """
    with open(path) as stream:
        lines = stream.read().splitlines(keepends=True)
    n_columns = sum(1 for line in lines if re.match(r"#\s*\d+:", line))
    if lines and not lines[-1].startswith("#"):
        last = lines[-1]
        if not last.endswith("\n") or len(last.split()) != n_columns:
            trimmed = path + ".trimmed"
            with open(trimmed, "w") as stream:
                stream.writelines(lines[:-1])
            return ndda_output.read_table(trimmed)
    return ndda_output.read_table(path)


def classify(code, message, stats):
    """The class of one run and the figures it rests on (see the top)."""
    figures = dict(
        steps=0,
        time_reached=0.0,
        step_cuts=0,
        open_close_cuts=0,
        mean_open_close_iterations=float("nan"),
        max_penetration=float("nan"),
        max_energy_gain=float("nan"),
        energy_reference=float("nan"),
    )
    finite = True
    if stats is not None and len(stats["Time (s)"]):
        gain = stats["Energy gain (J)"]
        held = (
            stats["Kinetic energy (J)"]
            + stats["Strain energy (J)"]
            + stats["Contact energy (J)"]
        )
        # gain = held - work of loads - initial kinetic energy; the initial
        # kinetic energy from the first row, where all three are still small
        # (later rows of a run that blows up lose it in the rounding of the
        # 7 digits the file keeps)
        work = stats["Work of loads (J)"]
        initial_kinetic = held[0] - gain[0] - work[0]
        figures.update(
            steps=int(stats["Time step number"][-1]),
            time_reached=float(stats["Time (s)"][-1]),
            step_cuts=int(np.nansum(stats["Step cuts"])),
            open_close_cuts=int(np.nansum(stats["Open-close cuts"])),
            mean_open_close_iterations=float(
                np.nanmean(stats["Open-close iterations"])
            ),
            max_penetration=float(np.max(stats["Max penetration (m)"])),
            max_energy_gain=float(np.max(gain)),
            energy_reference=float(np.max(np.abs(work + initial_kinetic))),
        )
        finite = all(np.all(np.isfinite(column)) for column in stats.values())
    if not finite:
        return "diverged", figures
    if code is not None and code != 0:
        if "open-close iteration" in message:
            return "open-close not converged", figures
        return "diverged", figures
    # A finished run, or one stopped by the timeout: the rows it wrote.
    if figures["open_close_cuts"] > 0:
        return "open-close not converged", figures
    if figures["max_energy_gain"] > ENERGY_LIMIT * figures["energy_reference"]:
        return "energy gained", figures
    if code is None:
        return "timed out", figures
    return None, figures


def class_without_cuts(row):
    """For a run classed by its open-close cuts alone: the class it would
    have without that criterion (energy gained, penetrated, stable, timed
    out); '' for every other run."""
    if row["class"] != "open-close not converged" or row["exit_code"] not in (0, ""):
        return ""
    if row["max_energy_gain"] > ENERGY_LIMIT * row["energy_reference"]:
        return "energy gained"
    if row["max_penetration"] > row["penetration_tolerance"]:
        return "penetrated"
    return "stable" if row["exit_code"] == 0 else "timed out"


def run_case(ndda, scene, integrator, method, penalty, dt_factor, work, timeout):
    """One run of the sweep: its CSV row (a dict)."""
    dt = scene.dt * dt_factor
    text = override(
        scene.text,
        {
            ("Control", "Time step"): repr(dt),
            ("Control", "End time"): repr(scene.end_time),
            ("Control", "Time integrator"): integrator,
            ("Contact", "Penalty"): "fixed",
            ("Contact", "Penalty factor"): repr(penalty),
            ("Contact", "Vertex-vertex method"): method,
            ("Output", "Directory"): os.path.join(work, "out") + "/",
            ("Output", "Write vtu"): "false",
            ("Output", "Interval"): repr(scene.end_time),
            # statistics are written at every progress line: an error exit
            # keeps the rows up to the last one
            ("Output", "Progress interval"): "0.5",
        },
    )
    code, stderr, seconds = run_ndda(ndda, text, work, timeout)
    message = error_message(stderr) if code != 0 else ""
    stats = None
    statistics = os.path.join(work, "out", "statistics")
    if os.path.exists(statistics):
        try:
            stats = read_statistics(statistics)
        except ndda_output.OutputError as error:
            message = (message + "; " if message else "") + str(error)
    run_class, figures = classify(code, message, stats)
    if code is None:
        message = (
            f"stopped by --timeout {timeout:g} s at t = {figures['time_reached']:.4g} s "
            f"of {scene.end_time:g} s, {figures['steps']} steps, "
            f"{figures['step_cuts']} step cuts"
        )
    if run_class is None:
        run_class = (
            "penetrated"
            if figures["max_penetration"] > scene.tolerance
            else "stable"
        )
    row = dict(
        scene=scene.name,
        integrator=integrator,
        method=method,
        penalty_factor=penalty,
        dt_factor=dt_factor,
        dt=dt,
        end_time=scene.end_time,
        message=message,
        exit_code="" if code is None else code,
        penetration_tolerance=scene.tolerance,
        wall_time=seconds,
        **figures,
    )
    row["class"] = run_class
    return row


# ----------------------------------------------------------------- output


def read_csv(path):
    """The rows of a runs.csv this script wrote, with their types."""
    integers = ("steps", "step_cuts", "open_close_cuts")
    text = ("scene", "integrator", "method", "class", "class_without_cuts", "message")
    try:
        with open(path, newline="") as stream:
            rows = list(csv.DictReader(stream))
    except OSError as error:
        raise MapError(f"--from-csv {path}: cannot read: {error}")
    for row in rows:
        for key, value in row.items():
            if key in text:
                continue
            if key == "exit_code":
                row[key] = int(value) if value != "" else ""
            elif key in integers:
                row[key] = int(value)
            else:
                row[key] = float(value)
    return rows


def scene_penalties(scene, penalties):
    """The sweep's penalties, with the scene's own if it lies inside them."""
    values = set(penalties)
    if min(penalties) <= scene.penalty <= max(penalties):
        values.add(scene.penalty)
    return sorted(values)


def number(value):
    """A penalty or step factor as text: 10, 0.3, 40."""
    return f"{value:g}"


def plot_scene(scene, rows, penalties, step_factors, path):
    """2 x 2 panels of classes, penalty (x) against step factor (y)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch, Rectangle

    names = list(CLASSES)
    colours = ListedColormap([CLASSES[name]["colour"] for name in names])
    figure, axes = plt.subplots(
        len(INTEGRATORS),
        len(METHODS),
        figsize=(8.0, 6.8),
        sharex=True,
        sharey=True,
        squeeze=False,
    )
    present = set()
    for i, integrator in enumerate(INTEGRATORS):
        for j, method in enumerate(METHODS):
            ax = axes[i][j]
            grid = np.full((len(step_factors), len(penalties)), np.nan)
            for row in rows:
                if row["integrator"] != integrator or row["method"] != method:
                    continue
                if row["penalty_factor"] in penalties and row["dt_factor"] in step_factors:
                    y = step_factors.index(row["dt_factor"])
                    x = penalties.index(row["penalty_factor"])
                    grid[y, x] = names.index(row["class"])
                    present.add(row["class"])
                    label = CLASSES[row["class"]]["code"]
                    if class_without_cuts(row):
                        label += f" {row['open_close_cuts']}\n→{CLASSES[class_without_cuts(row)]['code']}"
                    if row["exit_code"] == "":
                        label += "†"
                    ax.text(
                        x,
                        y,
                        label,
                        ha="center",
                        va="center",
                        fontsize=8,
                        color="white" if row["class"] in ("diverged", "open-close not converged") else "black",
                    )
            ax.imshow(
                np.ma.masked_invalid(grid),
                cmap=colours,
                vmin=-0.5,
                vmax=len(names) - 0.5,
                origin="lower",
                aspect="auto",
            )
            if scene.penalty in penalties and 1.0 in step_factors:
                ax.add_patch(
                    Rectangle(
                        (penalties.index(scene.penalty) - 0.5, step_factors.index(1.0) - 0.5),
                        1,
                        1,
                        fill=False,
                        linewidth=2.5,
                        edgecolor="magenta" if (integrator, method) == (scene.integrator, scene.method) else "#999999",
                    )
                )
            elif 1.0 in step_factors:
                ax.axhline(step_factors.index(1.0), color="#999999", linewidth=0.8, linestyle=":")
            own = (integrator, method) == (scene.integrator, scene.method)
            ax.set_title(
                f"{integrator}, {method}" + ("  (scene's own)" if own else ""),
                fontsize=10,
                fontweight="bold" if own else "normal",
            )
            ax.set_xticks(range(len(penalties)))
            ax.set_xticklabels([number(p) for p in penalties], fontsize=8)
            ax.set_yticks(range(len(step_factors)))
            ax.set_yticklabels([number(f) for f in step_factors], fontsize=8)
            if i == len(INTEGRATORS) - 1:
                ax.set_xlabel("penalty factor (x E t, log spacing)", fontsize=9)
            if j == 0:
                ax.set_ylabel(f"time step / {scene.dt:g} s (log spacing)", fontsize=9)
    handles = [
        Patch(facecolor=CLASSES[name]["colour"], label=f"{CLASSES[name]['code']}: {name}")
        for name in names
        if name in present or name != "timed out"
    ]
    own_text = (
        f"own setting: {scene.integrator}, {scene.method}, penalty {number(scene.penalty)} E"
        + ("" if scene.penalty in penalties else " (outside the map; dotted line: own step)")
        + f", dt {scene.dt:g} s (outlined)"
    )
    figure.suptitle(
        f"{scene.name}: end time {scene.end_time:g} s, penetration tolerance "
        f"{scene.tolerance * 1e3:.3g} mm\n{own_text}",
        fontsize=10,
    )
    figure.legend(
        handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.03), ncol=3,
        fontsize=8, frameon=False,
    )
    figure.text(
        0.5,
        0.01,
        "OC n →X: finished with n steps halved by the open-close iteration; X: "
        "its class without that criterion.  †: stopped by the timeout",
        ha="center",
        fontsize=7.5,
    )
    figure.tight_layout(rect=(0, 0.1, 1, 0.93))
    figure.savefig(path, dpi=90)
    plt.close(figure)


def write_csv(rows, path):
    """runs.csv; called after every run, so that a stopped sweep keeps its
    rows (--from-csv draws them)."""
    with open(path, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=CSV_FIELDS, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            row = dict(row, class_without_cuts=class_without_cuts(row))
            writer.writerow(
                {
                    key: (f"{value:.6g}" if isinstance(value, float) else value)
                    for key, value in row.items()
                }
            )


def describe_cells(cells, penalties, step_factors):
    """'penalty 100-1000 E at steps x3-x10' style text for a set of cells."""
    by_penalty = collections.defaultdict(list)
    for penalty, factor in cells:
        by_penalty[penalty].append(factor)
    groups = collections.OrderedDict()
    for penalty in sorted(by_penalty):
        key = tuple(sorted(by_penalty[penalty]))
        groups.setdefault(key, []).append(penalty)

    def span(values, everything, unit, prefix=""):
        values = sorted(values)
        if values == sorted(everything):
            return "all " + ("penalties" if unit == " E" else "steps")
        indices = [everything.index(v) for v in values]
        if indices == list(range(indices[0], indices[-1] + 1)) and len(values) > 1:
            return f"{prefix}{number(values[0])}-{number(values[-1])}{unit}"
        return ", ".join(f"{prefix}{number(v)}" for v in values) + unit

    parts = []
    for factors, group in groups.items():
        parts.append(
            f"{span(group, penalties, ' E')} at "
            f"{span(factors, step_factors, '', 'x')}".replace("all steps", "every step")
        )
    return "; ".join(parts)


def evidence(rows):
    """What the failing runs measured, for the sentence after the cells."""
    run_class = rows[0]["class"]
    if run_class == "energy gained":
        worst = max(rows, key=lambda r: r["max_energy_gain"] / r["energy_reference"])
        return (
            f"gain up to {100 * worst['max_energy_gain'] / worst['energy_reference']:.3g} % "
            f"of the energy supplied (penalty {number(worst['penalty_factor'])} E, "
            f"step x{number(worst['dt_factor'])})"
        )
    if run_class == "penetrated":
        worst = max(rows, key=lambda r: r["max_penetration"])
        return (
            f"penetration up to {worst['max_penetration'] / worst['penetration_tolerance']:.3g} "
            f"times the tolerance (penalty {number(worst['penalty_factor'])} E, "
            f"step x{number(worst['dt_factor'])})"
        )
    messages = collections.Counter(
        shorten(r["message"]) if r["message"] else f"finished with {r['open_close_cuts']} open-close cuts"
        for r in rows
    )
    return "; ".join(
        f"{count} x '{text}'" if count > 1 else f"'{text}'" for text, count in messages.most_common(3)
    )


def shorten(message):
    """An error message without its step number and time, to group them."""
    text = re.sub(r"^Step \d+ at t = \S+:\s*", "", message)
    text = re.sub(r"\s*Increase .*$|\s*Reduce .*$", "", text)
    text = re.sub(r"[-+]?\d+(\.\d+)?(e[-+]?\d+)?", "N", text)
    return text.rstrip(". ,")


def markdown_scene(scene, rows, penalties, step_factors, png_name):
    lines = []
    own = (
        f"own setting {scene.integrator}, {scene.method}, penalty "
        f"{number(scene.penalty)} E ({scene.penalty_mode}), dt {scene.dt:g} s"
    )
    lines += [
        f"### {scene.name}",
        "",
        f"End time {scene.end_time:g} s ({scene.why}); {own}; penetration "
        f"tolerance {scene.penetration_ratio:g} x {scene.half_height:.4g} m = "
        f"{scene.tolerance * 1e3:.3g} mm. "
        + (
            ""
            if scene.penalty in penalties
            else f"The scene's own penalty ({number(scene.penalty)} E) lies outside the map. "
        ),
        "",
        f"![{scene.name}]({png_name})",
        "",
    ]
    header = "| integrator | method | penalty (E t) | " + " | ".join(
        f"dt x{number(f)}" for f in step_factors
    ) + " |"
    lines += [header, "|" + "---|" * (3 + len(step_factors))]
    index = {
        (r["integrator"], r["method"], r["penalty_factor"], r["dt_factor"]): r for r in rows
    }
    for integrator in INTEGRATORS:
        for method in METHODS:
            for penalty in penalties:
                cells = []
                for factor in step_factors:
                    r = index.get((integrator, method, penalty, factor))
                    if r is None:
                        cells.append("")
                        continue
                    code = CLASSES[r["class"]]["code"]
                    if class_without_cuts(r):
                        rest = CLASSES[class_without_cuts(r)]["code"]
                        code += f" ({r['open_close_cuts']} cuts; else {rest})"
                    elif r["class"] == "energy gained":
                        code += f" ({100 * r['max_energy_gain'] / r['energy_reference']:.2g} %)"
                    elif r["class"] == "penetrated":
                        code += f" ({r['max_penetration'] / r['penetration_tolerance']:.2g}x)"
                    elif r["class"] in ("diverged", "timed out") and r["time_reached"]:
                        code += f" (t {r['time_reached']:.3g})"
                    if r["exit_code"] == "":
                        code += " †"
                    cells.append(code)
                mark = " **own**" if (
                    (integrator, method, penalty) == (scene.integrator, scene.method, scene.penalty)
                ) else ""
                lines.append(
                    f"| {integrator} | {method} | {number(penalty)}{mark} | " + " | ".join(cells) + " |"
                )
    lines += [
        "",
        "Cells: S stable, P penetrated (largest penetration / tolerance), E "
        "energy gained (largest gain, % of the energy supplied), OC open-close "
        "not converged (with 'cuts': finished, with that many steps halved "
        "because the iteration did not settle, and the class the run would "
        "have without this criterion; without: stopped with the error), D diverged (t: last time in the statistics), T timed out; † "
        "stopped by the timeout, classified from the rows written until then.",
        "",
    ]
    # where each method fails, from the results
    for integrator in INTEGRATORS:
        for method in METHODS:
            group = [r for r in rows if r["integrator"] == integrator and r["method"] == method]
            failing = collections.OrderedDict()
            for name in CLASSES:
                chosen = [r for r in group if r["class"] == name]
                if chosen and name != "stable":
                    failing[name] = chosen
            n_stable = sum(r["class"] == "stable" for r in group)
            if not failing:
                lines.append(f"- {integrator}, {method}: all {len(group)} runs stable.")
                continue
            parts = [
                f"{name} ({len(chosen)}) at "
                f"{describe_cells([(r['penalty_factor'], r['dt_factor']) for r in chosen], penalties, step_factors)}"
                f" — {evidence(chosen)}"
                for name, chosen in failing.items()
            ]
            lines.append(
                f"- {integrator}, {method}: {n_stable} of {len(group)} stable; "
                + "; ".join(parts)
                + "."
            )
    lines.append("")
    lines += compare(rows, "method", METHODS, ("integrator",), penalties, step_factors)
    lines += compare(rows, "integrator", INTEGRATORS, ("method",), penalties, step_factors)
    return lines


def compare(rows, key, values, others, penalties, step_factors):
    """Sentences on the runs where two methods (or integrators) differ: the
    first value against each other one (none for a single value)."""
    lines = []
    for second in values[1:]:
        lines += compare_pair(rows, key, values[0], second, others, penalties, step_factors)
    return lines


def compare_pair(rows, key, first, second, others, penalties, step_factors):
    """Sentences on the runs where @p first and @p second differ."""
    index = {}
    for r in rows:
        index[(r[key], tuple(r[o] for o in others), r["penalty_factor"], r["dt_factor"])] = r
    lines = []
    for other in sorted({tuple(r[o] for o in others) for r in rows}):
        differ = []
        for penalty in penalties:
            for factor in step_factors:
                a = index.get((first, other, penalty, factor))
                b = index.get((second, other, penalty, factor))
                if a and b and a["class"] != b["class"]:
                    differ.append((penalty, factor, a["class"], b["class"]))
        label = ", ".join(other)
        if not differ:
            lines.append(f"- {label}: {first} and {second} give the same class in every run.")
            continue
        pairs = collections.Counter((a, b) for _, _, a, b in differ)
        text = "; ".join(
            f"{first} {a} where {second} is {b} in {n} run{'s' if n > 1 else ''} "
            f"({describe_cells([(p, f) for p, f, x, y in differ if (x, y) == (a, b)], penalties, step_factors)})"
            for (a, b), n in pairs.most_common()
        )
        lines.append(f"- {label}: {first} and {second} differ in {len(differ)} runs: {text}.")
    lines.append("")
    return lines


def count_table(rows, scenes):
    names = list(CLASSES)
    lines = [
        "| scene | integrator | method | " + " | ".join(names) + " | wall time (s) |",
        "|" + "---|" * (4 + len(names)),
    ]
    for scene in scenes:
        for integrator in INTEGRATORS:
            for method in METHODS:
                group = [
                    r
                    for r in rows
                    if (r["scene"], r["integrator"], r["method"]) == (scene.name, integrator, method)
                ]
                if not group:
                    continue
                counts = collections.Counter(r["class"] for r in group)
                lines.append(
                    f"| {scene.name} | {integrator} | {method} | "
                    + " | ".join(str(counts.get(n, 0)) for n in names)
                    + f" | {sum(r['wall_time'] for r in group):.0f} |"
                )
    return lines + [""]


HAND_BEGIN = "<!-- hand-written begin -->"
HAND_END = "<!-- hand-written end -->"


def write_markdown(path, scenes, rows, grids, args, total_seconds, out_dir):
    kept = ""
    if os.path.exists(path):
        with open(path) as stream:
            old = stream.read()
        if HAND_BEGIN in old and HAND_END in old:
            kept = old[old.index(HAND_BEGIN) : old.index(HAND_END) + len(HAND_END)]
    relative = os.path.relpath(out_dir, os.path.dirname(os.path.abspath(path)))
    lines = [
        "## Stability map: penalty x step size",
        "",
        f"Generated by `scripts/stability_map.py` on {datetime.date.today().isoformat()}"
        f"{' (--quick)' if args.quick else ''}: {len(rows)} ndda runs, one at a time, "
        f"{total_seconds / 60:.1f} min of wall time in all. Fixed penalty (`Penalty = fixed`), "
        "factors of E t; steps relative to each scene's own; both vertex-vertex "
        f"methods and the integrators {', '.join(INTEGRATORS)}. Each run is "
        "classified by ndda's own "
        "checks, the first that applies: diverged (an error exit other than "
        "the open-close one: step below 1e-6 of the nominal step, increment "
        "still too large after all cuts; or NaN/inf in the statistics) > "
        "open-close not converged (the error exit that says so, or "
        "`Open-close cuts` > 0 in a finished run) > energy gained (`Energy "
        "gain (J)` above 1 % of the energy supplied, the largest |work of "
        "loads + initial kinetic energy| of the run, the latter read from the "
        "first row as kinetic + strain + contact energy - gain - work of "
        "loads) > penetrated (`Max penetration (m)` above "
        "`Maximum penetration ratio` x half the scene height, ndda's own "
        "tolerance) > stable. Every run is in "
        f"[runs.csv]({os.path.join(relative, 'runs.csv')}) with its message, "
        "penetration, energy gain, cuts and wall time.",
        "",
        "Runs per class:",
        "",
    ]
    lines += count_table(rows, scenes)
    for scene in scenes:
        penalties, step_factors, png = grids[scene.name]
        lines += markdown_scene(
            scene,
            [r for r in rows if r["scene"] == scene.name],
            penalties,
            step_factors,
            os.path.join(relative, png),
        )
    if kept:
        lines += [kept, ""]
    with open(path, "w") as stream:
        stream.write("\n".join(lines).rstrip("\n") + "\n")


def main():
    global INTEGRATORS
    parser = argparse.ArgumentParser(
        description="Stability map of ndda's contact over penalty x step size "
        "(see the top of this file)."
    )
    parser.add_argument("--ndda", required=True, help="the ndda binary")
    parser.add_argument("--prm-dir", required=True, help="folder of the scenes' .prm files")
    parser.add_argument("--out-dir", required=True, help="folder for the PNGs and runs.csv")
    parser.add_argument("--markdown", required=True, help="markdown fragment to write")
    parser.add_argument(
        "--scenes",
        default=",".join(SCENES),
        help="comma-separated scenes (default: %(default)s)",
    )
    parser.add_argument(
        "--quick",
        action="store_true",
        help=f"a tiny sweep to check the script: {QUICK_SCENE}, penalties "
        f"{QUICK_PENALTIES}, steps x{QUICK_STEP_FACTORS}",
    )
    parser.add_argument(
        "--timeout",
        type=float,
        default=30,
        help="wall seconds a run may take; a run stopped then is classified "
        "from the statistics it wrote, else 'timed out' (default 30)",
    )
    parser.add_argument(
        "--integrators",
        default=",".join(INTEGRATORS),
        help="comma-separated values of Control/Time integrator, one row of "
        "panels each (default: %(default)s)",
    )
    parser.add_argument("--keep", action="store_true", help="keep the runs' output folders")
    parser.add_argument(
        "--from-csv",
        metavar="RUNS_CSV",
        help="run nothing but the probes: draw the maps and write the "
        "markdown from the rows of an earlier runs.csv",
    )
    args = parser.parse_args()
    INTEGRATORS = tuple(i.strip() for i in args.integrators.split(",") if i.strip())

    ndda = os.path.abspath(args.ndda)
    if not os.access(ndda, os.X_OK):
        raise MapError(f"--ndda {args.ndda}: not an executable file")
    names = [QUICK_SCENE] if args.quick else [s.strip() for s in args.scenes.split(",") if s.strip()]
    unknown = [n for n in names if n not in SCENES]
    if unknown:
        raise MapError(f"--scenes: unknown scene(s) {unknown}; known: {list(SCENES)}")
    base_penalties = QUICK_PENALTIES if args.quick else PENALTIES
    step_factors = list(QUICK_STEP_FACTORS if args.quick else STEP_FACTORS)
    os.makedirs(args.out_dir, exist_ok=True)
    scratch = tempfile.mkdtemp(prefix="stability_map_")

    scenes = [Scene(n, args.prm_dir, SCENES[n]) for n in names]
    earlier = []
    if args.from_csv:
        earlier = [r for r in read_csv(args.from_csv) if r["scene"] in names]
    plan = []
    grids = {}
    for scene in scenes:
        if args.from_csv:
            # the tolerance the runs were classified with; no ndda run
            tolerances = {r["penetration_tolerance"] for r in earlier if r["scene"] == scene.name}
            if len(tolerances) != 1:
                raise MapError(f"--from-csv {args.from_csv}: {scene.name} has no single tolerance")
            scene.tolerance = tolerances.pop()
            scene.half_height = scene.tolerance / scene.penetration_ratio
        else:
            scene.probe(ndda, os.path.join(scratch, scene.name + "_probe"), args.timeout)
        penalties = base_penalties if args.quick else scene_penalties(scene, base_penalties)
        grids[scene.name] = (list(penalties), step_factors, f"{scene.name}.png")
        for integrator in INTEGRATORS:
            for method in METHODS:
                for penalty in penalties:
                    for factor in step_factors:
                        plan.append((scene, integrator, method, penalty, factor))

    rows = []
    if args.from_csv:
        rows = earlier
        plan = []
    start = time.monotonic()
    for number_run, (scene, integrator, method, penalty, factor) in enumerate(plan, 1):
        work = os.path.join(scratch, f"run{number_run:04d}")
        row = run_case(ndda, scene, integrator, method, penalty, factor, work, args.timeout)
        rows.append(row)
        write_csv(rows, os.path.join(args.out_dir, "runs.csv"))
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
        elapsed = time.monotonic() - start
        print(
            f"[{number_run}/{len(plan)} {elapsed:6.0f} s] {scene.name} {integrator} "
            f"{method} {number(penalty)} E dt x{number(factor)}: {row['class']} "
            f"({row['wall_time']:.1f} s){' ' + row['message'][:100] if row['message'] else ''}",
            flush=True,
        )
    total = sum(r["wall_time"] for r in rows)
    if not args.keep:
        shutil.rmtree(scratch, ignore_errors=True)

    write_csv(rows, os.path.join(args.out_dir, "runs.csv"))
    for scene in scenes:
        penalties, factors, png = grids[scene.name]
        plot_scene(
            scene,
            [r for r in rows if r["scene"] == scene.name],
            penalties,
            factors,
            os.path.join(args.out_dir, png),
        )
    write_markdown(args.markdown, scenes, rows, grids, args, total, args.out_dir)
    print(f"{len(rows)} runs in {total:.0f} s; wrote {args.out_dir} and {args.markdown}")


if __name__ == "__main__":
    try:
        main()
    except (MapError, ndda_output.OutputError) as error:
        sys.exit(f"stability_map.py: error: {error}")
