#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes docs/cli.md, the command line reference, from the help the `morphreg` executable prints: `morphreg --help`,
then `morphreg <command> --help` for every subcommand that help lists, each in a code block. The reference is the
help itself, so the two cannot disagree; --check compares instead of writing and names the first line that differs
(StyleTest.CliReferenceIsCurrent runs it against the built executable); both refuse a short flag that means
different options in different subcommands.

usage: cli_reference.py [--check] MORPHREG [OUTPUT]    (OUTPUT: docs/cli.md of this tree by default)
"""
import argparse
import re
import pathlib
import subprocess
import sys

DEFAULT_OUTPUT = pathlib.Path(__file__).resolve().parent.parent / "docs" / "cli.md"
HEADER = """# Command line reference

Generated from `morphreg --help` and `morphreg <command> --help` by `scripts/cli_reference.py`; do not edit by hand.
After changing an option, regenerate it from the project root with

```sh
python3 scripts/cli_reference.py build/tools/morphreg
```

(`ctest -R StyleTest.CliReferenceIsCurrent` fails while this file differs from the built command line's help). What
the commands do, with examples, is in [commands.md](commands.md); the README has the main jobs.
"""


def run_help(binary, args):
    """The help text of `binary args --help`, with the executable's path shown as plain `morphreg`."""
    result = subprocess.run([binary, *args, "--help"], capture_output=True, text=True, timeout=60)
    if result.returncode != 0:
        sys.exit(f"cli_reference.py: `{binary} {' '.join(args)} --help` exited with {result.returncode}: "
                 f"{result.stderr.strip()}")
    return result.stdout.replace(f"Usage: {binary} ", "Usage: morphreg ").rstrip() + "\n"


def subcommands(top_help):
    """The subcommand names the top-level help lists under "Subcommands:", in its order."""
    names, inside = [], False
    for line in top_help.splitlines():
        if line.startswith("Subcommands:"):
            inside = True
        elif inside and line.startswith("  ") and line.strip():
            names.append(line.split()[0])
        elif inside and line.strip():
            break
    if not names:
        sys.exit("cli_reference.py: the top-level help lists no subcommands under \"Subcommands:\"")
    return names


def reference(binary):
    """The whole of docs/cli.md for the executable `binary`."""
    top = run_help(binary, [])
    commands = subcommands(top)
    parts = [HEADER, "Commands: " + ", ".join(f"[{c}](#{c})" for c in commands) + ".\n",
             "## morphreg\n", "```text\n" + top + "```\n"]
    for command in commands:
        parts += [f"## {command}\n", "```text\n" + run_help(binary, [command]) + "```\n"]
    return "\n".join(parts)


def short_flag_conflicts(text):
    """Sentences naming each short flag that stands for different long options in different subcommands."""
    meanings = {}
    for short, long in re.findall(r"^\s+(-[A-Za-z]),(--[A-Za-z0-9-]+)", text, flags=re.M):
        meanings.setdefault(short, set()).add(long)
    return [f"{short} means {' and '.join(sorted(longs))}" for short, longs in sorted(meanings.items())
            if len(longs) > 1]


def first_difference(expected, actual):
    """A sentence naming the first line where the file `actual` differs from the generated `expected`."""
    want, have = expected.splitlines(), actual.splitlines()
    for number, (w, h) in enumerate(zip(want, have), start=1):
        if w != h:
            return f"line {number} is\n  {h}\nbut the help gives\n  {w}"
    if len(want) != len(have):
        return f"it has {len(have)} lines where the help gives {len(want)}"
    return "it differs in its line endings"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true", help="compare with OUTPUT instead of writing it")
    parser.add_argument("binary", help="the morphreg executable, e.g. build/tools/morphreg")
    parser.add_argument("output", nargs="?", type=pathlib.Path, default=DEFAULT_OUTPUT)
    args = parser.parse_args()
    text = reference(args.binary)
    conflicts = short_flag_conflicts(text)
    if conflicts:
        sys.exit("short flags must mean one option in every subcommand: " + "; ".join(conflicts))
    if not args.check:
        args.output.write_text(text)
        print(f"wrote {args.output}")
        return 0
    if not args.output.is_file():
        sys.exit(f"{args.output}: no such file (run scripts/cli_reference.py {args.binary} to write it)")
    actual = args.output.read_text()
    if actual == text:
        print(f"{args.output} matches the help of {args.binary}")
        return 0
    sys.exit(f"{args.output} is out of date with the help of {args.binary}: {first_difference(text, actual)}\n"
             f"regenerate it: python3 scripts/cli_reference.py {args.binary}")


if __name__ == "__main__":
    sys.exit(main())
