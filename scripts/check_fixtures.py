#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks the test suite's fixtures in a build folder: every FIXTURES_REQUIRED of a test names a fixture that some
test sets up (FIXTURES_SETUP). A name that nothing sets up (e.g. "a;b" taken as one fixture) gives no order at all:
the test may then run before the files it needs exist. Exits 1 listing each such reference.

Usage: check_fixtures.py BUILD_DIR | --self-test
"""
import json
import subprocess
import sys


def unknown_fixtures(tests):
    """(test, fixture) for each required fixture that no test sets up."""
    setups = {name for test in tests for prop in test.get("properties", []) if prop["name"] == "FIXTURES_SETUP"
              for name in prop["value"]}
    return [(test["name"], name) for test in tests for prop in test.get("properties", [])
            if prop["name"] == "FIXTURES_REQUIRED" for name in prop["value"] if name not in setups]


def self_test():
    """A required fixture that is set up passes; one named "a;b" is reported."""
    tests = [{"name": "Setup", "properties": [{"name": "FIXTURES_SETUP", "value": ["a", "b"]}]},
             {"name": "Good", "properties": [{"name": "FIXTURES_REQUIRED", "value": ["a", "b"]}]},
             {"name": "Bad", "properties": [{"name": "FIXTURES_REQUIRED", "value": ["a;b"]}]}]
    found = unknown_fixtures(tests)
    if found != [("Bad", "a;b")]:
        print(f"check_fixtures self-test failed: {found}")
        return 1
    print("check_fixtures self-test passed")
    return 0


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    if sys.argv[1] == "--self-test":
        return self_test()
    listing = subprocess.run(["ctest", "--show-only=json-v1"], cwd=sys.argv[1], check=True, capture_output=True,
                             text=True).stdout
    tests = json.loads(listing)["tests"]
    found = unknown_fixtures(tests)
    for test, name in found:
        print(f"{test}: requires fixture '{name}', which no test sets up")
    print(f"check_fixtures: {len(tests)} tests, {len(found)} unknown fixture reference(s)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
