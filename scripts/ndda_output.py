"""Readers for the files an ndda run writes into its output directory.

Used by plot_frames.py and plot_history.py (import it from the same
folder); needs only the Python standard library and numpy. Run it with
Debian's /usr/bin/python3 (python3-numpy).

- read_pvd(path): the (time, file) pairs of a ParaView collection
  (solution.pvd).
- read_vtu(path): a VTK XML UnstructuredGrid file as deal.II 9.4 writes it
  (format="binary": base64, zlib-compressed in blocks with a UInt32 or
  UInt64 header, or uncompressed; format="ascii" also works). Returns the
  points, the cells (connectivity, offsets, types) and every PointData and
  CellData array by name, as numpy arrays.
- read_table(path): ndda's column files: 'statistics' (a '# N: Name' line
  per column, then one row per step) and 'measure_points.txt' (one header
  line '# time  [point 0 at x y: u_x u_y ...]  [point 1 ...]', then one row
  per step). Returns an ordered dict column name -> numpy array; measure
  point columns are named as in the file's header, 'point 0 sigma_xx'
  etc.; measure_point_positions(path) gives each point's (x, y).
- scene_name(directory): 'Scene name' from the run's parameters.prm.
- read_prm_text(text), read_parameters(directory): the entries of a .prm
  text or of the run's parameters.prm as {'Materials/rock/Density': '2600'};
  points_of('x, y; x, y') the points of a polygon entry.
- first_crack_time(directory): the first time with 'Cracked edges' > 0 in
  the statistics file (None without a crack).
- cell_corners(vtu), cell_areas(vtu, corners), cell_block_ids(vtu,
  corners): the triangles of a VTU file, their areas on the mesh written
  (the deformed one) and their block ids.
- stress_resultant(vtu, cells, component, height, thickness): a force
  from cell stresses by the mean stress theorem (a specimen's axial load).
- plate_force(directory, name, times): a plate's load from its contact
  forces (the 'block forces' statistics columns), at the given times.
- parse_time(text): '2.1e-3' (s), '2.1ms' or '210us' in seconds.

Every error names the file and what is wrong with it.
"""

import base64
import collections
import os
import re
import xml.etree.ElementTree as ET
import zlib

import numpy as np


class OutputError(Exception):
    """A file of an ndda output directory that cannot be read."""


_VTK_TYPES = {
    "Int8": np.int8,
    "UInt8": np.uint8,
    "Int16": np.int16,
    "UInt16": np.uint16,
    "Int32": np.int32,
    "UInt32": np.uint32,
    "Int64": np.int64,
    "UInt64": np.uint64,
    "Float32": np.float32,
    "Float64": np.float64,
}


