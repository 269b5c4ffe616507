"""The Gold error texts the wire layer shows are the interpreter's own, code for code."""

import os
import re

from conftest import ROOT
from uprog.error_texts import GOLD_EC_TEXTS


def test_gold_texts_match_the_interpreter_table():
    path = os.path.join(ROOT, "src", "dialects", "gold", "interpreter_errors.def")
    with open(path, encoding="utf-8") as f:
        rows = re.findall(r'^EC\((\d+),\s*\w+,\s*"([^"]*)"\)', f.read(), re.M)
    assert rows, "no EC rows read"
    assert GOLD_EC_TEXTS == {int(code): text for code, text in rows}
