#!/usr/bin/env python3
"""Refuses two test files that define the same file-scope name.

The test suite is compiled as a unity build (CMakeLists.txt: eight test files to a unit), so the
helpers one test file keeps in its anonymous namespace share a unit with seven others. Two
definitions of one name there fail to compile, or worse, two overloads of one name compile and a
call silently reaches the other file's helper. This check lists every name defined at file scope
(column 0: functions, types, constants) in more than one test file.

Usage: check_test_names.py --root SOURCE_DIR   (exit 1 and one line per shared name if any)
"""
import argparse
import collections
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
    names = set()
    for line in path.read_text(encoding="utf-8").splitlines():
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True, type=pathlib.Path)
    args = parser.parse_args()
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
        print(f"check_test_names: {len(shared)} name(s) defined in more than one test file; the "
              "unity build puts test files together, so give each its own name (or share one "
              "helper from tests/support/)", file=sys.stderr)
        return 1
    print(f"check_test_names: {len(files)} test files, no file-scope name defined twice")
    return 0


if __name__ == "__main__":
    sys.exit(main())
