#!/usr/bin/env python3
"""Refuses two sources of one unity build that define the same file-scope name.

The test suite and every module are compiled as unity builds (CMakeLists.txt, cmake/
PyroModules.cmake: several sources to a unit), so the helpers one source keeps in its anonymous
namespace share a unit with its neighbours. Two definitions of one name there fail to compile, or
worse, two overloads of one name compile and a call silently reaches the other file's helper.

  --root SOURCE_DIR            every name defined at file scope (column 0: functions, types,
                               constants) in more than one test file (any two may share a unit);
  --modules pyro_modules.json  every name defined in an anonymous namespace or as a `static` at
                               file scope in more than one source of one module (or of the
                               command line's library, tools/pyro).

Exit 1 and one line per shared name if any.
"""
import argparse
import collections
import json
import pathlib
import re
import sys

# Definitions start at column 0 (the project's namespaces are not indented).
TYPE = re.compile(r"^(?:struct|class|enum class|enum|union)\s+(\w+)\s*(?:final\s*)?[:{]")
ALIAS = re.compile(r"^using\s+(\w+)\s*=")
CONSTANT = re.compile(r"^(?:static\s+)?(?:inline\s+)?(?:constexpr|const)\s+[\w:<>,\s]+?\s+(\w+)\s*(?:\[[^\]]*\])?\s*(?:=|\{)")
MORE_CONSTANTS = re.compile(r",\s*(\w+)\s*=")
FUNCTION = re.compile(r"^(?:static\s+|inline\s+|constexpr\s+|\[\[\w+\]\]\s+)*(?:template\s*<[^>]*>\s*)?[\w:<>,\s*&]+?[\s*&](\w+)\s*\(")
# PrintTo: GoogleTest's printer, one overload per printed type by design.
NOT_NAMES = {"PrintTo", "if", "for", "while", "switch", "return", "TEST", "TEST_F", "TEST_P", "main",
             "INSTANTIATE_TEST_SUITE_P", "operator"}


def names_in(path):
    return names_in_lines(path.read_text(encoding="utf-8").splitlines())


def names_in_lines(lines):
    names = set()
    for line in lines:
        if not line or line[0] in " \t#/}" or line.startswith(("namespace", "TEST", "INSTANTIATE")):
            continue
        if ALIAS.match(line):  # the same alias twice is allowed; two targets fail to compile
            continue
        for pattern in (TYPE, CONSTANT):
            m = pattern.match(line)
            if m:
                names.add(m.group(1))
                if pattern is CONSTANT:
                    names.update(MORE_CONSTANTS.findall(line[m.end():]))
                break
        else:
            m = FUNCTION.match(line)
            if m and m.group(1) not in NOT_NAMES:
                names.add(m.group(1))
    return names


NAMESPACE_OPEN = re.compile(r"^namespace\s*([\w:]*)\s*\{")
NAMESPACE_CLOSE = re.compile(r"^\}\s*//\s*namespace")


def internal_lines(path):
    """The column-0 lines of a source that define internal names: inside an anonymous namespace,
    or `static` outside any class."""
    stack = []
    for line in path.read_text(encoding="utf-8").splitlines():
        opened = NAMESPACE_OPEN.match(line)
        if opened:
            stack.append(opened.group(1))
            continue
        if NAMESPACE_CLOSE.match(line) and stack:
            stack.pop()
            continue
        if "" in stack or line.startswith("static "):
            yield line


def module_sources(table, root):
    """Each module's .cpp files, relative to root, as the build assigns them."""
    claimed = {f for m in table["modules"].values() for f in m.get("files", [])}
    for name, m in sorted(table["modules"].items()):
        if m.get("files"):
            files = [f for f in m["files"] if f.endswith(".cpp")]
        else:
            files = sorted(p.relative_to(root).as_posix() for p in (root / m["folder"]).rglob("*.cpp"))
            files = [f for f in files if f not in claimed]
        yield name, files
    # The command line (tools/pyro) is no module but one library, pyro_cli, built the same way.
    cli = root / "tools" / "pyro"
    if cli.is_dir():
        yield "pyro_cli", sorted(p.relative_to(root).as_posix() for p in cli.glob("*.cpp"))


def check_modules(table_path, root):
    table = json.loads(table_path.read_text(encoding="utf-8"))
    shared, count = [], 0
    for module, files in module_sources(table, root):
        where = collections.defaultdict(list)
        for f in files:
            count += 1
            for name in names_in_lines(internal_lines(root / f)):
                where[name].append(f)
        shared += [(module, n, fs) for n, fs in sorted(where.items()) if len(fs) > 1]
    for module, name, fs in shared:
        print(f"{name}: defined at file scope in {', '.join(fs)} (module {module})")
    if shared:
        print(f"check_unity_names: {len(shared)} name(s) defined in more than one source of a module; "
              "its unity build puts them together, so give each its own name (or share one helper)",
              file=sys.stderr)
        return 1
    print(f"check_unity_names: {count} module sources, no internal name defined twice in a module")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True, type=pathlib.Path)
    parser.add_argument("--modules", type=pathlib.Path)
    args = parser.parse_args()
    if args.modules:
        return check_modules(args.modules, args.root)
    tests = args.root / "tests"
    files = sorted(p for p in tests.rglob("*.cpp")
                   if "consumer" not in p.relative_to(tests).parts
                   and not re.fullmatch(r"fuzz_[a-z_]+_main\.cpp", p.name))
    where = collections.defaultdict(list)
    for f in files:
        for name in names_in(f):
            where[name].append(f.relative_to(args.root).as_posix())
    shared = {n: fs for n, fs in where.items() if len(fs) > 1}
    for name in sorted(shared):
        print(f"{name}: defined at file scope in {', '.join(shared[name])}")
    if shared:
        print(f"check_unity_names: {len(shared)} name(s) defined in more than one test file; the "
              "unity build puts test files together, so give each its own name (or share one "
              "helper from tests/support/)", file=sys.stderr)
        return 1
    print(f"check_unity_names: {len(files)} test files, no file-scope name defined twice")
    return 0


if __name__ == "__main__":
    sys.exit(main())
