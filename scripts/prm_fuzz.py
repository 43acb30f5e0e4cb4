#!/usr/bin/env python3
"""Mutation fuzzer for ndda's .prm scene files.

Takes the seed scenes of a directory (prm/ by default), makes mutants of
them (1-3 random mutations each: lines deleted, duplicated or swapped,
numbers replaced by extremes, values by garbage, the file truncated,
unknown entries and subsections inserted, subsections renamed, 'end's
dropped, list elements dropped or repeated, random bytes inserted, also
non-UTF-8), and runs 'ndda --validate' on every mutant and, for a fraction
of them, a short run (a few time steps into a per-mutant output directory).
Every invocation is classified:

  ok          exit status 0
  refused     non-zero exit status with a message, no signal
  crash       killed by a signal, a crash marker in the output ('terminate
              called', 'Segmentation fault', an uncaught deal.II exception
              dump 'An error occurred in line', ...) or a non-zero exit
              status without any message
  hang        did not end within --timeout seconds
  silent_nan  exit status 0, but a nan or inf number in the run's output
              files (statistics, measure_points.txt, the .vtu data, ...)

and informational flags are collected: validate_ok_run_refused (validate
accepted the mutant, the short run refused it), refused_unclear (the error
message does not name a parameter section or the file, e.g. a bare
internal deal.II message), validate_wrote_files (--validate left files
behind), nan_in_log (nan/inf only on the console), bad_alloc (the
address-space limit hit: a clean failure, but a sign of a runaway
allocation).

Python 3 standard library only. Runs one invocation at a time, each under
resource limits (address space --memory-gb, no core files, output file
size limit) in its own process group, killed as a group on timeout.

Example:
  python3 scripts/prm_fuzz.py --ndda build/ndda --prm-dir prm --count 200 \\
      --work-dir /tmp/fuzz --runs-fraction 0.25 --keep-failures

Mutant i of a given --seed is always the same (its random generator is
seeded from the seed and i), so a reproducer can be regenerated with
--first I --count 1.
"""

import argparse
import array
import base64
import collections
import json
import math
import os
import random
import re
import resource
import shutil
import signal
import struct
import subprocess
import sys
import time
import zlib

# --------------------------------------------------------------------------
# Mutations
# --------------------------------------------------------------------------

EXTREMES = [
    "0", "-0", "-1", "1e308", "-1e308", "1e-308", "-1e-308", "4.9e-324",
    "1e30", "-1e30", "NaN", "nan", "-nan", "inf", "-inf", "Infinity",
    "1e999", "-1e999", "99999999999999999999999999999", "2147483648",
    "-2147483649", "18446744073709551616", "0.0", "1e-30",
]

