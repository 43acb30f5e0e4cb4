#!/usr/bin/python3
"""Speed against accuracy: error against CPU time of ndda over its settings.

For five validation cases the script runs ndda over a sweep of settings,
computes each run's error from the files ndda writes (exactly as the C++
test of the case measures it) against the analytical reference or, where
the test has none, against the case's finest meshed run, and the run's
time; it writes one PNG per case (error against time, log-log, the Pareto
front drawn and labelled), a CSV of all runs and a markdown fragment (the
error measures and references, a table of all runs, the Pareto front in
words and, where the block model is swept, each model's errors, place on
the front and time against meshed, everything from this run's data).

- elastic_bar_wave (tests/elastic_bar_wave.cc): the thesis's bar, a 1 MPa
  sin^2 pulse of 40 us; wave speed from the centroids in time of the
  particle velocity pulse at x = 0.25 and 0.5 m against the bar speed
  sqrt(E / rho), and the peak particle velocity at 0.5 and 0.97 m against
  d'Alembert's solution. Sweep: mesh size x time step x element degree x
  integrator (DDA, Newmark, generalized-alpha at its default rho_inf = 0).
- sliding_block (tests/sliding_block.cc): a block on a 30 degree incline,
  friction angle 20 degrees; its centre's slide along the slope at t = 1 s
  against g (sin a - cos a tan phi) t^2 / 2. Sweep: time step x penalty
  factor x integrator (DDA on six steps, Newmark and generalized-alpha on
  three).
- brazilian_disc (tests/brazilian_disc.cc): the disc between two plates
  with fracture switched off, to 1.5 ms (before the first crack at about
  2.1 ms); the centre's sigma_xx against 2 P / (pi D t), P the top
  plate's contact force ('block forces' statistics); the largest error
  from 20 % of the load on (the test's measure) and the error at the end
  time. Sweep: mesh size x element degree with the scene's rigid plates,
  and affine and meshed plates (the plates' block model; the disc stays
  meshed) on five of those (DISC_MODEL_RUNS).
- brick_wall (tests/stacks_stay_still.cc): 102 bricks on a rigid base
  settling under gravity, to 0.5 s (the test: 1 s; at rest long before).
  The test has bounds only (drift, speed), no reference value: the
  settlement of the top corners (measure points) at the end and its
  largest value over the run against the finest meshed run of the sweep
  (h = 0.25 m, dt = 0.5 ms); drift and speed in the table. Sweep: block
  model of the bricks (rigid, affine, meshed, auto; the base stays rigid)
  x time step (2, 1, 0.5 ms), meshed bricks also at h = 0.5 and 0.25 m.
  The rock has no fracture, so auto bricks stay affine.
- wall_impact (tests/automatic_kinematics.cc): a boulder strikes 198
  bricks, 0.3 s as the scene and the test; every block's centroid at the
  end against the meshed run of the smallest step (0.5 ms) and, as the
  test pairs them, against the meshed run of the same step, in % of the
  scene's size (target 1 %, issue 15). Sweep: block model of every block
  but the rigid base x time step (2, 1, 0.5 ms).

Time: the sum of the statistics file's 'Wall time per step (s)' (the time
stepping only: no start-up, meshing or output); runs under --repeat-below
seconds are run twice more and the smallest time is taken (the machine is
shared: the least disturbed run). The process's wall and CPU time are in
the CSV too. One ndda process at a time. The full sweep takes about 18
minutes on two cores (the bar and the block 8-9, the disc 2-3, the brick
wall 3, the wall impact 4); --quick about a minute.

Pareto front: the runs that no cheaper run beats on the error, cheapest
first; a run joins only if it cuts the error by 5 % or more (FRONT_GAIN).

Writes OUT_DIR/<case>.png, OUT_DIR/speed_accuracy.csv,
OUT_DIR/speed_accuracy_run.json (date, load, noise of the timings) and
the markdown; --from-csv redraws the PNGs and rewrites the markdown from
the CSV and the JSON without running ndda.

Run it with Debian's Python (python3-numpy, python3-matplotlib):

    /usr/bin/python3 scripts/speed_accuracy.py --ndda build/ndda \\
        --prm-dir prm --out-dir doc/speed_accuracy \\
        --markdown doc/speed_accuracy/speed_accuracy.md
    ... --quick     # 2-4 runs per case, to check that the script works
    ... --cases brick_wall,wall_impact   # some of the cases only
"""

import argparse
import collections
import csv
import itertools
import json
import math
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ndda_output  # noqa: E402

CASES = ("elastic_bar_wave", "sliding_block", "brazilian_disc", "brick_wall", "wall_impact")
# The block kinematics models (Control/Kinematics and a block's own entry).
MODELS = ("rigid", "affine", "meshed", "auto")

BAR_END = 3e-4  # end time of the bar, as the test
BAR_POINTS = (0.25, 0.5, 0.97)  # x of the bar's measure points, as the test
DISC_END = 1.5e-3  # end time of the disc: before its first crack
DISC_INTERVAL = 1e-4  # VTU frames of the disc, for the plate force
DISC_FROM = 0.2  # the disc's error from this fraction of the last load on
# (mesh size, degree) of the disc runs with affine and meshed plates: a
# subset of the rigid plates' sweep, coarse to fine.
DISC_MODEL_RUNS = ((0.004, 1), (0.004, 2), (0.0022, 1), (0.0022, 2), (0.0011, 1))
# End time of the brick wall: the test runs 1 s; the top has settled to four
# digits from 0.3 s on (meshed, h = 0.25 m, dt = 0.5 ms, the least damped).
WALL_END = 0.5
WALL_MESH = 2.0  # the wall's mesh size in prm/brick_wall.prm (two cells a brick)
IMPACT_END = 0.3  # end time of the wall impact, as the scene and the test
# The target of issue 15 and tests/automatic_kinematics.cc: final block
# centroids within 1 % of the scene's size of the all-meshed run's.
IMPACT_TARGET = 0.01
# Targets of tests/elastic_bar_wave.cc for Newmark: wave speed and peak
# particle velocity.
BAR_TARGETS = dict(speed_error=0.01, peak_error=0.03)
# A run joins a Pareto front only if it cuts the error of the cheaper
# front point by at least this fraction (smaller gains are noise).
FRONT_GAIN = 0.05

# Short labels of the integrators in plots and run names.
INTEGRATOR_LABELS = collections.OrderedDict(
    [("DDA", "DDA"), ("Newmark", "NM"), ("generalized-alpha", "GA")]
)


# Settings of a run: (key, column name in the CSV and tables).
SETTING_NAMES = collections.OrderedDict(
    [
        ("model", "block model"),
        ("mesh_size", "mesh size (m)"),
        ("time_step", "time step (s)"),
        ("degree", "element degree"),
        ("integrator", "integrator"),
        ("penalty", "penalty factor"),
    ]
)


# --------------------------------------------------------------------------
# Sweeps


def bar_runs(quick):
    """Settings of the elastic bar runs."""
    if quick:
        combos = [
            (0.012, 2e-6, 1, "Newmark"),
            (0.012, 2e-6, 1, "DDA"),
            (0.012, 4e-6, 2, "Newmark"),
            (0.012, 2e-6, 1, "generalized-alpha"),
        ]
    else:
        combos = itertools.product(
            (0.012, 0.008, 0.005, 0.0035),
            (4e-6, 2e-6, 1e-6, 5e-7),
            (1, 2),
            ("DDA", "Newmark", "generalized-alpha"),
        )
    return [
        dict(mesh_size=h, time_step=dt, degree=p, integrator=i)
        for h, dt, p, i in combos
    ]


def sliding_runs(quick):
    """Settings of the sliding block runs."""
    if quick:
        return [
            dict(time_step=2e-3, penalty=100, integrator="DDA"),
            dict(time_step=5e-3, penalty=100, integrator="DDA"),
        ]
    runs = [
        dict(time_step=dt, penalty=k, integrator="DDA")
        for dt in (1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3)
        for k in (10, 100, 1000)
    ]
    # Below the sweep's smallest step: where the error goes as dt -> 0.
    runs += [dict(time_step=5e-5, penalty=100, integrator="DDA")]
    runs += [
        dict(time_step=dt, penalty=k, integrator=i)
        for i in ("Newmark", "generalized-alpha")
        for dt in (1e-4, 5e-4, 2e-3)
        for k in (10, 100, 1000)
    ]
    return runs


def disc_runs(quick):
    """Settings of the Brazilian disc runs: every mesh size and degree with
    the scene's rigid plates, and a subset with affine and meshed plates."""
    if quick:
        return [dict(mesh_size=0.004, degree=p, model="rigid") for p in (1, 2)] + [
            dict(mesh_size=0.004, degree=1, model=m) for m in ("affine", "meshed")
        ]
    sizes = (0.004, 0.003, 0.0022, 0.0015, 0.0011)
    runs = [dict(mesh_size=h, degree=p, model="rigid") for h in sizes for p in (1, 2)]
    runs += [
        dict(mesh_size=h, degree=p, model=m)
        for m in ("affine", "meshed")
        for h, p in DISC_MODEL_RUNS
    ]
    return runs


def brick_wall_runs(quick):
    """Settings of the brick wall runs: every model at the scene's mesh over
    three steps; meshed bricks also on two finer meshes (the finest meshed
    run is the reference)."""
    if quick:
        return [dict(mesh_size=WALL_MESH, time_step=2e-3, model=m)
                for m in ("rigid", "affine", "meshed")]
    steps = (2e-3, 1e-3, 5e-4)
    runs = [dict(mesh_size=WALL_MESH, time_step=dt, model=m) for m in MODELS for dt in steps]
    runs += [dict(mesh_size=h, time_step=dt, model="meshed") for h in (0.5, 0.25) for dt in steps]
    return runs


def wall_impact_runs(quick):
    """Settings of the wall impact runs: every model over three steps (the
    meshed run of the smallest step is the reference)."""
    if quick:
        return [dict(time_step=2e-3, model=m) for m in ("rigid", "meshed")]
    return [dict(time_step=dt, model=m) for dt in (2e-3, 1e-3, 5e-4) for m in MODELS]


# --------------------------------------------------------------------------
# Scene text


def overrides(case, settings):
    """The entries appended to the case's .prm file (the last set wins)."""
    control = ["subsection Control"]
    if "time_step" in settings:
        control.append(f"  set Time step = {settings['time_step']:g}")
    if "degree" in settings:
        control.append(f"  set Element degree = {settings['degree']}")
    if "integrator" in settings:
        control.append(f"  set Time integrator = {settings['integrator']}")
    if "model" in settings and case != "brazilian_disc":
        # The scene's default: every block without its own Kinematics entry
        # (the rigid base keeps its own).
        control.append(f"  set Kinematics = {settings['model']}")
    if case in CASE_END_TIMES:
        control.append(f"  set End time = {CASE_END_TIMES[case]:g}")
    text = control + ["end"] + CASE_OVERRIDES[case](settings)
    return "\n".join(text) + "\n"


def bar_overrides(settings):
    """As tests/elastic_bar_wave.cc: to 0.3 ms, points at 0.25, 0.5, 0.97 m."""
    return [
        "subsection Geometry",
        "  subsection bar",
        f"    set Mesh size = {settings['mesh_size']:g}",
        "  end",
        "end",
        "subsection Output",
        "  set Write vtu = false",
        "  set Measure points = " + "; ".join(f"{x:g}, 0.015" for x in BAR_POINTS),
        "end",
    ]


def sliding_overrides(settings):
    """As tests/sliding_block.cc: penetration tolerance 1e-3 of half the
    scene's height."""
    return [
        "subsection Contact",
        f"  set Penalty factor = {settings['penalty']:g}",
        "  set Maximum penetration ratio = 1e-3",
        "end",
        "subsection Output",
        "  set Write vtu = false",
        "end",
    ]


