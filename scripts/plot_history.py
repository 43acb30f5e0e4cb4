#!/usr/bin/python3
"""Plot time histories of an ndda run: measure points and statistics
columns against time, optionally with an analytical curve.

Reads an ndda output directory: measure_points.txt (columns named as in
its header, 'point 0 sigma_xx', 'point 1 u_y', ...) and the 'statistics'
file (columns by their names, 'Kinetic energy (J)', 'Cracked edges', ...),
and parameters.prm for the scene name. Writes one PNG (--out). Columns
with the same unit share a panel, one panel per unit, time in ms on the
shared horizontal axis; stresses are drawn in MPa, displacements and
lengths in mm, angles in degrees, the rest in the file's units.

--reference-expr EXPR adds a curve: a Python expression in t (time in s,
a numpy array) with numpy as np and its functions (pi, sin, exp, sqrt,
where, minimum, ...) at hand, giving a value in the SI unit of the column
it goes with (the first --column, or --reference-column), e.g. Pa for a
stress. The script prints the largest difference between the reference
and that column in the plotted time range.

Run it with Debian's Python (python3-numpy, python3-matplotlib):

    /usr/bin/python3 scripts/plot_history.py output/brazilian_disc \\
        --column "point 0 sigma_xx" --column "point 1 sigma_xx" \\
        --reference-expr "where(t < 2.09e-3, 12e6 * t / 2.09e-3, nan)" \\
        --reference-label "linear rise to T" --out /tmp/disc_history.png
    /usr/bin/python3 scripts/plot_history.py output/brazilian_disc --list
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ndda_output  # noqa: E402

TABLES = ("measure_points.txt", "statistics")
TIME_COLUMNS = ("time", "Time (s)")


class Column:
    """One column against time, with its unit and the scale to draw it."""

    def __init__(self, name, table_path, time, values, si_unit):
        self.name = name
        self.table_path = table_path
        self.time = time
        self.values = values
        self.si_unit = si_unit
        self.unit, self.scale = display_unit(si_unit)


def display_unit(si_unit):
    """(unit drawn, factor from SI): MPa for Pa, mm for m, deg for rad."""
    return {"Pa": ("MPa", 1e-6), "m": ("mm", 1e3), "rad": ("deg", 180 / np.pi)}.get(
        si_unit, (si_unit, 1.0)
    )


def axis_label(unit):
    """'stress (MPa)' etc.: the quantity a unit stands for, with the unit."""
    quantities = {
        "MPa": "stress",
        "mm": "displacement, length",
        "m/s": "velocity",
        "J": "energy",
        "s": "time",
        "N/m": "stiffness",
        "deg": "angle",
    }
    if not unit:
        return "count"
    return f"{quantities[unit]} ({unit})" if unit in quantities else f"({unit})"


def measure_point_unit(quantity):
    """SI unit of a measure point quantity (u_x, v_y, sigma_xy, ...)."""
    for prefix, unit in (("u_", "m"), ("v_", "m/s"), ("sigma_", "Pa")):
        if quantity.startswith(prefix):
            return unit
    return ""


def statistics_unit(name):
    """SI unit of a statistics column: what its name gives in brackets."""
    if name.endswith(")") and "(" in name:
        return name[name.rindex("(") + 1 : -1]
    return ""


def load_columns(directory):
    """Every column of the run's tables: {name: Column}; the tables read."""
    columns = {}
    found = []
    for table_name in TABLES:
        path = os.path.join(directory, table_name)
        if not os.path.exists(path):
            continue
        table = ndda_output.read_table(path)
        time_name = next((n for n in TIME_COLUMNS if n in table), None)
        if time_name is None:
            raise ndda_output.OutputError(
                f"{path}: no time column ({' or '.join(TIME_COLUMNS)})"
            )
        found.append(path)
        positions = (
            ndda_output.measure_point_positions(path)
            if table_name == "measure_points.txt"
            else {}
        )
        for name, values in table.items():
            if name == time_name:
                continue
            if name.startswith("point "):
                index, quantity = name.split()[1:3]
                unit = measure_point_unit(quantity)
                where = positions.get(int(index))
                label = name
                if where is not None:
                    label += f" at ({where[0] * 1e3:g}, {where[1] * 1e3:g}) mm"
            else:
                unit = statistics_unit(name)
                label = name
            column = Column(name, path, table[time_name], values, unit)
            column.label = label
            columns[name] = column
    if not found:
        raise ndda_output.OutputError(
            f"{directory}: neither {' nor '.join(TABLES)} found"
        )
    return columns


