#!/usr/bin/python3
"""Load curves of an ndda run: the stress-strain curve of a compression
test and the Brazilian disc's centre stress against 2 P / (pi D t).

The compression curve takes the load from the cell stresses of each VTU
frame by the mean stress theorem: a body in
equilibrium between two faces h apart (normal y) carries the force
F = -t sum_c A_c sigma_yy,c / h (ndda_output.stress_resultant; A_c on the
deformed mesh, sigma_yy the cell's mean stress). This is exact for a body
at rest and a good estimate while the inertia forces are small (slow
loading); after failure, when pieces move fast, it is only an estimate.
One point per VTU frame: write frames as often as the curve needs
('Output/Interval').

- compression DIRECTORY: a specimen pressed between its top and bottom
  faces (prm/uniaxial_compression_*.prm). Axial stress = F / w (w the
  specimen's width at the start, per unit thickness), F from all cells
  with h the current distance between the top and bottom faces (their
  points found in the reference configuration); axial strain = 1 - h /
  h0. The straight line E * strain (the intact specimen, free to expand
  sideways) is drawn for comparison, E the first material's Young's
  modulus; the first crack (statistics: 'Cracked edges' > 0) and the peak
  are marked.
- brazilian DIRECTORY: a disc between two plates
  (prm/brazilian_disc*.prm): the centre's sigma_xx (measure point 0, every
  step) against time, with 2 P / (pi D t) at every frame for P from the
  top plate and from the bottom plate (blocks named 'top' and 'bottom',
  D the disc's width, t 'Materials/Thickness'; P the plate's contact
  force, the statistics column '<plate> contact force y (N)' of the
  'block forces' postprocessor, as tests/plates.h takes it: the plates
  are rigid blocks, without stress). The
  elastic solution holds until the disc cracks; the first crack and the
  tensile strength are marked.

Run it with Debian's Python (python3-numpy, python3-matplotlib):

    /usr/bin/python3 scripts/plot_load_curves.py compression \\
        output/uniaxial_compression_one_crack --out /tmp/stress_strain.png
    /usr/bin/python3 scripts/plot_load_curves.py brazilian \\
        output/brazilian_disc --out /tmp/disc_centre.png
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ndda_output  # noqa: E402


def frames_of(directory):
    pvd = os.path.join(directory, "solution.pvd")
    return ndda_output.read_pvd(pvd)


def first_material(parameters, entry):
    """An entry of the first material in 'Materials/Names'."""
    name = parameters["Materials/Names"].split(",")[0].strip()
    key = f"Materials/{name}/{entry}"
    if key not in parameters:
        raise ndda_output.OutputError(f"parameters.prm: no '{key}'")
    return float(parameters[key])


def finish(figure, axes, xlabel, ylabel, title, args):
    """Labels, grid, legend and title; write args.out."""
    import matplotlib.pyplot as plt

    axes.set_xlabel(xlabel)
    axes.set_ylabel(ylabel)
    axes.grid(True, linewidth=0.4, alpha=0.5)
    axes.legend(fontsize=8, loc="upper left")
    axes.set_title(title, fontsize=10)
    figure.savefig(args.out, dpi=args.dpi)
    plt.close(figure)


# ------------------------------------------------------------ compression
def compression_curve(directory):
    """(times, strains, stresses in Pa (compression positive), h0, w)."""
    files = frames_of(directory)
    first = ndda_output.read_vtu(files[0][1])
    reference = first.points[:, :2] - first.point_data["displacement"][:, :2]
    y0, y1 = reference[:, 1].min(), reference[:, 1].max()
    height0 = y1 - y0
    width = reference[:, 0].max() - reference[:, 0].min()
    tolerance = 1e-6 * height0
    rows = []
    for time, path in files:
        vtu = first if path == files[0][1] else ndda_output.read_vtu(path)
        xy = vtu.points[:, :2]
        ref = xy - vtu.point_data["displacement"][:, :2]
        top = np.abs(ref[:, 1] - y1) < tolerance
        bottom = np.abs(ref[:, 1] - y0) < tolerance
        height = xy[top, 1].mean() - xy[bottom, 1].mean()
        n_cells = len(vtu.offsets)
        force = ndda_output.stress_resultant(
            vtu, np.ones(n_cells, dtype=bool), "stress_yy", height, 1.0
        )
        rows.append((time, 1 - height / height0, force / width))
    rows = np.array(rows)
    return rows[:, 0], rows[:, 1], rows[:, 2], height0, width


def plot_compression(args):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    directory = args.directory
    times, strain, stress, height0, width = compression_curve(directory)
    parameters = ndda_output.read_parameters(directory)
    young = first_material(parameters, "Young's modulus")
    crack = ndda_output.first_crack_time(directory)

    figure, axes = plt.subplots(figsize=(6.5, 4.4), dpi=args.dpi, layout="constrained")
    axes.plot(strain * 1e3, stress * 1e-6, "-o", markersize=2.5, linewidth=1.4,
              label="ndda: mean axial stress (mean stress theorem, every frame)")
    line = np.array([0, strain.max()])
    axes.plot(line * 1e3, young * line * 1e-6, "--", color="black", linewidth=1.0,
              label=f"E strain (intact specimen, E = {young * 1e-9:g} GPa)")
    peak = int(np.argmax(stress))
    axes.plot(strain[peak] * 1e3, stress[peak] * 1e-6, "v", color="tab:purple",
              markersize=7, label=f"peak {stress[peak] * 1e-6:.3g} MPa, "
              f"t = {times[peak] * 1e3:.3g} ms")
    if crack is not None:
        s_crack = np.interp(crack, times, strain)
        p_crack = np.interp(crack, times, stress)
        axes.plot(s_crack * 1e3, p_crack * 1e-6, "o", color="tab:red",
                  markersize=7, markerfacecolor="none", markeredgewidth=1.6,
                  label=f"first crack, t = {crack * 1e3:.3g} ms "
                  f"({p_crack * 1e-6:.3g} MPa)")
    axes.set_ylim(bottom=min(0, stress.min() * 1e-6 * 1.05), top=stress.max() * 1e-6 * 1.5)
    finish(
        figure,
        axes,
        "axial strain 1 - h / h0 (‰)",
        "axial stress F / w (MPa)",
        f"{ndda_output.scene_name(directory)}: stress-strain "
        f"(h0 = {height0 * 1e3:g} mm, w = {width * 1e3:g} mm)",
        args,
    )
    print(
        f"{args.out}: {len(times)} frames, peak {stress[peak] * 1e-6:.4g} MPa at "
        f"strain {strain[peak]:.4g} (t = {times[peak] * 1e3:.4g} ms)"
        + (f", first crack at {crack * 1e3:.4g} ms" if crack is not None else "")
    )


# ------------------------------------------------------------- brazilian
def disc_curve(directory):
    """Frames' (time, 2 P_top / (pi D t), 2 P_bottom / (pi D t)) and the
    disc's D, t."""
    parameters = ndda_output.read_parameters(directory)
    names = [n.strip() for n in parameters["Geometry/Blocks"].split(",")]
    for needed in ("disc", "top", "bottom"):
        if needed not in names:
            raise ndda_output.OutputError(
                f"{directory}/parameters.prm: no block '{needed}' in "
                f"Geometry/Blocks ({', '.join(names)})"
            )
    disc = ndda_output.points_of(parameters["Geometry/disc/Outer boundary"])
    diameter = disc[:, 0].max() - disc[:, 0].min()
    thickness = float(parameters.get("Materials/Thickness", "1"))
    times = [time for time, _ in frames_of(directory) if time > 0]
    factor = 2 / (np.pi * diameter * thickness)
    top = ndda_output.plate_force(directory, "top", times)
    bottom = ndda_output.plate_force(directory, "bottom", times)
    rows = [(time, factor * p, factor * q) for time, p, q in zip(times, top, bottom)]
    return np.array(rows), diameter, thickness, parameters