def disc_overrides(settings):
    """Before the first crack only: no fracture, to 1.5 ms; VTU frames every
    0.1 ms give the times of the plate force; the plates' model."""
    plates = []
    if "model" in settings:
        for plate in ("top", "bottom"):
            plates += [f"  subsection {plate}", f"    set Kinematics = {settings['model']}",
                       "  end"]
    return [
        "subsection Materials",
        "  subsection rock",
        "    set Fracture = false",
        "  end",
        "end",
        "subsection Geometry",
        "  subsection disc",
        f"    set Mesh size = {settings['mesh_size']:g}",
        "  end",
    ] + plates + [
        "end",
        "subsection Output",
        "  set Write vtu = true",
        f"  set Interval = {DISC_INTERVAL:g}",
        "end",
    ]


def brick_wall_overrides(settings):
    """The bricks' mesh size (the region 'wall'); the top corners' measure
    points of the scene; no VTU files."""
    return [
        "subsection Geometry",
        "  subsection wall",
        f"    set Mesh size = {settings['mesh_size']:g}",
        "  end",
        "end",
        "subsection Output",
        "  set Write vtu = false",
        "end",
    ]


def wall_impact_overrides(settings):
    """VTU frames at the start and the end only: the blocks' centroids."""
    return [
        "subsection Output",
        "  set Write vtu = true",
        f"  set Interval = {IMPACT_END:g}",
        "end",
    ]


CASE_END_TIMES = {
    "elastic_bar_wave": BAR_END,
    "brazilian_disc": DISC_END,
    "brick_wall": WALL_END,
    "wall_impact": IMPACT_END,
}
CASE_OVERRIDES = {
    "elastic_bar_wave": bar_overrides,
    "sliding_block": sliding_overrides,
    "brazilian_disc": disc_overrides,
    "brick_wall": brick_wall_overrides,
    "wall_impact": wall_impact_overrides,
}


# The .prm reader and the polygon parser live in ndda_output.py (shared
# with the gallery's scripts).
read_prm_text = ndda_output.read_prm_text
points_of = ndda_output.points_of


# --------------------------------------------------------------------------
# Running ndda


class Timing:
    """The times of one run (seconds)."""

    def __init__(self, step_sum, process_wall, process_cpu):
        self.step_sum = step_sum
        self.process_wall = process_wall
        self.process_cpu = process_cpu


def run_ndda(binary, scene_text, run_dir, timeout):
    """Run ndda on scene_text in run_dir/out; return (Timing, log text).

    Raises RuntimeError with the end of the log when ndda fails."""
    out_dir = os.path.join(run_dir, "out")
    if os.path.isdir(out_dir):
        shutil.rmtree(out_dir)
    os.makedirs(run_dir, exist_ok=True)
    scene = os.path.join(run_dir, "scene.prm")
    with open(scene, "w") as stream:
        stream.write(scene_text)
        stream.write(f"subsection Output\n  set Directory = {out_dir}/\nend\n")
        # The wall time of every step is not in the statistics by default
        # (a statistics file without it can be pinned): ask for it.
        stream.write(
            "subsection Postprocess\n"
            "  set List of postprocessors = displacement, velocity, stress, "
            "block and material, crack faces, kinematics, time step, energy, "
            "fracture, contact, block forces, wall time\n"
            "end\n"
        )
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    try:
        process = subprocess.run(
            [binary, scene],
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            timeout=timeout,
            cwd=run_dir,
        )
    except subprocess.TimeoutExpired:
        raise RuntimeError(f"no result within the time limit of {timeout:g} s")
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if process.returncode != 0:
        errors = [line for line in process.stdout.splitlines() if "ndda: error:" in line]
        what = errors[-1].strip() if errors else " / ".join(process.stdout.strip().splitlines()[-3:])
        raise RuntimeError(f"ndda returned {process.returncode}: {what}")
    statistics = ndda_output.read_table(os.path.join(out_dir, "statistics"))
    step_sum = float(np.sum(statistics["Wall time per step (s)"]))
    return Timing(step_sum, wall, cpu), process.stdout


def mesh_size_of_log(log):
    """(cells, degrees of freedom) from ndda's screen output."""
    match = re.search(r"cells:\s*(\d+).*degrees of freedom:\s*(\d+)", log)
    return (int(match.group(1)), int(match.group(2))) if match else (None, None)


# --------------------------------------------------------------------------
# Errors, as the C++ tests measure them


def parabola_peak(t, f):
    """Peak of samples f(t) by a parabola through the largest sample
    (peak() of tests/elastic_bar_wave.cc)."""
    i = int(np.argmax(f))  # the first largest, as the test's strict '>'
    if i == 0 or i + 1 == len(f):
        return t[i], f[i]
    a = 0.5 * (f[i + 1] - 2 * f[i] + f[i - 1])
    b = 0.5 * (f[i + 1] - f[i - 1])
    s = -b / (2 * a)
    h = t[i + 1] - t[i]
    return t[i] + s * h, f[i] + b * s + a * s * s


def time_centroid(t, f, t_end):
    """Centroid in time of f on [0, t_end] (centroid() of the test)."""
    keep = t <= t_end
    return np.sum(f[keep] * t[keep]) / np.sum(f[keep])


def arrival(t, f):
    """First time f reaches 1 % of its largest value (arrival() of the test)."""
    level = 0.01 * max(0.0, float(np.max(f)))
    for k in range(1, len(f)):
        if f[k] >= level:
            return t[k - 1] + (level - f[k - 1]) / (f[k] - f[k - 1]) * (t[k] - t[k - 1])
    return float("nan")


class Bar:
    """The elastic bar: the test's quantities and its reference."""

    name = "elastic_bar_wave"
    title = "Elastic bar: P-wave (tests/elastic_bar_wave.cc)"
    measures = [
        ("speed_error", "wave speed error |c_measured / c - 1|"),
        ("peak_error", "peak velocity error (worse of 0.5 and 0.97 m)"),
    ]
    points = BAR_POINTS
    # The pulse of prm/elastic_bar_wave.prm (checked against its load).
    p0, duration = 1e6, 4e-5

    def __init__(self, parameters):
        value = parameters["Loads/pulse/Value"]
        if value.replace(" ", "") != "if(t<4e-5,1e6*sin(pi*t/4e-5)^2,0)":
            raise RuntimeError(f"the bar's pulse is '{value}', not the test's")
        bar = points_of(parameters["Geometry/bar/Outer boundary"])
        self.length = bar[:, 0].max() - bar[:, 0].min()
        self.height = bar[:, 1].max() - bar[:, 1].min()
        self.rho = float(parameters["Materials/rock/Density"])
        self.E = float(parameters["Materials/rock/Young's modulus"])
        self.c = math.sqrt(self.E / self.rho)
        # The exact peaks at 0.5 and 0.97 m, from d'Alembert's solution
        # sampled every 10 ns up to 0.3 ms, as the test does.
        s = np.arange(0.0, BAR_END, 1e-8)
        self.exact_velocity_peak = {}
        self.exact_compression_peak = {}
        for x in self.points[1:]:
            incident = self.pulse(s - x / self.c)
            reflected = self.pulse(s - (2 * self.length - x) / self.c)
            self.exact_velocity_peak[x] = np.max((incident + reflected) / (self.rho * self.c))
            self.exact_compression_peak[x] = np.max(incident - reflected)

    def pulse(self, s):
        inside = (s >= 0) & (s <= self.duration)
        return np.where(inside, self.p0 * np.sin(np.pi * s / self.duration) ** 2, 0.0)

    def evaluate(self, out_dir):
        m = ndda_output.read_table(os.path.join(out_dir, "measure_points.txt"))
        t = m["time"]
        compression = [-m[f"point {p} sigma_xx"] for p in range(3)]
        velocity = [m[f"point {p} v_x"] for p in range(3)]
        x = self.points
        # The incident pulse only: before the reflection reaches the point.
        t25 = time_centroid(t, velocity[0], (2 * self.length - x[0]) / self.c)
        t50 = time_centroid(t, velocity[1], (2 * self.length - x[1]) / self.c)
        speed = (x[1] - x[0]) / (t50 - t25)
        result = dict(
            wave_speed=speed,
            speed_error=abs(speed / self.c - 1),
            speed_error_signed=speed / self.c - 1,
            arrival_05=arrival(t, compression[1]),
        )
        worst = 0.0
        for p, tag in ((1, "05"), (2, "097")):
            _, v = parabola_peak(t, velocity[p])
            _, sc = parabola_peak(t, compression[p])
            v_error = v / self.exact_velocity_peak[x[p]] - 1
            result[f"peak_velocity_{tag}"] = v
            result[f"peak_velocity_error_{tag}"] = v_error
            result[f"peak_compression_{tag}"] = sc
            result[f"peak_compression_error_{tag}"] = sc / self.exact_compression_peak[x[p]] - 1
            worst = max(worst, abs(v_error))
        result["peak_error"] = worst
        return result


class SlidingBlock:
    """The block on the incline: the test's slide and its reference."""

    name = "sliding_block"
    title = "Sliding block on an incline (tests/sliding_block.cc)"
    measures = [("error", "slide error |s / s_exact - 1| at the end time")]

    def __init__(self, parameters):
        incline = points_of(parameters["Geometry/incline/Outer boundary"])
        top = incline[np.argmax(incline[:, 1])]
        self.slope = math.atan2(top[1], top[0])
        self.phi = math.radians(float(parameters["Materials/Joint/Friction angle"]))
        for material in parameters["Materials/Names"].split(","):
            own = parameters.get(f"Materials/{material.strip()}/Joint friction angle", "-1")
            if float(own) >= 0:
                raise RuntimeError("a material has its own joint friction angle")
        gravity = [float(v) for v in parameters["Loads/Gravity"].split(";")]
        self.g = math.hypot(*gravity)
        self.end_time = float(parameters["Control/End time"])
        block = points_of(parameters["Geometry/block/Outer boundary"])
        self.block_sides = sorted(
            [np.linalg.norm(block[1] - block[0]), np.linalg.norm(block[2] - block[1])],
            reverse=True,
        )
        self.expected = (
            0.5
            * self.g
            * (math.sin(self.slope) - math.cos(self.slope) * math.tan(self.phi))
            * self.end_time**2
        )

    def evaluate(self, out_dir):
        m = ndda_output.read_table(os.path.join(out_dir, "measure_points.txt"))
        if abs(m["time"][-1] - self.end_time) > 1e-9:
            raise RuntimeError(f"the last row is at t = {m['time'][-1]:g} s")
        ux, uy = m["point 0 u_x"][-1], m["point 0 u_y"][-1]
        slide = -(ux * math.cos(self.slope) + uy * math.sin(self.slope))
        # The excess slide over the rigid block's, fitted by a line over the
        # second half of the run: its slope is an extra velocity.
        t = m["time"]
        along = -(m["point 0 u_x"] * math.cos(self.slope) + m["point 0 u_y"] * math.sin(self.slope))
        excess = along - self.expected * (t / self.end_time) ** 2
        late = t >= 0.5 * self.end_time
        extra_velocity = float(np.polyfit(t[late], excess[late], 1)[0])
        s = ndda_output.read_table(os.path.join(out_dir, "statistics"))
        return dict(
            slide=slide,
            extra_velocity=extra_velocity,
            error=abs(slide / self.expected - 1),
            error_signed=slide / self.expected - 1,
            max_penetration=float(np.max(s["Max penetration (m)"])),
            open_close_per_step=float(np.mean(s["Open-close iterations"])),
            step_cuts=int(np.sum(s["Step cuts"])),
        )


