#!/usr/bin/python3
"""tools/'s Python modules import one another without a cycle: each import of a module of tools/
(`import X` or `from X import ...` at any indentation, as a function's late import is one too)
is an arrow, and no arrow leads back to where it started.

Usage: /usr/bin/python3 tests/tools/tools_imports_test.py
"""
import pathlib
import re
import unittest

TOOLS = pathlib.Path(__file__).resolve().parents[2] / "tools"
IMPORT = re.compile(r"^\s*(?:import|from)\s+(\w+)")


def import_graph(folder: pathlib.Path) -> dict:
    modules = {p.stem for p in folder.glob("*.py")}
    graph = {}
    for path in folder.glob("*.py"):
        found = (IMPORT.match(line) for line in path.read_text().splitlines())
        graph[path.stem] = {m.group(1) for m in found if m and m.group(1) in modules and m.group(1) != path.stem}
    return graph


def cycles(graph: dict) -> list:
    """Every cycle found by a depth-first walk from each module, as the modules along it."""
    found = []

    def walk(path):
        for nxt in sorted(graph[path[-1]]):
            if nxt in path:
                found.append(path[path.index(nxt):] + [nxt])
            elif len(path) < len(graph):
                walk(path + [nxt])

    for module in sorted(graph):
        walk([module])
    return found


class ToolsImports(unittest.TestCase):
    def test_no_module_of_tools_imports_itself_round_a_cycle(self):
        graph = import_graph(TOOLS)
        self.assertGreater(len(graph), 10)
        self.assertEqual(cycles(graph), [])

    def test_a_cycle_is_found(self):
        self.assertEqual(cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}})[0], ["a", "b", "c", "a"])
        self.assertEqual(cycles({"a": {"b"}, "b": set()}), [])


if __name__ == "__main__":
    unittest.main()
