#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Scenes give the same results with OpenBLAS as with the reference BLAS
(issue 19: "check results against the reference BLAS").

    blas_reference.py NDDA WORK_DIR [--tolerance T] SCENE.prm[:T] ...

Runs every scene twice, with `LD_LIBRARY_PATH` pointing at Debian's
reference BLAS and at Debian's single-threaded OpenBLAS
(libopenblas0-serial), whatever BLAS the system has chosen. Each run's log
must name the BLAS it was given (the line "BLAS: ..."). The two runs'
measure_points.txt must agree, with the same number of rows: every value
within T (default 1e-9) times the largest magnitude of its quantity over
all points and components (displacements u_*, velocities v_*, stresses
sigma_*; the time by itself). A component that is zero but for round-off
(u_x of a block that only falls) is compared with the size of its field.
A scene given as SCENE.prm:T has its own tolerance: a contact force is a
penalty stiffness times a penetration that is a small difference of
displacements, so its round-off, and that of the stresses it causes, is
larger than the displacements' by about their ratio to the penetration.

Exits 77 (skipped) if either BLAS is not installed, 1 with what differs.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys

LIBDIR = "/usr/lib/x86_64-linux-gnu"
BLAS = {
    "reference": (os.path.join(LIBDIR, "blas"), "not OpenBLAS"),
    "OpenBLAS": (os.path.join(LIBDIR, "openblas-serial"), "OpenBLAS"),
}


def run(ndda, prm, directory, blas):
    """Run prm in directory with the given BLAS; its measure point rows."""
    libdir, expected = BLAS[blas]
    os.makedirs(directory, exist_ok=True)
    env = dict(os.environ, LD_LIBRARY_PATH=libdir)
    result = subprocess.run([ndda, prm], cwd=directory, env=env,
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{prm} with the {blas} BLAS failed:\n{result.stderr}")
    blas_line = [line for line in result.stdout.splitlines()
                 if line.strip().startswith("BLAS:")]
    if not blas_line or not blas_line[0].split("BLAS:")[1].strip().startswith(
            expected) or libdir not in blas_line[0]:
        sys.exit(f"{prm}: asked for the {blas} BLAS in {libdir}, the log "
                 f"says: {blas_line}")
    name = os.path.splitext(os.path.basename(prm))[0]
    rows, kinds = [], []
    for root, _, files in os.walk(os.path.join(directory, "output")):
        if "measure_points.txt" in files:
            with open(os.path.join(root, "measure_points.txt")) as f:
                lines = f.read().splitlines()
            # "# time  [point 0 at x y: u_x u_y ...] [point 1 ...]"
            kinds = ["time"] + [
                column.split("_")[0]
                for point in re.findall(r"\[point [^:]*: ([^\]]*)\]",
                                        lines[0])
                for column in point.split()]
            rows = [[float(x) for x in line.split()]
                    for line in lines if line.strip() and line[0] != "#"]
    if not rows or len(kinds) != len(rows[0]):
        sys.exit(f"{name}: no measure points written, or a header that "
                 f"does not name {len(rows[0]) if rows else 0} columns")
    return blas_line[0].strip(), kinds, rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("ndda")
    parser.add_argument("work_dir")
    parser.add_argument("scenes", nargs="+")
    parser.add_argument("--tolerance", type=float, default=1e-9)
    args = parser.parse_args()

    for blas, (libdir, _) in BLAS.items():
        if not os.path.exists(os.path.join(libdir, "libblas.so.3")):
            print(f"the {blas} BLAS is not installed ({libdir}): skipped")
            sys.exit(77)

    failed = False
    for scene in args.scenes:
        prm, _, own_tolerance = scene.partition(":")
        tolerance = float(own_tolerance) if own_tolerance else args.tolerance
        name = os.path.splitext(os.path.basename(prm))[0]
        results = {}
        for blas in BLAS:
            directory = os.path.join(args.work_dir, name, blas)
            shutil.rmtree(directory, ignore_errors=True)
            results[blas] = run(args.ndda, prm, directory, blas)
        kinds = results["reference"][1]
        reference, fast = results["reference"][2], results["OpenBLAS"][2]
        if len(reference) != len(fast):
            print(f"{name}: {len(reference)} rows with the reference BLAS, "
                  f"{len(fast)} with OpenBLAS")
            failed = True
            continue
        scales = {}
        for j, kind in enumerate(kinds):
            scales[kind] = max(scales.get(kind, 0.0),
                               max(abs(r[j]) for r in reference + fast))
        worst, worst_column = 0.0, 0
        for j, kind in enumerate(kinds):
            scale = scales[kind]
            if scale == 0:
                continue
            difference = max(abs(a[j] - b[j])
                             for a, b in zip(reference, fast)) / scale
            if difference > worst:
                worst, worst_column = difference, j
        verdict = "met" if worst <= tolerance else "NOT met"
        print(f"{name}: {len(reference)} rows, largest difference "
              f"{worst:.2e} of its quantity's largest value (column "
              f"{worst_column}, {kinds[worst_column]}); within "
              f"{tolerance:g}: {verdict}")
        print(f"@value blas_reference.{name}.difference {worst:.2g}")
        print(f"@value blas_reference.{name}.met {verdict}")
        failed = failed or worst > tolerance
    for blas in BLAS:
        print(f"{blas}: {results[blas][0]}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