class Disc:
    """The Brazilian disc before cracking: centre sigma_xx and 2P/(pi D t)."""

    name = "brazilian_disc"
    title = "Brazilian disc before the first crack (tests/brazilian_disc.cc)"
    measures = [
        ("error", "centre stress error |sigma_xx / (2P/(pi D t)) - 1|, largest"),
        ("end_error", "centre stress error at the end time (highest load)"),
    ]

    def __init__(self, parameters):
        disc = points_of(parameters["Geometry/disc/Outer boundary"])
        self.D = disc[:, 0].max() - disc[:, 0].min()
        self.t = float(parameters["Materials/Thickness"])
        names = [n.strip() for n in parameters["Geometry/Blocks"].split(",")]
        if "top" not in names or "bottom" not in names:
            raise RuntimeError("the disc scene has no blocks 'top' and 'bottom'")
        self.integrator = parameters["Control/Time integrator"]
        self.time_step = float(parameters["Control/Time step"])
        self.plate_mesh = float(parameters["Geometry/top/Mesh size"])

    def evaluate(self, out_dir):
        m = ndda_output.read_table(os.path.join(out_dir, "measure_points.txt"))
        samples = []
        times = [
            t
            for t, _ in ndda_output.read_pvd(os.path.join(out_dir, "solution.pvd"))
            if t > 0
        ]
        # The plates' load from their contact forces (rigid plates have no
        # stress; ndda_output.plate_force, as plate_force() of
        # tests/plates.h).
        top = ndda_output.plate_force(out_dir, "top", times)
        bottom = ndda_output.plate_force(out_dir, "bottom", times)
        for frame_time, p_top, p_bottom in zip(times, top, bottom):
            row = int(np.argmin(np.abs(m["time"] - frame_time)))
            if abs(m["time"][row] - frame_time) > 1e-12:
                raise RuntimeError(f"no measure point row at t = {frame_time:g} s")
            samples.append((frame_time, m["point 0 sigma_xx"][row], p_top, p_bottom))
        samples = np.array(samples)
        last_p = samples[-1, 2]
        # As the test: from 20 % of the last load on (the test's last load
        # is the crack load; here the load at the end time).
        used = samples[samples[:, 2] >= DISC_FROM * last_p]
        reference = 2 * used[:, 2] / (np.pi * self.D * self.t)
        errors = used[:, 1] / reference - 1
        worst = int(np.argmax(np.abs(errors)))
        return dict(
            error=float(abs(errors[worst])),
            error_signed=float(errors[worst]),
            end_error_signed=float(errors[-1]),
            end_error=float(abs(errors[-1])),
            n_frames=len(used),
            force_end=float(last_p),
            centre_sxx_end=float(used[-1, 1]),
            plate_difference=float(np.max(np.abs(used[:, 3] / used[:, 2] - 1))),
        )


def reference_run(runs):
    """The reference run of a case measured against its own best run: the
    meshed run with the smallest mesh size, then the smallest step."""
    meshed = [r for r in runs if r.get("ok") and r["settings"].get("model") == "meshed"]
    if not meshed:
        return None
    return min(meshed, key=lambda r: (r["settings"].get("mesh_size", 0.0),
                                      r["settings"].get("time_step", 0.0)))


def kinematics_statistics(out_dir):
    """Step cuts, open-close iterations per step, promotions and the most
    blocks meshed at once, from the statistics file."""
    s = ndda_output.read_table(os.path.join(out_dir, "statistics"))
    return dict(
        step_cuts=int(np.sum(s["Step cuts"])),
        open_close_per_step=float(np.mean(s["Open-close iterations"])),
        promotions=int(s["Promotions"][-1]) if "Promotions" in s else 0,
        most_meshed=int(np.max(s["Blocks meshed"])) if "Blocks meshed" in s else 0,
    )


class BrickWall:
    """The 102-brick wall settling under gravity: the top corners against
    the finest meshed run of the sweep (the test has no reference value)."""

    name = "brick_wall"
    title = "Brick wall settling under gravity (tests/stacks_stay_still.cc)"
    measures = [
        ("error", "settlement error at the end |s / s_ref - 1|"),
        ("peak_settlement_error", "largest settlement error |s_max / s_max,ref - 1|"),
    ]
    targets = {}

    def __init__(self, parameters):
        wall = points_of(parameters["Geometry/wall/Outer boundary"])
        self.width = wall[:, 0].max() - wall[:, 0].min()
        self.height = wall[:, 1].max() - wall[:, 1].min()
        self.points = points_of(parameters["Output/Measure points"])
        if len(self.points) != 2 or np.any(self.points[:, 1] < wall[:, 1].max() - 0.5):
            raise RuntimeError("the wall's measure points are not two points of its top course")
        self.rho = float(parameters["Materials/rock/Density"])
        self.E = float(parameters["Materials/rock/Young's modulus"])
        nu = float(parameters["Materials/rock/Poisson's ratio"])
        self.plane = parameters.get("Materials/Plane condition", "plane stress")
        self.g = math.hypot(*[float(v) for v in parameters["Loads/Gravity"].split(";")])
        # A jointless column of the wall's height under its own weight,
        # uniaxial: its top settles by rho g H^2 / (2 E') (E' = E in plane
        # stress, E / (1 - nu^2) in plane strain).
        factor = 1.0 if self.plane == "plane stress" else 1.0 - nu**2
        self.column = factor * self.rho * self.g * self.height**2 / (2 * self.E)
        self.end_time = float(parameters["Control/End time"])

    def evaluate(self, out_dir):
        m = ndda_output.read_table(os.path.join(out_dir, "measure_points.txt"))
        if abs(m["time"][-1] - self.end_time) > 1e-9:
            raise RuntimeError(f"the last row is at t = {m['time'][-1]:g} s")
        settlement = -0.5 * (m["point 0 u_y"] + m["point 1 u_y"])
        result = dict(
            settlement=float(settlement[-1]),
            peak_settlement=float(np.max(settlement)),
            # The test's drift and speed, over the two top corners.
            # How far the top still moves over the last 40 % of the run.
            late_change=float(np.max(np.abs(settlement[m["time"] >= 0.6 * self.end_time]
                                            - settlement[-1]))),
            drift=float(max(np.max(np.abs(m[f"point {p} u_x"])) for p in (0, 1))),
            max_speed=float(max(np.max(np.abs(m[f"point {p} {c}"]))
                                for p in (0, 1) for c in ("v_x", "v_y"))),
        )
        result.update(kinematics_statistics(out_dir))
        return result

    def finish(self, runs):
        """The errors against the reference run, once all runs are done."""
        reference = reference_run(runs)
        for r in runs:
            if not r.get("ok"):
                continue
            r["is_reference"] = int(r is reference)
            for key, measure in (("settlement", "error"),
                                 ("peak_settlement", "peak_settlement_error")):
                signed = (r[key] / reference[key] - 1
                          if reference is not None and r is not reference else math.nan)
                r[measure + "_signed"] = signed
                r[measure] = abs(signed)


def block_centroids(vtu):
    """(block ids, area-weighted centroids) of a VTU frame's blocks on its
    (deformed) mesh, as block_centroids() of tests/automatic_kinematics.cc."""
    corners = ndda_output.cell_corners(vtu)
    area = np.abs(ndda_output.cell_areas(vtu, corners))
    block = ndda_output.cell_block_ids(vtu, corners)
    middle = vtu.points[corners][:, :, :2].mean(axis=1)
    ids = np.unique(block)
    n = ids.max() + 1
    total = np.bincount(block, area, n)
    centroid = np.stack([np.bincount(block, area * middle[:, k], n) for k in (0, 1)], axis=1)
    return ids, centroid[ids] / total[ids, None]


def centroid_difference(run, other):
    """(largest centroid distance (m), its block id) of two wall impact runs,
    over the blocks both have."""
    ids, c = run["centroids"]
    other_ids, other_c = other["centroids"]
    common, mine, theirs = np.intersect1d(ids, other_ids, return_indices=True)
    off = np.linalg.norm(c[mine] - other_c[theirs], axis=1)
    worst = int(np.argmax(off))
    return float(off[worst]), int(common[worst])


class WallImpact:
    """The boulder striking the 198-brick wall: every block's centroid at
    the end against the all-meshed runs (tests/automatic_kinematics.cc)."""

    name = "wall_impact"
    title = "Boulder striking a brick wall (tests/automatic_kinematics.cc)"
    measures = [
        ("error", "largest block centroid difference against the reference run, of the scene size"),
        ("off_same_step", "the same against the meshed run of the same step (the test's measure)"),
    ]
    axis_labels = {
        "error": "centroid difference against the reference / scene size",
        "off_same_step": "against meshed of the same step / scene size",
    }
    targets = {"error": IMPACT_TARGET, "off_same_step": IMPACT_TARGET}

    def __init__(self, parameters):
        self.end_time = float(parameters["Control/End time"])
        self.block_names = [n.strip() for n in parameters["Geometry/Blocks"].split(",")]
        if "boulder" not in self.block_names:
            raise RuntimeError("the wall impact scene has no block 'boulder'")
        self.velocity = [float(v) for v in
                         parameters["Geometry/boulder/Initial velocity"].split(";")]

    def evaluate(self, out_dir):
        frames = ndda_output.read_pvd(os.path.join(out_dir, "solution.pvd"))
        if abs(frames[0][0]) > 1e-12 or abs(frames[-1][0] - self.end_time) > 1e-9:
            raise RuntimeError(f"frames at t = {frames[0][0]:g} and {frames[-1][0]:g} s")
        first = ndda_output.read_vtu(frames[0][1])
        last = ndda_output.read_vtu(frames[-1][1])
        # The scene's size as the test's: the larger side of the initial
        # mesh's bounding box.
        extent = first.points[:, :2].max(axis=0) - first.points[:, :2].min(axis=0)
        ids, centroid = block_centroids(last)
        result = dict(scene_size=float(extent.max()), n_blocks=len(ids), centroids=(ids, centroid))
        result.update(kinematics_statistics(out_dir))
        return result

    def finish(self, runs):
        """The errors against the reference run and against the meshed run
        of the same step, once all runs are done."""
        reference = reference_run(runs)
        meshed = {r["settings"]["time_step"]: r for r in runs
                  if r.get("ok") and r["settings"]["model"] == "meshed"}
        for r in runs:
            if not r.get("ok"):
                continue
            r["is_reference"] = int(r is reference)
            same = meshed.get(r["settings"]["time_step"])
            for other, key in ((reference, "error"), (same, "off_same_step")):
                off, block = (centroid_difference(r, other)
                              if other is not None and other is not r else (math.nan, -1))
                r[key + "_m"] = off
                r[key + "_block"] = block
                r[key] = off / r["scene_size"]


CASE_CLASSES = {
    "elastic_bar_wave": Bar,
    "sliding_block": SlidingBlock,
    "brazilian_disc": Disc,
    "brick_wall": BrickWall,
    "wall_impact": WallImpact,
}
CASE_RUNS = {
    "elastic_bar_wave": bar_runs,
    "sliding_block": sliding_runs,
    "brazilian_disc": disc_runs,
    "brick_wall": brick_wall_runs,
    "wall_impact": wall_impact_runs,
}


# --------------------------------------------------------------------------
# Formatting


