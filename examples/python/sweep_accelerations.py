"""A parameter sweep: one move of 20000 counts at SP=50000 under 200 accelerations, each test a
drive of its own, spread over processes by pytest-xdist (docs/python.md, "Scale out"):
    /usr/bin/python3 -m pytest -n auto examples/python/sweep_accelerations.py"""

import pytest

ACCELERATIONS = [250_000 + 25_000 * i for i in range(200)]  # counts/s²


@pytest.mark.parametrize("ac", ACCELERATIONS)
def test_move_settles_in_time(sim_drive, ac):
    d = sim_drive("gold")
    for line in ("UM=5", "MO=1"):
        d.command(line)
    d.run_until("SO==1", timeout=1)
    d.command(f"SP=50000;AC={ac};DC={ac};PA=20000")
    d.command("BG")
    took = d.run_until("MS==0", timeout=5)
    # A trapezoid (each ramp 50000²/(2·ac) ≤ 5000 counts, so it reaches SP): its profile lasts
    # 20000/50000 s at speed plus one ramp's time 50000/ac; settling adds a little.
    profile_s = 20000 / 50000 + 50000 / ac
    assert profile_s <= took <= profile_s + 0.05
    assert abs(d.query("PX") - 20000) <= d.query("TR[1]")