def plot_brazilian(args):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    directory = args.directory
    rows, diameter, thickness, parameters = disc_curve(directory)
    table = ndda_output.read_table(os.path.join(directory, "measure_points.txt"))
    t, centre = table["time"], table["point 0 sigma_xx"]
    crack = ndda_output.first_crack_time(directory)

    figure, axes = plt.subplots(figsize=(7, 4.4), dpi=args.dpi, layout="constrained")
    axes.plot(t * 1e3, centre * 1e-6, linewidth=1.4,
              label="ndda: sigma_xx at the centre (measure point 0)")
    axes.plot(rows[:, 0] * 1e3, rows[:, 1] * 1e-6, "o", color="black",
              markersize=3.5, markerfacecolor="none",
              label="2P/(πDt), P of the top plate")
    axes.plot(rows[:, 0] * 1e3, rows[:, 2] * 1e-6, "x", color="tab:gray",
              markersize=4, label="2P/(πDt), P of the bottom plate")
    try:
        strength = first_material(parameters, "Tensile strength")
        axes.axhline(strength * 1e-6, color="tab:orange", linewidth=1.0,
                     linestyle="-.", label=f"tensile strength {strength * 1e-6:g} MPa")
    except ndda_output.OutputError:
        pass
    if crack is not None:
        axes.axvline(crack * 1e3, color="tab:red", linestyle=":", linewidth=1.2,
                     label=f"first crack, {crack * 1e3:.4g} ms")
        before = rows[rows[:, 0] < crack]
        if len(before):
            last = before[-1]
            k = int(np.argmin(np.abs(t - last[0])))
            print(
                f"last frame before the crack, t = {last[0] * 1e3:.4g} ms: centre "
                f"{centre[k] * 1e-6:.4g} MPa, 2P/(pi D t) {last[1] * 1e-6:.4g} MPa "
                f"(top), {last[2] * 1e-6:.4g} MPa (bottom): "
                f"{centre[k] / last[1] - 1:+.2%}"
            )
    finish(
        figure,
        axes,
        "time (ms)",
        "stress (MPa, tension positive)",
        f"{ndda_output.scene_name(directory)}: centre stress against "
        f"2P/(πDt) (D = {diameter * 1e3:.3g} mm, t = {thickness * 1e3:.3g} mm)",
        args,
    )
    print(f"{args.out}: {len(rows)} frames")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="See the top of this file for how the load is found.",
    )
    parser.add_argument("kind", choices=("compression", "brazilian"))
    parser.add_argument("directory", help="ndda output directory")
    parser.add_argument("--out", required=True, help="PNG file to write")
    parser.add_argument("--dpi", type=int, default=110, help="resolution (default 110)")
    args = parser.parse_args()
    try:
        if args.kind == "compression":
            plot_compression(args)
        else:
            plot_brazilian(args)
    except (ndda_output.OutputError, KeyError) as error:
        sys.exit(f"plot_load_curves: {error}")


if __name__ == "__main__":
    main()
