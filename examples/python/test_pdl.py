"""HIWIN PDL with pytest: examples/pdl's programs on the simulated drive or over the wire.
    /usr/bin/python3 -m pytest -p uprog.pytest_plugin examples/python/test_pdl.py [-n 2]"""

import os

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PDL = os.path.join(HERE, "..", "pdl")
# The manual's 2.2.11 home search with TOUT, as tests/transcripts/pdl keeps it.
HOME_SEARCH = os.path.join(HERE, "..", "..", "tests", "transcripts", "pdl", "programs",
                           "tout_home_2_2_11.pdl")


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


@pytest.mark.uprog_sim_only
def test_home_input_ends_the_search(sim_drive):
    # Manual 2.2.11: jog at 2000 counts/s until the home input or 3 s of TOUT. A home cam on
    # input 3 at 3000..4000 counts is reached after about 1.5 s: "OK, found home limit".
    d = sim_drive("pdl")
    d.place_switch(3, 3000, 4000)
    d.load(HOME_SEARCH)
    d.run(2.5)
    assert d.output() == ["%P 1 00000101 00000000 OK, found home limit"]
    assert d.query("X_homed") == 1


@pytest.mark.uprog_sim_only
def test_home_search_times_out_without_the_input(sim_drive):
    d = sim_drive("pdl", program=HOME_SEARCH)
    d.run(3.5)  # TOUT's 60000 phases of 50 us: 3 s
    assert d.output() == ["%P 1 00000101 00000000 ERROR time out when search home limit"]
