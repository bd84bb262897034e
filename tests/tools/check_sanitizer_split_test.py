#!/usr/bin/env python3
"""Tests of tools/check_sanitizer_split.py on small trees written to a temp folder, and of the
unity-name check's module mode (tools/check_unity_names.py --modules)."""
import json
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools"))
import check_sanitizer_split as split  # noqa: E402
import check_unity_names as unity  # noqa: E402

DRAWING = '#include "tests/support/rendered_frame.h"\nTEST(A, B) {}\n'
PLAIN = '#include "engine/core/rng.h"\nTEST(C, D) {}\n'


class Tree:
    def __init__(self, root):
        self.root = pathlib.Path(root)

    def write(self, path, text):
        f = self.root / path
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text(text, encoding="utf-8")


class SanitizerSplit(unittest.TestCase):
    def problems(self, files, split_text, docs="`tests/render/`"):
        with tempfile.TemporaryDirectory() as d:
            tree = Tree(d)
            for path, text in files.items():
                tree.write(path, text)
            tree.write("tests/sanitizer_split.txt", split_text)
            tree.write("docs/reliability.md", docs)
            return list(split.problems(tree.root))

    def test_a_documented_release_only_folder_covers_its_drawing_tests(self):
        found = self.problems({"tests/render/a_test.cpp": DRAWING, "tests/engine/b_test.cpp": PLAIN},
                              "release-only tests/render/ image tests\n")
        self.assertEqual(found, [])

    def test_a_drawing_test_listed_neither_way_is_refused(self):
        found = self.problems({"tests/render/a_test.cpp": DRAWING, "tests/systems/c_test.cpp": DRAWING},
                              "release-only tests/render/ image tests\n")
        self.assertEqual(len(found), 1)
        self.assertIn("tests/systems/c_test.cpp", found[0])

    def test_a_drawing_test_listed_as_sanitized_passes(self):
        found = self.problems({"tests/render/a_test.cpp": DRAWING, "tests/systems/c_test.cpp": DRAWING},
                              "release-only tests/render/ image tests\n"
                              "sanitized tests/systems/c_test.cpp its buffers\n")
        self.assertEqual(found, [])

    def test_an_undocumented_release_only_entry_is_refused(self):
        found = self.problems({"tests/render/a_test.cpp": DRAWING, "tests/tools/d_test.cpp": PLAIN},
                              "release-only tests/render/ image tests\n"
                              "release-only tests/tools/d_test.cpp slow\n")
        self.assertEqual(len(found), 1)
        self.assertIn("docs/reliability.md does not list `tests/tools/d_test.cpp`", found[0])

    def test_unknown_kinds_missing_reasons_missing_files_and_repeats_are_refused(self):
        found = self.problems({"tests/render/a_test.cpp": DRAWING},
                              "release-only tests/render/ image tests\n"
                              "sometimes tests/render/a_test.cpp why\n"
                              "sanitized tests/gone_test.cpp reason\n"
                              "sanitized tests/render/a_test.cpp\n"
                              "sanitized tests/render/a_test.cpp again\n")
        text = "\n".join(found)
        self.assertIn("kind 'sometimes'", text)
        self.assertIn("tests/gone_test.cpp names no test file", text)
        self.assertIn("has no reason", text)
        self.assertIn("listed twice", text)


class ModuleUnityNames(unittest.TestCase):
    def check(self, sources):
        with tempfile.TemporaryDirectory() as d:
            tree = Tree(d)
            for path, text in sources.items():
                tree.write(path, text)
            table = {"modules": {"m": {"folder": "engine/m", "files": []},
                                 "n": {"folder": "engine/n", "files": []}}}
            tree.write("modules.json", json.dumps(table))
            return unity.check_modules(tree.root / "modules.json", tree.root)

    def test_one_internal_name_in_two_sources_of_a_module_is_refused(self):
        helper = "namespace pyro {\nnamespace {\n\nint helper(int x) { return x; }\n\n}  // namespace\n}  // namespace pyro\n"
        other = helper.replace("int x", "double x")
        self.assertEqual(self.check({"engine/m/a.cpp": helper, "engine/m/b.cpp": other}), 1)

    def test_the_same_name_in_two_modules_or_outside_anonymous_namespaces_passes(self):
        helper = "namespace pyro {\nnamespace {\n\nint helper(int x) { return x; }\n\n}  // namespace\n}  // namespace pyro\n"
        public = "namespace pyro {\n\nint overload(int x) { return x; }\n\n}  // namespace pyro\n"
        self.assertEqual(self.check({"engine/m/a.cpp": helper, "engine/n/b.cpp": helper,
                                     "engine/m/c.cpp": public, "engine/m/d.cpp": public.replace("int x", "float x")}), 0)

    def test_file_scope_statics_count(self):
        text = "static int counter(int x) { return x; }\n"
        self.assertEqual(self.check({"engine/m/a.cpp": text, "engine/m/b.cpp": text}), 1)


if __name__ == "__main__":
    unittest.main()
