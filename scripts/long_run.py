#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Long-run benchmark: does a run keep its memory and its speed?

Runs a scene (by default prm/brick_wall.prm) for many more steps than it
was written for and samples, while it runs, the resident memory of the
ndda process (VmRSS) and its progress lines (steps and wall time per step
since the previous line). Prints and optionally writes as markdown:

- the resident memory after the first 1000 steps and at the end, and the
  largest in between;
- the wall time per step around step 1000 and over the last steps;
- the sizes of the files the run wrote.

The scene's end time, output interval, progress interval and output
directory are overridden by entries appended to a copy of the scene (a
ParameterHandler entry set twice takes its last value).

    python3 scripts/long_run.py --ndda build/ndda --end-time 200 \\
        --work-dir /tmp/long_run --markdown /tmp/long_run/long_run.md
"""

import argparse
import os
import re
import subprocess
import sys
import threading
import time

PROGRESS = re.compile(r"^\s*step\s+(\d+)\s+t =\s*(\S+) s.*wall\s+(\S+) s/step")


def rss_kb(pid):
    """Resident set size of process pid in kB (None once it is gone)."""
    try:
        with open("/proc/%d/status" % pid) as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


def scene_copy(prm, work_dir, end_time, interval, progress):
    """A copy of scene prm that runs to end_time and writes to work_dir."""
    with open(prm) as f:
        text = f.read()
    out = os.path.join(work_dir, "output") + "/"
    text += (
        "\n# long_run.py\n"
        "subsection Control\n  set End time = %s\nend\n"
        "subsection Output\n  set Interval = %s\n"
        "  set Progress interval = %s\n  set Directory = %s\nend\n"
        % (end_time, interval, progress, out)
    )
    path = os.path.join(work_dir, "scene.prm")
    with open(path, "w") as f:
        f.write(text)
    return path, out


def run(ndda, scene, sample_period):
    """Run ndda on scene; return (progress lines, memory samples, wall)."""
    process = subprocess.Popen(
        [ndda, scene],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        bufsize=1,
    )
    progress = []  # (step, model time, wall s/step)
    last_step = [0]
    output = []

    def read():
        for line in process.stdout:
            output.append(line)
            m = PROGRESS.match(line)
            if m:
                step = int(m.group(1))
                last_step[0] = step
                progress.append((step, float(m.group(2)), float(m.group(3))))

    reader = threading.Thread(target=read)
    reader.start()
    samples = []  # (wall, last reported step, rss kB)
    start = time.time()
    while process.poll() is None:
        kb = rss_kb(process.pid)
        if kb is not None:
            samples.append((time.time() - start, last_step[0], kb))
        time.sleep(sample_period)
    reader.join()
    wall = time.time() - start
    if process.returncode != 0:
        sys.stderr.write("".join(output[-20:]))
        sys.exit("ndda failed with exit code %d" % process.returncode)
    return progress, samples, wall


def mean(values):
    return sum(values) / len(values) if values else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ndda", required=True)
    parser.add_argument(
        "--prm",
        default=os.path.join(
            os.path.dirname(os.path.abspath(__file__)), "..", "prm", "brick_wall.prm"
        ),
    )
    parser.add_argument("--end-time", default="200")
    parser.add_argument("--output-interval", default="5")
    parser.add_argument("--progress-interval", default="1")
    parser.add_argument("--sample-period", type=float, default=0.5)
    parser.add_argument("--work-dir", required=True)
    parser.add_argument("--markdown")
    args = parser.parse_args()

    os.makedirs(args.work_dir, exist_ok=True)
    scene, out = scene_copy(
        args.prm,
        args.work_dir,
        args.end_time,
        args.output_interval,
        args.progress_interval,
    )
    progress, samples, wall = run(args.ndda, scene, args.sample_period)
    if not progress or not samples:
        sys.exit("no progress lines or memory samples: the run was too short")

    with open(os.path.join(args.work_dir, "progress.csv"), "w") as f:
        f.write("step,time,wall_per_step\n")
        for p in progress:
            f.write("%d,%g,%g\n" % p)
    with open(os.path.join(args.work_dir, "memory.csv"), "w") as f:
        f.write("wall,step,rss_kb\n")
        for s in samples:
            f.write("%g,%d,%d\n" % s)
    n_steps = progress[-1][0]
    early = [s for s in samples if s[1] >= 1000]
    rss_early = early[0][2] if early else samples[0][2]
    rss_end = samples[-1][2]
    rss_max = max(s[2] for s in samples)
    # Wall time per step: progress lines whose step lies in the first few
    # thousand steps after step 1000, and in the last 3 % of the run.
    first = [p[2] for p in progress if 1000 <= p[0] <= 4000]
    last = [p[2] for p in progress if p[0] >= 0.97 * n_steps]
    files = sorted(
        (f, os.path.getsize(os.path.join(out, f)))
        for f in os.listdir(out)
        if not f.startswith("solution-")
    )
    rows = [
        ("steps", "%d" % n_steps),
        ("wall time", "%.1f s" % wall),
        ("resident memory after step 1000", "%.1f MB" % (rss_early / 1024)),
        ("resident memory at the end", "%.1f MB" % (rss_end / 1024)),
        ("largest resident memory", "%.1f MB" % (rss_max / 1024)),
        (
            "growth after step 1000",
            "%+.2f %% (%.3f kB a step)"
            % (
                100 * (rss_max - rss_early) / rss_early,
                (rss_max - rss_early) / max(n_steps - 1000, 1),
            ),
        ),
        ("wall time per step, steps 1000-4000", "%.3f ms" % (1e3 * mean(first))),
        ("wall time per step, last 3 %", "%.3f ms" % (1e3 * mean(last))),
        ("ratio last / first", "%.3f" % (mean(last) / mean(first))),
    ] + [("file " + f, "%.1f kB" % (size / 1024)) for f, size in files]
    width = max(len(r[0]) for r in rows)
    for name, value in rows:
        print("%-*s  %s" % (width, name, value))
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("| quantity | value |\n|---|---|\n")
            for name, value in rows:
                f.write("| %s | %s |\n" % (name, value))


if __name__ == "__main__":
    main()
