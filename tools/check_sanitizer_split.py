#!/usr/bin/env python3
"""Checks tests/sanitizer_split.txt, the list of what the sanitizer half of CI leaves out.

CI builds and runs the whole suite in Release, then again under AddressSanitizer and
UndefinedBehaviorSanitizer without the `release-only` entries of tests/sanitizer_split.txt (GL-heavy
image tests and benchmarks that mostly exercise Mesa). So that no test lands in the wrong half
unseen, this check refuses:

  * a test file outside the release-only folders that draws and reads back frames (it includes
    tests/support's frame helpers, or the bench, charts or import modules) and is listed neither
    `release-only` nor `sanitized`;
  * an entry of an unknown kind, without a reason, naming no test file or folder, or listed twice;
  * a `release-only` entry whose path docs/reliability.md does not name (every exclusion is listed
    there with its reason).

Usage: check_sanitizer_split.py --root SOURCE_DIR   (exit 1 and one line per problem)
"""
import argparse
import pathlib
import re
import sys

KINDS = ("release-only", "sanitized")
# What a test file includes when it draws frames and reads them back: the image helpers, or the
# applications that measure renders.
DRAWS_FRAMES = re.compile(
    r'^\s*#\s*include\s*"(tests/support/(rendered_frame|splat_drawing|cli_render|one_particle_scene)\.h'
    r'|tools/(bench|charts|import)/)', re.M)


def read_split(path):
    """The entries: (line number, kind, path, reason)."""
    entries = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        fields = line.split(None, 2)
        entries.append((number, fields[0], fields[1] if len(fields) > 1 else "",
                        fields[2].strip() if len(fields) > 2 else ""))
    return entries


def test_files(root):
    tests = root / "tests"
    return sorted(p.relative_to(root).as_posix() for p in tests.rglob("*.cpp")
                  if "consumer" not in p.relative_to(tests).parts
                  and not re.fullmatch(r"fuzz_[a-z_]+_main\.cpp", p.name))


def covers(entry_path, file):
    return file == entry_path or (entry_path.endswith("/") and file.startswith(entry_path))


def problems(root):
    split = root / "tests" / "sanitizer_split.txt"
    docs = (root / "docs" / "reliability.md").read_text(encoding="utf-8")
    files = test_files(root)
    entries = read_split(split)
    seen = set()
    for number, kind, path, reason in entries:
        where = f"tests/sanitizer_split.txt:{number}"
        if kind not in KINDS:
            yield f"{where}: kind '{kind}' is neither {' nor '.join(KINDS)}"
        if not reason:
            yield f"{where}: {path or 'the entry'} has no reason"
        if not any(covers(path, f) for f in files):
            yield f"{where}: {path} names no test file or folder of tests/"
        if path in seen:
            yield f"{where}: {path} is listed twice"
        seen.add(path)
        if kind == "release-only" and f"`{path}`" not in docs:
            yield f"{where}: docs/reliability.md does not list `{path}`, which CI runs in Release only"
    listed = [p for _, _, p, _ in entries]
    for f in files:
        if any(covers(p, f) for p in listed):
            continue
        if DRAWS_FRAMES.search((root / f).read_text(encoding="utf-8")):
            yield (f"{f}: draws and reads back frames but tests/sanitizer_split.txt lists it neither "
                   f"release-only (GL-heavy: the sanitizer half leaves it out) nor sanitized (both "
                   f"halves run it); add it with its reason")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True, type=pathlib.Path)
    args = parser.parse_args()
    found = list(problems(args.root))
    for p in found:
        print(p)
    if found:
        print(f"check_sanitizer_split: {len(found)} problem(s)", file=sys.stderr)
        return 1
    print("check_sanitizer_split: every test file that draws frames is in one half or both, and "
          "every release-only entry is documented")
    return 0


if __name__ == "__main__":
    sys.exit(main())
