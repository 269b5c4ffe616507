#!/usr/bin/python3
"""Plots a move on the simulated drive: examples/gold/first_move.ehl, position and velocity
recorded from the begin of motion, drawn with matplotlib.
    PYTHONPATH=python:build/python /usr/bin/python3 examples/python/plot_move.py move.png"""

import os
import sys

import uprog

HERE = os.path.dirname(os.path.abspath(__file__))


def main(path):
    d = uprog.SimDrive("gold")
    d.load(os.path.join(HERE, "..", "gold", "first_move.ehl"))
    # 20 % before the trigger, a sample every 40 servo cycles (2 ms): 2.4 s in all.
    d.record(["PX", "VX", "PE"], trigger="begin", pretrigger=20, length=1200, gap=40)
    d.command("XQ##main")
    d.run_until(lambda: d.query("PS") == 0, timeout=5)
    d.run(0.5)
    r = d.recording()
    print(f"PX {r['PX'][-1]:.0f} counts at the end, VX at most {r['VX'].max():.0f} counts/s")
    print("plot:", d.plot(path, title="first_move.ehl"))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "move.png")
