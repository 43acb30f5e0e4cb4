#!/usr/bin/python3
"""Draw PNG frames of an ndda run: cells coloured by stress, blocks outlined,
cracks marked.

Reads an ndda output directory (output/<scene name>/ or the scene's
Output/Directory): solution.pvd and the solution-NNNNN.vtu files it lists
(VTK XML, base64 + zlib, one vertex per cell corner, read with
ndda_output.py: xml.etree, base64, zlib and numpy only), the 'statistics'
file for the 'Cracked edges' column if there is one, and parameters.prm
for the scene name. Writes one PNG per chosen frame, PREFIX_NNNNN.png
(NNNNN the frame's number in solution.pvd) or, with --auto,
PREFIX_start.png, PREFIX_first_crack.png, PREFIX_propagation.png and
PREFIX_end.png, or with --times and --names, PREFIX_NAME.png.

Run it with Debian's Python (python3-numpy, python3-matplotlib):

    /usr/bin/python3 scripts/plot_frames.py output/brazilian_disc --auto --out /tmp/disc
    /usr/bin/python3 scripts/plot_frames.py output/bar_spalling --times 0.26ms,0.4ms \
        --field stress_xx --xlim 900,1000 --out /tmp/bar

What a frame shows:
- Cells coloured by --field (default 'principal': at each point the
  principal stress of the larger magnitude, signed, so compression is blue
  and tension red whichever of the two it is), in MPa, with a diverging
  colour map and symmetric limits. The limits are the same for every frame
  of the scene: the largest over all frames of the --percentile of |value|
  (default 95 %, so that the stress peaks at point contacts, a few cells
  with ten times the stress of the rest, do not wash out the picture;
  values beyond are drawn in the end colours and the colour bar has
  pointed ends), or --limit. Stress fields are constant in a P1
  cell and drawn flat; fields that vary in a cell are drawn with Gouraud
  shading.
- Block outlines in black: the edges that belong to one triangle of a
  block only. ndda writes every cell with its own three vertices, so edges
  are matched by their end points' exact float32 coordinates (and the
  block id): the vertices of an unbroken mesh are written bit for bit the
  same by every cell that shares them, while the two copies of a vertex
  split by a crack move apart.
- Cracks in green: the crack faces ndda writes beside each frame
  (cracks-NNNNN.txt: every crack face, pre-existing or new, on the present
  geometry), which shows fresh cracks whose faces still touch. For runs
  without those files (older ndda): the outline edges of a frame that
  were not outline edges before the first crack (in the first frame, or in any frame
  before the statistics file's 'Cracked edges' becomes non-zero: the
  faces of a pre-existing crack coincide in the first frame and move
  apart under load). They are matched by their midpoints in the reference
  configuration (position minus displacement, the same on both faces of a
  crack), within 2 % of the median outline edge length; this survives
  large motions of the blocks. Limits: a crack whose faces still touch to
  the last bit of float32 (usually the first step or two after it forms,
  or a closed crack under compression) cannot be told from unbroken
  material in the VTU file, and a pre-existing crack that stays closed
  until the first new crack is drawn green once it opens; the title gives
  the statistics file's 'Cracked edges' count so that the count is never
  missed.

--initial-cracks draws the scene's pre-existing cracks ('Cracks' of the
blocks in parameters.prm) on the frames at t = 0, where their faces still
coincide.

--stretch S draws y S times larger than x, for a thin bar along x (the
title says so); --xlim/--ylim zoom in.

--auto picks the first frame, the first frame with a crack (the first
output at or after the first step with 'Cracked edges' > 0 in the
statistics file; without that column, the first frame whose outline has
new edges), the frame of the propagation whose crack count is closest to
halfway between that first crack and the end, and the last frame. A scene
without cracks gets the first, middle and last frames.
"""

import argparse
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ndda_output  # noqa: E402

# VTK cell types whose first three vertices are a triangle's corners:
# triangle, quadratic triangle, Lagrange triangle.
TRIANGLE_TYPES = (5, 22, 69)

PRINCIPAL = "principal"
CRACK_COLOUR = "#00a000"
INITIAL_CRACK_COLOUR = "#8b00c0"


