#!/usr/bin/env python3
"""Every path docs/architecture.md names exists (issue: the house, point 7): a map of
the code that names a file the code no longer has misleads whoever adds the next thing.

A path is a `backticked` token that starts at one of the repository's top folders
(src/, include/, tests/, ...), or a bare file name with a source extension
(`film_shape.cpp`), which must be some file's name in the tree. Placeholders
(`<name>_table.h`) and globs are skipped.

    python3 tests/scripts/doc_paths_test.py [REPO] [DOC ...]
"""
import re
import sys
from pathlib import Path

ROOTS = ("src/", "include/", "tests/", "scripts/", "docs/", "python/", "configs/", "benchmarks/", ".ci/")
EXTENSIONS = (".h", ".cpp", ".py", ".sh", ".md", ".yaml", ".csv", ".json", ".txt")


def named_paths(text):
    for token in re.findall(r"`([^`\s]+)`", text):
        token = token.rstrip(".,;:")
        if "<" in token or "*" in token or "…" in token:
            continue
        # A symbol with its file (film_gap.h's FilmGap) or a call: the path part alone.
        token = token.split("(")[0].split("::")[0]
        if token.startswith(ROOTS) or ("/" not in token and token.endswith(EXTENSIONS)):
            yield token


def missing(repo, doc):
    names = {p.name for p in repo.rglob("*") if p.is_file() and ".git" not in p.parts}
    out = []
    for path in sorted(set(named_paths(doc.read_text(encoding="utf-8")))):
        if "/" in path:
            if not (repo / path).exists():
                out.append(path)
        elif path not in names:
            out.append(path)
    return out


def main(argv):
    repo = Path(argv[1]) if len(argv) > 1 else Path(__file__).resolve().parents[2]
    docs = [repo / d for d in argv[2:]] or [repo / "docs" / "architecture.md"]
    bad = 0
    for doc in docs:
        gone = missing(repo, doc)
        for path in gone:
            print(f"{doc.relative_to(repo)} names {path}, which the repository does not have")
        bad += len(gone)
        if not gone:
            print(f"{doc.relative_to(repo)}: every path it names exists")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
