"""Gold (Elmo) with pytest: examples/gold's programs on the simulated drive, or on a drive over its
wire with --uprog-drive (the tests marked uprog_sim_only need the simulation's world).
    /usr/bin/python3 -m pytest -p uprog.pytest_plugin examples/python/test_gold.py [-n 2]"""

import os

import pytest

from uprog.pytest_plugin import assert_recording_matches

HERE = os.path.dirname(os.path.abspath(__file__))
GOLD = os.path.join(HERE, "..", "gold")
REFERENCE = os.path.join(HERE, "first_steps.csv")


def test_first_move(sim_drive):
    # examples/gold/first_move.txt: 100000 counts at SP=50000, AC=DC=1e6 (2.05 s), then
    # `moves` counts 1 and the program ends.
    d = sim_drive("gold", program=os.path.join(GOLD, "first_move.ehl"))
    d.command("XQ##main")
    d.run_until(lambda: d.query("PS") == 0, timeout=5)
    assert d.query("moves") == 1
    assert abs(d.query("PX") - 100000) <= 2


@pytest.mark.uprog_sim_only
def test_move_recording(sim_drive):
    # The first steps of a trapezoid (first_steps.csv, worked out by hand: DV[2] = a k TS,
    # DV[3] = round(a (k TS)^2 / 2), a sample every 20 cycles of TS = 50 us).
    d = sim_drive("gold")
    d.command("MO=1")
    d.run(0.03)
    d.command("SP=50000;AC=1000000;DC=1000000;PA=100000")
    d.record("DV[2],DV[3]", trigger="begin", length=8, gap=20)
    d.command("BG")
    d.run(0.01)
    assert_recording_matches(d.recording(), REFERENCE)


@pytest.mark.uprog_sim_only
def test_input_event(sim_drive):
    # moves_by_inputs: input 2 requests 9000 counts through AUTO_I2 (SP=10000, AC=DC=1e5: 1 s).
    d = sim_drive("gold", program=os.path.join(GOLD, "moves_by_inputs.ehl"))
    d.command("XQ##main")
    d.run(0.1)
    d.set_input(2, 1)
    d.run(0.01)
    d.set_input(2, 0)
    d.run(1.5)
    assert abs(d.query("PX") - 9000) <= 2
    assert d.query("done_count") == 1


@pytest.mark.uprog_sim_only
def test_fault_and_recovery(sim_drive):
    # p2p_with_recovery: a feedback fault (MF 4) turns the motor off; AUTO_ER counts it and
    # restarts main 500 ms later, which enables the motor again.
    d = sim_drive("gold", program=os.path.join(GOLD, "p2p_with_recovery.ehl"))
    d.command("XQ##main")
    d.run(2.1)
    d.inject_fault("feedback")
    d.run(0.1)
    assert d.command("MO; MF; faults; last_fault") == ["0", "4", "1", "4"]
    d.run(0.7)
    assert d.command("MO; PS; moves") == ["1", "1", "1"]
