#!/usr/bin/env python3
"""Fails when a C++ function under engine/, systems/ or an application folder of tools/ is longer
than the limit (80 lines).

A function's length is counted from the first line of its declaration (template line included)
to its closing brace. Comments, string literals (raw ones too) and preprocessor lines are blanked
before the braces are matched, so braces inside them do not count; lambdas count towards the
function they are written in.

  tools/check_function_length.py [--root DIR] [--limit N] [--allow FILE] [PATH ...]

PATHs (files or folders, relative to --root) default to engine, systems and the application
folders of tools/ (every folder there but the command line, tools/pyro, and the scripts'). The allow-list names
offenders that are known and still to be split, one `path: function` a line (# starts a comment);
an allowed function that is no longer too long is reported too, so the list only shrinks.
Exit status: 0 when nothing is over the limit outside the allow-list, 1 otherwise, 2 on bad usage.
"""
import argparse
import pathlib
import re
import sys

SOURCE_SUFFIXES = {".cpp", ".h", ".hpp", ".cc", ".inl"}

# What may follow a parameter list before a function body: cv- and ref-qualifiers, noexcept,
# override/final, a trailing return type, a requires-clause.
_AFTER_PARAMETERS = re.compile(
    r"\)\s*(?:(?:const|volatile|mutable|override|final|noexcept(?:\s*\([^()]*\))?|&&?|"
    r"->\s*[\w:<>,\s*&]+|requires\b.*)\s*)*$",
    re.S)
# A constructor's member-initialiser list has begun: `) :` (not `::`).
_INIT_LIST = re.compile(r"\)\s*(?:noexcept\s*)?:(?!:)", re.S)
_SCOPE = re.compile(r"(?:inline\s+)?(?:namespace|extern)\b[^()]*$", re.S)
_CLASS_HEAD = re.compile(r"\b(?:class|struct|union)\s+[\w:]+(?:\s+final)?\s*(?::[^;(){}]*)?$", re.S)
_ENUM = re.compile(r"\benum(?:\s+(?:class|struct))?(?:\s+\w+)?\s*(?::[\w:\s]+)?$", re.S)
_ACCESS = re.compile(r"^\s*(?:(?:public|private|protected)\s*:(?!:)\s*)+")
_CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|do|else|try)\b")


