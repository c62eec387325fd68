#!/usr/bin/env python3
"""Functions and files in the C++ sources that are longer than a limit.

    python3 scripts/long_functions.py [--function-lines N] [--file-lines M] [DIR ...]

DIR defaults to src/ of this repository; N to 150, M to 600. A function's length is
the lines from the first line of its signature (its template line, if any, included;
comments above it excluded) to the line of its closing brace, both counted. A lambda
or a local class is part of the function it is written in, not a function of its own;
a lambda outside any function (`const auto k = [] {...}();` at namespace scope, or
passed as an argument there) is a function of its own, from its `[` on. A file's
length is its number of lines (as `wc -l`, plus one if the last line has no newline).

The scan matches braces on the text with comments, string and character literals
(prefixed and raw ones too) blanked out, and of each `#if ... #endif` only the first
branch kept (the others blanked); it knows namespaces, classes, structs, unions,
enums, `extern "C"` blocks, brace initializers, braces inside a parameter list (a
default argument `= {}`) and constructors' member initializer lists. It does not
expand macros: a macro that opens or closes a brace would mislead it (twb has none).
Files are read as UTF-8.

Prints each offender as `path:line: name: N lines` (files as `path: N lines`), and
exits 1 if there is any, 0 otherwise; --all prints every function's length instead,
and exits 0. A file whose braces do not balance (a `}` with nothing open, or a brace
still open at its end) is an error: its name and line on stderr, status 2.
"""
import argparse
import re
import signal
import sys
from pathlib import Path

IDENT = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")
# A preprocessing number: digits, letters, `.`, digit separators, exponents' signs.
PP_NUMBER = re.compile(r"\.?[0-9](?:'[0-9A-Za-z_]|[eEpP][+-]|[0-9A-Za-z_.])*")
SCOPE_KEYWORDS = ("class", "struct", "union", "enum")
LITERAL_PREFIXES = ("u8", "u", "U", "L")


class Unbalanced(Exception):
    """Braces that do not balance: a `}` with nothing open, or a `{` never closed."""

    def __init__(self, line, what):
        super().__init__(f"line {line}: {what}")
        self.line = line


def blank(text):
    """Blanks (spaces, newlines kept) in place of every character but newlines."""
    return re.sub(r"[^\n]", " ", text)


def blank_comments_and_literals(text):
    """The text with comments, literals and preprocessor lines replaced by spaces, and
    of each #if ... #endif only the first branch kept, newlines kept, so that offsets
    and line numbers stay those of the file."""
    out = []
    directives = []  # (offset, name) of each preprocessor line
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
            out.append(blank(text[i:j]))
            i = j
        elif c.isalpha() or c == "_":
            m = IDENT.match(text, i)
            word, j = m.group(0), m.end()
            quote = text[j] if j < n else ""
            raw = word.endswith("R") and word[:-1] in LITERAL_PREFIXES + ("",)
            if quote == '"' and raw:
                # R"delimiter( ... )delimiter", with any prefix (u8R, LR, ...).
                d = re.match(r'"([^()\\\s"]{0,16})\(', text[j:])
                if d:
                    close = text.find(")" + d.group(1) + '"', j + d.end())
                    k = n if close < 0 else close + len(d.group(1)) + 2
                    out.append(" " * (j - i) + blank(text[j:k]))
                    i = k
                    continue
            if quote in ("'", '"') and word in LITERAL_PREFIXES:
                out.append(" " * (j - i))  # the literal itself is blanked next
            else:
                out.append(word)
            i = j
        elif c.isdigit() or (c == "." and i + 1 < n and text[i + 1].isdigit()):
            # A digit separator (1'000) is not a character literal.
            m = PP_NUMBER.match(text, i)
            out.append(m.group(0))
            i = m.end()
        elif c in "\"'":
            # Up to the closing quote; a newline ends an unterminated literal.
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1 if j < n and text[j] == c else j, n)
            out.append(blank(text[i:j]))
            i = j
        elif c == "#" and text[text.rfind("\n", 0, i) + 1:i].strip() == "":
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
            name = re.match(r"#\s*([A-Za-z]*)", text[i:k]).group(1)
            directives.append((sum(map(len, out)), name))
            out.append(blank(text[i:k]))
            i = k
        else:
            out.append(c)
            i += 1
    return keep_first_branches("".join(out), directives)


