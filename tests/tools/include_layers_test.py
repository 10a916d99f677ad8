#!/usr/bin/python3
"""tools/include_layers.py: fabform's own include graph has no arrow running upward between its
folders' layers; on a synthetic tree, an upward include is named by file and line (exit 1), a
downward one and a top-level header pass, and a folder in no layer is refused (exit 2).

Usage: /usr/bin/python3 tests/tools/include_layers_test.py
"""
import pathlib
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
TOOL = str(ROOT / "tools" / "include_layers.py")


def run(root: str, *extra: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, TOOL, "--root", root, *extra], capture_output=True, text=True)


def tree(files: dict) -> tempfile.TemporaryDirectory:
    folder = tempfile.TemporaryDirectory()
    for name, text in files.items():
        path = pathlib.Path(folder.name) / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return folder


class IncludeLayers(unittest.TestCase):
    def test_fabform_has_no_upward_arrow(self):
        result = run(str(ROOT))
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("; 0 upward", result.stdout)

    def test_an_upward_include_is_named_by_file_and_line(self):
        with tree({"src/model/term.cpp": '#include "fabform/error.hpp"\n#include "fabform/fabric/fabric.hpp"\n',
                   "src/fabric/fabric.cpp": '#include <vector>\n\n#include "fabform/model/term.hpp"\n',
                   "include/fabform/error.hpp": "#pragma once\n",
                   "include/fabform/fabric/fabric.hpp": "#pragma once\n",
                   "include/fabform/model/term.hpp": "#pragma once\n"}) as root:
            result = run(root)
            self.assertEqual(result.returncode, 1, result.stdout + result.stderr)
            self.assertIn("fabric -> model: 1 include(s)  UPWARD\n    src/fabric/fabric.cpp:3\n", result.stdout)
            self.assertIn("model -> fabric: 1 include(s)\n", result.stdout)
            self.assertIn("2 arrows between 2 folders; 1 upward", result.stdout)
            dot = run(root, "--dot")
            self.assertIn('"fabric" -> "model" [label=1, color=red];', dot.stdout)
            self.assertIn('"model" -> "fabric" [label=1];', dot.stdout)

    def test_a_top_level_file_including_a_folder_runs_upward(self):
        with tree({"src/error.cpp": '#include "fabform/model/term.hpp"\n',
                   "include/fabform/model/term.hpp": "#pragma once\n"}) as root:
            result = run(root)
            self.assertEqual(result.returncode, 1, result.stdout + result.stderr)
            self.assertIn("(top level) -> model: 1 include(s)  UPWARD\n    src/error.cpp:1\n", result.stdout)

    def test_a_folder_in_no_layer_is_refused(self):
        with tree({"src/gadgets/gadget.cpp": '#include "fabform/model/term.hpp"\n',
                   "include/fabform/model/term.hpp": "#pragma once\n"}) as root:
            result = run(root)
            self.assertEqual(result.returncode, 2)
            self.assertIn("gadgets in no layer", result.stderr)


if __name__ == "__main__":
    unittest.main()
