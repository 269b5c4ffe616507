"""HIWIN PDL with pytest: examples/pdl's programs on the simulated drive or over the wire.
    /usr/bin/python3 -m pytest -p uprog.pytest_plugin examples/python/test_pdl.py [-n 2]"""

import os

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PDL = os.path.join(HERE, "..", "pdl")


def test_move_with_timeout(sim_drive):
    # 10000 counts at 20000 counts/s (0.1 s ramps): about 0.6 s, well within its 2 s timeout.
    d = sim_drive("pdl", program=os.path.join(PDL, "move_with_timeout.pdl"))
    d.run_until(lambda: d.query("result") == 1, timeout=3)
    assert d.query("ref_pos") == 10000


def test_printl_events(sim_drive):
    # printl/103 from task 2: `%P task mode1 mode2 text` (pdl-drive.md, "Events"); the ramp's
    # level is step squared, ratio = level / 25.
    d = sim_drive("pdl", program=os.path.join(PDL, "printl_report.pdl"))
    lines = []
    d.run_until(lambda: lines.extend(d.output()) or len(lines) >= 5, timeout=3)
    assert [line.rstrip() for line in lines[:2]] == [
        "%P 2 00000103 00000000 ramp report : step=1 level=0001 ratio=0.04",
        "%P 2 00000103 00000000 ramp report : step=2 level=0004 ratio=0.16"]


@pytest.mark.uprog_sim_only
def test_move_recording(sim_drive):
    d = sim_drive("pdl", program=os.path.join(PDL, "move_with_timeout.pdl"))
    # The profile of 10000 counts at 20000 counts/s: from 0 to the target, one way, never faster.
    d.record("reference_position,reference_velocity", trigger="immediate", length=1000, gap=20)
    d.run(1.0)
    r = d.recording()
    position, velocity = r["reference_position"], r["reference_velocity"]
    assert position[0] == 0 and position[-1] == 10000
    assert (position[1:] >= position[:-1]).all()
    assert velocity.max() == 20000