# ----------------------------------------------------------------- frames
class Frame:
    """One VTU file reduced to what a picture needs."""

    def __init__(self, path, time, field):
        data = ndda_output.read_vtu(path)
        self.path = path
        self.time = time
        self.triangles = triangle_corners(data, path)
        self.pieces = drawing_triangles(data, self.triangles)
        self.xy = data.points[:, :2]
        self.values, self.label, self.scale, self.diverging = field_values(
            data, field, path
        )
        self.block = block_ids(data, len(self.xy))
        displacement = data.point_data.get("displacement")
        self.reference = (
            self.xy - displacement[:, :2] if displacement is not None else self.xy
        )
        self.outline = outline_edges(data.points, self.triangles, self.block)


def triangle_corners(data, path):
    """Corner point indices (n_triangles x 3) of the triangular cells."""
    starts = np.concatenate(([0], data.offsets[:-1]))
    keep = np.isin(data.types, TRIANGLE_TYPES)
    if not keep.any():
        raise ndda_output.OutputError(
            f"{path}: no triangular cells (VTK types {sorted(set(data.types))})"
        )
    starts = starts[keep]
    return np.stack([data.connectivity[starts + i] for i in range(3)], axis=1)


# A VTK quadratic triangle (corners 0 1 2, then the midpoints of 0-1, 1-2,
# 2-0) cut into four triangles, so that all six values are drawn.
QUADRATIC_PIECES = ((0, 3, 5), (3, 1, 4), (5, 4, 2), (3, 4, 5))


def drawing_triangles(data, corners):
    """The triangles to colour: P1 cells as they are, quadratic (P2) cells
    in four pieces; other cells by their corners."""
    starts = np.concatenate(([0], data.offsets[:-1]))
    types = data.types[np.isin(data.types, TRIANGLE_TYPES)]
    starts = starts[np.isin(data.types, TRIANGLE_TYPES)]
    quadratic = starts[types == 22]
    pieces = [corners[types != 22]]
    for piece in QUADRATIC_PIECES:
        pieces.append(np.stack([data.connectivity[quadratic + i] for i in piece], axis=1))
    return np.concatenate(pieces)


def block_ids(data, n_points):
    if "block_id" in data.point_data:
        return np.rint(data.point_data["block_id"]).astype(np.int64)
    return np.zeros(n_points, dtype=np.int64)


def field_values(data, field, path):
    """Point values of a field: (values, colour bar label, scale, diverging)."""
    fields = dict(data.point_data)
    if field == PRINCIPAL:
        for name in ("principal_stress_1", "principal_stress_2"):
            if name not in fields:
                raise ndda_output.OutputError(
                    f"{path}: no point field '{name}' for --field {PRINCIPAL}"
                )
        s1 = fields["principal_stress_1"].astype(float)
        s2 = fields["principal_stress_2"].astype(float)
        values = np.where(np.abs(s1) >= np.abs(s2), s1, s2)
        return (
            values * 1e-6,
            "principal stress of larger magnitude (MPa)",
            1e-6,
            True,
        )
    if field not in fields:
        if field in data.cell_data:
            raise ndda_output.OutputError(
                f"{path}: '{field}' is cell data; only point fields are drawn"
            )
        raise ndda_output.OutputError(
            f"{path}: no point field '{field}'; there are: "
            + ", ".join([PRINCIPAL] + list(fields))
        )
    values = fields[field].astype(float)
    if values.ndim == 2:
        values = np.linalg.norm(values, axis=1)
        name = f"|{field}|"
    else:
        name = field
    if "stress" in field:
        return values * 1e-6, f"{name} (MPa)", 1e-6, True
    if field == "displacement":
        return values * 1e3, f"{name} (mm)", 1e3, False
    if field == "velocity":
        return values, f"{name} (m/s)", 1.0, False
    return values, name, 1.0, False


def vertex_keys(points, block):
    """One integer id per distinct (block, float32 x, float32 y)."""
    bits = points[:, :2].astype(np.float32).view(np.uint32).astype(np.int64)
    rows = np.column_stack((block, bits))
    _, ids = np.unique(rows, axis=0, return_inverse=True)
    return ids.reshape(-1)


def outline_edges(points, triangles, block):
    """Point index pairs of the edges that belong to one triangle only."""
    ids = vertex_keys(points, block)
    local = np.concatenate(
        [triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]
    )
    keys = np.sort(ids[local], axis=1)
    _, inverse, counts = np.unique(
        keys, axis=0, return_inverse=True, return_counts=True
    )
    return local[counts[inverse.reshape(-1)] == 1]


