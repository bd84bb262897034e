#!/usr/bin/env python3
"""Tests of tools/check_function_length.py on small source trees written to a temp folder."""
import pathlib
import sys
import tempfile
import unittest
from contextlib import redirect_stderr, redirect_stdout
from io import StringIO

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools"))
import check_function_length as checker  # noqa: E402


def function(name, lines, head="void", params="int x"):
    """A function of exactly `lines` lines: signature, body statements, closing brace."""
    body = [f"  x += {k};" for k in range(lines - 2)]
    return "\n".join([f"{head} {name}({params}) {{"] + body + ["}"]) + "\n"


class FindFunctions(unittest.TestCase):
    def lengths(self, text):
        return {name: last - first + 1 for name, first, last in checker.find_functions(text)}

    def test_counts_from_the_signature_to_the_closing_brace(self):
        text = function("eighty", 80) + "\n" + function("eighty_one", 81)
        self.assertEqual(self.lengths(text), {"eighty": 80, "eighty_one": 81})

    def test_template_and_multi_line_signatures_count(self):
        text = "template <class T>\nint f(T a,\n      T b) {\n  return a + b;\n}\n"
        self.assertEqual(self.lengths(text), {"f": 5})

    def test_braces_in_comments_strings_and_raw_strings_are_ignored(self):
        text = ('void g() {\n  // }\n  /* { { */\n  const char* s = "}}";\n  char c = \'}\';\n'
                '  const char* glsl = R"(void main() { } })";\n  int n = 1\'000;\n}\n'
                "void h() {}\n")
        self.assertEqual(self.lengths(text), {"g": 8, "h": 1})

    def test_namespaces_and_classes_are_looked_into_enums_and_initialisers_are_not(self):
        text = ("namespace a { namespace {\n"
                "enum class E : int { x, y };\n"
                "const int table[] = {1, 2};\n"
                "struct S : Base<int> {\n public:\n  int m() const { return 1; }\n"
                "  S(int v) : v_{v}, w_(v) {\n    m();\n  }\n  int v_, w_;\n};\n"
                "}  // namespace\n}  // namespace a\n")
        self.assertEqual(self.lengths(text), {"m": 1, "S": 3})

    def test_lambdas_count_towards_their_function_and_control_blocks_are_not_functions(self):
        text = ("Sys make() {\n  return {\"n\", [](World& w) {\n    if (w.ok()) {\n"
                "      w.run();\n    }\n  }};\n}\n"
                "Runtime::Runtime(const Options& o)\n    : f_(o.f ? o.f : std::function<void()>([] { g(); })) {\n"
                "  f_();\n}\n")
        self.assertEqual(self.lengths(text), {"make": 7, "Runtime::Runtime": 4})

    def test_preprocessor_lines_are_ignored(self):
        text = "#define OPEN {\n#define M(x) \\\n  { x }\nvoid k() {\n#if 1\n  OPEN\n#endif\n}\n"
        self.assertEqual(self.lengths(text), {"k": 5})


class CommandLine(unittest.TestCase):
    def run_checker(self, files, allow=None, extra=()):
        with tempfile.TemporaryDirectory() as d:
            root = pathlib.Path(d)
            for rel, text in files.items():
                (root / rel).parent.mkdir(parents=True, exist_ok=True)
                (root / rel).write_text(text)
            args = ["--root", str(root), *extra]
            if allow is not None:
                (root / "allow.txt").write_text(allow)
                args += ["--allow", str(root / "allow.txt")]
            out, err = StringIO(), StringIO()
            with redirect_stdout(out), redirect_stderr(err):
                status = checker.main(args)
            return status, out.getvalue(), err.getvalue()

    def test_a_long_function_under_engine_fails_naming_file_line_and_length(self):
        status, _, err = self.run_checker({"engine/a.cpp": "\n" + function("too_long", 81),
                                           "systems/s/b.cpp": function("fine", 80)})
        self.assertEqual(status, 1)
        self.assertIn("engine/a.cpp:2: too_long is 81 lines, over the limit of 80", err)
        self.assertNotIn("fine", err)

    def test_short_functions_pass(self):
        status, out, err = self.run_checker({"engine/a.cpp": function("f", 80),
                                             "systems/s/b.h": function("g", 3, head="inline int")})
        self.assertEqual((status, err), (0, ""))
        self.assertIn("2 files", out)

    def test_the_allow_list_admits_named_offenders_only(self):
        files = {"engine/a.cpp": function("long_a", 90), "systems/b.cpp": function("long_b", 90)}
        status, out, err = self.run_checker(files, allow="# still to split\nengine/a.cpp: long_a\n")
        self.assertEqual(status, 1)
        self.assertIn("long_a is 90 lines (allowed", out)
        self.assertIn("systems/b.cpp:1: long_b is 90 lines", err)
        status, _, err = self.run_checker(files, allow="engine/a.cpp: long_a\nsystems/b.cpp: long_b\n")
        self.assertEqual((status, err), (0, ""))

    def test_a_stale_allow_list_entry_fails(self):
        status, _, err = self.run_checker({"engine/a.cpp": function("now_short", 10),
                                           "systems/b.cpp": ""},
                                          allow="engine/a.cpp: now_short\n")
        self.assertEqual(status, 1)
        self.assertIn("`engine/a.cpp: now_short` is no longer over 80 lines", err)

    def test_bad_usage_exits_two(self):
        status, _, err = self.run_checker({"engine/a.cpp": ""}, allow="no colon here\n")
        self.assertEqual(status, 2)
        self.assertIn("allow.txt:1: expected `path: function`", err)
        status, _, err = self.run_checker({"engine/a.cpp": ""}, extra=["missing_folder"])
        self.assertEqual(status, 2)
        self.assertIn("missing_folder: no such file or folder", err)


if __name__ == "__main__":
    unittest.main()
