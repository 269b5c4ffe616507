"""The recorder's CSV file read and written by the Python side: each reference file of
tests/transcripts/recorder comes back byte for byte (as recording_csv_test.cpp asks of the C++
side), and the comparison follows docs/recorder.md's rules and wording."""

import glob
import os

import pytest

from conftest import ROOT

pytest.importorskip("numpy")
from uprog.recording import compare, read_csv  # noqa: E402

REFERENCES = sorted(glob.glob(os.path.join(ROOT, "tests", "transcripts", "recorder", "*.csv")))


@pytest.mark.parametrize("path", REFERENCES, ids=os.path.basename)
def test_round_trip(path, tmp_path):
    again = tmp_path / "again.csv"
    read_csv(path).to_csv(again)
    with open(path, encoding="utf-8") as f:
        assert again.read_text(encoding="utf-8") == f.read()


def test_shape_differences_are_named():
    steps = read_csv(os.path.join(ROOT, "tests", "transcripts", "recorder", "first_steps.csv"))
    other = read_csv(os.path.join(ROOT, "tests", "transcripts", "recorder", "gold_dv2.csv"))
    assert compare(steps, steps) is None
    assert str(compare(steps, steps, {"PX": 1})) == (
        "tolerance PX: the reference has no channel 'PX'")
    assert compare(other, steps) is not None
