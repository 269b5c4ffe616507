#!/usr/bin/python3
"""Runs pytest for ctest: exit 77 (the ctest entries' SKIP_RETURN_CODE) when pytest, or a module
the suite names with --needs, is missing; pytest's own status otherwise (5, "no tests ran", is
a failure here: an entry that runs nothing is a defect).
Usage: run_pytest.py [--needs MODULE]... PYTEST-ARGS..."""

import importlib
import sys

args = sys.argv[1:]
needs = ["pytest"]
while len(args) >= 2 and args[0] == "--needs":
    needs.append(args[1])
    args = args[2:]
for name in needs:
    try:
        importlib.import_module(name)
    except ImportError as e:
        print(f"skipped: {name} is not importable ({e})")
        sys.exit(77)
import pytest  # noqa: E402  (after the check above)

sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", *args]))