def keep_first_branches(code, directives):
    """The code with everything from each conditional's first #elif or #else to its
    #endif blanked: only the first branch of each is read."""
    cut = []  # (start, end) of the branches blanked
    open_ = []  # for each #if open: the offset of its first #elif/#else, if any yet
    for offset, name in directives:
        if name in ("if", "ifdef", "ifndef"):
            open_.append(None)
        elif name in ("elif", "else", "elifdef", "elifndef"):
            if open_ and open_[-1] is None:
                open_[-1] = offset
        elif name == "endif" and open_:
            first_other = open_.pop()
            if first_other is not None:
                cut.append((first_other, offset))
    for first_other in open_:
        if first_other is not None:
            cut.append((first_other, len(code)))
    for a, b in cut:
        code = code[:a] + blank(code[a:b]) + code[b:]
    return code


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
    stripped = without_template(h)
    if re.match(r"^(typedef\s+)?(%s)\b" % "|".join(SCOPE_KEYWORDS), stripped) and "(" not in stripped.split(":")[0]:
        return "scope"
    if "(" in h:
        return "function"
    return "initializer"


def without_template(h):
    """h without the `template <...>` lines it begins with (their `<>` balanced, a `>`
    inside parentheses not counted)."""
    while True:
        m = re.match(r"template\s*<", h)
        if not m:
            return h
        angle, paren = 1, 0
        for k in range(m.end(), len(h)):
            if h[k] in "([":
                paren += 1
            elif h[k] in ")]":
                paren -= 1
            elif paren == 0 and h[k] == "<":
                angle += 1
            elif paren == 0 and h[k] == ">":
                angle -= 1
                if angle == 0:
                    break
        else:
            return h
        h = h[k + 1:].lstrip()


QUALIFIER = r"(?:[A-Za-z_][A-Za-z_0-9]*\s*(?:<[^<>()]*>)?\s*::\s*)*"
OPERATOR_NAME = re.compile(r"(%soperator\s*(?:\(\s*\)|\[\s*\]|(?:new|delete)(?:\s*\[\s*\])?|[^\s\w(]+|"
                           r"[A-Za-z_][\w:<>,\s*&]*?))\s*\(" % QUALIFIER)
PLAIN_NAME = re.compile(r"(%s~?[A-Za-z_][A-Za-z_0-9]*(?:\s*<[^<>()]*>)?)\s*$" % QUALIFIER)
# Attributes, which hold parentheses of their own: [[...]], __attribute__((...)), alignas(...).
ATTRIBUTES = re.compile(r"\[\[.*?\]\]|\b__attribute__\s*\(\((?:[^()]|\([^()]*\))*\)\)|\balignas\s*\([^()]*\)")
NOT_NAMES = ("decltype", "alignas", "noexcept", "requires", "__attribute__", "__declspec", "sizeof")


def function_name(head):
    """The name before the parameter list of a signature (qualified, operators kept),
    any `template <...>` before it aside."""
    h = ATTRIBUTES.sub(" ", without_template(" ".join(head.split())))
    m = OPERATOR_NAME.search(h)
    if m:
        name = re.sub(r"\s+", "", m.group(1))
        return re.sub(r"operator(?=[A-Za-z_])", "operator ", name)  # operator bool
    # The (qualified) name before the first parenthesis outside parentheses and
    # template arguments (std::function<void(int)> f(...): f), decltype(...) aside.
    angle = paren = 0
    for k, ch in enumerate(h):
        if ch == "<":
            angle += 1
        elif ch == ">" and angle > 0 and h[k - 1] != "-":
            angle -= 1
        elif ch == ")":
            paren -= 1
        elif ch == "(":
            if angle == 0 and paren == 0:
                m = PLAIN_NAME.search(h[:k])
                if m and re.sub(r"\s+", "", m.group(1)) not in NOT_NAMES:
                    return re.sub(r"\s+", "", m.group(1))
            paren += 1
    return h[:40]


# A lambda's introducer and declarator up to its body's `{`: [captures] <template>
# (parameters) specifiers -> return type.
LAMBDA = re.compile(r"\[[^\[\]{};]*\]\s*(?:<[^{};]*?>\s*)?(?:\((?:[^()]|\([^()]*\))*\)\s*)?"
                    r"(?:(?:mutable|constexpr|consteval|static|noexcept(?:\s*\([^()]*\))?)\s*)*(?:->[^{};=]*)?")


def lambda_at(head):
    """Where in head the lambda begins whose body the `{` after head opens, or None:
    the `[` of an introducer (not a subscript, an array's bound or an attribute)."""
    for k in range(len(head) - 1, -1, -1):
        if head[k] != "[" or not LAMBDA.fullmatch(head, k):
            continue
        before = head[:k].rstrip()
        if before and (before[-1].isalnum() or before[-1] in "_])[") and not re.search(r"\breturn$", before):
            return None
        return k
    return None


