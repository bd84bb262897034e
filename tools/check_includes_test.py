#!/usr/bin/env python3
"""Unit tests of tools/check_includes.py on small trees written to a temporary folder, and on a
copy of the project's own layers with one forbidden include added (when PYRO_MODULE_TABLE names
the build's pyro_modules.json, as the check_includes_test ctest does)."""

import contextlib
import io
import json
import os
import shutil
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_includes  # noqa: E402

PROJECT_ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def module(folder, public=(), private=(), files=()):
    return {"folder": folder, "files": list(files), "public": list(public),
            "private": list(private)}


class TreeTest(unittest.TestCase):
    """A tree with engine/core, engine/gpu, components, systems/{a,b}, the application module
    tools/app and the command line tools/cli (no module), each include legal."""

    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="check_includes_")
        self.addCleanup(shutil.rmtree, self.root)
        self.write("engine/core/log.h", "#pragma once\n#include <string>\n")
        self.write("engine/core/log.cpp", '#include "engine/core/log.h"\n')
        self.write("engine/gpu/gl.h", "#pragma once\n#include <epoxy/gl.h>\n")
        self.write("engine/gpu/gl.cpp",
                   '#include "engine/gpu/gl.h"\n#include "engine/core/log.h"\n')
        self.write("components/pose.h", '#pragma once\n#include <glm/vec3.hpp>\n'
                   '#include "engine/core/log.h"\n')
        self.write("systems/a/a.h", '#pragma once\n#include "components/pose.h"\n')
        self.write("systems/a/a.cpp", '#include "systems/a/a.h"\n#include "engine/gpu/gl.h"\n')
        self.write("systems/b/b.h", '#pragma once\n#include "systems/a/a.h"\n')
        self.write("systems/b/b.cpp", '#include "b.h"\n')
        self.write("tools/app/app.h", '#pragma once\n#include "systems/b/b.h"\n')
        self.write("tools/app/app.cpp", '#include "tools/app/app.h"\n')
        self.write("tools/cli/main.cpp", '#include "tools/app/app.h"\n#include "tests/x.h"\n')
        self.table = {
            "modules": {
                "engine_core": module("engine/core"),
                "engine_gpu": module("engine/gpu", public=["epoxy"], private=["engine_core"]),
                "components": module("components", public=["engine_core", "glm"]),
                "system_a": module("systems/a", public=["components"], private=["engine_gpu"]),
                "system_b": module("systems/b", public=["system_a"]),
                "tool_app": module("tools/app", public=["system_b"]),
            },
            "third_party": {"epoxy": ["epoxy/"], "glm": ["glm/"], "glfw": ["GLFW/"]},
        }

    def write(self, path, text):
        full = os.path.join(self.root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "w", encoding="utf-8") as f:
            f.write(text)

    def append(self, path, text):
        with open(os.path.join(self.root, path), "a", encoding="utf-8") as f:
            f.write(text)

    def check(self):
        """(exit status, printed lines) of the script on the tree and the table."""
        table = os.path.join(self.root, "modules.json")
        with open(table, "w", encoding="utf-8") as f:
            json.dump(self.table, f)
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            status = check_includes.main(["--modules", table, "--root", self.root])
        return status, out.getvalue().splitlines()

    def assert_fails(self, *fragments):
        status, lines = self.check()
        self.assertEqual(status, 1, lines)
        text = "\n".join(lines)
        for fragment in fragments:
            self.assertIn(fragment, text)

    def test_legal_tree_passes(self):
        status, lines = self.check()
        self.assertEqual(status, 0, lines)

    def test_engine_including_components_fails(self):
        self.append("engine/core/log.cpp", '#include "components/pose.h"\n')
        self.assert_fails("engine/core/log.cpp:2", "files under engine/ may include only engine/")

    def test_engine_including_systems_fails(self):
        self.append("engine/gpu/gl.h", '#include "systems/a/a.h"\n')
        self.assert_fails("engine/gpu/gl.h:3", "includes systems/a/a.h")

    def test_components_including_systems_fails(self):
        self.append("components/pose.h", '#include "systems/b/b.h"\n')
        self.assert_fails("components/pose.h:4", "may include only components/ and engine/")

    def test_system_including_undeclared_system_fails(self):
        self.append("systems/a/a.cpp", '#include "systems/b/b.h"\n')
        # a -> b is undeclared; declaring it would close the cycle a -> b -> a.
        self.assert_fails("systems/a/a.cpp:3", "module system_a does not depend on system_b")
        self.table["modules"]["system_a"]["private"].append("system_b")
        self.assert_fails("cycle between modules: system_a -> system_b -> system_a")

    def test_system_including_tools_fails(self):
        self.append("systems/a/a.cpp", '#include "tools/app/app.h"\n')
        self.assert_fails("systems/a/a.cpp:3", "systems/ never includes tools/")

    def test_tools_module_including_tests_fails(self):
        self.append("tools/app/app.cpp", '#include "tests/support/world.h"\n')
        self.assert_fails("tools/app/app.cpp:2", "files under tools/ may include only")

    def test_tools_module_including_undeclared_system_fails(self):
        self.append("tools/app/app.cpp", '#include "engine/gpu/gl.h"\n')
        self.assert_fails("tools/app/app.cpp:2", "module tool_app does not depend on engine_gpu")

    def test_tools_outside_module_folders_are_not_checked(self):
        self.write("tools/app/extra/extra.cpp", "int extra = 0;\n")
        self.table["modules"]["tool_app"]["folder"] = "tools/app/extra"
        self.table["modules"]["tool_app"]["public"] = []
        self.write("tools/app/app.cpp", "int app = 0;\n")
        self.write("tools/app/app.h", "#pragma once\n")
        status, lines = self.check()
        self.assertEqual(status, 0, lines)  # tools/app itself is no module folder now: unchecked

    def test_private_dependency_in_a_header_fails(self):
        self.append("systems/a/a.h", '#include "engine/gpu/gl.h"\n')
        self.assert_fails("systems/a/a.h:3", "a PRIVATE dependency of system_a")

    def test_public_dependency_no_header_uses_fails(self):
        self.table["modules"]["engine_gpu"]["private"] = []
        self.table["modules"]["engine_gpu"]["public"].append("engine_core")
        self.assert_fails("engine_gpu: declares engine_core PUBLIC", "make it PRIVATE")

    def test_unused_dependency_fails(self):
        self.table["modules"]["system_b"]["private"] = ["engine_gpu"]
        self.assert_fails("system_b: declares engine_gpu but no file of it includes")

    def test_undeclared_third_party_fails(self):
        self.append("systems/b/b.cpp", "#include <GLFW/glfw3.h>\n")
        self.assert_fails("systems/b/b.cpp:2", "module system_b does not depend on glfw")

    def test_file_outside_every_module_fails(self):
        self.write("systems/c/c.cpp", "int c = 0;\n")
        self.assert_fails("systems/c/c.cpp: belongs to no module")

    def test_files_claimed_by_a_module_leave_the_folder_module(self):
        self.write("engine/gpu/window.h", "#pragma once\n")
        self.write("engine/gpu/window.cpp",
                   '#include "engine/gpu/window.h"\n#include <GLFW/glfw3.h>\n')
        self.table["modules"]["engine_window"] = module(
            "engine/gpu", private=["glfw"], files=["engine/gpu/window.h", "engine/gpu/window.cpp"])
        status, lines = self.check()
        self.assertEqual(status, 0, lines)
        self.append("systems/a/a.cpp", '#include "engine/gpu/window.h"\n')
        self.assert_fails("module system_a does not depend on engine_window")


@unittest.skipUnless(os.environ.get("PYRO_MODULE_TABLE"), "PYRO_MODULE_TABLE names no build")
class ProjectTest(unittest.TestCase):
    """The project's own layers, copied, pass; one forbidden include makes them fail."""

    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="check_includes_project_")
        self.addCleanup(shutil.rmtree, self.root)
        for layer in check_includes.LAYERS:
            shutil.copytree(os.path.join(PROJECT_ROOT, layer), os.path.join(self.root, layer))
        self.table = os.environ["PYRO_MODULE_TABLE"]

    def check(self):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            status = check_includes.main(["--modules", self.table, "--root", self.root])
        return status, out.getvalue()

    def test_copy_passes_and_an_upward_include_fails(self):
        status, text = self.check()
        self.assertEqual(status, 0, text)
        with open(os.path.join(self.root, "engine/core/user_error.h"), "a", encoding="utf-8") as f:
            f.write('#include "components/camera.h"\n')
        status, text = self.check()
        self.assertEqual(status, 1, text)
        self.assertIn("engine/core/user_error.h", text)
        self.assertIn("files under engine/ may include only engine/", text)


if __name__ == "__main__":
    unittest.main()
