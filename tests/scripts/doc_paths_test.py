#!/usr/bin/env python3
"""Every path docs/architecture.md names exists (issue: the house, point 7): a map of
the code that names a file the code no longer has misleads whoever adds the next thing.

A path is a `backticked` token that starts at one of the repository's top folders
(src/, include/, tests/, ...), or a bare file name with a source extension
(`film_shape.cpp`), which must be the name of a file the repository tracks (git
ls-files: a results file a run left in the tree is not one). Placeholders
(`<name>_table.h`), globs and the names of results files (`states.csv`) are skipped.

    python3 tests/scripts/doc_paths_test.py [REPO] [DOC ...]
"""
import re
import subprocess
import sys
from pathlib import Path

ROOTS = ("src/", "include/", "tests/", "scripts/", "docs/", "python/", "configs/", "benchmarks/", ".ci/")
EXTENSIONS = (".h", ".cpp", ".py", ".sh", ".md", ".yaml")


def named_paths(text):
    for token in re.findall(r"`([^`\s]+)`", text):
        token = token.rstrip(".,;:")
        if "<" in token or "*" in token or "…" in token:
            continue
        # A symbol with its file (film_gap.h's FilmGap) or a call: the path part alone.
        token = token.split("(")[0].split("::")[0]
        if token.startswith(ROOTS) or ("/" not in token and token.endswith(EXTENSIONS)):
            yield token


def tracked(repo):
    """The repository's files (git ls-files), or every file under it outside .git and
    the build folders when it is not a git checkout."""
    try:
        listed = subprocess.run(["git", "-C", str(repo), "ls-files"], capture_output=True, text=True, check=True)
        return [Path(line) for line in listed.stdout.splitlines() if line]
    except (OSError, subprocess.CalledProcessError):
        return [p.relative_to(repo) for p in repo.rglob("*")
                if p.is_file() and not {".git", "build", "build-tests", "results"} & set(p.relative_to(repo).parts)]


def missing(repo, doc):
    files = tracked(repo)
    paths = {str(p) for p in files}
    folders = {str(parent) + "/" for p in files for parent in p.parents if str(parent) != "."}
    names = {p.name for p in files}
    out = []
    for path in sorted(set(named_paths(doc.read_text(encoding="utf-8")))):
        if "/" in path:
            if path not in paths and path not in folders and path.rstrip("/") + "/" not in folders:
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
