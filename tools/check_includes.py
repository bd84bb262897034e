#!/usr/bin/env python3
"""Checks that the sources respect the layers the build declares.

The module declarations in CMakeLists.txt (cmake/PyroModules.cmake) are the one source of truth:
configuring writes them to <build>/pyro_modules.json, which this script reads. The rules:

  * every header and source under engine/, components/ and systems/ belongs to a module; under
    tools/, the folders that modules declare (tools/bench, tools/viewer, ...) are checked, while
    the command line (tools/pyro, not a module) and the scripts are not;
  * engine/ includes nothing from components/, systems/, tools/ or tests/;
  * components/ includes only engine/ and components/;
  * systems/ (the frame: what opening a run or drawing a frame executes) includes only engine/,
    components/ and systems/, never tools/ (the applications);
  * a tools/ module includes only engine/, components/, systems/ and tools/;
  * a module includes only its own files and the modules and third-party libraries it declares
    (PUBLIC or PRIVATE); a header includes only PUBLIC ones; a PUBLIC dependency is one that some
    header of the module includes (otherwise it must be PRIVATE); no declared dependency is unused;
  * the declared dependencies between modules form no cycle.

Exit status 0 when every rule holds, 1 with one line per violation (file:line: what and how to mend
it) otherwise, 2 on bad arguments. `--suggest` prints, for each module, the dependency lists its
includes call for, as they would be written in CMakeLists.txt.
"""

import argparse
import json
import os
import re
import sys

LAYERS = ("engine", "components", "systems", "tools")
# Which top-level folders a file of each layer may include from (quoted project includes).
ALLOWED_LAYERS = {
    "engine": {"engine"},
    "components": {"engine", "components"},
    "systems": {"engine", "components", "systems"},
    "tools": {"engine", "components", "systems", "tools"},
}
# Layers checked file by file only in the folders that modules declare (the rest of tools/ is
# the command line and scripts, which belong to no module).
MODULE_FOLDER_LAYERS = ("tools",)
INCLUDE_RE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".cc", ".inl")


class Modules:
    """The module table: which module owns a file, and what each module declares."""

    def __init__(self, table):
        self.modules = table["modules"]
        self.third_party = table.get("third_party", {})
        self.file_owner = {}
        self.folder_owner = {}
        for name, m in self.modules.items():
            if m.get("files"):
                for f in m["files"]:
                    self.file_owner[f] = name
            else:
                self.folder_owner[m["folder"]] = name

    def owner(self, path):
        """The module owning a path relative to the root, or None."""
        if path in self.file_owner:
            return self.file_owner[path]
        folder = os.path.dirname(path)
        while folder:
            if folder in self.folder_owner:
                return self.folder_owner[folder]
            folder = os.path.dirname(folder)
        return None

    def third_party_of(self, include):
        for name, prefixes in self.third_party.items():
            if any(include.startswith(p) for p in prefixes):
                return name
        return None

    def declared(self, module):
        m = self.modules[module]
        return set(m.get("public", [])), set(m.get("private", []))


def layer_roots(root, modules):
    """The folders walked for each layer: the whole layer, or its module folders."""
    for layer in LAYERS:
        if layer not in MODULE_FOLDER_LAYERS:
            yield os.path.join(root, layer)
            continue
        folders = {m["folder"] for m in modules.modules.values()
                   if m["folder"].split("/", 1)[0] == layer}
        for folder in sorted(folders):
            yield os.path.join(root, folder)


def layer_files(root, modules):
    seen = set()
    for top in layer_roots(root, modules):
        for folder, dirs, files in os.walk(top):
            dirs.sort()
            for f in sorted(files):
                path = os.path.relpath(os.path.join(folder, f), root).replace(os.sep, "/")
                if f.endswith(SOURCE_SUFFIXES) and path not in seen:
                    seen.add(path)
                    yield path


def is_header(path):
    return path.endswith((".h", ".hpp", ".inl"))


def includes_of(root, path):
    """(line number, kind, target) for each #include of a file; kind is 'project' or a third-party
    name; target is the included path relative to the root (or the text as written)."""
    with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            m = INCLUDE_RE.match(line)
            if not m:
                continue
            text = m.group(2)
            top = text.split("/", 1)[0]
            if top in LAYERS or top in ("tools", "tests"):
                yield number, "project", text
            elif m.group(1) == '"':
                sibling = os.path.normpath(os.path.join(os.path.dirname(path), text))
                if os.path.isfile(os.path.join(root, sibling)):
                    yield number, "project", sibling.replace(os.sep, "/")
            else:
                yield number, "third_party", text


