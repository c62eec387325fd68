#!/usr/bin/env python3
"""Whether two results directories hold the same numbers: every CSV file of one in the
other, cell by cell as text, timing columns aside (`wall_ms` and any column ending in
`_ms`). For changes that must not change results (a restructuring of the code): run
the same scenes with the build before and after and compare.

    python3 scripts/same_results.py [--added-columns] BEFORE AFTER

With --added-columns, columns that only AFTER has are listed but are no difference (a
change that adds results and must leave the old ones as they were); the shared columns
are compared by name.
Directories are compared recursively (a directory of runs, one per scene). Prints each
difference (file, row, column, both cells) and exits 1 if there is any, 0 otherwise.
"""
import csv
import sys
from pathlib import Path


def timing(column):
    return column == "wall_ms" or column.endswith("_ms")


def rows(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def compare_file(before, after, name, out, added, allow_added):
    a, b = rows(before), rows(after)
    if not a or not b:
        if a != b:
            out.append(f"{name}: one file is empty")
        return
    new = [c for c in b[0] if c not in a[0]]
    if a[0] != b[0] and not (allow_added and [c for c in b[0] if c in a[0]] == a[0]):
        out.append(f"{name}: columns differ: {a[0]} / {b[0]}")
        return
    if new:
        added.append(f"{name}: added columns {new}")
    if len(a) != len(b):
        out.append(f"{name}: {len(a) - 1} rows / {len(b) - 1} rows")
    header = a[0]
    where = {column: k for k, column in enumerate(b[0])}
    for r, (ra, rb) in enumerate(zip(a[1:], b[1:]), start=1):
        for c, column in enumerate(header):
            if timing(column):
                continue
            x = ra[c] if c < len(ra) else ""
            y = rb[where[column]] if where[column] < len(rb) else ""
            if x != y:
                out.append(f"{name}: row {r}, {column}: {x} / {y}")


def main(argv):
    allow_added = "--added-columns" in argv[1:]
    argv = [argv[0]] + [a for a in argv[1:] if a != "--added-columns"]
    if len(argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    before, after = Path(argv[1]), Path(argv[2])
    for d in (before, after):
        if not d.is_dir():
            print(f"error: {d} is not a directory", file=sys.stderr)
            return 2
    names = sorted({p.relative_to(before) for p in before.rglob("*.csv")} |
                   {p.relative_to(after) for p in after.rglob("*.csv")})
    if not names:
        print("error: no CSV files to compare", file=sys.stderr)
        return 2
    out, added = [], []
    for name in names:
        pa, pb = before / name, after / name
        if not pa.exists() or not pb.exists():
            out.append(f"{name}: only in {'after' if not pa.exists() else 'before'}")
            continue
        compare_file(pa, pb, str(name), out, added, allow_added)
    for line in added + out:
        print(line)
    print(f"{len(names)} files compared: " + (f"{len(out)} differences" if out else "the same"))
    return 1 if out else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