NUMBER = re.compile(rb"(?<![A-Za-z_0-9.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
SET_LINE = re.compile(rb"^(\s*set\s+)([^=]*?)(\s*=\s*)(.*?)(\s*)$", re.S)
SUBSECTION_LINE = re.compile(rb"^(\s*subsection\s+)(.*?)(\s*)$", re.S)
END_LINE = re.compile(rb"^\s*end\s*$")


def split_lines(data):
    """Lines with their line ends (the last one may have none)."""
    return data.splitlines(keepends=True)


def show(line, limit=100):
    """A line for a report: decoded with escapes, shortened."""
    text = line.rstrip(b"\r\n").decode("utf-8", "backslashreplace")
    if len(text) > limit:
        text = text[:limit] + "...(%d chars)" % len(text)
    return repr(text)


def significant(lines):
    """Indices of lines that are neither blank nor comments."""
    result = [i for i, l in enumerate(lines)
              if l.strip() and not l.lstrip().startswith(b"#")]
    return result or list(range(len(lines)))


def indices_matching(lines, pattern):
    return [i for i, l in enumerate(lines) if pattern.match(l)]


def with_eol(text):
    return text if text.endswith(b"\n") else text + b"\n"


def random_garbage(rng):
    kind = rng.choice(["printable", "printable", "empty", "long", "spaces",
                       "symbols"])
    if kind == "empty":
        return b"", "empty string"
    if kind == "spaces":
        return b"   ", "blanks"
    if kind == "long":
        n = rng.choice([1000, 100000, 1000000])
        chunk = bytes(rng.choice(b"abcdefghijklmnopqrstuvwxyz0123456789,;. ")
                      for _ in range(64))
        return (chunk * (n // 64 + 1))[:n], "a %d character string" % n
    if kind == "symbols":
        return bytes(rng.choice(b"#=;,()[]{}\\\"'*/+-^%$&|<>!?~`")
                     for _ in range(rng.randint(1, 12))), None
    # printable ASCII; '#' starts a comment, keep it too
    return bytes(rng.randint(32, 126) for _ in range(rng.randint(1, 40))), None


def mutate_delete_line(rng, lines):
    i = rng.choice(significant(lines))
    old = lines.pop(i)
    return "delete line %d: %s" % (i + 1, show(old))


def mutate_duplicate_line(rng, lines):
    i = rng.choice(significant(lines))
    lines.insert(i + 1, with_eol(lines[i]))
    lines[i] = with_eol(lines[i])
    return "duplicate line %d: %s" % (i + 1, show(lines[i]))


def mutate_swap_lines(rng, lines):
    candidates = significant(lines)
    if len(candidates) < 2:
        return None
    i, j = sorted(rng.sample(candidates, 2))
    a, b = with_eol(lines[i]), with_eol(lines[j])
    lines[i], lines[j] = b, a
    return "swap lines %d and %d: %s <-> %s" % (i + 1, j + 1, show(a), show(b))


def set_lines_with_numbers(lines):
    result = []
    for i, l in enumerate(lines):
        m = SET_LINE.match(l)
        if m and NUMBER.search(m.group(4)):
            result.append(i)
    return result


def mutate_extreme_number(rng, lines):
    candidates = set_lines_with_numbers(lines)
    if not candidates:
        return None
    i = rng.choice(candidates)
    m = SET_LINE.match(lines[i])
    value = m.group(4)
    numbers = list(NUMBER.finditer(value))
    n = rng.choice(numbers)
    extreme = rng.choice(EXTREMES).encode()
    new_value = value[:n.start()] + extreme + value[n.end():]
    old = lines[i]
    lines[i] = m.group(1) + m.group(2) + m.group(3) + new_value + m.group(5)
    return "line %d: number %s -> %s: %s -> %s" % (
        i + 1, n.group().decode(), extreme.decode(), show(old), show(lines[i]))


def mutate_garbage_value(rng, lines):
    candidates = indices_matching(lines, SET_LINE)
    if not candidates:
        return None
    i = rng.choice(candidates)
    m = SET_LINE.match(lines[i])
    garbage, what = random_garbage(rng)
    old = lines[i]
    eol = b"\n" if old.endswith(b"\n") else b""
    lines[i] = m.group(1) + m.group(2) + m.group(3) + garbage + eol
    return "line %d: value -> %s: %s -> %s" % (
        i + 1, what or repr(garbage.decode("latin-1")), show(old),
        show(lines[i]))


def mutate_other_value(rng, lines):
    """Give an entry the value of another entry (type confusion)."""
    candidates = indices_matching(lines, SET_LINE)
    if len(candidates) < 2:
        return None
    i, j = rng.sample(candidates, 2)
    mi, mj = SET_LINE.match(lines[i]), SET_LINE.match(lines[j])
    old = lines[i]
    eol = b"\n" if old.endswith(b"\n") else b""
    lines[i] = mi.group(1) + mi.group(2) + mi.group(3) + mj.group(4) + eol
    return "line %d: value of line %d: %s -> %s" % (
        i + 1, j + 1, show(old), show(lines[i]))


def mutate_list_element(rng, lines):
    """Drop, repeat or swap one element of a ';' or ',' separated value."""
    candidates = []
    for i, l in enumerate(lines):
        m = SET_LINE.match(l)
        if m and (b";" in m.group(4) or b"," in m.group(4)):
            candidates.append(i)
    if not candidates:
        return None
    i = rng.choice(candidates)
    m = SET_LINE.match(lines[i])
    value = m.group(4)
    separator = b";" if b";" in value and rng.random() < 0.7 else b","
    if separator not in value:
        separator = b";"
    parts = value.split(separator)
    action = rng.choice(["drop", "repeat", "swap", "keep one"])
    k = rng.randrange(len(parts))
    if action == "drop":
        del parts[k]
    elif action == "repeat":
        parts.insert(k, parts[k])
    elif action == "swap" and len(parts) > 1:
        a, b = rng.sample(range(len(parts)), 2)
        parts[a], parts[b] = parts[b], parts[a]
    else:
        action = "keep one"
        parts = [parts[k]]
    old = lines[i]
    lines[i] = (m.group(1) + m.group(2) + m.group(3) + separator.join(parts)
                + m.group(5))
    return "line %d: list element (%s, '%s'): %s -> %s" % (
        i + 1, action, separator.decode(), show(old), show(lines[i]))


def mutate_truncate(rng, lines):
    data = b"".join(lines)
    if not data:
        return None
    cut = rng.randrange(len(data))
    lines[:] = split_lines(data[:cut])
    line_no = data[:cut].count(b"\n") + 1
    return "truncate at byte %d of %d (line %d)" % (cut, len(data), line_no)


def random_name(rng):
    words = ["Fuzz", "Time step", "Names", "Material", "rock", "Control",
             "x", "", " ", "subsection", "end", "set", "Ünïcode", "a=b"]
    if rng.random() < 0.5:
        return rng.choice(words).encode()
    return bytes(rng.choice(b"abcdefghijklmnopqrstuvwxyzABC _-'0123456789")
                 for _ in range(rng.randint(1, 16)))


def mutate_unknown_entry(rng, lines):
    i = rng.randint(0, len(lines))
    value = rng.choice([b"1", b"0", b"", b"true", b"nan", b"x"])
    new = b"set " + random_name(rng) + b" = " + value + b"\n"
    lines.insert(i, new)
    return "insert before line %d: %s" % (i + 1, show(new))


def mutate_unknown_subsection(rng, lines):
    i = rng.randint(0, len(lines))
    name = random_name(rng)
    body = [b"subsection " + name + b"\n"]
    if rng.random() < 0.5:
        body.append(b"  set " + random_name(rng) + b" = 1\n")
    body.append(b"end\n")
    lines[i:i] = body
    return "insert before line %d: %s" % (
        i + 1, " / ".join(show(l) for l in body))


def mutate_rename_subsection(rng, lines):
    candidates = indices_matching(lines, SUBSECTION_LINE)
    if not candidates:
        return None
    i = rng.choice(candidates)
    m = SUBSECTION_LINE.match(lines[i])
    name = m.group(2)
    how = rng.choice(["other", "case", "typo", "empty", "random"])
    if how == "other":
        others = [SUBSECTION_LINE.match(lines[j]).group(2) for j in candidates]
        new_name = rng.choice(others)
    elif how == "case":
        new_name = name.swapcase()
    elif how == "typo" and name:
        k = rng.randrange(len(name))
        new_name = name[:k] + name[k + 1:] if rng.random() < 0.5 else \
            name[:k] + bytes([rng.randint(97, 122)]) + name[k:]
    elif how == "empty":
        new_name = b""
    else:
        new_name = random_name(rng)
    old = lines[i]
    lines[i] = m.group(1) + new_name + m.group(3)
    return "line %d: rename subsection (%s): %s -> %s" % (
        i + 1, how, show(old), show(lines[i]))


def mutate_drop_end(rng, lines):
    candidates = indices_matching(lines, END_LINE)
    if not candidates:
        return None
    i = rng.choice(candidates)
    old = lines.pop(i)
    return "delete 'end' at line %d: %s" % (i + 1, show(old))


def mutate_random_bytes(rng, lines):
    data = b"".join(lines)
    pos = rng.randint(0, len(data))
    kind = rng.choice(["non-utf8", "control", "any", "nul"])
    n = rng.randint(1, 16)
    if kind == "non-utf8":
        chunk = bytes(rng.choice([0x80, 0xbf, 0xc0, 0xc3, 0xe2, 0xf5, 0xfe,
                                  0xff]) for _ in range(n))
    elif kind == "control":
        chunk = bytes(rng.choice([0, 1, 7, 8, 9, 11, 12, 13, 27, 127])
                      for _ in range(n))
    elif kind == "nul":
        chunk = b"\x00" * n
    else:
        chunk = bytes(rng.randrange(256) for _ in range(n))
    data = data[:pos] + chunk + data[pos:]
    lines[:] = split_lines(data)
    return "insert %d random bytes (%s) %r at byte %d (line %d)" % (
        n, kind, chunk, pos, data[:pos].count(b"\n") + 1)


MUTATIONS = [
    # (name, function, weight)
    ("delete_line", mutate_delete_line, 2),
    ("duplicate_line", mutate_duplicate_line, 1),
    ("swap_lines", mutate_swap_lines, 1),
    ("extreme_number", mutate_extreme_number, 6),
    ("garbage_value", mutate_garbage_value, 3),
    ("other_value", mutate_other_value, 1),
    ("list_element", mutate_list_element, 3),
    ("truncate", mutate_truncate, 1),
    ("unknown_entry", mutate_unknown_entry, 1),
    ("unknown_subsection", mutate_unknown_subsection, 1),
    ("rename_subsection", mutate_rename_subsection, 1),
    ("drop_end", mutate_drop_end, 1),
    ("random_bytes", mutate_random_bytes, 1),
]


def make_mutant(rng, seed_data):
    lines = split_lines(seed_data)
    descriptions = []
    # 1-3 mutations, one most often: a mutant with fewer defects gets
    # further into the program
    wanted = rng.choices([1, 2, 3], weights=[5, 3, 2])[0]
    attempts = 0
    while len(descriptions) < wanted and attempts < 50:
        attempts += 1
        name, function, _ = rng.choices(
            MUTATIONS, weights=[w for _, _, w in MUTATIONS])[0]
        if not lines:
            lines = [b"\n"]
        description = function(rng, lines)
        if description:
            descriptions.append("%s: %s" % (name, description))
    return b"".join(lines), descriptions


# --------------------------------------------------------------------------
# Running ndda
# --------------------------------------------------------------------------

Invocation = collections.namedtuple(
    "Invocation", "returncode signal timed_out seconds stdout stderr")


def limits(memory_bytes, file_bytes):
    def apply():
        resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        resource.setrlimit(resource.RLIMIT_FSIZE, (file_bytes, file_bytes))
    return apply


def tail_of(path, n_bytes=100000):
    """A file's text; of a long one the first and last n_bytes."""
    try:
        with open(path, "rb") as f:
            f.seek(0, os.SEEK_END)
            size = f.tell()
            f.seek(0)
            if size <= 2 * n_bytes:
                data = f.read()
            else:
                data = f.read(n_bytes) + b"\n[... %d bytes ...]\n" % (
                    size - 2 * n_bytes)
                f.seek(size - n_bytes)
                data += f.read()
            return data.decode("utf-8", "replace")
    except OSError:
        return ""


def invoke(args, cwd, log_prefix, timeout, memory_bytes, file_bytes, env):
    """Run one ndda invocation; stdout and stderr go to files."""
    out_path, err_path = log_prefix + ".out", log_prefix + ".err"
    start = time.monotonic()
    timed_out = False
    with open(out_path, "wb") as out, open(err_path, "wb") as err:
        try:
            process = subprocess.Popen(
                args, cwd=cwd, stdin=subprocess.DEVNULL, stdout=out,
                stderr=err, env=env, start_new_session=True,
                preexec_fn=limits(memory_bytes, file_bytes))
        except OSError as error:
            err.write(("prm_fuzz: cannot start %s: %s\n" %
                       (args[0], error)).encode())
            return Invocation(None, None, False, 0.0, "",
                              "prm_fuzz: cannot start: %s" % error)
        try:
            process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            process.wait()
    seconds = time.monotonic() - start
    rc = process.returncode
    sig = -rc if rc is not None and rc < 0 else None
    return Invocation(rc, sig, timed_out, seconds, tail_of(out_path),
                      tail_of(err_path))


CRASH_MARKERS = [
    "terminate called", "Aborted", "Segmentation fault",
    "An error occurred in line", "*** Process received signal",
    "double free", "free(): invalid", "malloc(): ", "corrupted size",
    "stack smashing detected", "Floating point exception",
    "Illegal instruction", "Bus error", "AddressSanitizer",
]


def classify(inv):
    """Class and a reason for one invocation."""
    if inv.returncode is None:
        return "harness_error", inv.stderr.strip()[-200:]
    if inv.timed_out:
        return "hang", "no end within the timeout (%.0f s)" % inv.seconds
    if inv.signal:
        try:
            name = signal.Signals(inv.signal).name
        except ValueError:
            name = "signal %d" % inv.signal
        return "crash", "killed by %s" % name
    text = inv.stdout + "\n" + inv.stderr
    for marker in CRASH_MARKERS:
        if marker in text:
            return "crash", "output contains %r (exit %d)" % (
                marker, inv.returncode)
    if inv.returncode == 0:
        return "ok", ""
    if inv.returncode in (134, 136, 139):
        return "crash", "exit status %d (a signal's status)" % inv.returncode
    if not text.strip():
        return "crash", "exit status %d without any message" % inv.returncode
    return "refused", error_message(text)[:2000]


def error_message(text):
    """The 'ndda: error: ...' message, or the last non-empty line."""
    m = re.search(r"ndda: (error: |unknown error)(.*)", text, re.S)
    if m:
        message = (m.group(1) + m.group(2)).strip()
        message = message.split("\n\n")[0]
        return " ".join(message.split())
    lines = [l for l in text.splitlines() if l.strip()]
    return lines[-1].strip() if lines else ""


# --------------------------------------------------------------------------
# NaN and inf in the output files
# --------------------------------------------------------------------------

NAN_TOKEN = re.compile(
    r"(?<![A-Za-z0-9_])[-+]?(?:nan(?:\([^)]*\))?|inf(?:inity)?|1\.#(?:INF|IND|QNAN))"
    r"(?![A-Za-z0-9_])", re.I)
DATA_ARRAY = re.compile(rb"<DataArray([^>]*)>(.*?)</DataArray>", re.S)
ATTRIBUTE = re.compile(rb'(\w+)="([^"]*)"')
VTK_FLOATS = {b"Float32": "f", b"Float64": "d"}


def nan_tokens_in_text(text, skip_comments=True):
    hits = []
    for number, line in enumerate(text.splitlines(), 1):
        if skip_comments and line.lstrip().startswith("#"):
            continue
        for m in NAN_TOKEN.finditer(line):
            hits.append("line %d: %s" % (number, m.group()))
            break
    return hits


def decode_vtk_binary(text, header_format, compressed):
    text = b"".join(text.split())
    word = struct.calcsize("<" + header_format)

    def b64_length(n):
        return 4 * ((n + 2) // 3)

    if not compressed:
        first = base64.b64decode(text[:b64_length(word)])
        n_bytes = struct.unpack("<" + header_format, first[:word])[0]
        rest = text[b64_length(word):]
        data = base64.b64decode(rest) if rest else b""
        if len(data) != n_bytes:
            data = base64.b64decode(text)[word:word + n_bytes]
        return data
    first = base64.b64decode(text[:b64_length(3 * word)])
    n_blocks = struct.unpack("<" + header_format, first[:word])[0]
    header_bytes = (3 + n_blocks) * word
    header_text = text[:b64_length(header_bytes)]
    header = struct.unpack("<%d%s" % (3 + n_blocks, header_format),
                           base64.b64decode(header_text)[:header_bytes])
    sizes = header[3:]
    payload_text = text[len(header_text):]
    payload = base64.b64decode(payload_text) if payload_text else b""
    if len(payload) != sum(sizes):
        payload = base64.b64decode(text)[header_bytes:]
    chunks, position = [], 0
    for size in sizes:
        chunks.append(zlib.decompress(payload[position:position + size]))
        position += size
    return b"".join(chunks)


def nan_in_vtu(path):
    """Names of float DataArrays with a non-finite value, or a read error."""
    with open(path, "rb") as f:
        data = f.read()
    head = data[:2000]
    compressed = b'compressor="vtkZLibDataCompressor"' in head
    header_format = "Q" if b'header_type="UInt64"' in head else "I"
    hits = []
    for m in DATA_ARRAY.finditer(data):
        attributes = dict(ATTRIBUTE.findall(m.group(1)))
        type_code = VTK_FLOATS.get(attributes.get(b"type"))
        if not type_code:
            continue
        name = attributes.get(b"Name", b"(points)").decode("utf-8", "replace")
        if attributes.get(b"format", b"ascii") == b"binary":
            try:
                raw = decode_vtk_binary(m.group(2), header_format, compressed)
                values = array.array(type_code)
                values.frombytes(raw[:len(raw) - len(raw) % values.itemsize])
                if sys.byteorder != "little":
                    values.byteswap()
            except (ValueError, zlib.error, struct.error, IndexError) as e:
                hits.append("%s: cannot decode (%s)" % (name, e))
                continue
            bad = next((v for v in values if not math.isfinite(v)), None)
            if bad is not None:
                hits.append("%s: %r" % (name, bad))
        else:
            found = NAN_TOKEN.search(m.group(2).decode("latin-1"))
            if found:
                hits.append("%s: %s" % (name, found.group()))
    return hits


def scan_output(directory):
    """(hits in data files, hits in log files) of a run's output."""
    data_hits, log_hits = [], []
    if not os.path.isdir(directory):
        return data_hits, log_hits
    for root, _, files in os.walk(directory):
        for name in sorted(files):
            path = os.path.join(root, name)
            relative = os.path.relpath(path, directory)
            if name == "parameters.prm":
                continue  # the input, echoed
            try:
                if name.endswith(".vtu"):
                    hits = nan_in_vtu(path)
                    target = data_hits
                elif name.endswith((".h5", ".hdf5")):
                    continue  # binary, no reader in the standard library
                else:
                    with open(path, "rb") as f:
                        text = f.read(50000000).decode("utf-8", "replace")
                    target = log_hits if name == "log.txt" else data_hits
                    hits = nan_tokens_in_text(text)
            except OSError as error:
                data_hits.append("%s: cannot read (%s)" % (relative, error))
                continue
            target.extend("%s: %s" % (relative, h) for h in hits[:3])
    return data_hits, log_hits


# --------------------------------------------------------------------------
# The fuzzing loop
# --------------------------------------------------------------------------

def top_level_sections(ndda, env):
    """The top level subsections and entries of 'ndda --print-parameters'."""
    try:
        text = subprocess.run([ndda, "--print-parameters"], env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              timeout=60).stdout.decode("utf-8", "replace")
    except (OSError, subprocess.TimeoutExpired):
        return []
    names = re.findall(r"^subsection (.+?)\s*$", text, re.M)
    names += re.findall(r"^set (.+?)\s*=", text, re.M)
    return names


def time_step_of(seed_data):
    """Control/Time step of a seed scene (default 1e-3)."""
    depth, section = [], None
    for line in seed_data.decode("utf-8", "replace").splitlines():
        line = line.split("#")[0].strip()
        m = re.match(r"subsection\s+(.*)", line)
        if m:
            depth.append(m.group(1).strip())
        elif line == "end" and depth:
            depth.pop()
        else:
            m = re.match(r"set\s+Time step\s*=\s*(\S+)", line)
            if m and depth == ["Control"]:
                section = m.group(1)
    try:
        value = float(section) if section else 1e-3
        return value if math.isfinite(value) and value > 0 else 1e-3
    except ValueError:
        return 1e-3


def short_run_text(mutant, end_time, directory):
    """The mutant with a short End time and its own output directory.

    deal.II's ParameterHandler takes the last value of an entry set twice,
    so the blocks appended at the end override the scene's entries."""
    return (mutant + b"\n\nsubsection Control\n  set End time = "
            + repr(end_time).encode() + b"\nend\n\nsubsection Output\n"
            + b"  set Directory = " + directory.encode() + b"\nend\n")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ndda", default="build/ndda",
                        help="the ndda binary (copy it if it is being "
                             "rebuilt while the fuzzer runs)")
    parser.add_argument("--prm-dir", default="prm",
                        help="directory of seed .prm scenes")
    parser.add_argument("--count", type=int, default=200,
                        help="number of mutants")
    parser.add_argument("--first", type=int, default=0,
                        help="index of the first mutant (to regenerate "
                             "mutant I of a run: --first I --count 1)")
    parser.add_argument("--seed", type=int, default=20240601,
                        help="random seed (fixed default: reproducible)")
    parser.add_argument("--timeout", type=float, default=20.0,
                        help="seconds per invocation")
    parser.add_argument("--work-dir", default="/tmp/prm_fuzz",
                        help="where the mutants and their outputs go")
    parser.add_argument("--runs-fraction", type=float, default=0.25,
                        help="fraction of mutants also run for a few steps")
    parser.add_argument("--steps", type=int, default=3,
                        help="time steps of a short run (End time = steps "
                             "x the seed's Time step)")
    parser.add_argument("--markdown", help="write a markdown table of counts")
    parser.add_argument("--keep-failures", action="store_true",
                        help="keep the mutants (and their outputs) that "
                             "crashed, hung or wrote nan as reproducers")
    parser.add_argument("--memory-gb", type=float, default=4.0,
                        help="address space limit of each invocation")
    parser.add_argument("--threads", type=int, default=1,
                        help="DEAL_II_NUM_THREADS of each invocation")
    parser.add_argument("--examples", type=int, default=5,
                        help="reproducers printed per failure class")
    args = parser.parse_args()

    ndda = os.path.abspath(args.ndda)
    if not os.access(ndda, os.X_OK):
        sys.exit("prm_fuzz: %s is not an executable" % ndda)
    seeds = sorted(os.path.join(args.prm_dir, f)
                   for f in os.listdir(args.prm_dir) if f.endswith(".prm"))
    if not seeds:
        sys.exit("prm_fuzz: no .prm files in %s" % args.prm_dir)
    seed_data = {}
    for path in seeds:
        with open(path, "rb") as f:
            seed_data[path] = f.read()

    work = os.path.abspath(args.work_dir)
    mutant_dir = os.path.join(work, "mutants")
    scratch = os.path.join(work, "scratch")
    for d in (work, mutant_dir, scratch):
        os.makedirs(d, exist_ok=True)
    env = dict(os.environ)
    env["DEAL_II_NUM_THREADS"] = str(args.threads)
    env["OMP_NUM_THREADS"] = "1"
    env["OPENBLAS_NUM_THREADS"] = "1"
    memory = int(args.memory_gb * 2 ** 30)
    file_size = 2 ** 30
    sections = top_level_sections(ndda, env)

    counts = collections.Counter()       # (kind, class)
    flags = collections.Counter()
    examples = collections.defaultdict(list)
    results_path = os.path.join(work, "results.jsonl")
    results = open(results_path, "w")
    started = time.monotonic()
    print("prm_fuzz: %d mutants of %d seeds, seed %d, ndda %s, work dir %s"
          % (args.count, len(seeds), args.seed, ndda, work), flush=True)

    for index in range(args.first, args.first + args.count):
        rng = random.Random("%d-%d" % (args.seed, index))
        seed_path = rng.choice(seeds)
        mutant, mutations = make_mutant(rng, seed_data[seed_path])
        do_run = rng.random() < args.runs_fraction
        stem = "m%05d_%s" % (index, os.path.basename(seed_path)[:-4])
        mutant_path = os.path.join(mutant_dir, stem + ".prm")
        with open(mutant_path, "wb") as f:
            f.write(mutant)
        record = {"index": index, "seed": seed_path, "mutant": mutant_path,
                  "mutations": mutations, "invocations": {}}
        keep = []   # files to keep if a failure is found
        failed = False

        # --validate, in an empty directory: it must write nothing
        cwd = os.path.join(scratch, stem + "_validate")
        os.makedirs(cwd, exist_ok=True)
        log = os.path.join(mutant_dir, stem + ".validate")
        inv = invoke([ndda, "--validate", mutant_path], cwd, log,
                     args.timeout, memory, file_size, env)
        cls, reason = classify(inv)
        left_behind = os.listdir(cwd)
        shutil.rmtree(cwd, ignore_errors=True)
        record["invocations"]["validate"] = {
            "class": cls, "reason": reason, "rc": inv.returncode,
            "seconds": round(inv.seconds, 2),
            "tail": (inv.stdout + inv.stderr)[-3000:]}
        if left_behind:
            flags["validate_wrote_files"] += 1
            record.setdefault("flags", []).append(
                "validate_wrote_files: %s" % left_behind[:5])
        counts[("validate", cls)] += 1
        outcomes = [("validate", cls, reason, inv, log)]

        # the short run
        if do_run and cls != "hang":
            out_dir = os.path.join(work, "runs", stem)
            shutil.rmtree(out_dir, ignore_errors=True)
            end_time = args.steps * time_step_of(seed_data[seed_path])
            run_path = os.path.join(mutant_dir, stem + ".run.prm")
            with open(run_path, "wb") as f:
                f.write(short_run_text(mutant, end_time, out_dir))
            cwd = os.path.join(scratch, stem + "_run")
            os.makedirs(cwd, exist_ok=True)
            log = os.path.join(mutant_dir, stem + ".run")
            run = invoke([ndda, run_path], cwd, log, args.timeout, memory,
                         file_size, env)
            rcls, rreason = classify(run)
            if rcls == "ok":
                data_hits, log_hits = scan_output(out_dir)
                if data_hits:
                    rcls, rreason = "silent_nan", "; ".join(data_hits[:4])
                elif log_hits:
                    flags["nan_in_log"] += 1
                    record.setdefault("flags", []).append(
                        "nan_in_log: %s" % "; ".join(log_hits[:3]))
            if cls == "ok" and rcls == "refused":
                flags["validate_ok_run_refused"] += 1
                record.setdefault("flags", []).append(
                    "validate_ok_run_refused: %s" % rreason[:300])
                examples["validate_ok_run_refused"].append(
                    (record, "run", rreason, run, log))
            record["invocations"]["run"] = {
                "class": rcls, "reason": rreason, "rc": run.returncode,
                "seconds": round(run.seconds, 2), "run_file": run_path,
                "output": out_dir, "tail": (run.stdout + run.stderr)[-3000:]}
            counts[("run", rcls)] += 1
            outcomes.append(("run", rcls, rreason, run, log))
            shutil.rmtree(cwd, ignore_errors=True)
            keep += [run_path, out_dir]

        for kind, c, reason, inv, log in outcomes:
            if c == "refused":
                if "std::bad_alloc" in reason:
                    flags["bad_alloc"] += 1
                    record.setdefault("flags", []).append(
                        "bad_alloc (%s)" % kind)
                message = reason[len("error: "):] if reason.startswith(
                    "error: ") else reason
                message = message[:200]
                if not any(message.startswith(s) for s in sections) and \
                        not message.startswith(("Error in '", "Step ")):
                    flags["refused_unclear"] += 1
                    record.setdefault("flags", []).append(
                        "refused_unclear (%s): %s" % (kind, reason[:300]))
                    examples["refused_unclear"].append(
                        (record, kind, reason, inv, log))
            if c in ("crash", "hang", "silent_nan", "harness_error"):
                failed = True
                examples[c].append((record, kind, reason, inv, log))
            keep += [log + ".out", log + ".err"]

        record["failed"] = failed
        results.write(json.dumps(record) + "\n")
        results.flush()
        if not (failed and args.keep_failures):
            for path in [mutant_path] + keep:
                if os.path.isdir(path):
                    shutil.rmtree(path, ignore_errors=True)
                elif os.path.exists(path):
                    os.remove(path)
        else:
            record["kept"] = True
        done = index - args.first + 1
        if failed or done % 25 == 0 or done == args.count:
            elapsed = time.monotonic() - started
            status = " ".join("%s/%s=%d" % (k, c, n)
                              for (k, c), n in sorted(counts.items()))
            print("[%d/%d %.0f s] %s%s" % (
                done, args.count, elapsed, status,
                ("  <- %s: %s" % (stem, ", ".join(
                    "%s %s" % (o[0], o[1]) for o in outcomes
                    if o[1] not in ("ok", "refused")))) if failed else ""),
                flush=True)
    results.close()
    shutil.rmtree(scratch, ignore_errors=True)
    elapsed = time.monotonic() - started

    # ---- report
    classes = ["ok", "refused", "crash", "hang", "silent_nan", "harness_error"]
    print("\n=== prm_fuzz summary: %d mutants, %.0f s wall time (%.2f s per "
          "mutant)" % (args.count, elapsed, elapsed / max(1, args.count)))
    print("%-12s %10s %10s" % ("class", "validate", "run"))
    for c in classes:
        print("%-12s %10d %10d" % (c, counts[("validate", c)],
                                   counts[("run", c)]))
    print("informational:", ", ".join("%s=%d" % kv for kv in
                                      sorted(flags.items())) or "none")
    for c in ["crash", "hang", "silent_nan", "harness_error",
              "validate_ok_run_refused", "refused_unclear"]:
        if not examples[c]:
            continue
        print("\n--- %s: %d (showing %d)" % (c, len(examples[c]),
                                            min(args.examples,
                                                len(examples[c]))))
        for record, kind, reason, inv, log in examples[c][:args.examples]:
            print("* %s (%s of seed %s)" % (record["mutant"], kind,
                                            record["seed"]))
            if kind == "run":
                print("  run file: %s" %
                      record["invocations"]["run"]["run_file"])
            for m in record["mutations"]:
                print("  mutation: %s" % m)
            print("  reason: %s" % reason[:500])
            tail = [l for l in (inv.stdout + "\n" + inv.stderr).splitlines()
                    if l.strip()][-8:]
            for l in tail:
                print("  | %s" % l[:300])
    print("\nper-mutant results: %s" % results_path)

    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("| class | validate | short run |\n|---|---:|---:|\n")
            for c in classes:
                f.write("| %s | %d | %d |\n" % (c, counts[("validate", c)],
                                                counts[("run", c)]))
            for name, n in sorted(flags.items()):
                f.write("| %s (info) | %d | |\n" % (name, n))
            f.write("\n%d mutants, seed %d, %.0f s wall time.\n"
                    % (args.count, args.seed, elapsed))
    failures = sum(counts[(k, c)] for k in ("validate", "run")
                   for c in ("crash", "hang", "silent_nan"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