class Checker:
    def __init__(self, root, modules):
        self.root = root
        self.modules = modules
        self.errors = []
        # module -> dependency -> set of (is_header)
        self.used = {name: {} for name in modules.modules}

    def error(self, where, message):
        self.errors.append(f"{where}: {message}")

    def check_file(self, path):
        module = self.modules.owner(path)
        if module is None:
            self.error(path, "belongs to no module: declare one for its folder in CMakeLists.txt "
                       "(pyro_add_module)")
            return
        layer = path.split("/", 1)[0]
        for number, kind, target in includes_of(self.root, path):
            where = f"{path}:{number}"
            if kind == "project":
                dep = self.check_project_include(where, layer, target)
            else:
                dep = self.modules.third_party_of(target)
                if dep is None:
                    continue
            if dep is None or dep == module:
                continue
            self.used[module].setdefault(dep, set()).add(is_header(path))
            self.check_declared(where, module, dep, target, is_header(path))

    def check_project_include(self, where, layer, target):
        top = target.split("/", 1)[0]
        if layer == "systems" and top == "tools":
            self.error(where, f"includes {target}: systems/ never includes tools/ (the frame "
                       "stands below the applications; move what both need into systems/)")
            return None
        if top not in ALLOWED_LAYERS[layer]:
            allowed = " and ".join(f"{a}/" for a in sorted(ALLOWED_LAYERS[layer]))
            self.error(where, f"includes {target}: files under {layer}/ may include only "
                       f"{allowed}")
            return None
        dep = self.modules.owner(target)
        if dep is None:
            self.error(where, f"includes {target}, which belongs to no module")
        return dep

    def check_declared(self, where, module, dep, target, header):
        public, private = self.modules.declared(module)
        if dep not in public and dep not in private:
            kind = "PUBLIC" if header else "PRIVATE"
            self.error(where, f"includes {target} ({dep}) but module {module} does not depend "
                       f"on {dep}: add it to {module}'s {kind} list, if the layers allow it")
        elif header and dep not in public:
            self.error(where, f"header includes {target} ({dep}), a PRIVATE dependency of "
                       f"{module}: a dependency its headers expose must be PUBLIC")

    def check_declarations(self):
        for module in sorted(self.modules.modules):
            public, private = self.modules.declared(module)
            used = self.used[module]
            for dep in sorted(public | private):
                if dep not in self.modules.modules and not self.modules.third_party.get(dep):
                    continue  # link-only dependencies (Threads, EGL) have no header to find
                if dep not in used:
                    self.error(module, f"declares {dep} but no file of it includes {dep}: "
                               "remove the dependency")
                elif dep in public and True not in used[dep]:
                    self.error(module, f"declares {dep} PUBLIC but only its sources include it: "
                               "make it PRIVATE")

    def check_cycles(self):
        graph = {}
        for name in self.modules.modules:
            public, private = self.modules.declared(name)
            graph[name] = sorted(d for d in public | private if d in self.modules.modules)
        state = {}
        stack = []

        def visit(node):
            state[node] = "open"
            stack.append(node)
            for nxt in graph[node]:
                if state.get(nxt) == "open":
                    self.report_cycle(stack[stack.index(nxt):] + [nxt])
                elif nxt not in state:
                    visit(nxt)
            stack.pop()
            state[node] = "done"

        for name in sorted(graph):
            if name not in state:
                visit(name)

    def report_cycle(self, cycle):
        self.error("dependencies", "cycle between modules: " + " -> ".join(cycle))

    def run(self):
        for path in layer_files(self.root, self.modules):
            self.check_file(path)
        self.check_declarations()
        self.check_cycles()
        return self.errors

    def suggestions(self):
        lines = []
        for module in sorted(self.used):
            used = self.used[module]
            public = sorted(d for d, kinds in used.items() if True in kinds)
            private = sorted(d for d, kinds in used.items() if True not in kinds)
            lines.append(f"{module}: PUBLIC {' '.join(public) or '-'}  "
                         f"PRIVATE {' '.join(private) or '-'}")
        return lines


def load_modules(path):
    try:
        with open(path, encoding="utf-8") as f:
            table = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"check_includes: cannot read the module table {path}: {e}")
    if not isinstance(table, dict) or not isinstance(table.get("modules"), dict):
        sys.exit(f"check_includes: {path}: expected an object with a 'modules' object")
    for name, m in table["modules"].items():
        if not isinstance(m, dict) or "folder" not in m:
            sys.exit(f"check_includes: {path}: /modules/{name}: expected an object with 'folder'")
    return Modules(table)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--modules", required=True, help="pyro_modules.json written by CMake")
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."),
                        help="source tree (default: this script's project)")
    parser.add_argument("--suggest", action="store_true",
                        help="print the dependencies each module's includes call for")
    args = parser.parse_args(argv)
    checker = Checker(os.path.abspath(args.root), load_modules(args.modules))
    errors = checker.run()
    if args.suggest:
        print("\n".join(checker.suggestions()))
        return 0
    for e in errors:
        print(e)
    if errors:
        print(f"check_includes: {len(errors)} violation(s) of the declared layers")
        return 1
    print(f"check_includes: {len(checker.modules.modules)} modules, layers respected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