def sig(value, digits=3):
    """A number with `digits` significant digits, plain where readable."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "–"
    if value == 0:
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    if -4 <= exponent < 6:
        decimals = max(0, digits - 1 - exponent)
        return f"{value:.{decimals}f}"
    return f"{value:.{digits - 1}e}"


def percent(value, digits=3):
    return sig(100 * value, digits) + " %"


def setting_text(key, value):
    """One setting in words: 'h = 5 mm', 'dt = 1 µs', 'P2', 'Newmark',
    'affine'."""
    if key == "mesh_size":
        if value >= 0.1:
            return f"h = {sig(value, 2)} m"
        return f"h = {sig(value * 1e3, 2)} mm"
    if key == "time_step":
        return f"dt = {sig(value * 1e6, 2)} µs" if value < 1e-4 else f"dt = {sig(value * 1e3, 2)} ms"
    if key == "degree":
        return f"P{value}"
    if key in ("integrator", "model"):
        return str(value)
    if key == "penalty":
        return f"penalty {value:g} E"
    return f"{key} = {value}"


def settings_text(settings):
    return ", ".join(setting_text(k, v) for k, v in settings.items())


def short_label(settings):
    """A short label for the plot."""
    parts = []
    for key, value in settings.items():
        if key == "model":
            parts.append(value)
        elif key == "mesh_size":
            parts.append(f"h{sig(value, 2)}m" if value >= 0.1 else f"h{sig(value * 1e3, 2)}")
        elif key == "time_step":
            parts.append(f"dt{sig(value * 1e6, 2)}µ" if value < 1e-4 else f"dt{sig(value * 1e3, 2)}m")
        elif key == "degree":
            parts.append(f"P{value}")
        elif key == "integrator":
            parts.append(INTEGRATOR_LABELS.get(value, value))
        elif key == "penalty":
            parts.append(f"k{value:g}")
    return " ".join(parts)


# --------------------------------------------------------------------------
# Pareto front


def has_value(run, measure):
    """Whether a run has a finite value of the measure (a case's reference
    run has none of the errors against itself)."""
    value = run.get(measure) if run.get("ok") else None
    return isinstance(value, (int, float)) and math.isfinite(value)


def pareto_front(runs, measure):
    """The runs no other run beats in both time and error, cheapest first;
    a run joins only if it cuts the front's error by FRONT_GAIN at least."""
    candidates = sorted(
        (r for r in runs if has_value(r, measure)),
        key=lambda r: (r["cpu"], r[measure]),
    )
    front, best = [], math.inf
    for r in candidates:
        if r[measure] < (1 - FRONT_GAIN) * best:
            front.append(r)
            best = r[measure]
    return front


def describe_front(front, measure, runs):
    """The Pareto front in words: which settings for which target error."""
    lines = []
    n_ok = sum(1 for r in runs if has_value(r, measure))
    lines.append(
        f"Pareto front: {len(front)} of the {n_ok} runs (cheapest first; each one the "
        f"cheapest run that reaches its error; a run counts only if it cuts the error by "
        f"{sig(100 * FRONT_GAIN, 2)} % or more):"
    )
    lines.append("")
    for i, r in enumerate(front):
        what = f"**{settings_text(r['settings'])}** ({sig(r['cpu'])} s, error {percent(r[measure])})"
        if i == 0:
            lines.append(f"- for a target error of {percent(r[measure])} or more: {what};")
        else:
            lines.append(
                f"- for a target from {percent(r[measure])} to below "
                f"{percent(front[i - 1][measure])}: {what};"
            )
    lines.append(
        f"- below {percent(front[-1][measure])}: no run of this sweep; "
        f"the smallest error costs {sig(front[-1]['cpu'])} s."
    )
    # Which values the front is made of.
    keys = list(front[0]["settings"].keys())
    summary = []
    for key in keys:
        counts = collections.Counter(r["settings"][key] for r in front)
        if len(set(r["settings"][key] for r in runs if r.get("ok"))) < 2:
            continue
        parts = [
            f"{setting_text(key, value)} {n}×"
            for value, n in sorted(counts.items(), key=lambda item: -item[1])
        ]
        summary.append(", ".join(parts))
    lines.append("")
    lines.append("On the front: " + "; ".join(summary) + ".")
    # Runs more accurate than the cheapest front point: if their errors
    # have both signs, small magnitudes may be zero crossings.
    signed = [r.get(measure + "_signed", r.get("error_signed") if measure == "error" else None)
              for r in runs if has_value(r, measure) and r[measure] < front[0][measure]]
    signed = [v for v in signed if v is not None and math.isfinite(v)]
    if signed and min(signed) < 0 < max(signed):
        lines.append(
            f"The signed errors below the cheapest run's have both signs ({percent(min(signed))} "
            f"to {percent(max(signed))}), so the smallest magnitudes are partly luck (a "
            "zero crossing), not a trend."
        )
    # How far the cheapest run is from the most accurate one.
    if len(front) > 1:
        lines.append(
            f"Going from the cheapest to the most accurate point of the front "
            f"costs {sig(front[-1]['cpu'] / front[0]['cpu'], 2)} times the time "
            f"for an error {sig(front[0][measure] / front[-1][measure], 2)} times smaller."
        )
    return lines


# --------------------------------------------------------------------------
# Plots


MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*"]


class PlotStyle:
    """Colour by the first numeric setting with several values, markers by
    the categorical ones (block model, degree, integrator), size by the
    second numeric one; the rest in the labels."""

    def __init__(self, ok, cmap):
        keys = list(ok[0]["settings"].keys())
        varying = [k for k in keys if len(set(r["settings"][k] for r in ok)) > 1]
        numeric = [k for k in varying if k in ("mesh_size", "time_step", "penalty")]
        self.colour_key = numeric[0] if numeric else None
        self.marker_keys = [k for k in varying if k in ("model", "degree", "integrator")]
        self.size_key = numeric[1] if len(numeric) > 1 else None
        self.colour_values = (sorted(set(r["settings"][self.colour_key] for r in ok))
                              if self.colour_key else [None])
        n = max(1, len(self.colour_values) - 1)
        self.colours = {v: cmap(0.9 * i / n) for i, v in enumerate(self.colour_values)}
        self.marker_values = sorted(set(self.marker_of(r["settings"]) for r in ok))
        self.markers = {v: MARKERS[i % len(MARKERS)] for i, v in enumerate(self.marker_values)}
        self.size_values = (sorted(set(r["settings"][self.size_key] for r in ok))
                            if self.size_key else [None])
        self.sizes = {v: 22 + 30 * i for i, v in enumerate(self.size_values)}

    def marker_of(self, settings):
        return tuple(settings[k] for k in self.marker_keys)

    def scatter_style(self, settings):
        """The keyword arguments of a run's point."""
        return dict(
            color=self.colours[settings[self.colour_key]] if self.colour_key else "C0",
            marker=self.markers[self.marker_of(settings)],
            s=self.sizes[settings[self.size_key]] if self.size_key else 36,
            edgecolors="k", linewidths=0.4, alpha=0.85, zorder=3,
        )

    def legend_handles(self, with_target, with_reference):
        """Legend entries: colours, markers, sizes, the front (the target, the
        reference run's time)."""
        from matplotlib.lines import Line2D

        handles = []
        if self.colour_key:
            handles += [
                Line2D([], [], marker="o", ls="", color=self.colours[v], markeredgecolor="k",
                       label=setting_text(self.colour_key, v))
                for v in self.colour_values
            ]
        handles += [
            Line2D([], [], marker=self.markers[v], ls="", color="0.6", markeredgecolor="k",
                   label=", ".join(setting_text(k, x) for k, x in zip(self.marker_keys, v))
                   or "run")
            for v in self.marker_values
        ]
        if self.size_key:
            handles += [
                Line2D([], [], marker="o", ls="", color="white", markeredgecolor="k",
                       markersize=math.sqrt(self.sizes[v]), label=setting_text(self.size_key, v))
                for v in self.size_values
            ]
        handles.append(Line2D([], [], color="crimson", label="Pareto front"))
        if with_target:
            handles.append(Line2D([], [], color="0.3", ls="--", lw=1, label="target"))
        if with_reference:
            handles.append(Line2D([], [], color="0.5", ls=":", lw=1,
                                  label="time of the reference run"))
        return handles


def plot_case(case, runs, path):
    """Error against time, log-log, one panel per measure, the Pareto front
    as a line with its points labelled (and the case's target, if any)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FuncFormatter, LogLocator

    ok = [r for r in runs if r.get("ok")]
    style = PlotStyle(ok, plt.get_cmap("viridis"))
    reference = reference_of_runs(ok)
    measures = case.measures
    targets = getattr(case, "targets", {})
    figure, axes = plt.subplots(
        1, len(measures), figsize=(6.4 * len(measures), 5.2), squeeze=False, dpi=100
    )
    plain = FuncFormatter(lambda v, _: f"{v:g}")
    fronts = []
    for axis, (measure, label) in zip(axes[0], measures):
        floor = 1e-7

        def y(r):
            return 100 * max(r[measure], floor)  # in percent

        for r in ok:
            if has_value(r, measure):  # not the reference run
                axis.scatter(r["cpu"], y(r), **style.scatter_style(r["settings"]))
        front = pareto_front(ok, measure)
        axis.plot([r["cpu"] for r in front], [y(r) for r in front], "-", color="crimson",
                  lw=1.4, zorder=2, label="Pareto front")
        if measure in targets:
            axis.axhline(100 * targets[measure], color="0.3", ls="--", lw=1, zorder=1)
        if reference is not None:
            axis.axvline(reference["cpu"], color="0.5", ls=":", lw=1, zorder=1)
        axis.set_xscale("log")
        axis.set_yscale("log")
        fronts.append((axis, [(r["cpu"], y(r), short_label(r["settings"])) for r in front]))
        axis.set_xlabel("time of the time steps (s, sum of 'Wall time per step')")
        axis.set_ylabel(getattr(case, "axis_labels", {}).get(measure, label) + " (%)")
        for which in (axis.xaxis, axis.yaxis):
            which.set_major_formatter(plain)
            which.set_minor_formatter(FuncFormatter(lambda v, _: ""))
            which.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
        axis.grid(True, which="major", alpha=0.35)
        axis.grid(True, which="minor", alpha=0.12)
        # Room for the labels on the right.
        low, high = axis.get_xlim()
        axis.set_xlim(low, high * 2.2)
    handles = style.legend_handles(bool(targets), reference is not None)
    n_columns = min(len(handles), 4 * len(measures))
    figure.legend(handles=handles, loc="lower center", ncol=n_columns, fontsize=8,
                  frameon=False)
    figure.suptitle(case.title, fontsize=11)
    n_rows = math.ceil(len(handles) / n_columns)
    figure.tight_layout(rect=(0, 0.01 + 0.04 * n_rows, 1, 1))
    for axis, points in fronts:
        place_labels(figure, axis, points)
    save_png(figure, path)
    plt.close(figure)


def place_labels(figure, axis, points):
    """Label the front's points where the labels overlap neither each
    other nor the axes' edges, trying a few offsets around each point."""
    renderer = figure.canvas.get_renderer()
    frame = axis.get_window_extent(renderer)
    offsets = [(6, 3, "left"), (6, -11, "left"), (-6, 3, "right"), (-6, -11, "right"),
               (6, 12, "left"), (6, -20, "left"), (-6, 12, "right"), (-6, -20, "right")]
    placed = []
    for x, y, text in points:
        for dx, dy, align in offsets:
            label = axis.annotate(text, (x, y), xytext=(dx, dy), textcoords="offset points",
                                  fontsize=7, color="crimson", ha=align, zorder=4)
            box = label.get_window_extent(renderer)
            inside = (box.x0 >= frame.x0 and box.x1 <= frame.x1
                      and box.y0 >= frame.y0 and box.y1 <= frame.y1)
            if inside and not any(box.overlaps(other) for other in placed):
                break
            label.remove()
        else:
            label = axis.annotate(text, (x, y), xytext=offsets[0][:2],
                                  textcoords="offset points", fontsize=7, color="crimson",
                                  zorder=4)
            box = label.get_window_extent(renderer)
        placed.append(box)