def add_derived(columns, specification, directory):
    """Add the column 'NAME|UNIT|EXPR' (see the top of the file)."""
    parts = specification.split("|", 2)
    if len(parts) != 3 or not parts[0].strip():
        raise ndda_output.OutputError(
            f"--derived '{specification}': expected 'NAME|UNIT|EXPR'"
        )
    name, unit, expression = (part.strip() for part in parts)
    used = []

    def col(wanted):
        column = find_column(columns, wanted, directory)
        if used and len(column.time) != len(used[0].time):
            raise ndda_output.OutputError(
                f"--derived '{name}': '{wanted}' and '{used[0].name}' come "
                f"from tables with different rows"
            )
        used.append(column)
        return column.values

    namespace = {n: getattr(np, n) for n in dir(np) if not n.startswith("_")}
    namespace.update(np=np, numpy=np, col=col)
    # t: the time of the first table read (measure_points.txt if there is
    # one); the columns of the expression must come from that table.
    namespace["t"] = next(iter(columns.values())).time
    try:
        values = eval(expression, {"__builtins__": {}}, namespace)
    except ndda_output.OutputError:
        raise
    except Exception as error:  # the user's expression: say what failed
        raise ndda_output.OutputError(
            f"--derived '{name}': cannot evaluate '{expression}': "
            f"{type(error).__name__}: {error}"
        )
    if not used:
        raise ndda_output.OutputError(
            f"--derived '{name}': the expression uses no col('...')"
        )
    base = used[0]
    values = np.broadcast_to(np.asarray(values, dtype=float), base.time.shape)
    column = Column(name, base.table_path, base.time, values, unit)
    column.label = name
    columns[name] = column


def find_column(columns, wanted, directory):
    """The column named wanted: exactly, else ignoring case and spaces."""
    if wanted in columns:
        return columns[wanted]

    def simple(text):
        return "".join(text.lower().split())

    matches = [c for n, c in columns.items() if simple(n) == simple(wanted)]
    if len(matches) == 1:
        return matches[0]
    close = [n for n in columns if simple(wanted) in simple(n)]
    hint = close if close else list(columns)
    raise ndda_output.OutputError(
        f"{directory}: no column '{wanted}' in {' or '.join(TABLES)}; "
        f"{'similar' if close else 'there are'}: " + ", ".join(f"'{n}'" for n in hint)
    )


def evaluate(expression, t):
    """The reference expression at times t (s), as an array like t."""
    namespace = {name: getattr(np, name) for name in dir(np) if not name.startswith("_")}
    namespace.update(np=np, numpy=np, t=t)
    try:
        values = eval(expression, {"__builtins__": {}}, namespace)
        values = np.broadcast_to(np.asarray(values, dtype=float), t.shape)
    except Exception as error:  # the user's expression: say what failed
        raise ndda_output.OutputError(
            f"--reference-expr '{expression}': cannot evaluate it for t in s: "
            f"{type(error).__name__}: {error}"
        )
    return values


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        epilog="See the top of this file for the column names and units.",
    )
    parser.add_argument(
        "directory", help="ndda output directory (measure_points.txt, statistics)"
    )
    parser.add_argument(
        "--column",
        action="append",
        default=[],
        help="a column to plot (repeat for more): 'point 0 sigma_xx', "
        "'Kinetic energy (J)', ...; --list shows them",
    )
    parser.add_argument(
        "--list", action="store_true", help="list the columns of the run and stop"
    )
    parser.add_argument(
        "--reference-expr",
        action="append",
        default=[],
        help="analytical curve: a Python expression in t (s) with numpy's "
        "functions, in the SI unit of the reference column (repeatable)",
    )
    parser.add_argument(
        "--reference-label",
        action="append",
        default=[],
        help="legend text of each --reference-expr (default: the expression)",
    )
    parser.add_argument(
        "--reference-column",
        action="append",
        default=[],
        help="the column the references go with (axis, unit, printed "
        "difference); default the first --column; once per "
        "--reference-expr to pair them one by one",
    )
    parser.add_argument(
        "--derived",
        action="append",
        default=[],
        help="a computed column 'NAME|UNIT|EXPR', EXPR in t and "
        "col('column name') (see the top of the file)",
    )
    parser.add_argument(
        "--mark-first-crack",
        action="store_true",
        help="a dotted line at the first crack (statistics: 'Cracked edges')",
    )
    parser.add_argument("--tmin", help="start of the time range (s, or 2.1ms, 210us)")
    parser.add_argument("--tmax", help="end of the time range (s, or 2.1ms, 210us)")
    parser.add_argument("--title", help="title (default: the scene name)")
    parser.add_argument("--out", help="PNG file to write (needed unless --list)")
    parser.add_argument("--dpi", type=int, default=120, help="resolution (default 120)")
    args = parser.parse_args()

    try:
        t_min = ndda_output.parse_time(args.tmin) if args.tmin else -np.inf
        t_max = ndda_output.parse_time(args.tmax) if args.tmax else np.inf
    except ValueError as error:
        parser.error(f"--tmin/--tmax: {error}")
    if len(args.reference_label) > len(args.reference_expr):
        parser.error("more --reference-label than --reference-expr")
    if len(args.reference_column) not in (0, 1, len(args.reference_expr)):
        parser.error(
            f"{len(args.reference_column)} --reference-column for "
            f"{len(args.reference_expr)} --reference-expr: give one, or one each"
        )

    try:
        columns = load_columns(args.directory)
        for specification in args.derived:
            add_derived(columns, specification, args.directory)
        if args.list:
            for column in columns.values():
                unit = f" [{column.si_unit}]" if column.si_unit else ""
                print(f"{column.name}{unit}  ({os.path.basename(column.table_path)})")
            return
        if not args.column:
            parser.error("give at least one --column (--list shows them)")
        if not args.out:
            parser.error("--out FILE.png is needed")
        chosen = [find_column(columns, name, args.directory) for name in args.column]
        names = args.reference_column or [chosen[0].name]
        if len(names) == 1:
            names = names * len(args.reference_expr)
        reference_columns = [find_column(columns, n, args.directory) for n in names]
        for column in reference_columns:
            if column not in chosen:
                chosen.append(column)
        crack = (
            ndda_output.first_crack_time(args.directory)
            if args.mark_first_crack
            else None
        )
        if args.mark_first_crack and crack is None:
            print("plot_history: no crack in this run; nothing to mark")
        plot(args, chosen, reference_columns, t_min, t_max, crack)
    except ndda_output.OutputError as error:
        sys.exit(f"plot_history: {error}")


