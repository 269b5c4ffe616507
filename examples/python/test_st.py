"""Kollmorgen S300/S700 ST macros with pytest: examples/st's programs on the simulated drive or
over the wire.
    /usr/bin/python3 -m pytest -p uprog.pytest_plugin examples/python/test_st.py [-n 2]"""

import os

import pytest

numpy = pytest.importorskip("numpy")

HERE = os.path.dirname(os.path.abspath(__file__))
ST = os.path.join(HERE, "..", "st")


def test_init_parameters(sim_drive):
    # PLCINIT's XWRITEs: ramps 50, VLIM 2500, PEINPOS 10, and motion task 192.
    d = sim_drive("st", program=os.path.join(ST, "init_parameters.st"))
    d.run_until(lambda: d.query("MTMUX") == 192, timeout=1)
    assert [d.query(name) for name in ("ACC", "DEC", "VLIM", "PEINPOS")] == [50, 50, 2500, 10]
    assert d.command("ORDER 192") == ["192 20000 5000 8192 10 10 0 0 0 0"]


@pytest.mark.uprog_sim_only
def test_move_sequence_recording(sim_drive):
    # move_sequence.st: out to 5000 and back to 0 three times (ROUNDS), then DIS (STEP 4). In
    # counts (PGEARO 65536 per PGEARI 10000 units) the target is 32768: three peaks, never past.
    d = sim_drive("st", program=os.path.join(ST, "move_sequence.st"))
    d.record("reference_position", trigger="immediate", length=700, gap=80)  # every 10 ms
    d.run(7.0)
    position = d.recording()["reference_position"]
    rising = numpy.diff(position) > 0
    peaks = (rising[:-1] & ~rising[1:]).sum()
    assert (peaks, position[0], position[-1]) == (3, 0, 0)
    assert 0 < position.max() <= 32768
    assert (d.query("ROUNDS"), d.query("STEP"), d.query("ACTIVE")) == (3, 4, 0)


@pytest.mark.uprog_sim_only
def test_limit_monitor_input(sim_drive):
    # limit_monitor.st: PLC1 clamps DPRVAR1 to +/-1000 into DPRVAR2 every ms.
    d = sim_drive("st", program=os.path.join(ST, "limit_monitor.st"))
    d.run(0.001)
    d.command("DPRVAR1 5000")
    d.run(0.01)
    assert d.query("DPRVAR2") == 1000
    d.command("DPRVAR1 -1500")
    d.run(0.002)
    assert d.query("DPRVAR2") == -1000


@pytest.mark.uprog_sim_only
def test_fault_and_recovery(sim_drive):
    # ERRCODE lists every latched fault a line each; CLRFAULT clears them (the ASCII reference).
    d = sim_drive("st")
    d.command("EN")
    d.run(0.05)
    d.inject_fault("feedback")
    d.run(0.001)
    assert d.command("ERRCODE") == ["F04 Feedback"]
    d.command("CLRFAULT")
    assert d.command("ERRCODE") == ["no error"]
