#!/usr/bin/python3
"""The include graph of fabform's C++ between its folders, against the layers they are meant to
stand in: a folder may include its own layer's headers and those of layers below it, never above.

Layers, lowest first:
  the top-level files (error.hpp and the like) < geometry, material, linalg < fabric < io < model
  < solver < scene < analysis < run < output < study < cli
A file's folder is the first folder under src/ or include/fabform/; an include names its folder
as "fabform/FOLDER/..." (or "FOLDER/..." for src/'s private headers).

Prints each arrow FOLDER -> FOLDER with the number of files that include across it, marking the
arrows that run upward with the file and line of each include; --dot prints the graph in
Graphviz's language instead (upward arrows red), to draw it: `... --dot | dot -Tsvg > graph.svg`.
Exit status 0 when no arrow runs upward, 1 when one does, 2 when a folder is in no layer.

Usage: /usr/bin/python3 tools/include_layers.py [--root DIR] [--dot]
"""
import argparse
import collections
import pathlib
import re
import sys

TOP = "(top level)"  # error.hpp, number_text.hpp and the like: under every folder
LAYERS = [(TOP,), ("geometry", "material", "linalg"), ("fabric",), ("io",), ("model",), ("solver",), ("scene",),
          ("analysis",), ("run",), ("output",), ("study",), ("cli",)]
INCLUDE = re.compile(r'^\s*#\s*include\s+"(?:fabform/)?([a-z_]+)/')


def rank_of(folder: str) -> int:
    for rank, layer in enumerate(LAYERS):
        if folder in layer:
            return rank
    raise KeyError(folder)


def arrows(root: pathlib.Path) -> dict:
    """{(from, to): [(file, line), ...]} over every C++ file under src/ and include/fabform/."""
    found = collections.defaultdict(list)
    bases = (root / "src", root / "include" / "fabform")
    for base in bases:
        for path in sorted(base.rglob("*.[ch]pp")):
            parts = path.relative_to(base).parts
            folder = parts[0] if len(parts) > 1 else TOP
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                match = INCLUDE.match(line)
                if match and match.group(1) != folder and any((b / match.group(1)).is_dir() for b in bases):
                    found[(folder, match.group(1))].append((str(path.relative_to(root)), number))
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", default=str(pathlib.Path(__file__).resolve().parent.parent),
                        help="the repository (default: this one)")
    parser.add_argument("--dot", action="store_true", help="print the graph in Graphviz's language")
    args = parser.parse_args()
    graph = arrows(pathlib.Path(args.root))
    folders = sorted({f for pair in graph for f in pair})
    unknown = [f for f in folders if not any(f in layer for layer in LAYERS)]
    if unknown:
        print(f"include_layers.py: folder(s) {', '.join(unknown)} in no layer: add them to LAYERS", file=sys.stderr)
        return 2
    upward = {pair: files for pair, files in graph.items() if rank_of(pair[0]) < rank_of(pair[1])}
    if args.dot:
        print("digraph includes {\n  rankdir=BT;")
        for (a, b), files in sorted(graph.items()):
            colour = ', color=red' if (a, b) in upward else ''
            print(f'  "{a}" -> "{b}" [label={len(files)}{colour}];')
        print("}")
    else:
        for (a, b), files in sorted(graph.items(), key=lambda item: (rank_of(item[0][0]), item[0])):
            print(f"{a} -> {b}: {len(files)} include(s){'  UPWARD' if (a, b) in upward else ''}")
            if (a, b) in upward:
                for file, line in files:
                    print(f"    {file}:{line}")
        print(f"{len(graph)} arrows between {len(folders)} folders; {len(upward)} upward")
    return 1 if upward else 0


if __name__ == "__main__":
    sys.exit(main())
