"""Akribis AG300 PUP with pytest: examples/pup's programs on the simulated drive or over the wire.
    /usr/bin/python3 -m pytest -p uprog.pytest_plugin examples/python/test_pup.py [-n 2]"""

import os

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PUP = os.path.join(HERE, "..", "pup")


def test_point_to_point(sim_drive):
    # Four moves of 20000 counts (0.3 s each, after the 20 ms the motor takes to be ready),
    # counted in AGenData[1]; then the thread halts (AProgStatus 3).
    d = sim_drive("pup", program=os.path.join(PUP, "point_to_point.pup"))
    d.command("AProgRun[1],1")
    d.run_until(lambda: d.query("AGenData[1]") == 4, timeout=3)
    d.run_until(lambda: d.query("AProgStatus[1]") == 3, timeout=1)
    assert abs(d.query("APos")) <= 2


@pytest.mark.uprog_sim_only
def test_point_to_point_recording(sim_drive):
    # The profile: out to FAR (20000) and back at ASpeed 100000 counts/s, four times.
    d = sim_drive("pup", program=os.path.join(PUP, "point_to_point.pup"))
    d.record("reference_position,reference_velocity", trigger="begin", length=1500, gap=20)
    d.command("AProgRun[1],1")
    d.run(1.5)
    r = d.recording()
    assert r["reference_position"].max() == 20000 and r["reference_position"][-1] == 0
    assert abs(r["reference_velocity"]).max() == 100000


@pytest.mark.uprog_sim_only
def test_input_event(sim_drive):
    # input_event.pup: each rising edge of input 3 counts and toggles output 2 (ADoutPort bit 1).
    d = sim_drive("pup", program=os.path.join(PUP, "input_event.pup"))
    d.command("AProgRun[1],1")
    d.run(0.001)
    d.set_input(3, 1)
    d.run(0.001)
    assert (d.query("AGenData[1]"), d.query("ADoutPort")) == (1, 2)
    d.set_input(3, 0)
    d.run(0.001)
    d.set_input(3, 1)
    d.run(0.001)
    assert (d.query("AGenData[1]"), d.query("ADoutPort")) == (2, 0)


@pytest.mark.uprog_sim_only
def test_fault_and_recovery(sim_drive):
    # A latched fault disables the drive; AMotorFault is MF (feedback loss 4); AClearFault is
    # refused (23) while it is latched; switching the motor on clears a fault whose cause is gone.
    d = sim_drive("pup")
    d.command("AMotorOn=1")
    d.run(0.05)
    d.inject_fault("feedback")
    d.run(0.001)
    assert (d.query("AMotorOn"), d.query("AMotorFault")) == (0, 4)
    import uprog
    with pytest.raises(uprog.DriveError) as refused:
        d.command("AClearFault")
    assert refused.value.code == 23
    d.command("AMotorOn=1")
    d.run(0.05)
    assert d.query("AMotorFault") == 0