def read_pvd(path):
    """Return a list of (time in s, absolute path of the data file)."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as error:
        raise OutputError(f"{path}: cannot read the ParaView collection: {error}")
    frames = []
    for data_set in root.iter("DataSet"):
        try:
            time = float(data_set.get("timestep"))
            name = data_set.get("file")
        except (TypeError, ValueError):
            raise OutputError(
                f"{path}: a DataSet entry without a numeric 'timestep' and a 'file'"
            )
        frames.append((time, os.path.join(os.path.dirname(os.path.abspath(path)), name)))
    if not frames:
        raise OutputError(f"{path}: no DataSet entries (no frames written?)")
    frames.sort(key=lambda frame: frame[0])
    return frames


def _decode_binary(text, dtype, header_dtype, compressed, where):
    """Decode one format="binary" DataArray of a VTK XML file.

    deal.II base64-encodes the header and the data separately and writes
    the two strings one after the other; VTK itself may encode them
    together. Both are accepted.
    """
    text = "".join(text.split())
    header_size = np.dtype(header_dtype).itemsize

    def b64_length(n_bytes):
        return 4 * ((n_bytes + 2) // 3)

    try:
        if not compressed:
            # One header word (number of bytes), then the data.
            first = base64.b64decode(text[: b64_length(header_size)])
            n_bytes = int(np.frombuffer(first[:header_size], header_dtype)[0])
            rest = text[b64_length(header_size) :]
            data = base64.b64decode(rest) if rest else b""
            if len(data) != n_bytes:
                # Header and data encoded together.
                data = base64.b64decode(text)[header_size : header_size + n_bytes]
            return np.frombuffer(data, dtype)
        # Compressed: [n_blocks, block_size, last_block_size, sizes...].
        first = base64.b64decode(text[: b64_length(3 * header_size)])
        n_blocks = int(np.frombuffer(first[:header_size], header_dtype)[0])
        header_bytes = (3 + n_blocks) * header_size
        header_text = text[: b64_length(header_bytes)]
        header = np.frombuffer(
            base64.b64decode(header_text)[:header_bytes], header_dtype
        ).astype(np.int64)
        sizes = header[3:]
        payload_text = text[len(header_text) :]
        payload = base64.b64decode(payload_text) if payload_text else b""
        if len(payload) != int(sizes.sum()):
            payload = base64.b64decode(text)[header_bytes:]
        chunks = []
        position = 0
        for size in sizes:
            chunks.append(zlib.decompress(payload[position : position + size]))
            position += size
        return np.frombuffer(b"".join(chunks), dtype)
    except (ValueError, zlib.error, IndexError) as error:
        raise OutputError(f"{where}: cannot decode the binary data: {error}")


def _read_data_array(element, compressed, header_dtype, path):
    name = element.get("Name", "(unnamed)")
    where = f"{path}, DataArray '{name}'"
    type_name = element.get("type")
    if type_name not in _VTK_TYPES:
        raise OutputError(f"{where}: unknown type '{type_name}'")
    dtype = np.dtype(_VTK_TYPES[type_name]).newbyteorder("<")
    n_components = int(element.get("NumberOfComponents", "1"))
    data_format = element.get("format", "ascii")
    text = element.text or ""
    if data_format == "ascii":
        values = np.array(text.split(), dtype=dtype)
    elif data_format == "binary":
        values = _decode_binary(text, dtype, header_dtype, compressed, where)
    else:
        raise OutputError(
            f"{where}: format '{data_format}' is not supported (ascii or binary)"
        )
    if n_components > 1:
        if values.size % n_components:
            raise OutputError(
                f"{where}: {values.size} values are not a multiple of "
                f"{n_components} components"
            )
        values = values.reshape(-1, n_components)
    return values


VtuData = collections.namedtuple(
    "VtuData", "points connectivity offsets types point_data cell_data"
)


def read_vtu(path):
    """Read a VTK XML UnstructuredGrid (.vtu) file with one piece."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as error:
        raise OutputError(f"{path}: cannot read the VTU file: {error}")
    if root.get("type") != "UnstructuredGrid":
        raise OutputError(f"{path}: not an UnstructuredGrid VTK file")
    if root.get("byte_order", root.get("ByteOrder", "LittleEndian")) != "LittleEndian":
        raise OutputError(f"{path}: big-endian VTU files are not supported")
    compressor = root.get("compressor", "")
    if compressor not in ("", "vtkZLibDataCompressor"):
        raise OutputError(f"{path}: compressor '{compressor}' is not supported")
    header_dtype = np.dtype(_VTK_TYPES[root.get("header_type", "UInt32")]).newbyteorder("<")
    pieces = root.findall("./UnstructuredGrid/Piece")
    if len(pieces) != 1:
        raise OutputError(f"{path}: {len(pieces)} pieces; one is expected")
    piece = pieces[0]

    def arrays(tag):
        section = piece.find(tag)
        result = collections.OrderedDict()
        if section is not None:
            for element in section.findall("DataArray"):
                result[element.get("Name")] = _read_data_array(
                    element, bool(compressor), header_dtype, path
                )
        return result

    points_element = piece.find("./Points/DataArray")
    if points_element is None:
        raise OutputError(f"{path}: no Points")
    points = _read_data_array(points_element, bool(compressor), header_dtype, path)
    cells = arrays("Cells")
    for name in ("connectivity", "offsets", "types"):
        if name not in cells:
            raise OutputError(f"{path}: no Cells array '{name}'")
    n_points = int(piece.get("NumberOfPoints"))
    n_cells = int(piece.get("NumberOfCells"))
    if len(points) != n_points or len(cells["offsets"]) != n_cells:
        raise OutputError(
            f"{path}: {len(points)} points and {len(cells['offsets'])} cells "
            f"read, the Piece says {n_points} and {n_cells}"
        )
    return VtuData(
        points=points.astype(np.float64),
        connectivity=cells["connectivity"].astype(np.int64),
        offsets=cells["offsets"].astype(np.int64),
        types=cells["types"].astype(np.int64),
        point_data=arrays("PointData"),
        cell_data=arrays("CellData"),
    )