def skip_braces(code, i, line_of):
    """The offset just past the brace group that opens at code[i]."""
    depth = 0
    for j in range(i, len(code)):
        if code[j] == "{":
            depth += 1
        elif code[j] == "}":
            depth -= 1
            if depth == 0:
                return j + 1
    raise Unbalanced(line_of[i], "a { never closed")


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
    opened = []  # and their offsets
    head_start = 0  # offset where the current declaration's text begins
    i, n = 0, len(code)
    while i < n:
        c = code[i]
        in_function = any(isinstance(k, tuple) for k in stack)
        if c == "{":
            if in_function:
                stack.append("inner")
                opened.append(i)
                i += 1
                continue
            head = code[head_start:i]
            in_initializer_list = re.search(r"\)\s*(noexcept\s*)?:(?!:)", " ".join(head.split()))
            k = lambda_at(head)
            if k is not None and not in_initializer_list:
                # A lambda outside any function: a function of its own. The declaration
                # it is part of goes on after it (head_start stays).
                stack.append(("lambda", line_of[head_start + k], lambda_name(head[:k])))
                opened.append(i)
                i += 1
                continue
            if head.count("(") > head.count(")"):
                # A brace inside parentheses (a default argument `= {}`, a braced
                # argument) belongs to the declaration being read.
                i = skip_braces(code, i, line_of)
                continue
            kind = head_kind(head)
            if kind == "function" and in_initializer_list:
                # In a member initializer list, `name{...}` initializes a member.
                before = code[head_start:i].rstrip()
                if before and (before[-1].isalnum() or before[-1] in "_>"):
                    tail = IDENT.findall(before[-40:])
                    if tail and tail[-1] not in ("const", "noexcept", "override", "final", "mutable"):
                        i = skip_braces(code, i, line_of)
                        continue
            if kind == "function":
                first = head_start + (len(head) - len(head.lstrip()))
                stack.append(("function", line_of[first], function_name(head)))
            else:
                stack.append(kind)
            opened.append(i)
            head_start = i + 1
        elif c == "}":
            if not stack:
                raise Unbalanced(line_of[i], "a } with nothing open")
            top = stack.pop()
            opened.pop()
            if isinstance(top, tuple):
                kind, first, name = top
                functions.append((name, first, line_of[i]))
            lambda_closed = isinstance(top, tuple) and top[0] == "lambda"
            if not any(isinstance(k, tuple) for k in stack) and not lambda_closed:
                head_start = i + 1
        elif c == ";" and not in_function:
            head_start = i + 1
        elif c == ":" and not in_function:
            # `public:` and friends end a declaration's text inside a class.
            m = re.search(r"\b(public|private|protected)\s*$", code[head_start:i])
            if m and (i + 1 >= n or code[i + 1] != ":"):
                head_start = i + 1
        i += 1
    if stack:
        raise Unbalanced(line_of[opened[0]], "a { never closed")
    return functions


def lambda_name(before):
    """A lambda's name: `lambda` and what it initializes or is passed to, from the text
    before its `[`."""
    h = " ".join(before.split())
    m = re.search(r"([A-Za-z_][A-Za-z_0-9]*)\s*(?:\[[^\]]*\]\s*)?(?:=|\{)\s*$", h)
    if m:
        return f"lambda ({m.group(1)})"
    m = re.search(r"(%s[A-Za-z_][A-Za-z_0-9]*)\s*(?:<[^<>]*>)?\s*\([^()]*$" % QUALIFIER, h)
    if m:
        return "lambda (argument of %s)" % re.sub(r"\s+", "", m.group(1))
    return "lambda"


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
    unbalanced = False
    for path in files:
        text = path.read_text(encoding="utf-8")
        lines = text.count("\n") + (0 if text.endswith("\n") or not text else 1)
        shown = path.relative_to(root) if path.is_relative_to(root) else path
        if lines > args.file_lines:
            offenders.append(f"{shown}: {lines} lines (file)")
        try:
            functions = scan(text)
        except Unbalanced as e:
            print(f"{shown}:{e.line}: the braces do not balance ({e}): not scanned", file=sys.stderr)
            unbalanced = True
            continue
        for name, first, last in functions:
            length = last - first + 1
            everything.append((length, f"{shown}:{first}: {name}: {length} lines"))
            if length > args.function_lines:
                offenders.append(f"{shown}:{first}: {name}: {length} lines")
    if args.all:
        for _, text in sorted(everything, key=lambda e: -e[0]):
            print(text)
    else:
        for o in offenders:
            print(o)
    return 2 if unbalanced else 0 if args.all else 1 if offenders else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
