#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Lists the functions in the given folders whose bodies are longer than a limit; exits 1 if there are any.

The project's layout (.clang-format) puts a function's opening brace on a line of its own, after the signature;
a body runs from that brace to the closing brace at the same indentation. Lambdas and blocks inside a function
count towards it.

usage: check_function_length.py [--max-lines N] DIR...
"""
import argparse
import pathlib
import re
import sys

OPENING = re.compile(r"^(?P<indent> *)\{\s*$")
NOT_A_FUNCTION = re.compile(r"^\s*(namespace|struct|class|enum|union)\b|[=,]\s*$")
SIGNATURE_END = re.compile(r"(\)|\bconst|\boverride|\bnoexcept|\bfinal)\s*(->.*)?$|^\s*[:,].*\)\s*$")


def long_functions(path, max_lines):
    lines = path.read_text(encoding="utf-8", errors="replace").split("\n")
    found = []
    i = 1
    while i < len(lines):
        opening = OPENING.match(lines[i])
        signature = lines[i - 1].rstrip()
        if not opening or NOT_A_FUNCTION.search(signature) or not SIGNATURE_END.search(signature):
            i += 1
            continue
        closing = re.compile("^" + opening.group("indent") + r"\}")
        end = i + 1
        while end < len(lines) and not closing.match(lines[end]):
            end += 1
        body = end - i - 1
        if body > max_lines:
            found.append((body, i + 1, signature.strip()))
        i = end + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-lines", type=int, default=60)
    parser.add_argument("dirs", nargs="+")
    args = parser.parse_args()
    failures = 0
    for folder in args.dirs:
        for path in sorted(pathlib.Path(folder).rglob("*")):
            if path.suffix not in (".h", ".hpp", ".cpp"):
                continue
            for body, line, signature in long_functions(path, args.max_lines):
                print(f"{path}:{line}: {body} lines (limit {args.max_lines}): {signature[:80]}")
                failures += 1
    print(f"check_function_length: {failures} function(s) longer than {args.max_lines} lines")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
