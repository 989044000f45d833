#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Lists the project's source files (C++, CMake, Python, shell) that do not name their licence with an SPDX line,
`SPDX-License-Identifier: BSD-3-Clause`, in their first lines; exits 1 if there are any.

Every file under ROOT is looked at except version control, build trees (folders holding a CMakeCache.txt) and the
fuzzers' corpora, so a file added later is checked without any list to update. --fix adds the line (after a
shebang); --self-test checks the checker on a temporary tree with files of each kind, with and without the line.

usage: check_spdx.py [--fix] ROOT | --self-test
"""
import argparse
import os
import pathlib
import sys
import tempfile

LICENCE = "BSD-3-Clause"
TAG = "SPDX-License-Identifier: " + LICENCE
LINES_SEARCHED = 5
CPP_SUFFIXES = {".cpp", ".h", ".hpp"}
HASH_SUFFIXES = {".py", ".pyi", ".sh", ".cmake"}
SKIPPED_FOLDERS = {".git", "__pycache__", "corpus", "crashes"}


def comment_prefix(path):
    """The comment leader of a source file's kind ("//" or "#"), None for files that are not source."""
    name = path.name
    if path.suffix in CPP_SUFFIXES:
        return "//"
    if path.suffix in HASH_SUFFIXES or name == "CMakeLists.txt" or name.endswith(".cmake.in"):
        return "#"
    try:
        with open(path, "rb") as stream:
            if stream.read(2) == b"#!":  # a script without a suffix, e.g. .ci/run
                return "#"
    except OSError:
        pass
    return None


def source_files(root):
    for folder, subfolders, files in os.walk(root):
        subfolders[:] = sorted(s for s in subfolders if s not in SKIPPED_FOLDERS
                               and not os.path.exists(os.path.join(folder, s, "CMakeCache.txt")))
        for name in sorted(files):
            path = pathlib.Path(folder, name)
            prefix = comment_prefix(path)
            if prefix and path.is_file():
                yield path, prefix


def has_tag(path):
    with open(path, encoding="utf-8", errors="replace") as stream:
        return any(TAG in stream.readline() for _ in range(LINES_SEARCHED))


def add_tag(path, prefix):
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    at = 1 if lines and lines[0].startswith("#!") else 0
    lines.insert(at, prefix + " " + TAG + "\n")
    path.write_text("".join(lines), encoding="utf-8")


def check(root, fix, quiet=False):
    missing = [(path, prefix) for path, prefix in source_files(root) if not has_tag(path)]
    for path, prefix in missing:
        if fix:
            add_tag(path, prefix)
        if not quiet:
            print(f"{path.relative_to(root)}: {'added' if fix else 'no'} '{TAG}' line")
    return missing


def self_test():
    """Files of each kind with and without the line: exactly those without must be reported, and --fix mends them."""
    with tempfile.TemporaryDirectory() as root:
        files = {"src/a.cpp": "//", "include/a.h": "//", "impl/a.hpp": "//", "CMakeLists.txt": "#",
                 "cmake/a.cmake": "#", "cmake/aConfig.cmake.in": "#", "a.py": "#", "a.pyi": "#", "a.sh": "#",
                 ".ci/run": "#"}
        for name, prefix in files.items():
            for variant, tagged in (("good", True), ("bad", False)):
                path = pathlib.Path(root, variant, name)
                path.parent.mkdir(parents=True, exist_ok=True)
                body = "#!/bin/sh\n" if name == ".ci/run" else ""
                path.write_text(body + (prefix + " " + TAG + "\n" if tagged else "") + "x\n")
        pathlib.Path(root, "bad", "notes.txt").write_text("not source\n")
        pathlib.Path(root, "build").mkdir()
        pathlib.Path(root, "build", "CMakeCache.txt").write_text("")
        pathlib.Path(root, "build", "generated.cpp").write_text("x\n")
        reported = {str(path.relative_to(root)) for path, _ in check(pathlib.Path(root), fix=False, quiet=True)}
        expected = {os.path.join("bad", name) for name in files}
        if reported != expected:
            print(f"self-test FAILED: reported {sorted(reported)}, expected {sorted(expected)}")
            return 1
        check(pathlib.Path(root), fix=True, quiet=True)
        if check(pathlib.Path(root), fix=False, quiet=True) or not pathlib.Path(root, "bad/.ci/run").read_text().startswith("#!"):
            print("self-test FAILED: --fix left files without the line or moved a shebang")
            return 1
    print("self-test passed")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", nargs="?", type=pathlib.Path)
    parser.add_argument("--fix", action="store_true", help="add the line to the files that lack it")
    parser.add_argument("--self-test", action="store_true", help="check the checker")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    if args.root is None:
        parser.error("ROOT is required")
    missing = check(args.root.resolve(), args.fix)
    if missing and not args.fix:
        print(f"{len(missing)} source file(s) without '{TAG}' (scripts/check_spdx.py --fix {args.root} adds it)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