def plot(args, chosen, reference_columns, t_min, t_max, crack=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    units = []
    for column in chosen:
        if column.unit not in units:
            units.append(column.unit)
    figure, panels = plt.subplots(
        len(units),
        1,
        sharex=True,
        squeeze=False,
        figsize=(7, 2.2 + 2.4 * len(units)),
        dpi=args.dpi,
        layout="constrained",
    )
    panels = panels[:, 0]
    low, high = np.inf, -np.inf
    for column in chosen:
        keep = (column.time >= t_min) & (column.time <= t_max)
        if not keep.any():
            raise ndda_output.OutputError(
                f"{column.table_path}: no rows of '{column.name}' between "
                f"{t_min} s and {t_max} s"
            )
        axes = panels[units.index(column.unit)]
        axes.plot(
            column.time[keep] * 1e3,
            column.values[keep] * column.scale,
            label=column.label,
            linewidth=1.4,
        )
        low = min(low, column.time[keep][0])
        high = max(high, column.time[keep][-1])

    if args.reference_expr:
        t = np.linspace(low, high, 2000)
        styles = ["--", ":", "-."]
        per_panel = {}
        for i, expression in enumerate(args.reference_expr):
            reference_column = reference_columns[i]
            axes = panels[units.index(reference_column.unit)]
            style = styles[per_panel.setdefault(reference_column.unit, 0) % len(styles)]
            per_panel[reference_column.unit] += 1
            label = (
                args.reference_label[i]
                if i < len(args.reference_label)
                else f"reference: {expression}"
            )
            axes.plot(
                t * 1e3,
                evaluate(expression, t) * reference_column.scale,
                style,
                color="black",
                linewidth=1.2,
                label=label,
            )
            report_difference(expression, reference_column, low, high)

    if crack is not None and low <= crack <= high:
        for i, axes in enumerate(panels):
            axes.axvline(
                crack * 1e3,
                color="tab:red",
                linestyle=":",
                linewidth=1.2,
                label=f"first crack, {crack * 1e3:.4g} ms" if i == 0 else None,
            )
    for unit, axes in zip(units, panels):
        axes.set_ylabel(axis_label(unit))
        axes.grid(True, linewidth=0.4, alpha=0.5)
        axes.legend(fontsize=8, loc="best")
    panels[-1].set_xlabel("time (ms)")
    panels[0].set_title(args.title or ndda_output.scene_name(args.directory))
    figure.savefig(args.out, dpi=args.dpi)
    plt.close(figure)
    print(f"{args.out}: {', '.join(c.name for c in chosen)}")


def report_difference(expression, column, low, high):
    """Print the largest |column - reference| in [low, high] where the
    reference is finite (a reference may be nan outside its range)."""
    keep = (column.time >= low) & (column.time <= high)
    time, values = column.time[keep], column.values[keep]
    reference = evaluate(expression, time)
    finite = np.isfinite(reference)
    if not finite.any():
        print(f"reference '{expression}': not finite at any row of '{column.name}'")
        return
    difference = np.abs(values[finite] - reference[finite])
    worst = int(np.argmax(difference))
    size = np.max(np.abs(reference[finite]))
    relative = f" ({difference[worst] / size:.2%} of max |reference|)" if size > 0 else ""
    print(
        f"'{column.name}' - reference '{expression}': largest difference "
        f"{difference[worst] * column.scale:.4g} {column.unit} at "
        f"t = {time[finite][worst] * 1e3:.4g} ms{relative}"
    )


if __name__ == "__main__":
    main()
