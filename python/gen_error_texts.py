#!/usr/bin/python3
"""Writes python/uprog/error_texts.py from src/dialects/gold/interpreter_errors.def, the Gold
interpreter's error table (tests/test_error_texts.py fails until it is run after a change there).
Usage: /usr/bin/python3 python/gen_error_texts.py"""

import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
DEF = os.path.join(HERE, "..", "src", "dialects", "gold", "interpreter_errors.def")
OUT = os.path.join(HERE, "uprog", "error_texts.py")
HEADER = '''"""The Gold command interpreter's error texts by EC code (its interpreter_errors.def).

A Gold drive's own wire sends a refused command's code as one byte and `?;`, no text: a host
shows the text from this table. Written by python/gen_error_texts.py; tests/test_error_texts.py
keeps it equal to the .def file."""

'''


def rows(path=DEF):
    with open(path, encoding="utf-8") as f:
        return [(int(code), text) for code, text in
                re.findall(r'^EC\((\d+),\s*\w+,\s*"([^"]*)"\)', f.read(), re.M)]


def text_of_module():
    body = "".join(f"    {code}: {text!r},\n" for code, text in rows())
    return HEADER + "GOLD_EC_TEXTS = {\n" + body + "}\n"


if __name__ == "__main__":
    with open(OUT, "w", encoding="utf-8") as f:
        f.write(text_of_module())
    print(f"wrote {OUT}")
