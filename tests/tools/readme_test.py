#!/usr/bin/env python3
"""The documentation names only what the repository ships.

Every Markdown file the repository holds is read; each link to a local target, and each path it
names in backticks under one of the repository's folders (`tools/fit.sh`, the files of a command
such as `build/fabform run scenes/mold.toml`), must exist, relative to the file or to the
repository's root. What commands write (build/, results/, an output folder) and placeholders
(`scenes/NAME.toml`, `*.csv`) are not files to ship, nor paths in another repository that a
paragraph cites (it names ARCSim, or a repository at a commit, "owner/name @ 1a2b3c4"); licence
texts kept verbatim (LICENSES/) are not ours to check. The README a user reads first must not
point outside the repository.
"""
import pathlib
import re
import subprocess
import sys
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FOLDERS = ("tools", "scenes", "materials", "molds", "tests", "studies", "src", "include", "docs", "cmake", ".ci")
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
CODE = re.compile(r"`([^`\n]+)`")
PATH = re.compile(r"^(?:\./)?(?:%s)/[\w./+-]*[\w/]$" % "|".join(re.escape(f) for f in FOLDERS))
PLACEHOLDER = re.compile(r"[A-Z]{2,}(?![a-z])|[*{}<>]")
CAPITALISED_FILES = re.compile(r"README|LICENSES?|SOURCES|FORMAT")  # real names, not placeholders
CITES_UPSTREAM = re.compile(r"ARCSim|[\w.-]+/[\w.-]+ @ [0-9a-f]{7}|in the repository `")


def markdown_files():
    listed = subprocess.run(["git", "ls-files", "*.md"], cwd=ROOT, capture_output=True, text=True)
    if listed.returncode == 0 and listed.stdout.strip():
        found = [ROOT / name for name in listed.stdout.split()]
    else:
        found = [p for p in ROOT.rglob("*.md") if not any(part.startswith("build") for part in p.parts)]
    return [p for p in found if "LICENSES" not in p.parts and "licenses" not in p.parts]


def tracked():
    """The files git tracks (and their folders), or None outside a checkout: a file that exists
    here but is not committed would not reach a clone."""
    listed = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True)
    if listed.returncode != 0:
        return None
    names = set()
    for name in listed.stdout.split("\n"):
        path = pathlib.PurePosixPath(name)
        names.update({str(path), *(str(p) for p in path.parents)})
    return names


TRACKED = tracked()


def exists(name, beside):
    name = name.split("#", 1)[0].rstrip("/")
    if not name:
        return True
    for path in (beside / name, ROOT / name):
        try:
            relative = str(pathlib.PurePosixPath(path.resolve().relative_to(ROOT)))
        except ValueError:
            continue
        if path.exists() and (TRACKED is None or relative in TRACKED):
            return True
    return False


def paragraphs(text):
    """(first line's number, lines) of each block between blank lines."""
    block, start = [], 1
    for number, line in enumerate(text.splitlines() + [""], 1):
        if line.strip():
            if not block:
                start = number
            block.append(line)
        elif block:
            yield start, block
            block = []


def named_paths(text):
    """(line, path) for each local link target and each repository path named in backticks."""
    for start, block in paragraphs(text):
        cites_upstream = bool(CITES_UPSTREAM.search(" ".join(block)))
        for number, line in enumerate(block, start):
            yield from named_in_line(number, line, cites_upstream)


def named_in_line(number, line, cites_upstream):
    for target in LINK.findall(line):
        if not re.match(r"^(https?:|mailto:|#)", target):
            yield number, target
    if not cites_upstream:
        for code in CODE.findall(line):
            for word in code.replace("=", " ").replace(",", " ").split():
                word = word.strip("'\"();:")
                if PATH.match(word) and not PLACEHOLDER.search(CAPITALISED_FILES.sub("", word)):
                    yield number, word


class ShippedNames(unittest.TestCase):
    def test_every_named_file_exists(self):
        missing = []
        for md in markdown_files():
            for number, name in named_paths(md.read_text(encoding="utf-8")):
                if not exists(name, md.parent):
                    missing.append(f"{md.relative_to(ROOT)}:{number}: {name}")
        self.assertEqual(missing, [], "named but not shipped:\n" + "\n".join(missing))

    def test_readme_points_nowhere_outside(self):
        text = (ROOT / "README.md").read_text(encoding="utf-8")
        for outside in ("../shared", "DESIGN.md"):
            self.assertNotIn(outside, text)

    def test_the_checker_sees_a_missing_file(self):
        named = list(named_paths("run `tools/no_such_tool.py --x` and see [the page](docs/nowhere.md)\n"
                                 "`results/mold/report.html` `scenes/NAME.toml` `build/fabform`"))
        self.assertEqual(named, [(1, "docs/nowhere.md"), (1, "tools/no_such_tool.py")])
        self.assertFalse(exists("tools/no_such_tool.py", ROOT))
        self.assertTrue(exists("tools/fit.sh", ROOT))


if __name__ == "__main__":
    sys.exit(unittest.main())