def save_png(figure, path, dpi=100):
    """An 8-bit palette PNG (as plot_frames.py), 24-bit without PIL."""
    try:
        from PIL import Image
    except ImportError:
        figure.savefig(path, dpi=dpi)
        return
    figure.set_dpi(dpi)
    figure.canvas.draw()
    image = Image.frombuffer(
        "RGBA", figure.canvas.get_width_height(), figure.canvas.buffer_rgba()
    ).convert("RGB")
    image = image.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    image.save(path, optimize=True, dpi=(dpi, dpi))


# --------------------------------------------------------------------------
# CSV and markdown


MEASURE_COLUMNS = {
    "elastic_bar_wave": [
        ("wave_speed", "wave speed (m/s)"),
        ("speed_error_signed", "wave speed error"),
        ("peak_velocity_error_05", "peak velocity error at 0.5 m"),
        ("peak_velocity_error_097", "peak velocity error at 0.97 m"),
        ("peak_compression_error_05", "peak compression error at 0.5 m"),
        ("peak_compression_error_097", "peak compression error at 0.97 m"),
        ("arrival_05", "arrival at 0.5 m (s)"),
    ],
    "sliding_block": [
        ("slide", "slide (m)"),
        ("error_signed", "slide error"),
        ("extra_velocity", "extra velocity (m/s)"),
        ("max_penetration", "max penetration (m)"),
        ("open_close_per_step", "open-close iterations per step"),
        ("step_cuts", "step cuts"),
    ],
    "brazilian_disc": [
        ("error_signed", "largest centre stress error"),
        ("end_error_signed", "error at the end"),
        ("force_end", "P at the end (N)"),
        ("centre_sxx_end", "centre sigma_xx at the end (Pa)"),
        ("plate_difference", "top against bottom plate"),
        ("n_frames", "frames used"),
    ],
    "brick_wall": [
        ("is_reference", "reference run"),
        ("settlement", "settlement at the end (m)"),
        ("error_signed", "settlement error"),
        ("peak_settlement", "largest settlement (m)"),
        ("peak_settlement_error_signed", "largest settlement error"),
        ("late_change", "settlement change over the last 40 % of the run (m)"),
        ("drift", "largest |u_x| of the top corners (m)"),
        ("max_speed", "largest velocity component of the top corners (m/s)"),
        ("open_close_per_step", "open-close iterations per step"),
        ("step_cuts", "step cuts"),
        ("promotions", "promotions"),
        ("most_meshed", "most blocks meshed at once"),
    ],
    "wall_impact": [
        ("is_reference", "reference run"),
        ("error_m", "largest centroid difference against the reference (m)"),
        ("error_block", "block of the largest difference"),
        ("off_same_step_m", "largest centroid difference against meshed, same step (m)"),
        ("off_same_step_block", "block of the largest difference, same step"),
        ("scene_size", "scene size (m)"),
        ("n_blocks", "blocks at the end"),
        ("open_close_per_step", "open-close iterations per step"),
        ("step_cuts", "step cuts"),
        ("promotions", "promotions"),
        ("most_meshed", "most blocks meshed at once"),
    ],
}


def _csv_measures():
    keys = []
    for case in CASES:
        for key, _ in MEASURE_COLUMNS[case] + CASE_CLASSES[case].measures:
            if key not in keys:
                keys.append(key)
    return keys


CSV_MEASURES = _csv_measures()
INTEGER_MEASURES = ("step_cuts", "n_frames", "is_reference", "promotions", "most_meshed",
                    "n_blocks", "error_block", "off_same_step_block")