class EdgeSet:
    """Midpoints of edges in the reference configuration, found again by
    position within a tolerance (a hash grid of cells of that size)."""

    def __init__(self, frames, tolerance):
        self.tolerance = tolerance
        self.cells = set()
        for frame in frames:
            for i, j in self._bins(frame, frame.outline):
                for di in (-1, 0, 1):
                    for dj in (-1, 0, 1):
                        self.cells.add((i + di, j + dj))

    def _bins(self, frame, edges):
        middle = 0.5 * (frame.reference[edges[:, 0]] + frame.reference[edges[:, 1]])
        return [tuple(b) for b in np.floor(middle / self.tolerance).astype(np.int64)]

    def new_edges(self, frame):
        """The outline edges of frame that are not in this set."""
        is_new = [b not in self.cells for b in self._bins(frame, frame.outline)]
        return frame.outline[np.array(is_new, dtype=bool)]


# ---------------------------------------------------------- run metadata
def cracked_edges(directory):
    """(times, 'Cracked edges') from the statistics file, or None."""
    path = os.path.join(directory, "statistics")
    if not os.path.exists(path):
        return None
    table = ndda_output.read_table(path)
    if "Cracked edges" not in table or "Time (s)" not in table:
        return None
    return table["Time (s)"], table["Cracked edges"]


def count_at(history, time):
    """The statistics' count at the last step at or before time."""
    times, counts = history
    index = np.searchsorted(times, time * (1 + 1e-9) + 1e-15, side="right") - 1
    return int(counts[index]) if index >= 0 else 0


# ------------------------------------------------------------- selection
def closest_frame(frames, time):
    return int(np.argmin([abs(t - time) for t, _ in frames]))


