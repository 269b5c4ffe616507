"""The Gold error texts the wire layer shows are the interpreter's own, code for code."""

import os
import sys

from conftest import ROOT

sys.path.insert(0, os.path.join(ROOT, "python"))
import gen_error_texts  # noqa: E402  (python/, beside the package)


def test_gold_texts_match_the_interpreter_table():
    assert gen_error_texts.rows(), "no EC rows read"
    with open(gen_error_texts.OUT, encoding="utf-8") as f:
        written = f.read()
    assert written == gen_error_texts.text_of_module(), (
        "src/dialects/gold/interpreter_errors.def changed: run /usr/bin/python3 "
        "python/gen_error_texts.py")