def write_csv(path, all_runs):
    columns = ["case"] + list(SETTING_NAMES) + [
        "cells", "dofs", "cpu_step_sum_s", "cpu_min_s", "cpu_max_s", "n_timings",
        "process_wall_s", "process_cpu_s", "status",
    ]
    extra = CSV_MEASURES
    columns += extra
    with open(path, "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(columns)
        for r in all_runs:
            row = [r["case"]]
            row += [r["settings"].get(k, "") for k in SETTING_NAMES]
            row += [
                r.get("cells", ""), r.get("dofs", ""),
                f"{r['cpu']:.6g}" if r.get("cpu") is not None else "",
                f"{min(r['times']):.6g}" if r.get("times") else "",
                f"{max(r['times']):.6g}" if r.get("times") else "",
                len(r.get("times", [])),
                f"{r['process_wall']:.6g}" if r.get("process_wall") is not None else "",
                f"{r['process_cpu']:.6g}" if r.get("process_cpu") is not None else "",
                "ok" if r.get("ok") else r.get("failure", "failed"),
            ]
            row += [
                (f"{r[k]:.6g}" if isinstance(r.get(k), float) else r.get(k, "")) for k in extra
            ]
            writer.writerow(row)


def case_explanation(case, reference, runs):
    """The error measure and its reference, with the numbers of this run."""
    if case == "elastic_bar_wave":
        b = reference
        return [
            f"The thesis's bar ({sig(b.length, 3)} m × {sig(b.height, 3)} m, plane stress, rho = {sig(b.rho, 4)} kg/m³, "
            f"E = {sig(b.E / 1e9, 3)} GPa), loaded by the pulse "
            f"p(s) = p0 sin²(pi s / T), p0 = {sig(b.p0 / 1e6)} MPa, T = {sig(b.duration * 1e6)} µs, "
            f"to {sig(BAR_END * 1e3)} ms, measure points at x = "
            + ", ".join(f"{x:g}" for x in BAR_POINTS)
            + " m (as the test). "
            "Reference: d'Alembert's solution at the bar speed "
            f"c = sqrt(E / rho) = {sig(b.c, 4)} m/s:",
            "",
            "    sigma(x, t) = -p(t - x/c) + p(t - (2L - x)/c)",
            "    v(x, t)     = (p(t - x/c) + p(t - (2L - x)/c)) / (rho c)",
            "",
            "- *Wave speed error*: `|c_measured / c - 1|`, c_measured = 0.25 m over the "
            "time between the centroids in time of the particle velocity v_x at "
            "x = 0.25 and 0.5 m, each over the incident pulse only (up to (2L - x)/c).",
            "- *Peak error*: the peak particle velocity (a parabola through the largest "
            "sample) against the exact peak of v(x, t) "
            f"({sig(b.exact_velocity_peak[0.5], 4)} m/s at 0.5 m, "
            f"{sig(b.exact_velocity_peak[0.97], 4)} m/s at 0.97 m, where incident and "
            "reflected pulses overlap), the worse of the two points, as the test checks it. "
            "The test prints the peak compression too (the stress of the cell around "
            "the point, against "
            f"{sig(b.exact_compression_peak[0.5] / 1e6)} MPa at 0.5 m); it is in the CSV.",
        ]
    if case == "sliding_block":
        s = reference
        return [
            "prm/sliding_block.prm with the test's penetration tolerance: a "
            f"{sig(s.block_sides[0], 3)} m × {sig(s.block_sides[1], 3)} m block "
            f"on a {sig(math.degrees(s.slope), 3)}° incline, joint friction angle "
            f"{sig(math.degrees(s.phi), 3)}°, gravity {sig(s.g, 3)} m/s². Reference: the rigid "
            f"block's slide along the slope at t = {sig(s.end_time)} s,",
            "",
            "    s = g (sin a - cos a tan phi) t² / 2"
            f" = {sig(s.expected, 5)} m,",
            "",
            "against the displacement of the block's centre (the measure point) along the "
            "slope, `-(u_x cos a + u_y sin a)`, at the last step. Error `|s_measured / s - 1|`.",
        ]
    if case == "brazilian_disc":
        d = reference
        return [
            f"prm/brazilian_disc.prm (D = {sig(d.D * 1e3, 3)} mm, t = {sig(d.t * 1e3, 3)} mm, "
            f"{d.integrator}, {setting_text('time_step', d.time_step)}) with fracture switched "
            f"off (`Materials/rock/Fracture = false`) and ended at {sig(DISC_END * 1e3)} ms, "
            "before the first crack (doc/validation.md). Reference: the "
            "centre stress under diametral point loads (thesis 7.14),",
            "",
            "    sigma_xx = 2 P / (pi D t),",
            "",
            "with P the force through the top (driven) plate at the same time: as the test "
            "(plate_force() of tests/plates.h), the vertical resultant of the contact forces "
            "on the plate, the statistics column `top contact force y (N)` of the `block "
            "forces` postprocessor, here at the times of the VTU frames (every "
            f"{sig(DISC_INTERVAL * 1e3)} ms; the test uses every step). "
            "The centre's sigma_xx is the "
            "first measure point's (the mean stress of the cell around the centre). Error: "
            "the largest `|sigma_xx / (2P/(pi D t)) - 1|` over the frames from "
            f"{sig(100 * DISC_FROM)} % of the "
            "last load on (the test: of the crack load). Even a perfect mesh keeps an error "
            "here: for the contact width the plates make, Hondros' solution is "
            "`(sin 2 alpha - alpha) / alpha` times 2P/(pi D t) (doc/validation.md), so the "
            "errors level off rather than go to zero.",
        ] + disc_model_explanation(d, runs)
    if case == "brick_wall":
        return brick_wall_explanation(reference, runs)
    if case == "wall_impact":
        return wall_impact_explanation(reference, runs)
    return []


def disc_model_explanation(d, runs):
    """The disc's block model axis in words (none for runs without it)."""
    if not any("model" in r["settings"] for r in runs):
        return []
    return [
        "",
        "*Block model* is that of the two loading plates (`Kinematics` of the blocks "
        "`top` and `bottom`; the scene's is `rigid`, 3 unknowns each); the disc stays "
        "meshed. The rigid plates run every mesh size and degree; affine (6 unknowns) and "
        f"meshed plates (their own meshes, {setting_text('mesh_size', d.plate_mesh)}) run "
        + ", ".join(f"{setting_text('mesh_size', h)} P{p}" for h, p in DISC_MODEL_RUNS)
        + ". P is the plate's contact force whatever its model.",
    ]


def reference_of_runs(runs):
    """The run marked as the case's reference (also in a CSV read back)."""
    return next((r for r in runs if r.get("ok") and r.get("is_reference")), None)


def brick_wall_explanation(w, runs):
    """case_explanation() of the brick wall."""
    ref = reference_of_runs(runs)
    lines = [
        f"prm/brick_wall.prm: 102 bricks of 1 m × 0.5 m in 12 staggered courses "
        f"({sig(w.width, 2)} m × {sig(w.height, 2)} m, rho = {sig(w.rho, 4)} kg/m³, "
        f"E = {sig(w.E / 1e9, 3)} GPa, {w.plane}) on a rigid base, settling under gravity, "
        f"run to {sig(WALL_END)} s (the test: 1 s; the wall is at rest long before, see "
        "below). *Block model* is the bricks' (Control/Kinematics; "
        "the base keeps its own `rigid`); rigid, affine and auto bricks keep the scene's mesh "
        f"({setting_text('mesh_size', WALL_MESH)}, two cells a brick: their contact "
        "nodes), meshed bricks also run on finer meshes.",
        "",
        "tests/stacks_stay_still.cc judges the wall by bounds only (every vertex's "
        "horizontal drift and displacement below 1 mm, every velocity component below "
        "5 cm/s, no penetration beyond the tolerance); it has no reference value. The "
        "errors here are the settlement of the wall's top, `s = -(u_y,0 + u_y,1) / 2` of "
        "the scene's two measure points in the top corner bricks "
        + "; ".join(f"({sig(x, 3)}, {sig(y, 3)})" for x, y in w.points)
        + ", against the same of the **reference run: the finest meshed run of the sweep** "
        + (f"(**{settings_text(ref['settings'])}**: s = {sig(ref['settlement'] * 1e6, 4)} µm "
           f"at the end, {sig(ref['peak_settlement'] * 1e6, 4)} µm at most)"
           if ref else "(it failed: no errors)")
        + ":",
        "",
        "- *Settlement error*: `|s / s_ref - 1|` at the end time (the wall at rest).",
        "- *Largest settlement error*: the same for the largest settlement over the run "
        "(the overshoot of the first tenth of a second: gravity acts from the first step, "
        "and how much of it the step damps; the test's 'largest displacement').",
        "",
        "For comparison, a jointless column of the wall's height under its own weight "
        f"settles by `rho g H² / (2 E)` = {sig(w.column * 1e6, 4)} µm"
        + (f"; the reference run's {sig(ref['settlement'] * 1e6, 4)} µm is "
           f"{percent(ref['settlement'] / w.column - 1, 2)} off it." if ref else ".")
        + " The drift and speed bounds of the test are in the table, over the two top corners.",
    ]
    return lines


def wall_impact_explanation(w, runs):
    """case_explanation() of the wall impact."""
    ref = reference_of_runs(runs)
    sizes = sorted(set(r["scene_size"] for r in runs if r.get("ok") and "scene_size" in r))
    size = sig(sizes[0], 3) + " m" if sizes else "the scene's size"
    return [
        "prm/wall_impact.prm: a boulder (1 m × 1 m) strikes a staggered wall of 198 bricks "
        f"(16 m × 6 m, on a rigid base) at {sig(math.hypot(*w.velocity), 2)} m/s, gravity, "
        f"joint friction 35°, to {sig(IMPACT_END)} s as the scene and the test. "
        "*Block model* is that of every block "
        "(Control/Kinematics; the scene's is `auto`) but the base, which keeps its own "
        "`rigid`. Meshed blocks "
        "may crack (the rock has `Fracture = true`); auto blocks start affine and are "
        "meshed near the impact only (doc/theory.md, \"Automatic kinematics\").",
        "",
        "Error as tests/automatic_kinematics.cc measures it: every block's area-weighted "
        "centroid on the deformed mesh of the last VTU frame (t = "
        f"{sig(IMPACT_END)} s), the largest distance between a block's centroid and the "
        f"same block's in the other run, divided by the scene's size ({size}, the larger "
        "side of the initial mesh's bounding box). The target of issue 15 and of the test: "
        f"{percent(IMPACT_TARGET, 2)} (dashed line).",
        "",
        "- *Against the reference run*: **the meshed run with the smallest step of the "
        "sweep** "
        + (f"(**{settings_text(ref['settings'])}**)" if ref else "(it failed: no errors)")
        + "; the meshed runs with larger steps show what the step alone changes.",
        "- *Against the meshed run of the same step*: the test's pairing (auto against "
        "all-meshed, both with the scene's step), for every model and step; the meshed runs "
        "have no such error.",
        "",
        "After an impact the blocks' paths are chaotic (doc/validation.md): a small "
        "difference early (a step, a model) can move a block by centimetres at the end.",
    ]


# The tables' columns after the settings: (key, header, format) with the
# formats 'percent', 'mm/s', 'kN', 'int' and 'number'.
TABLE_COLUMNS = {
    "elastic_bar_wave": [
        ("speed_error_signed", "wave speed error", "percent"),
        ("peak_velocity_error_05", "peak velocity error at 0.5 m", "percent"),
        ("peak_velocity_error_097", "at 0.97 m", "percent"),
        ("peak_compression_error_05", "peak compression error at 0.5 m", "percent"),
    ],
    "sliding_block": [
        ("error_signed", "slide error", "percent"),
        ("extra_velocity", "extra velocity (mm/s)", "mm/s"),
        ("max_penetration", "max penetration (m)", "number"),
        ("open_close_per_step", "open-close iterations per step", "number"),
        ("step_cuts", "step cuts", "int"),
    ],
    "brazilian_disc": [
        ("error_signed", "largest centre stress error", "percent"),
        ("end_error_signed", "at the end", "percent"),
        ("force_end", "P at the end (kN)", "kN"),
        ("plate_difference", "top against bottom plate, largest", "percent"),
    ],
    "brick_wall": [
        ("error_signed", "settlement error", "percent"),
        ("peak_settlement_error_signed", "largest settlement error", "percent"),
        ("settlement", "settlement at the end (µm)", "µm"),
        ("peak_settlement", "largest (µm)", "µm"),
        ("drift", "largest top corner u_x (µm)", "µm"),
        ("max_speed", "largest top corner velocity (mm/s)", "mm/s"),
        ("open_close_per_step", "open-close iterations per step", "number"),
        ("promotions", "promotions", "int"),
    ],
    "wall_impact": [
        ("error", "against the reference", "percent"),
        ("error_m", "against the reference (m)", "number"),
        ("off_same_step", "against meshed, same step", "percent"),
        ("error_block", "block farthest off", "block"),
        ("step_cuts", "step cuts", "int"),
        ("promotions", "promotions", "int"),
        ("most_meshed", "most blocks meshed at once", "int"),
    ],
}


def table_cell(value, kind):
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "–"
    if kind == "µm":
        return sig(1e6 * value)
    if kind == "percent":
        return percent(value)
    if kind == "mm/s":
        return sig(1e3 * value)
    if kind == "kN":
        return sig(1e-3 * value, 4)
    if kind == "int":
        return str(int(value))
    if kind == "block":  # a block id, -1 for none
        return str(int(value)) if value >= 0 else "–"
    return sig(value, 3)


def short_failure(text):
    """(message, time) of a failed run: ndda's error line without its step,
    time and numbers in brackets, and the time it gives (or '')."""
    match = re.search(r"ndda: error: (.*)", text)
    if not match:
        return text, ""
    message = match.group(1).strip()
    when = re.match(r"Step \d+ at t = ([-+0-9.eE]+): ", message)
    if when:
        message = message[when.end():]
    message = re.sub(r"\s*\([^)]*\d[^)]*\)", "", message)
    message = message.split(". ")[0].rstrip(".")
    return message, (sig(float(when.group(1)), 4) + " s") if when else ""


def markdown_table(case_name, runs):
    keys = list(runs[0]["settings"].keys())
    columns = TABLE_COLUMNS[case_name]
    head = [SETTING_NAMES[k] for k in keys] + ["cells", "dofs"]
    head += [header for _, header, _ in columns] + ["time (s)", "range of repeats (s)"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in runs:
        cells = [setting_text(k, r["settings"][k]) for k in keys]
        if r.get("is_reference"):
            cells[0] = f"**{cells[0]}** (reference)"
        cells += [str(r.get("cells", "")), str(r.get("dofs", ""))]
        if not r.get("ok"):
            cells += ["failed"] + [""] * (len(head) - len(cells) - 1)
        else:
            cells += [table_cell(r.get(key), kind) for key, _, kind in columns]
            times = r["times"]
            cells.append(sig(r["cpu"]))
            cells.append(f"{sig(min(times))}–{sig(max(times))}" if len(times) > 1 else "")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def case_remarks(case_name, ok):
    """What the data of a case say beyond its fronts, in words."""
    lines = []
    if case_name == "elastic_bar_wave":
        within = [r for r in ok if all(r[k] <= v for k, v in BAR_TARGETS.items())]
        targets = " and ".join(
            f"{percent(v, 2)} on the {k.replace('_', ' ')}" for k, v in BAR_TARGETS.items()
        )
        if within:
            best = min(within, key=lambda r: r["cpu"])
            lines.append(
                f"**Both errors together.** {len(within)} of the {len(ok)} runs meet the test's "
                f"targets ({targets}); the cheapest is **{settings_text(best['settings'])}** "
                f"({sig(best['cpu'])} s: wave speed {percent(best['speed_error'])}, peak "
                f"{percent(best['peak_error'])})."
            )
        else:
            lines.append(f"No run meets the test's targets ({targets}).")
        for integrator in INTEGRATOR_LABELS:
            runs = [r for r in ok if r["settings"]["integrator"] == integrator]
            if runs:
                lines.append(
                    f"{integrator}: peak error from {percent(min(r['peak_error'] for r in runs))} "
                    f"to {percent(max(r['peak_error'] for r in runs))}."
                )
        dda = [r for r in ok if r["settings"]["integrator"] == "DDA"]
        if dda:
            by_step = collections.defaultdict(list)
            for r in dda:
                by_step[r["settings"]["time_step"]].append(r["peak_error"])
            lines.append(
                "The DDA scheme's peak loss depends on the step, hardly on the mesh or "
                "the degree: "
                + ", ".join(
                    f"{setting_text('time_step', dt)}: " + (
                        percent(min(v), 2) if percent(min(v), 2) == percent(max(v), 2)
                        else f"{percent(min(v), 2)}–{percent(max(v), 2)}")
                    for dt, v in sorted(by_step.items())
                )
                + "."
            )
        lines.append("")
    elif case_name == "sliding_block":
        dda = sorted(
            (r for r in ok if r["settings"]["integrator"] == "DDA"),
            key=lambda r: r["settings"]["time_step"],
        )
        if dda:
            by_step = collections.defaultdict(list)
            for r in dda:
                by_step[r["settings"]["time_step"]].append(r["extra_velocity"])
            steps = sorted(by_step)
            means = [float(np.mean(by_step[dt])) for dt in steps]
            spread = max(
                (max(v) - min(v)) / abs(np.mean(v)) for v in by_step.values() if len(v) > 1
            ) if any(len(v) > 1 for v in by_step.values()) else 0.0
            lines.append(
                "**Where the DDA runs' error comes from.** Their excess slide over the rigid "
                "block grows linearly in time: an extra velocity along the slope (the slope of "
                "a line fitted to the excess over the second half of the run) of "
                + ", ".join(
                    f"{sig(1e3 * v, 2)} mm/s at {setting_text('time_step', dt)}"
                    for dt, v in zip(steps, means)
                )
                + f"; the penalty factor changes it by at most {percent(spread, 2)}. "
                "It is picked up at the start, while the block, released at rest with no "
                "contact force, settles onto the incline (less normal force, less friction)"
                + (
                    ", and it grows as the step shrinks; large DDA steps damp the settling, so "
                    "they come closer to the rigid-block formula, which has no settling. The front "
                    if all(a >= b for a, b in zip(means, means[1:]))
                    else "; it does not fall steadily with the step. The front "
                )
                + 
                "therefore measures how well the step suppresses the start-up, not a "
                "discretisation error that vanishes as dt goes to 0."
            )
            if len(means) >= 3:
                increments = np.abs(np.diff(means[:3]))
                if increments[0] < increments[1]:
                    lines.append(
                        f"From {setting_text('time_step', steps[2])} to "
                        f"{setting_text('time_step', steps[0])} the increments shrink "
                        f"({sig(1e3 * increments[1], 2)}, then {sig(1e3 * increments[0], 2)} mm/s): "
                        "the extra velocity converges as the step shrinks, a property of the "
                        "elastic model rather than of the integrator."
                    )
        newmark = [r for r in ok if r["settings"]["integrator"] == "Newmark"]
        if newmark:
            lines.append(
                f"Newmark: slide errors from {percent(min(r['error'] for r in newmark))} to "
                f"{percent(max(r['error'] for r in newmark))} (the contact chatter of "
                "doc/contact.md, \"Known limits\")."
            )
        alpha = [r for r in ok if r["settings"]["integrator"] == "generalized-alpha"]
        if alpha:
            lines.append(
                f"Generalized-α (ρ∞ = 0): slide errors from "
                f"{percent(min(r['error'] for r in alpha))} to "
                f"{percent(max(r['error'] for r in alpha))}."
            )
        lines.append("")
    elif case_name == "brazilian_disc":
        at_end = collections.Counter()
        early = collections.Counter()
        for r in ok:
            key = f"P{r['settings']['degree']}"
            (at_end if r["error_signed"] == r["end_error_signed"] else early)[key] += 1
        lines.append(
            "Where the test's measure (the largest error from "
            f"{sig(100 * DISC_FROM)} % of the last load on) is taken: at the end time "
            "(highest load) in "
            + (", ".join(f"{n} {k} runs" for k, n in sorted(at_end.items())) or "no run")
            + "; earlier, at a lower load, in "
            + (", ".join(f"{n} {k} runs" for k, n in sorted(early.items())) or "no run")
            + ". The second panel, the error at the end time, shows the mesh's effect "
            "without the start-up of the loading."
        )
        lines.append("")
    return lines


def model_pairs(ok, model):
    """(run of the model, meshed run with every other setting the same)."""
    def others(r):
        return tuple((k, v) for k, v in r["settings"].items() if k != "model")

    meshed = {others(r): r for r in ok if r["settings"].get("model") == "meshed"}
    return [(r, meshed[others(r)]) for r in ok
            if r["settings"].get("model") == model and others(r) in meshed]


def model_remarks(case_name, ok):
    """Per block model: its errors, its place on the Pareto fronts and its
    time against the meshed run with the other settings the same."""
    models = [m for m in MODELS if any(r["settings"].get("model") == m for r in ok)]
    if len(models) < 2:
        return []
    lines = ["**Block models.** Errors by model (smallest–largest), and how many of its "
             "runs are on the Pareto front:", ""]
    for measure, label in CASE_CLASSES[case_name].measures:
        on = collections.Counter(r["settings"]["model"] for r in pareto_front(ok, measure))
        parts = []
        for m in models:
            values = [r[measure] for r in ok
                      if r["settings"].get("model") == m and has_value(r, measure)]
            if not values:
                parts.append(f"{m}: the reference")
                continue
            low, high = percent(min(values), 2), percent(max(values), 2)
            span = low if low == high else f"{low}–{high}"
            parts.append(f"{m} {span} ({on[m]} of {len(values)} on the front)")
        lines.append(f"- {label[0].upper() + label[1:]}: " + "; ".join(parts) + ".")
    lines += ["", "Time against meshed (the time of the steps of the run over that of "
              "the meshed run with every other setting the same):", ""]
    for m in models:
        pairs = model_pairs(ok, m) if m != "meshed" else []
        if pairs:
            ratios = [r["cpu"] / q["cpu"] for r, q in pairs]
            each = "; ".join(
                f"{sig(x, 2)} at "
                + ", ".join(setting_text(k, v) for k, v in r["settings"].items() if k != "model")
                for x, (r, _) in zip(ratios, pairs))
            measure = CASE_CLASSES[case_name].measures[0][0]
            differences = [abs(r[measure] - q[measure]) for r, q in pairs
                           if has_value(r, measure) and has_value(q, measure)]
            lines.append(
                f"- {m}: {each}" + (f"; median {sig(float(np.median(ratios)), 2)}"
                                    if len(pairs) > 1 else "")
                + (f". Its {measure.replace('_', ' ')} differs from the meshed run's by at most "
                   f"{sig(100 * max(differences), 2)} percentage points." if differences else "."))
    lines.append("")
    return lines


def brick_wall_remarks(ok, wall):
    """What the brick wall's data say beyond the fronts."""
    lines = []
    rigid = [r for r in ok if r["settings"]["model"] == "rigid"]
    if rigid and wall.column > 0:
        s = [r["settlement"] for r in rigid]
        low, high = sig(min(s) * 1e6, 2), sig(max(s) * 1e6, 2)
        span = low if low == high else f"{low}–{high}"
        lines.append(
            f"Rigid bricks settle by {span} µm at the "
            "end: the joints' contact springs only, a rigid brick does not shorten "
            f"(the jointless column: {sig(wall.column * 1e6, 3)} µm).")
    pairs = [(a, f) for a in ok if a["settings"]["model"] == "auto" for f in ok
             if f["settings"]["model"] == "affine"
             and all(f["settings"][k] == a["settings"][k] for k in a["settings"] if k != "model")]
    if pairs and all(a.get("promotions", 0) == 0 for a, _ in pairs):
        difference = max(abs(a["settlement"] - f["settlement"]) for a, f in pairs)
        lines.append(
            "No auto brick was promoted in any run: the scene's rock has no `Fracture = "
            "true`, and auto blocks of a material without fracture keep the start model "
            "(affine). The auto runs are the affine runs ("
            + ("identical settlements" if difference == 0
               else f"settlements within {sig(difference * 1e6, 2)} µm")
            + (", the same open-close iterations" if all(
                a["open_close_per_step"] == f["open_close_per_step"] for a, f in pairs) else "")
            + "); where their times differ (auto over "
            "affine: " + ", ".join(sig(a["cpu"] / f["cpu"], 2) for a, f in pairs)
            + "), that is the noise of the machine.")
    meshed = [r for r in ok if r["settings"]["model"] == "meshed"]
    if len(meshed) > 1:
        s = [r["settlement"] for r in meshed]
        by_size = collections.defaultdict(list)
        for r in sorted(meshed, key=lambda r: -r["settings"]["time_step"]):
            by_size[r["settings"]["mesh_size"]].append(sig(r["settlement"] * 1e6, 4))
        lines.append(
            f"The meshed runs settle by {sig(min(s) * 1e6, 4)}–{sig(max(s) * 1e6, 4)} µm "
            f"({percent((max(s) - min(s)) / max(s), 2)} apart; from the largest step to the "
            "smallest, "
            + "; ".join(f"{setting_text('mesh_size', h)}: {', '.join(v)}"
                        for h, v in sorted(by_size.items(), reverse=True))
            + " µm). A wall at rest on frictional joints keeps the shear the transient "
            "leaves in them, so the step changes the state it settles in.")
    measured = [r for r in ok if "late_change" in r]
    if measured:
        settled = max(measured, key=lambda r: r["late_change"])
        lines.append(
            f"Over the last 40 % of each run the top moves by at most "
            f"{sig(settled['late_change'] * 1e6, 2)} µm ({settings_text(settled['settings'])}).")
    worst_drift = max(ok, key=lambda r: r["drift"])
    worst_speed = max(ok, key=lambda r: r["max_speed"])
    lines.append(
        f"The test's bounds hold in every run: the largest horizontal displacement of a top "
        f"corner is {sig(worst_drift['drift'] * 1e6, 2)} µm "
        f"({settings_text(worst_drift['settings'])}; bound 1 mm), the largest velocity "
        f"component {sig(worst_speed['max_speed'] * 1e3, 2)} mm/s "
        f"({settings_text(worst_speed['settings'])}; bound 50 mm/s)."
        if worst_drift["drift"] < 1e-3 and worst_speed["max_speed"] < 5e-2 else
        f"The test's bounds fail: largest horizontal top corner displacement "
        f"{sig(worst_drift['drift'] * 1e3, 2)} mm, largest velocity "
        f"{sig(worst_speed['max_speed'] * 1e3, 2)} mm/s.")
    return lines + [""]


def wall_impact_remarks(ok, impact):
    """What the wall impact's data say beyond the fronts."""
    lines = []
    boulder = impact.block_names.index("boulder")
    for measure, label in WallImpact.measures:
        runs = [r for r in ok if has_value(r, measure)]
        if not runs:
            continue
        within = [r for r in runs if r[measure] <= IMPACT_TARGET]
        outside = [r for r in runs if r[measure] > IMPACT_TARGET]
        lines.append(
            f"{label[0].upper() + label[1:]}: {len(within)} of {len(runs)} runs within "
            f"{percent(IMPACT_TARGET, 2)}"
            + ("; outside it: " + "; ".join(f"{settings_text(r['settings'])} ({percent(r[measure], 2)})"
                                    for r in outside) if outside else "")
            + ".")
    farthest = collections.Counter(r["error_block"] == boulder for r in ok if has_value(r, "error"))
    if farthest:
        lines.append(
            f"The block farthest off the reference is the boulder in {farthest[True]} of "
            f"{sum(farthest.values())} runs.")
    auto = [r for r in ok if r["settings"]["model"] == "auto"]
    if auto:
        lines.append(
            "Auto runs: " + "; ".join(
                f"{settings_text(r['settings'])}: {r['promotions']} promotions, at most "
                f"{r['most_meshed']} blocks meshed at once" for r in auto) + ".")
    return lines + [""]


def write_markdown(path, meta, results, references, pngs, csv_path):
    """The markdown fragment: method, then per case the measure, the plot,
    the Pareto front in words and the table of all runs."""
    md_dir = os.path.dirname(os.path.abspath(path))
    noise = meta["noise"]
    lines = [
        "## Speed against accuracy",
        "",
        f"Generated by `scripts/speed_accuracy.py`{' --quick' if meta['quick'] else ''} "
        f"on {meta['date']} with ndda {meta['ndda_version']}: "
        f"{meta['n_runs']} settings, {meta['n_processes']} ndda runs, "
        f"{sig(meta['elapsed'] / 60, 2)} min in all "
        f"(load average {sig(meta['load'][0], 2)} at the start, {sig(meta['load'][1], 2)} "
        f"at the end, on {meta['cores']} cores, one ndda process at a time). All runs: "
        f"[{os.path.basename(csv_path)}]({os.path.relpath(csv_path, md_dir)}).",
        "",
        "**Time** is the sum of the statistics file's `Wall time per step (s)`: the time "
        "stepping only, without start-up, meshing and output (the process's wall and CPU "
        "time are in the CSV; start-up and output add about "
        f"{sig(noise['startup'], 2)} s of wall time to each run). Runs whose steps took less "
        f"than {sig(meta['repeat_below'], 2)} s were run {meta['repeats']} times; the time "
        "is the smallest of them (the least disturbed) and the tables give the range. "
        + (
            f"On this shared machine the range of those repeats was up to "
            f"{percent(noise['max_spread'], 2)} of the smallest time (median over the "
            f"repeated runs {percent(noise['median_spread'], 2)}); runs that were not "
            "repeated carry that much noise too."
            if noise["n_repeated"]
            else "No run was repeated."
        ),
        "",
        "**Error** is computed by the script from ndda's output files, the way the "
        "case's C++ test measures it, against an analytical reference or, where the test "
        "has none, against a run of the sweep (said in the case; that run has no error "
        "and is not plotted). The plots show magnitudes on log axes; the tables "
        "give the errors with their sign. The tables' cells and dofs are the whole "
        "mesh's whatever the blocks' models (the nodes of a rigid or affine block follow "
        "its 3 or 6 unknowns).",
        "",
    ]
    for case_name, runs in results.items():
        case = CASE_CLASSES[case_name]
        lines += [f"### {case.title}", ""]
        seconds = meta.get("case_seconds", {}).get(case_name)
        if seconds is not None:
            lines += [f"{len(runs)} settings, {sum(len(r.get('times', [])) or 1 for r in runs)} "
                      f"ndda runs, {sig(seconds / 60, 2)} min.", ""]
        lines += case_explanation(case_name, references[case_name], runs)
        lines += ["", f"![{case_name}]({os.path.relpath(pngs[case_name], md_dir)})", ""]
        ok = [r for r in runs if r.get("ok")]
        if ok:
            for measure, label in case.measures:
                front = pareto_front(ok, measure)
                if not front:
                    lines += [f"No run has the {label} (no reference run).", ""]
                    continue
                text = describe_front(front, measure, runs)
                if len(case.measures) > 1:
                    text[0] = f"**{label[0].upper() + label[1:]}.** " + text[0]
                lines += text + [""]
        lines += case_remarks(case_name, ok)
        lines += model_remarks(case_name, ok)
        if case_name == "brick_wall":
            lines += brick_wall_remarks(ok, references[case_name])
        elif case_name == "wall_impact":
            lines += wall_impact_remarks(ok, references[case_name])
        failed = [r for r in runs if not r.get("ok")]
        groups = collections.OrderedDict()
        for r in failed:
            message, when = short_failure(r["failure"])
            groups.setdefault(message, []).append(
                settings_text(r["settings"]) + (f" (at t = {when})" if when else ""))
        for message, which in groups.items():
            lines.append(f"{len(which)} run(s) failed with \"{message}\": " + "; ".join(which) + ".")
            lines.append("")
        lines += markdown_table(case_name, runs)
        lines.append("")
    with open(path, "w") as stream:
        stream.write("\n".join(lines))


def read_csv(path):
    """The runs of a CSV this script wrote (for --from-csv)."""
    runs = []
    with open(path, newline="") as stream:
        for row in csv.DictReader(stream):
            case_name = row["case"]
            settings = collections.OrderedDict()
            for key in SETTING_NAMES:
                # A CSV of an older version of the script lacks newer keys
                # (the block model): those runs have the scene's setting.
                value = row.get(key, "")
                if value != "":
                    settings[key] = (
                        int(value) if key == "degree"
                        else value if key in ("integrator", "model")
                        else float(value)
                    )
            record = dict(case=case_name, settings=settings, ok=row["status"] == "ok")
            if not record["ok"]:
                record["failure"] = row["status"]
            for key in ("cells", "dofs"):
                record[key] = int(row[key]) if row[key] else ""
            if row["cpu_step_sum_s"]:
                record["cpu"] = float(row["cpu_step_sum_s"])
                n = int(row["n_timings"])
                record["times"] = [float(row["cpu_min_s"])] + [float(row["cpu_max_s"])] * (n - 1)
                record["process_wall"] = float(row["process_wall_s"])
                record["process_cpu"] = float(row["process_cpu_s"])
            for key in CSV_MEASURES:
                if row.get(key, "") != "":
                    record[key] = int(row[key]) if key in INTEGER_MEASURES else float(row[key])
            runs.append(record)
    return runs


def noise_of(all_runs, startup):
    spreads = [
        (max(r["times"]) - min(r["times"])) / r["cpu"]
        for r in all_runs
        if r.get("ok") and len(r["times"]) > 1 and r["cpu"] > 0
    ]
    return dict(
        n_repeated=len(spreads),
        max_spread=max(spreads) if spreads else 0.0,
        median_spread=float(np.median(spreads)) if spreads else 0.0,
        startup=float(np.median(startup)) if startup else float("nan"),
    )


# --------------------------------------------------------------------------
# The sweep


def status_text(case_name, record):
    """A run's errors and time for the progress lines."""
    if not record.get("ok"):
        return "FAILED: " + record["failure"]
    measures = [(key, record.get(key)) for key, _ in CASE_CLASSES[case_name].measures]
    if all(value is None for _, value in measures):
        return f"{sig(record['cpu'])} s (errors once the reference run is done)"
    return ", ".join(f"{key} {percent(value) if value is not None else '–'}"
                     for key, value in measures) + f", {sig(record['cpu'])} s"


def measure_run(binary, text, run_dir, args, record, reference, startup):
    """Run one setting (again, if fast, for its time), evaluate its output
    and fill the record; raises what run_ndda and the evaluation raise."""
    record["processes"] = record.get("processes", 0) + 1
    timing, log = run_ndda(binary, text, run_dir, args.timeout)
    out_dir = os.path.join(run_dir, "out")
    record["cells"], record["dofs"] = mesh_size_of_log(log)
    record.update(reference.evaluate(out_dir))
    record["times"].append(timing.step_sum)
    record["process_wall"] = timing.process_wall
    record["process_cpu"] = timing.process_cpu
    startup.append(timing.process_wall - timing.step_sum)
    if timing.step_sum < args.repeat_below:
        for _ in range(args.repeats - 1):
            record["processes"] += 1
            again, _ = run_ndda(binary, text, run_dir + "_again", args.timeout)
            record["times"].append(again.step_sum)
        shutil.rmtree(run_dir + "_again", ignore_errors=True)
    record["cpu"] = float(np.min(record["times"]))


def run_case(case_name, settings_list, reference, args, binary, work_dir, startup):
    """Run the sweep of one case, one ndda process at a time; the records of
    its runs (errors against a run of the sweep once all are done)."""
    with open(os.path.join(args.prm_dir, case_name + ".prm")) as stream:
        base_text = stream.read()
    runs = []
    for n, settings in enumerate(settings_list):
        settings = collections.OrderedDict(
            (k, settings[k]) for k in SETTING_NAMES if k in settings)
        record = dict(case=case_name, settings=settings, times=[])
        run_dir = os.path.join(work_dir, case_name, f"run{n:03d}")
        text = base_text + "\n" + overrides(case_name, settings)
        try:
            measure_run(binary, text, run_dir, args, record, reference, startup)
            record["ok"] = True
        except (RuntimeError, ndda_output.OutputError, KeyError, ValueError,
                ZeroDivisionError, FloatingPointError) as error:
            record["ok"] = False
            record["failure"] = str(error).replace("|", "/")[:600]
        if not args.work_dir:
            shutil.rmtree(run_dir, ignore_errors=True)
        runs.append(record)
        print(f"{case_name} {n + 1}/{len(settings_list)}: "
              f"{settings_text(settings)}: {status_text(case_name, record)}", flush=True)
    if hasattr(reference, "finish"):
        reference.finish(runs)
        for r in runs:
            print(f"{case_name}: {settings_text(r['settings'])}"
                  f"{' (reference)' if r.get('is_reference') else ''}: "
                  f"{status_text(case_name, r)}", flush=True)
    return runs


# --------------------------------------------------------------------------


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--ndda", help="the ndda binary")
    parser.add_argument("--prm-dir", required=True, help="folder of the example scenes (prm/)")
    parser.add_argument("--out-dir", required=True, help="folder for the PNGs, the CSV and the run's metadata")
    parser.add_argument("--markdown", required=True, help="the markdown fragment to write")
    parser.add_argument("--cases", default=",".join(CASES),
                        help=f"comma separated, of {', '.join(CASES)}")
    parser.add_argument("--quick", action="store_true", help="2-4 runs per case")
    parser.add_argument("--work-dir", default=None,
                        help="folder for the runs' output, kept (default: a temporary one, removed)")
    parser.add_argument("--repeat-below", type=float, default=None,
                        help="repeat runs whose steps took less than this (s; default 2, --quick 0.3)")
    parser.add_argument("--repeats", type=int, default=3, help="runs of a repeated setting")
    parser.add_argument("--timeout", type=float, default=600, help="seconds per run")
    parser.add_argument("--from-csv", action="store_true",
                        help="run nothing: redraw the PNGs and rewrite the markdown from "
                        "OUT_DIR/speed_accuracy.csv and speed_accuracy_run.json")
    args = parser.parse_args()
    if args.repeat_below is None:
        args.repeat_below = 0.3 if args.quick else 2.0

    cases = [c.strip() for c in args.cases.split(",") if c.strip()]
    for c in cases:
        if c not in CASES:
            parser.error(f"--cases: unknown case '{c}' (known: {', '.join(CASES)})")
    os.makedirs(args.out_dir, exist_ok=True)
    os.makedirs(os.path.dirname(os.path.abspath(args.markdown)), exist_ok=True)
    csv_path = os.path.join(args.out_dir, "speed_accuracy.csv")
    meta_path = os.path.join(args.out_dir, "speed_accuracy_run.json")

    # The references come from the scenes as they are run (the case's .prm
    # with the first run's overrides; what they use is the same in all).
    def reference_of(case_name, settings):
        with open(os.path.join(args.prm_dir, case_name + ".prm")) as stream:
            text = stream.read() + "\n" + overrides(case_name, settings)
        return CASE_CLASSES[case_name](read_prm_text(text))

    results, references, pngs = collections.OrderedDict(), {}, {}
    if args.from_csv:
        all_runs = read_csv(csv_path)
        with open(meta_path) as stream:
            meta = json.load(stream)
        for case_name in cases:
            runs = [r for r in all_runs if r["case"] == case_name]
            if runs:
                results[case_name] = runs
                references[case_name] = reference_of(case_name, runs[0]["settings"])
    else:
        if not args.ndda:
            parser.error("--ndda is required unless --from-csv")
        binary = os.path.abspath(args.ndda)
        if not os.access(binary, os.X_OK):
            parser.error(f"--ndda: {binary} is not an executable")
        # ndda has no --version: the binary's date and the scenes' commit.
        commit = subprocess.run(
            ["git", "-C", os.path.abspath(args.prm_dir), "rev-parse", "--short", "HEAD"],
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
        ).stdout.strip()
        built = time.strftime("%Y-%m-%d %H:%M", time.gmtime(os.path.getmtime(binary)))
        work_dir = args.work_dir or tempfile.mkdtemp(prefix="speed_accuracy_")
        start = time.perf_counter()
        load_start = os.getloadavg()[0]
        startup, all_runs, case_seconds = [], [], {}
        for case_name in cases:
            case_start = time.perf_counter()
            settings_list = CASE_RUNS[case_name](args.quick)
            references[case_name] = reference_of(case_name, settings_list[0])
            runs = run_case(case_name, settings_list, references[case_name], args, binary,
                            work_dir, startup)
            results[case_name] = runs
            all_runs += runs
            case_seconds[case_name] = time.perf_counter() - case_start
        n_processes = sum(r.get("processes", 0) for r in all_runs)
        if not args.work_dir:
            shutil.rmtree(work_dir, ignore_errors=True)
        meta = dict(
            quick=args.quick,
            date=time.strftime("%Y-%m-%d"),
            ndda_version=f"built {built} UTC, scenes of commit {commit or 'unknown'}",
            n_runs=len(all_runs),
            n_processes=n_processes,
            elapsed=time.perf_counter() - start,
            load=(load_start, os.getloadavg()[0]),
            cores=os.cpu_count(),
            repeat_below=args.repeat_below,
            repeats=args.repeats,
            noise=noise_of(all_runs, startup),
            case_seconds=case_seconds,
        )
        write_csv(csv_path, all_runs)
        with open(meta_path, "w") as stream:
            json.dump(meta, stream, indent=1)
            stream.write("\n")

    for case_name, runs in results.items():
        png = os.path.join(args.out_dir, case_name + ".png")
        if any(r.get("ok") for r in runs):
            plot_case(CASE_CLASSES[case_name], runs, png)
        pngs[case_name] = png
    write_markdown(args.markdown, meta, results, references, pngs, csv_path)
    written = [args.markdown] + list(pngs.values())
    if not args.from_csv:
        written += [csv_path, meta_path]
    print(f"{meta['n_runs']} settings, {meta['n_processes']} runs in "
          f"{sig(meta['elapsed'] / 60, 2)} min; wrote {', '.join(written)}")
    n_failed = sum(1 for r in all_runs if not r.get("ok"))
    if n_failed:
        # A run that fails is a result of the sweep (listed in the markdown),
        # not a failure of the script.
        print(f"{n_failed} ndda runs failed; the markdown lists them")
    return 0


if __name__ == "__main__":
    sys.exit(main())