def auto_selection(frames, history, outline_growth):
    """[(label, frame index)] for --auto, each frame once."""
    last = len(frames) - 1
    times = np.array([t for t, _ in frames])
    if history is not None:
        counts = np.array([count_at(history, t) for t in times])
    else:
        counts = outline_growth()
    cracked = np.nonzero(counts > 0)[0]
    if len(cracked) == 0:
        print("plot_frames: no crack in this run; --auto draws start, middle, end")
        chosen = [("start", 0), ("middle", last // 2), ("end", last)]
    else:
        first = int(cracked[0])
        halfway = 0.5 * (counts[first] + counts[last])
        later = np.arange(first, last + 1)
        middle = int(later[np.argmin(np.abs(counts[later] - halfway))])
        chosen = [
            ("start", 0),
            ("first_crack", first),
            ("propagation", middle),
            ("end", last),
        ]
    unique = []
    for label, index in chosen:
        if index not in [i for _, i in unique]:
            unique.append((label, index))
    return unique


def initial_cracks(directory):
    """The pre-existing cracks of the scene: every 'Geometry/<block>/Cracks'
    entry of the run's parameters.prm ('x0, y0, x1, y1; ...'), as an
    array of segments (n x 2 x 2, m)."""
    parameters = ndda_output.read_parameters(directory)
    segments = []
    for key, value in parameters.items():
        if key.startswith("Geometry/") and key.endswith("/Cracks") and value.strip():
            for text in value.split(";"):
                numbers = [float(v) for v in text.split(",")]
                if len(numbers) != 4:
                    raise ndda_output.OutputError(
                        f"{directory}/parameters.prm: '{key}' has a crack "
                        f"'{text.strip()}', not 'x0, y0, x1, y1'"
                    )
                segments.append(np.reshape(numbers, (2, 2)))
    return np.array(segments).reshape(-1, 2, 2)


# --------------------------------------------------------------- drawing
def crack_segments(frame):
    """The crack faces ndda wrote next to this frame (cracks-NNNNN.txt
    beside solution-NNNNN.vtu, x1 y1 x2 y2 in m on the present geometry),
    as an array of shape (n, 2, 2); None if the run wrote none (no crack
    yet, or an ndda older than the file)."""
    name = os.path.basename(frame.path)
    match = re.fullmatch(r"solution-(\d+)\.vtu", name)
    if not match:
        return None
    path = os.path.join(os.path.dirname(frame.path), f"cracks-{match.group(1)}.txt")
    if not os.path.exists(path):
        return None
    try:
        data = np.loadtxt(path, ndmin=2)
    except ValueError as error:
        raise ndda_output.OutputError(f"{path}: {error}")
    if data.size == 0:
        return np.zeros((0, 2, 2))
    if data.shape[1] != 4:
        raise ndda_output.OutputError(f"{path}: expected 4 columns, got {data.shape[1]}")
    return data.reshape(-1, 2, 2)


def draw(frame, args, scene, limits, box, new_edges, n_cracked, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.tri import Triangulation

    x, y = frame.xy[:, 0] * 1e3, frame.xy[:, 1] * 1e3
    (x0, x1), (y0, y1) = box
    width, height = x1 - x0, y1 - y0
    figure, axes, bar_axes, wide = layout(plt, width, height * args.stretch, args)
    triangulation = Triangulation(x, y, frame.pieces)
    cell_values = frame.values[frame.pieces]
    vmin, vmax = limits
    cmap = plt.get_cmap(
        args.cmap if frame.diverging else "viridis", args.levels or None
    )
    span = np.ptp(cell_values, axis=1)
    if np.all(span <= 1e-6 * max(abs(vmin), abs(vmax), 1e-30)):
        mesh = axes.tripcolor(
            triangulation,
            facecolors=cell_values[:, 0],
            cmap=cmap,
            vmin=vmin,
            vmax=vmax,
            edgecolors="none",
            antialiased=False,  # no light seams between the cells
        )
    else:
        mesh = axes.tripcolor(
            triangulation, frame.values, shading="gouraud", cmap=cmap, vmin=vmin, vmax=vmax
        )
    if args.mesh:
        axes.triplot(triangulation, color="0.6", linewidth=0.2)

    def segments(edges):
        return np.stack((frame.xy[edges[:, 0]], frame.xy[edges[:, 1]]), axis=1) * 1e3

    axes.add_collection(
        LineCollection(
            segments(frame.outline), colors="black", linewidths=1.0, zorder=3
        )
    )
    # The crack faces: from ndda's cracks file when there is one (it shows
    # fresh cracks whose faces still touch), else the outline edges that
    # are new since the start.
    faces = crack_segments(frame)
    if faces is not None and len(faces):
        axes.add_collection(
            LineCollection(faces * 1e3, colors=CRACK_COLOUR, linewidths=1.6, zorder=4)
        )
    elif faces is None and len(new_edges):
        axes.add_collection(
            LineCollection(
                segments(new_edges), colors=CRACK_COLOUR, linewidths=1.6, zorder=4
            )
        )

    if args.initial_cracks and frame.time <= 0:
        cracks = initial_cracks(args.directory)
        if len(cracks):
            axes.add_collection(
                LineCollection(
                    cracks * 1e3, colors=INITIAL_CRACK_COLOUR, linewidths=1.6, zorder=5
                )
            )
    axes.set_aspect(args.stretch)
    axes.set_xlim(x0, x1)
    axes.set_ylim(y0, y1)
    axes.set_xlabel("x (mm)")
    axes.set_ylabel("y (mm)")
    title = f"{scene}, t = {frame.time * 1e3:.4g} ms"
    if args.stretch != 1:
        title += f", y drawn {args.stretch:g} times larger than x"
    if n_cracked is not None:
        title += f", {n_cracked} cracked edges"
    if len(new_edges) or (faces is not None and len(faces)):
        title += "\nblack: block outlines, green: crack faces"
    elif args.initial_cracks and frame.time <= 0 and len(initial_cracks(args.directory)):
        title += "\npurple: pre-existing cracks"
    axes.set_title(title, fontsize=10)
    low, high = np.min(frame.values), np.max(frame.values)
    extend = {(False, False): "neither", (True, False): "min", (False, True): "max"}
    bar = figure.colorbar(
        mesh,
        cax=bar_axes,
        orientation="horizontal" if wide else "vertical",
        extend=extend.get((low < vmin, high > vmax), "both"),
    )
    bar.set_label(frame.label)
    save_png(figure, path, args)
    plt.close(figure)


def layout(plt, width, height, args):
    """A figure --size inches wide whose plot has equal scales for a
    width x height (mm) box, the colour bar beside it (below it for a wide
    box), fixed margins in inches for the labels. Returns the figure, the
    plot's and the colour bar's axes, and whether the bar is below."""
    wide = width > 1.6 * height
    left, right, top = 0.85, 0.25, 0.55
    bottom = 1.1 if wide else 0.55
    if not wide:
        right += 1.05  # the bar and its label
    plot_width = args.size - left - right
    plot_height = plot_width * height / width
    highest = 1.4 * args.size - top - bottom
    if plot_height > highest:
        plot_width, plot_height = highest * width / height, highest
    figure_height = bottom + plot_height + top
    figure = plt.figure(figsize=(args.size, figure_height), dpi=args.dpi)
    # Centre a plot narrower than its room (a tall box).
    left += 0.5 * (args.size - left - right - plot_width)

    def box(x, y, w, h):
        return [x / args.size, y / figure_height, w / args.size, h / figure_height]

    axes = figure.add_axes(box(left, bottom, plot_width, plot_height))
    if wide:
        bar_width = 0.8 * plot_width
        bar_axes = figure.add_axes(
            box(left + 0.1 * plot_width, 0.42, bar_width, 0.14)
        )
    else:
        bar_axes = figure.add_axes(
            box(left + plot_width + 0.2, bottom, 0.16, plot_height)
        )
    return figure, axes, bar_axes, wide


def save_png(figure, path, args):
    """Save the figure; as an 8-bit palette PNG unless --full-colour
    (a third of the size; with --levels colours the cells lose nothing)."""
    try:
        from PIL import Image
    except ImportError:
        Image = None
    if args.full_colour or Image is None:
        figure.savefig(path, dpi=args.dpi)
        return
    figure.canvas.draw()
    image = Image.frombuffer(
        "RGBA", figure.canvas.get_width_height(), figure.canvas.buffer_rgba()
    ).convert("RGB")
    image = image.quantize(
        colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE
    )
    image.save(path, optimize=True, dpi=(args.dpi, args.dpi))


def bounding_box(frames, args):
    """Axis limits in mm: --xlim/--ylim, else all frames' points plus a
    margin (3 % of the geometric mean of the two extents)."""
    lows = np.min([f.xy.min(axis=0) for f in frames], axis=0) * 1e3
    highs = np.max([f.xy.max(axis=0) for f in frames], axis=0) * 1e3
    given = (args.xlim, args.ylim)
    box = [given[i] if given[i] is not None else (lows[i], highs[i]) for i in range(2)]
    extents = [high - low for low, high in box]
    margin = 0.03 * np.sqrt(max(extents[0], 1e-9) * max(extents[1], 1e-9))
    for i in range(2):
        if given[i] is None:
            box[i] = (box[i][0] - margin, box[i][1] + margin)
    return box


def parse_range(text):
    try:
        low, high = (float(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not 'low,high' in mm")
    if not low < high:
        raise argparse.ArgumentTypeError(f"'{text}': low must be below high")
    return (low, high)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="See the top of this file for what the pictures show.",
    )
    parser.add_argument("directory", help="ndda output directory (holds solution.pvd)")
    choice = parser.add_mutually_exclusive_group(required=True)
    choice.add_argument(
        "--times",
        help="comma-separated times; the frame closest to each is drawn "
        "(seconds, or with a unit: 2.1ms, 210us)",
    )
    choice.add_argument(
        "--auto",
        action="store_true",
        help="draw the start, the first crack, the propagation and the end",
    )
    parser.add_argument(
        "--out", required=True, help="prefix of the PNG files (PREFIX_....png)"
    )
    parser.add_argument(
        "--names",
        help="with --times: comma-separated names of the frames, one per "
        "time (PREFIX_NAME.png instead of PREFIX_NNNNN.png)",
    )
    parser.add_argument(
        "--field",
        default=PRINCIPAL,
        help="point field to colour the cells by: 'principal' (default: the "
        "principal stress of larger magnitude), stress_xx, stress_yy, "
        "stress_xy, principal_stress_1, principal_stress_2, or a vector "
        "field (displacement, velocity: its magnitude)",
    )
    parser.add_argument(
        "--limit",
        type=float,
        help="colour scale limit in the field's unit (MPa for stresses): "
        "-LIMIT..LIMIT; default from --percentile over all frames",
    )
    parser.add_argument(
        "--percentile",
        type=float,
        default=95.0,
        help="percentile of |value| per frame whose largest value over all "
        "frames sets the colour scale (default 95)",
    )
    parser.add_argument("--xlim", type=parse_range, help="x range in mm: low,high")
    parser.add_argument("--ylim", type=parse_range, help="y range in mm: low,high")
    parser.add_argument(
        "--stretch",
        type=float,
        default=1.0,
        help="draw y this many times larger than x (a thin bar: 10); "
        "default 1, equal scales",
    )
    parser.add_argument(
        "--mesh", action="store_true", help="also draw the cells' edges in grey"
    )
    parser.add_argument(
        "--initial-cracks",
        action="store_true",
        help="on frames at t = 0, draw the pre-existing cracks of the scene "
        "(Geometry/*/Cracks in parameters.prm) in purple: their faces "
        "coincide, the outline cannot show them",
    )
    parser.add_argument(
        "--cmap", default="RdBu_r", help="diverging colour map (default RdBu_r)"
    )
    parser.add_argument(
        "--levels",
        type=int,
        default=21,
        help="number of colours of the colour map (default 21: bands easy "
        "to read off, an odd number so that zero is white; 0: continuous)",
    )
    parser.add_argument(
        "--full-colour",
        action="store_true",
        help="write 24-bit PNGs (default: 8-bit palette, a third of the size)",
    )
    parser.add_argument("--dpi", type=int, default=120, help="resolution (default 120)")
    parser.add_argument(
        "--size", type=float, default=6.0, help="figure width in inches (default 6)"
    )
    args = parser.parse_args()
    if not args.stretch > 0:
        parser.error(f"--stretch {args.stretch}: must be positive")
    if not 0 < args.percentile <= 100:
        parser.error(f"--percentile {args.percentile}: must be in (0, 100]")
    try:
        times = [ndda_output.parse_time(t) for t in (args.times or "").split(",") if t]
    except ValueError as error:
        parser.error(f"--times: {error}")
    names = [n.strip() for n in args.names.split(",")] if args.names else None
    if names is not None and (args.auto or len(names) != len(times)):
        parser.error("--names needs --times and one name per time")

    try:
        pvd = os.path.join(args.directory, "solution.pvd")
        files = ndda_output.read_pvd(pvd)
        history = cracked_edges(args.directory)
        scene = ndda_output.scene_name(args.directory)

        # Every frame is read once: the colour scale and the axis limits
        # are the same for all pictures of a scene.
        frames = [Frame(path, time, args.field) for time, path in files]
        # What was an outline before the first crack is no crack: frame 0
        # and every frame before the statistics count a cracked edge (by
        # then the faces of pre-existing cracks have usually moved apart).
        uncracked = [
            f for f in frames if history is not None and count_at(history, f.time) == 0
        ]
        reference = EdgeSet(
            [frames[0]] + uncracked, 0.02 * median_edge_length(frames[0])
        )
        new_edges = [reference.new_edges(frame) for frame in frames]

        if args.auto:
            chosen = auto_selection(
                files, history, lambda: np.array([len(e) for e in new_edges])
            )
        else:
            chosen = []
            for k, time in enumerate(times):
                index = closest_frame(files, time)
                chosen.append((names[k] if names else f"{index:05d}", index))

        limits = colour_limits(frames, args)
        box = bounding_box(frames, args)
        for label, index in chosen:
            frame = frames[index]
            path = f"{args.out}_{label}.png"
            n_cracked = count_at(history, frame.time) if history is not None else None
            draw(frame, args, scene, limits, box, new_edges[index], n_cracked, path)
            print(f"{path}: t = {frame.time * 1e3:.6g} ms ({os.path.basename(frame.path)})")
    except ndda_output.OutputError as error:
        sys.exit(f"plot_frames: {error}")


def median_edge_length(frame):
    edges = frame.outline
    lengths = np.linalg.norm(
        frame.reference[edges[:, 0]] - frame.reference[edges[:, 1]], axis=1
    )
    return float(np.median(lengths))


def colour_limits(frames, args):
    if frames[0].diverging:
        if args.limit is not None:
            return (-abs(args.limit), abs(args.limit))
        limit = max(np.percentile(np.abs(f.values), args.percentile) for f in frames)
        limit = limit if limit > 0 else 1.0
        return (-limit, limit)
    low = min(f.values.min() for f in frames)
    high = max(f.values.max() for f in frames)
    if args.limit is not None:
        high = args.limit
    return (low, high if high > low else low + 1.0)


if __name__ == "__main__":
    main()
