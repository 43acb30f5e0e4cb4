#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A run killed with SIGKILL at random moments leaves only complete files
(but for the last line of the two streamed files, which may be cut).

    kill_at_random.py NDDA SCENE.prm WORK_DIR [--kills N] [--seed S]

Runs the scene once to its end (the reference), then N times killed with
SIGKILL after a random fraction of the reference's wall time. After every
kill each output file must be whole (ndda writes frames and collections
to a temporary name and renames them; it appends the rows of the
statistics and the measure points in one write each):

- every .vtu file ends with its closing tag, and so does solution.pvd,
  whose every frame exists;
- every row the statistics and measure-point files hold is the reference
  run's row (the runs are deterministic); the last one may be cut (they
  are appended with one write(), which Linux may stop at a page boundary
  when SIGKILL arrives) and must then be the start of the reference's
  row; a row from a corrupted buffer differs;
- parameters.prm is the reference's.

Leftover `.tmp` files are allowed (a kill during a write leaves one; the
next write replaces it). Exits 1 with the faults found.
"""

import argparse
import os
import random
import shutil
import signal
import subprocess
import sys
import time


def scene_copy(prm, directory, out):
    """The scene, writing often to out."""
    with open(prm) as f:
        text = f.read()
    text += (
        "\n# kill_at_random.py\nsubsection Output\n"
        "  set Directory = %s/\n  set Interval = 0.01\n"
        "  set Progress interval = 0.05\nend\n" % out
    )
    path = os.path.join(directory, "scene.prm")
    with open(path, "w") as f:
        f.write(text)
    return path


def read(path):
    with open(path, "rb") as f:
        return f.read()


def faults_of(out, reference, cut_last_lines):
    """What is incomplete in the output directory out; the streamed files
    whose last line is cut go to cut_last_lines."""
    faults = []
    names = sorted(os.listdir(out))
    for name in names:
        path = os.path.join(out, name)
        if name.endswith(".tmp"):
            continue
        data = read(path)
        if name.endswith(".vtu") or name.endswith(".pvd"):
            if not data.rstrip().endswith(b"</VTKFile>"):
                faults.append("%s: no closing tag (%d bytes)" % (name, len(data)))
        if name == "solution.pvd":
            for part in data.split(b'file="')[1:]:
                frame = part.split(b'"')[0].decode()
                if not os.path.exists(os.path.join(out, frame)):
                    faults.append("solution.pvd names %s, which is missing" % frame)
        if name in ("statistics", "measure_points.txt"):
            # Appended in one write(), which Linux may stop at a page
            # boundary when SIGKILL arrives (a 256 MB write killed after
            # 1.5 s left 14 MB): the last line may be cut, and must then
            # be the start of the complete run's line (checked below).
            if data and not data.endswith(b"\n"):
                cut_last_lines.append(name)
            whole = read(os.path.join(reference, name))
            if not whole.startswith(data):
                lines, ref = data.split(b"\n"), whole.split(b"\n")
                k = next(i for i, l in enumerate(lines) if i >= len(ref) or l != ref[i])
                faults.append("%s: line %d differs from the complete run's" % (name, k + 1))
        if name == "parameters.prm" and data != read(os.path.join(reference, name)):
            faults.append("parameters.prm differs from the complete run's")
    return faults


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("ndda")
    parser.add_argument("prm")
    parser.add_argument("work_dir")
    parser.add_argument("--kills", type=int, default=12)
    parser.add_argument("--seed", type=int, default=17)
    args = parser.parse_args()

    shutil.rmtree(args.work_dir, ignore_errors=True)
    os.makedirs(args.work_dir)
    reference = os.path.join(args.work_dir, "reference")
    out = os.path.join(args.work_dir, "out")
    # Both runs write to the same directory name, so that parameters.prm is
    # the same; the reference is moved aside.
    scene = scene_copy(args.prm, args.work_dir, out)
    start = time.time()
    subprocess.run([args.ndda, scene], check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - start
    os.rename(out, reference)
    print("reference run: %.2f s" % wall)

    rng = random.Random(args.seed)
    failures = 0
    for k in range(args.kills):
        shutil.rmtree(out, ignore_errors=True)
        delay = rng.uniform(0.5, 0.98) * wall
        process = subprocess.Popen([args.ndda, scene], stdout=subprocess.DEVNULL)
        time.sleep(delay)
        process.send_signal(signal.SIGKILL)
        process.wait()
        if not os.path.isdir(out):
            print("kill %d after %.2f s: no output directory yet" % (k, delay))
            continue
        names = os.listdir(out)
        rows = 0
        if "statistics" in names:
            rows = sum(
                1 for l in read(os.path.join(out, "statistics")).split(b"\n")
                if l and not l.startswith(b"#")
            )
        cut = []
        faults = faults_of(out, reference, cut)
        print(
            "kill %d after %.2f s: %d files (%d temporary), %d statistics rows: %s"
            % (
                k,
                delay,
                len(names),
                sum(n.endswith(".tmp") for n in names),
                rows,
                "; ".join(faults) if faults else "all complete",
            )
            + ("" if not cut else " (last line cut, a prefix of the complete run's: %s)" % ", ".join(cut))
        )
        failures += len(faults)
    print("OK" if failures == 0 else "FAILED: %d faults" % failures)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