_POINT_GROUP = re.compile(r"\[point\s+(\d+)\s+at\s+([^:]*):\s*([^\]]*)\]")


def _column_names(path, comment_lines):
    """Column names from the comment lines at the top of an ndda table."""
    numbered = {}
    for line in comment_lines:
        match = re.match(r"#\s*(\d+):\s*(.*\S)", line)
        if match:
            numbered[int(match.group(1))] = match.group(2)
    if numbered:
        return [numbered[i] for i in sorted(numbered)]
    for line in comment_lines:
        groups = _POINT_GROUP.findall(line)
        if groups:
            names = [line.lstrip("#").split()[0]]
            for index, _, quantities in groups:
                names += [f"point {index} {q}" for q in quantities.split()]
            return names
    raise OutputError(
        f"{path}: no column names found (expected '# N: Name' lines or "
        f"a '# time [point 0 at x y: ...]' line)"
    )


def read_table(path):
    """Read ndda's 'statistics' or 'measure_points.txt'."""
    try:
        with open(path) as stream:
            lines = stream.read().splitlines()
    except OSError as error:
        raise OutputError(f"{path}: cannot read: {error}")
    comments = [line for line in lines if line.startswith("#")]
    names = _column_names(path, comments)
    rows = []
    for number, line in enumerate(lines, start=1):
        if not line.strip() or line.startswith("#"):
            continue
        try:
            row = [float(word) for word in line.split()]
        except ValueError:
            raise OutputError(f"{path}, line {number}: not a row of numbers")
        if len(row) != len(names):
            raise OutputError(
                f"{path}, line {number}: {len(row)} values, the header names "
                f"{len(names)} columns"
            )
        rows.append(row)
    data = np.array(rows, dtype=float).reshape(-1, len(names))
    return collections.OrderedDict((name, data[:, i]) for i, name in enumerate(names))


def measure_point_positions(path):
    """{index: (x, y) in m} from the header of measure_points.txt."""
    try:
        with open(path) as stream:
            header = stream.readline()
    except OSError as error:
        raise OutputError(f"{path}: cannot read: {error}")
    positions = {}
    for index, where, _ in _POINT_GROUP.findall(header):
        try:
            positions[int(index)] = tuple(float(v) for v in where.split()[:2])
        except ValueError:
            raise OutputError(f"{path}: point {index} has no position 'x y'")
    return positions


def scene_name(directory):
    """'Scene name' from the run's parameters.prm, else the folder's name."""
    path = os.path.join(directory, "parameters.prm")
    try:
        with open(path) as stream:
            for line in stream:
                match = re.match(r"\s*set\s+Scene name\s*=\s*([^#\s]+)", line)
                if match:
                    return match.group(1)
    except OSError:
        pass
    return os.path.basename(os.path.normpath(directory))


def parse_time(text):
    """'2.1e-3' (seconds), '2.1ms' or '210us' -> seconds."""
    match = re.fullmatch(r"\s*([-+0-9.eE]+)\s*(s|ms|us|µs)?\s*", text)
    factor = {None: 1.0, "s": 1.0, "ms": 1e-3, "us": 1e-6, "µs": 1e-6}
    try:
        return float(match.group(1)) * factor[match.group(2)]
    except (AttributeError, ValueError):
        raise ValueError(f"'{text}' is not a time (e.g. 2.1e-3, 2.1ms, 210us)")


