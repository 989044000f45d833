#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that the command line stays an adapter over the library: the lines of tools/ (*.cpp, *.h) are at most a
given share of the library's (src/ and include/: *.cpp, *.h, *.hpp). A sequence that grows in tools/ instead of the
library shows up here. Exits 1 naming both counts and the share.

Usage: check_front_end_share.py ROOT --max-percent P | --self-test
"""
import argparse
import pathlib
import sys

LIBRARY_SUFFIXES = {".cpp", ".h", ".hpp"}
TOOLS_SUFFIXES = {".cpp", ".h"}


def line_count(folders, suffixes):
    """The lines of every file under the folders whose suffix is one of suffixes."""
    return sum(len(path.read_text(encoding="utf-8").splitlines()) for folder in folders
               for path in folder.rglob("*") if path.is_file() and path.suffix in suffixes)


def share_message(tools, library, max_percent):
    """None when tools is within max_percent of library, else the message."""
    share = 100.0 * tools / library
    if share <= max_percent:
        return None
    return (f"tools/ has {tools} lines, {share:.2f} % of the library's {library} (at most {max_percent} %): "
            "move the sequence into the library and leave tools/ the options and the output")


def self_test():
    """8 % passes at 8, 8.1 % fails with both counts named."""
    if share_message(80, 1000, 8.0) is not None:
        print("check_front_end_share self-test failed: 8 % refused")
        return 1
    message = share_message(81, 1000, 8.0)
    if message is None or "81 lines" not in message or "1000" not in message:
        print(f"check_front_end_share self-test failed: {message}")
        return 1
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", nargs="?")
    parser.add_argument("--max-percent", type=float, default=8.0)
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    root = pathlib.Path(args.root)
    tools = line_count([root / "tools"], TOOLS_SUFFIXES)
    library = line_count([root / "src", root / "include"], LIBRARY_SUFFIXES)
    message = share_message(tools, library, args.max_percent)
    print(message or f"tools/ {tools} lines, library {library}: {100.0 * tools / library:.2f} %")
    return 1 if message else 0


if __name__ == "__main__":
    sys.exit(main())
