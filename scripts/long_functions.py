#!/usr/bin/env python3
"""Functions and files in the C++ sources that are longer than a limit.

    python3 scripts/long_functions.py [--function-lines N] [--file-lines M] [DIR ...]

DIR defaults to src/ of this repository; N to 150, M to 600. A function's length is
the lines from the first line of its signature (its template line, if any, included;
comments above it excluded) to the line of its closing brace, both counted. A lambda
or a local class is part of the function it is written in, not a function of its own;
a lambda at namespace scope is counted as a function. A file's length is its number of
lines (as `wc -l`, plus one if the last line has no newline).

The scan matches braces on the text with comments, string and character literals
blanked out; it knows namespaces, classes, structs, unions, enums, `extern "C"`
blocks, brace initializers, braces inside a parameter list (a default argument `= {}`)
and constructors' member initializer lists; on the longest functions of src/ it agrees
with clang's AST. It does not expand macros: a macro that opens or closes a brace would
mislead it (twb has none).

Prints each offender as `path:line: name: N lines` (files as `path: N lines`), and
exits 1 if there is any, 0 otherwise.
"""
import argparse
import re
import signal
import sys
from pathlib import Path

IDENT = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")
SCOPE_KEYWORDS = ("class", "struct", "union", "enum")


def blank_comments_and_literals(text):
    """The text with comments and literals replaced by spaces, newlines kept, so that
    offsets and line numbers stay those of the file."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = text.find(")" + m.group(1) + '"', i + m.end())
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            # A digit separator (1'000) is not a character literal.
            if c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum():
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "#" and (i == 0 or text.rfind("\n", 0, i) == i - 1 or text[text.rfind("\n", 0, i) + 1:i].strip() == ""):
            # A preprocessor line (with its continuations) holds no braces of the code.
            j = i
            while True:
                k = text.find("\n", j)
                if k < 0:
                    k = n
                    break
                if text[k - 1] != "\\":
                    break
                j = k + 1
            out.append(re.sub(r"[^\n]", " ", text[i:k]))
            i = k
        else:
            out.append(c)
            i += 1
    return "".join(out)


def head_kind(head):
    """What a `{` opens at namespace or class scope, from the text before it."""
    h = " ".join(head.split())
    if not h:
        return "block"
    if re.match(r"^(inline\s+)?namespace\b", h) or h == 'extern' or re.match(r'^extern\s*$', h):
        return "namespace"
    if re.search(r"=\s*$", h) or re.search(r"\breturn\s*$", h):
        return "initializer"
    # template<...> class X : public Y<Z> {
    stripped = re.sub(r"^template\s*<.*?>\s*", "", h)
    if re.match(r"^(typedef\s+)?(%s)\b" % "|".join(SCOPE_KEYWORDS), stripped) and "(" not in stripped.split(":")[0]:
        return "scope"
    if "(" in h:
        return "function"
    return "initializer"


def function_name(head):
    """The name before the parameter list of a signature (qualified, operators kept)."""
    h = " ".join(head.split())
    # The name is the (qualified) identifier just before the first parenthesis.
    m = re.search(r"((?:[A-Za-z_][A-Za-z_0-9]*\s*::\s*)*(?:operator\s*[^\s(]+|~?[A-Za-z_][A-Za-z_0-9]*))\s*\(", h)
    return re.sub(r"\s+", "", m.group(1)) if m else h[:40]


def skip_braces(code, i):
    """The offset just past the brace group that opens at code[i]."""
    depth = 0
    for j in range(i, len(code)):
        if code[j] == "{":
            depth += 1
        elif code[j] == "}":
            depth -= 1
            if depth == 0:
                return j + 1
    return len(code)


def scan(text):
    """(name, first line, last line) of every function defined in the text."""
    code = blank_comments_and_literals(text)
    line_of = []
    line = 1
    for ch in code:
        line_of.append(line)
        if ch == "\n":
            line += 1
    functions = []
    stack = []  # kinds of the open braces
    head_start = 0  # offset where the current declaration's text begins
    i, n = 0, len(code)
    while i < n:
        c = code[i]
        in_function = any(isinstance(k, tuple) for k in stack)
        if c == "{":
            if in_function:
                stack.append("inner")
                i += 1
                continue
            head = code[head_start:i]
            if head.count("(") > head.count(")"):
                # A brace inside parentheses (a default argument `= {}`, a braced
                # argument) belongs to the declaration being read.
                i = skip_braces(code, i)
                continue
            kind = head_kind(head)
            if kind == "function" and re.search(r"\)\s*(noexcept\s*)?:(?!:)", " ".join(head.split())):
                # In a member initializer list, `name{...}` initializes a member.
                before = code[head_start:i].rstrip()
                if before and (before[-1].isalnum() or before[-1] in "_>"):
                    tail = IDENT.findall(before[-40:])
                    if tail and tail[-1] not in ("const", "noexcept", "override", "final", "mutable"):
                        i = skip_braces(code, i)
                        continue
            if kind == "function":
                first = head_start + (len(head) - len(head.lstrip()))
                stack.append(("function", line_of[first], function_name(head)))
            else:
                stack.append(kind)
            head_start = i + 1
        elif c == "}":
            top = stack.pop() if stack else "block"
            if isinstance(top, tuple):
                _, first, name = top
                functions.append((name, first, line_of[i]))
            if not any(isinstance(k, tuple) for k in stack):
                head_start = i + 1
        elif c == ";" and not in_function:
            head_start = i + 1
        elif c == ":" and not in_function:
            # `public:` and friends end a declaration's text inside a class.
            m = re.search(r"\b(public|private|protected)\s*$", code[head_start:i])
            if m and (i + 1 >= n or code[i + 1] != ":"):
                head_start = i + 1
        i += 1
    return functions


def main(argv):
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # quietly, into `head`
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dirs", nargs="*")
    parser.add_argument("--function-lines", type=int, default=150)
    parser.add_argument("--file-lines", type=int, default=600)
    parser.add_argument("--all", action="store_true", help="print every function's length, longest first")
    args = parser.parse_args(argv[1:])
    root = Path(__file__).resolve().parent.parent
    dirs = [Path(d) for d in args.dirs] or [root / "src"]
    files = sorted(p for d in dirs for p in d.rglob("*") if p.suffix in (".h", ".hpp", ".cpp", ".cc"))
    offenders = []
    everything = []
    for path in files:
        text = path.read_text()
        lines = text.count("\n") + (0 if text.endswith("\n") or not text else 1)
        shown = path.relative_to(root) if path.is_relative_to(root) else path
        if lines > args.file_lines:
            offenders.append(f"{shown}: {lines} lines (file)")
        for name, first, last in scan(text):
            length = last - first + 1
            everything.append((length, f"{shown}:{first}: {name}: {length} lines"))
            if length > args.function_lines:
                offenders.append(f"{shown}:{first}: {name}: {length} lines")
    if args.all:
        for _, text in sorted(everything, key=lambda e: -e[0]):
            print(text)
        return 0
    for o in offenders:
        print(o)
    return 1 if offenders else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