def read_prm_text(text):
    """{'Materials/rock/Density': '2600', ...} from a .prm text (the last
    set of an entry wins, as in ndda)."""
    entries = {}
    stack = []
    text = re.sub(r"\\\s*\n", " ", text)  # continuation lines
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        match = re.match(r"subsection\s+(.*\S)", line)
        if match:
            stack.append(match.group(1))
            continue
        if line == "end":
            stack.pop()
            continue
        match = re.match(r"set\s+([^=]*\S)\s*=\s*(.*)", line)
        if match:
            entries["/".join(stack + [match.group(1)])] = match.group(2).strip()
    return entries


def read_parameters(directory):
    """The entries of the run's parameters.prm (read_prm_text)."""
    path = os.path.join(directory, "parameters.prm")
    try:
        with open(path) as stream:
            return read_prm_text(stream.read())
    except OSError as error:
        raise OutputError(f"{path}: cannot read: {error}")


def points_of(text):
    """'x, y; x, y' -> array of points."""
    return np.array([[float(v) for v in p.split(",")] for p in text.split(";")])


def first_crack_time(directory):
    """Time (s) of the first statistics row with 'Cracked edges' > 0, or
    None (no crack, or no such column)."""
    path = os.path.join(directory, "statistics")
    if not os.path.exists(path):
        return None
    table = read_table(path)
    if "Cracked edges" not in table or "Time (s)" not in table:
        return None
    cracked = np.nonzero(table["Cracked edges"] > 0)[0]
    return float(table["Time (s)"][cracked[0]]) if len(cracked) else None


def cell_corners(vtu):
    """Corner point indices (n_cells x 3) of the VTU file's cells (the
    first three vertices of each: the corners of a P1 or P2 triangle)."""
    starts = vtu.offsets - np.diff(np.concatenate([[0], vtu.offsets]))
    return np.stack([vtu.connectivity[starts + k] for k in range(3)], axis=1)


def cell_areas(vtu, corners):
    """Areas of the triangles (from their three corners, on the mesh as
    written: the deformed configuration)."""
    p = vtu.points
    a = p[corners[:, 1]] - p[corners[:, 0]]
    b = p[corners[:, 2]] - p[corners[:, 0]]
    return 0.5 * (a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])


def cell_block_ids(vtu, corners):
    """Block id of each cell (its first corner's 'block_id')."""
    return np.rint(vtu.point_data["block_id"][corners[:, 0]]).astype(int)


def stress_resultant(vtu, cells, component, height, thickness):
    """-t sum_c A_c sigma_c / h over the chosen cells (a boolean mask of
    cell_corners' rows): by the mean stress theorem the compressive force
    a body in equilibrium carries between two faces h apart, normal to
    them (component 'stress_yy' for faces y = const). The VTU's stress is
    the cell's mean stress, the same on every point of the cell (P1)."""
    corners = cell_corners(vtu)[cells]
    area = cell_areas(vtu, corners)
    stress = vtu.point_data[component][corners[:, 0]]
    return -thickness * np.sum(area * stress) / height


def plate_force(directory, name, times):
    """The load P (N) on plate block `name` at each of `times` (s): the
    vertical component of the contact forces on its nodes, compression
    positive, from the statistics columns '<name> contact force y (N)'
    that the 'block forces' postprocessor writes (Postprocess/block
    forces/Blocks; plate_force() of tests/plates.h). A row is taken at
    each time; every time must be a step's."""
    path = os.path.join(directory, "statistics")
    table = read_table(path)
    column = f"{name} contact force y (N)"
    if column not in table:
        raise OutputError(
            f"{path}: no column '{column}' (list the block in "
            "'Postprocess/block forces/Blocks')"
        )
    t = table["Time (s)"]
    rows = [int(np.argmin(np.abs(t - time))) for time in times]
    for row, time in zip(rows, times):
        if abs(t[row] - time) > 1e-9 * max(1.0, abs(time)):
            raise OutputError(f"{path}: no row at t = {time:g} s")
    return np.abs(table[column][rows])
