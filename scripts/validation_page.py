#!/usr/bin/env python3
"""Write doc/validation.md from its template and the tests' measured values.

The validation programs in tests/ print every figure the page quotes as a
line

    @value KEY VALUE

(tests/values.h, ndda_tests::record; the bad_input_* tests' runner writes
them for the refusals). The template doc/validation.md.in is
the page with each figure written as a placeholder {{KEY}}; this script
fills them in. Nothing in the page's numbers is typed by hand.

    validation_page.py --template doc/validation.md.in \\
        --values build/tests --out doc/validation.md

--values takes files or directories (every file named 'screen-output'
below a directory, as ctest's runner writes them, or '*.log').

    validation_page.py --template doc/validation.md.in \\
        --values build/tests --check doc/validation.md

checks, without writing, that
  1. every placeholder of the template has a value in this run,
  2. the page is the template filled in (nobody edited one without the
     other), and
  3. the page's values agree with this run's to a relative 1e-3, except
     placeholders written {{~KEY}} (run times, and anything else that
     changes from run to run), which are only checked for presence.
Placeholders written {{?KEY}} (or {{?~KEY}}) are figures of the long runs
that only ./ndda.sh validate makes (finer meshes): when no value is
reported the page says "n/r" (not run), and the check
accepts whatever the page holds there.
The ctest 'validation_page' runs the check after the other tests, so the
page cannot silently go stale: a change that moves a figure makes the test
fail until `./ndda.sh validate` has rewritten the page.

Standard library only; any python3.
"""

import argparse
import datetime
import os
import re
import sys

PLACEHOLDER = re.compile(r"\{\{([~?]*)([A-Za-z0-9_.\-]+)\}\}")
NOT_RUN = "n/r"
VALUE_LINE = re.compile(r"^@value (\S+) (.*)$")
RELATIVE_TOLERANCE = 1e-3


class PageError(Exception):
    """A template, value file or page that does not fit together."""


def value_files(paths):
    """The files to read values from: files as given, and in directories
    every 'screen-output' and '*.log' file below them."""
    files = []
    for path in paths:
        if os.path.isdir(path):
            for root, _, names in os.walk(path):
                for name in sorted(names):
                    if name == "screen-output" or name.endswith(".log"):
                        files.append(os.path.join(root, name))
        elif os.path.isfile(path):
            files.append(path)
        else:
            raise PageError(f"--values: no such file or directory: {path}")
    return files


def read_values(paths):
    """KEY -> (text, file) from every '@value KEY VALUE' line."""
    values = {}
    for path in value_files(paths):
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                match = VALUE_LINE.match(line.rstrip("\n"))
                if not match:
                    continue
                key, text = match.group(1), match.group(2).strip()
                if key in values and values[key][1] != path:
                    raise PageError(
                        f"{path}: the key '{key}' is also reported by "
                        f"{values[key][1]}"
                    )
                values[key] = (text, path)
    return values


def fill(template, values, template_path):
    """The page: the template with every placeholder replaced."""
    missing = sorted(
        {m.group(2) for m in PLACEHOLDER.finditer(template) if "?" not in m.group(1)}
        - set(values)
    )
    if missing:
        raise PageError(
            f"{template_path}: no test reported "
            + ", ".join(f"'{k}'" for k in missing)
            + " (the tests print '@value KEY VALUE'; run them, or remove "
            "the placeholder)"
        )
    return PLACEHOLDER.sub(
        lambda m: values[m.group(2)][0] if m.group(2) in values else NOT_RUN,
        template,
    )


def page_values(template, page, template_path, page_path):
    """KEY -> text as it stands in the page, matching the page against the
    template line by line, each placeholder a wildcard within its line
    (values are one line each; a wildcard that may cross lines makes a
    stale page backtrack without end)."""
    template_lines, page_lines = template.splitlines(), page.splitlines()
    if len(template_lines) != len(page_lines):
        raise PageError(
            f"{page_path} has {len(page_lines)} lines, {template_path} "
            f"{len(template_lines)}: the page is not the template filled in; "
            "regenerate it with ./ndda.sh validate (or "
            "scripts/validation_page.py)."
        )
    values = []
    for number, (t, p) in enumerate(zip(template_lines, page_lines), start=1):
        pattern, keys, position = [], [], 0
        for m in PLACEHOLDER.finditer(t):
            pattern.append(re.escape(t[position : m.start()]))
            pattern.append(r"(.+?)")
            keys.append((m.group(1), m.group(2)))
            position = m.end()
        pattern.append(re.escape(t[position:]))
        match = re.fullmatch("".join(pattern), p)
        if not match:
            raise PageError(
                f"{page_path}:{number} does not match "
                f"{template_path}:{number}:\n  page:     {p}\n"
                f"  template: {t}\nRegenerate the page with "
                "./ndda.sh validate (or scripts/validation_page.py)."
            )
        values += [
            (loose, key, match.group(i + 1)) for i, (loose, key) in enumerate(keys)
        ]
    return values


def numbers_in(text):
    return [float(x) for x in re.findall(r"[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?", text)]


def agree(a, b):
    """Two texts agree if their words agree and their numbers agree to a
    relative RELATIVE_TOLERANCE."""
    if re.sub(r"[-+]?\d[\d.eE+\-]*", "#", a) != re.sub(
        r"[-+]?\d[\d.eE+\-]*", "#", b
    ):
        return False
    x, y = numbers_in(a), numbers_in(b)
    return len(x) == len(y) and all(
        abs(p - q) <= RELATIVE_TOLERANCE * max(abs(p), abs(q), 1e-300)
        for p, q in zip(x, y)
    )


def check(template, values, page, template_path, page_path):
    fill(template, values, template_path)  # 1: every key reported
    problems = []
    for flags, key, text in page_values(template, page, template_path, page_path):
        if "~" in flags or ("?" in flags and key not in values):
            continue
        now = values[key][0]
        if not agree(text, now):
            problems.append(
                f"  {key}: the page says '{text}', this run measured "
                f"'{now}' ({values[key][1]})"
            )
    if problems:
        raise PageError(
            f"{page_path} is stale; regenerate it with ./ndda.sh validate:\n"
            + "\n".join(problems)
        )


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=__doc__.split("\n", 1)[1],
    )
    parser.add_argument("--template", required=True, help="doc/validation.md.in")
    parser.add_argument(
        "--values",
        nargs="+",
        required=True,
        help="files or directories with '@value KEY VALUE' lines",
    )
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--out", help="write the page here")
    group.add_argument("--check", help="check this page against the run")
    args = parser.parse_args()
    try:
        with open(args.template, encoding="utf-8") as f:
            template = f.read()
        values = read_values(args.values)
        values["page.date"] = (datetime.date.today().isoformat(), "today")
        if args.out:
            page = fill(template, values, args.template)
            with open(args.out, "w", encoding="utf-8") as f:
                f.write(page)
            print(
                f"validation_page: wrote {args.out} "
                f"({len(PLACEHOLDER.findall(template))} values)"
            )
        else:
            with open(args.check, encoding="utf-8") as f:
                page = f.read()
            check(template, values, page, args.template, args.check)
            print(
                f"validation_page: {args.check} agrees with this run "
                f"({len(PLACEHOLDER.findall(template))} values)"
            )
    except (OSError, PageError) as error:
        print(f"validation_page: error: {error}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
