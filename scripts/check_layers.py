#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks the library's includes against the layers of docs/architecture.md: every `#include <morphreg/X/...>` (and
every relative include into another folder) of include/morphreg/F/ and src/F/ must name a folder X that the table
allows F to include. Also refuses public headers that name the shared data's path. Exits 1 listing every arrow that
breaks a rule.

usage: check_layers.py ROOT
       check_layers.py --self-test   (a tree with one arrow of each broken kind must fail, a clean one pass)
"""
import pathlib
import re
import sys
import tempfile

ROW = re.compile(r"^\|\s*`(?P<folder>[a-z_]+)`\s*\|(?P<allowed>[^|]*)\|")
NAME = re.compile(r"`([a-z_]+)`")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"](?:morphreg/(?P<public>[a-z_]+)/|(?:\.\./)+(?P<private>[a-z_]+)/)')


def layer_table(root):
    """folder -> the folders it may include, from the table of docs/architecture.md."""
    table = {}
    for line in (root / "docs" / "architecture.md").read_text(encoding="utf-8").splitlines():
        row = ROW.match(line)
        if row:
            table[row["folder"]] = set(NAME.findall(row["allowed"]))
    return table


def folder_files(root, folder):
    for base in (root / "include" / "morphreg" / folder, root / "src" / folder):
        if base.is_dir():
            yield from (p for p in sorted(base.rglob("*")) if p.suffix in (".h", ".hpp", ".cpp"))


def broken_arrows(root, table):
    found = []
    for folder, allowed in table.items():
        for path in folder_files(root, folder):
            for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                include = INCLUDE.match(line)
                if not include:
                    continue
                target = include["public"] or include["private"]
                if target != folder and target in table and target not in allowed:
                    found.append(f"{path.relative_to(root)}:{number}: {folder} -> {target} ({line.strip()})")
    return found


def shared_data_paths(root):
    found = []
    for path in sorted((root / "include" / "morphreg").rglob("*.h")):
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if "shared/data" in line:
                found.append(f"{path.relative_to(root)}:{number}: a public header names the shared data's path")
    return found


def problems_of(root):
    table = layer_table(root)
    folders = {p.name for p in (root / "src").iterdir() if p.is_dir()}
    problems = [f"src/{f}/ has no row in docs/architecture.md's layer table" for f in sorted(folders - set(table))]
    return table, problems + broken_arrows(root, table) + shared_data_paths(root)


def self_test():
    """A clean two-folder tree passes; an include upwards, a folder missing from the table and a shared-data path
    in a public header each make one problem."""
    with tempfile.TemporaryDirectory() as directory:
        root = pathlib.Path(directory)
        (root / "docs").mkdir()
        (root / "docs" / "architecture.md").write_text("| `low` | (nothing) | x |\n| `high` | `low` | y |\n")
        for folder, text in (("low", "#include <vector>\n"), ("high", "#include <morphreg/low/a.h>\n")):
            (root / "src" / folder).mkdir(parents=True)
            (root / "src" / folder / "a.cpp").write_text(text)
        (root / "include" / "morphreg" / "low").mkdir(parents=True)
        clean = len(problems_of(root)[1]) == 0
        (root / "src" / "low" / "b.cpp").write_text('#include "../high/a.h"\n')
        (root / "src" / "other").mkdir()
        (root / "src" / "other" / "c.cpp").write_text("\n")
        (root / "include" / "morphreg" / "low" / "d.h").write_text("// reads ../shared/data/x\n")
        broken = problems_of(root)[1]
        ok = clean and len(broken) == 3
        print(f"check_layers self-test: clean tree {'passes' if clean else 'FAILS'}, broken tree {len(broken)} problems")
        return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    table, problems = problems_of(root)
    for problem in problems:
        print(problem)
    print(f"check_layers: {len(table)} folders, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