def blank_non_code(text):
    """Returns `text` with comments, string and character literals and preprocessor lines
    replaced by spaces (newlines kept), so that only code braces remain."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":
            # A preprocessor directive, with its backslash continuations.
            j = i
            while j < n and text[j] != "\n":
                if text[j] == "\\" and j + 1 < n and text[j + 1] == "\n":
                    j += 1
                j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        if c in " \t":
            out.append(c)
            i += 1
            continue
        at_line_start = c == "\n"
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
        elif c == "R" and i + 1 < n and text[i + 1] == '"' and not _ident_char(text, i - 1):
            m = re.match(r'R"([^()\\ ]{0,16})\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = text.find(")" + m.group(1) + '"', i + m.end())
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and _ident_char(text, i - 1) and text[i - 1].isdigit():
                out.append(" ")  # a digit separator (1'000)
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def _ident_char(text, i):
    return 0 <= i < len(text) and (text[i].isalnum() or text[i] == "_")


def _matching_brace(code, open_at):
    depth = 0
    for k in range(open_at, len(code)):
        if code[k] == "{":
            depth += 1
        elif code[k] == "}":
            depth -= 1
            if depth == 0:
                return k
    return len(code) - 1


def _function_name(head):
    """The name before the first parenthesis of a declaration head that is not inside <...>."""
    depth = 0
    for k, c in enumerate(head):
        if c == "<":
            depth += 1
        elif c == ">":
            depth = max(depth - 1, 0)
        elif c == "(" and depth == 0:
            before = head[:k].rstrip()
            m = re.search(r"(operator\s*(?:\(\)|[^\w\s(]+|\w[\w\s]*)|~?[\w:]+(?:<[^()]*>)?)$", before)
            if m:
                return re.sub(r"\s+", " ", m.group(1))
            break
    return head.strip().split("\n")[-1][:40]


def find_functions(text):
    """Yields (name, first_line, last_line) for every function body outside another function."""
    code = blank_non_code(text)
    line_of = [0] * (len(code) + 1)
    line = 1
    for k, c in enumerate(code):
        line_of[k] = line
        if c == "\n":
            line += 1
    line_of[len(code)] = line

    functions = []

    def scan(begin, end):
        """Scans code[begin:end] at a level where declarations live (file, namespace, class)."""
        head_start = begin
        k = begin
        while k < end:
            c = code[k]
            if c in ";}":
                head_start = k + 1
            elif c == "{":
                head = code[head_start:k]
                close = _matching_brace(code, k)
                stripped = head.strip()
                if head.count("(") > head.count(")") or (
                        _INIT_LIST.search(head) and re.search(r"[\w>]\s*$", head)):
                    # Inside an argument list (a lambda, a braced argument), or a brace initialiser
                    # in a constructor's init list: part of the declaration being read.
                    k = close + 1
                    continue
                if _ENUM.search(stripped):
                    pass  # enumerators hold no functions
                elif _SCOPE.match(stripped) or _CLASS_HEAD.search(stripped):
                    scan(k + 1, close)  # a namespace, class or extern block: look inside
                elif (_AFTER_PARAMETERS.search(head) or _INIT_LIST.search(head)) and not _CONTROL.match(head):
                    access = _ACCESS.match(head)
                    skipped = access.end() if access else len(head) - len(head.lstrip())
                    functions.append((_function_name(head[skipped:]), line_of[head_start + skipped],
                                      line_of[close]))
                k = close + 1
                head_start = k
                continue
            k += 1

    scan(0, len(code))
    return functions


def read_allow_list(path):
    allowed = set()
    if path is None:
        return allowed
    for number, raw in enumerate(pathlib.Path(path).read_text().splitlines(), 1):
        entry = raw.split("#", 1)[0].strip()
        if not entry:
            continue
        if ":" not in entry:
            raise ValueError(f"{path}:{number}: expected `path: function`, found {raw!r}")
        file, function = (part.strip() for part in entry.split(":", 1))
        allowed.add((file, function))
    return allowed


def source_files(root, paths):
    for p in paths:
        full = root / p
        if full.is_file():
            yield full
        elif full.is_dir():
            yield from sorted(f for f in full.rglob("*") if f.suffix in SOURCE_SUFFIXES)
        else:
            raise FileNotFoundError(f"{full}: no such file or folder")


def application_folders(root):
    """tools/<name> for every folder of tools/ but the command line (tools/pyro)."""
    tools = pathlib.Path(root) / "tools"
    if not tools.is_dir():
        return []
    return [f"tools/{d.name}" for d in sorted(tools.iterdir()) if d.is_dir() and d.name != "pyro"]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("paths", nargs="*")
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent, type=pathlib.Path)
    parser.add_argument("--limit", type=int, default=80)
    parser.add_argument("--allow", help="allow-list file: `path: function` a line")
    args = parser.parse_args(argv)
    if not args.paths:
        args.paths = ["engine", "systems"] + application_folders(args.root)
    try:
        allowed = read_allow_list(args.allow)
        files = list(source_files(args.root, args.paths))
    except (OSError, ValueError) as e:
        print(f"check_function_length: {e}", file=sys.stderr)
        return 2

    offenders, still_allowed = [], set()
    for f in files:
        rel = f.relative_to(args.root).as_posix()
        for name, first, last in find_functions(f.read_text(errors="replace")):
            length = last - first + 1
            if length <= args.limit:
                continue
            if (rel, name) in allowed:
                still_allowed.add((rel, name))
                print(f"{rel}:{first}: {name} is {length} lines (allowed for now by {args.allow})")
            else:
                offenders.append(f"{rel}:{first}: {name} is {length} lines, over the limit of {args.limit}")
    stale = sorted(allowed - still_allowed)
    for rel, name in stale:
        offenders.append(f"{args.allow}: `{rel}: {name}` is no longer over {args.limit} lines "
                         "(or no longer exists): remove it from the allow-list")
    for line in offenders:
        print(line, file=sys.stderr)
    if offenders:
        return 1
    print(f"check_function_length: {len(files)} files, no function over {args.limit} lines"
          + (f" outside the {len(still_allowed)} allowed" if still_allowed else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
