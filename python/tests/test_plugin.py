"""The pytest plugin in pytests of their own: examples/python under `-n 2` on the simulated drive,
the same files against `uprog sim` over TCP and a pty for every dialect (--uprog-drive), and
the recording helper's failure as a user reads it."""

import os
import subprocess
import sys

import pytest

from conftest import ROOT, Sim

EXAMPLES = os.path.join(ROOT, "examples", "python")
DIALECTS = ("gold", "pdl", "pup", "st")


def pytest_command(*args):
    return [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
            "-p", "uprog.pytest_plugin", *args]


def test_examples_in_parallel_on_the_simulated_drive():
    pytest.importorskip("xdist")
    pytest.importorskip("uprog.sim")
    done = subprocess.run(pytest_command("-n", "2", EXAMPLES), capture_output=True, text=True,
                          timeout=300, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "17 passed" in done.stdout and "skipped" not in done.stdout, done.stdout


def test_examples_over_the_wire(uprog_binary):
    """Every dialect's example file against `uprog sim` over TCP and over a pty, all at once
    (over a wire time is the wall clock's)."""
    runs = []
    try:
        for dialect in DIALECTS:
            for scheme in ("tcp", "pty"):
                sim = Sim(uprog_binary, dialect, pty=scheme == "pty")
                # The whole folder: --uprog-dialect skips the other dialects' files.
                command = pytest_command(EXAMPLES, "--uprog-drive", sim.urls[scheme],
                                         "--uprog-dialect", dialect,
                                         "--uprog-binary", uprog_binary)
                runs.append((dialect, scheme, sim, subprocess.Popen(
                    command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)))
        for dialect, scheme, _, run in runs:
            out, _ = run.communicate(timeout=120)
            assert run.returncode == 0, f"{dialect} over {scheme}:\n{out}"
            assert " passed" in out and " skipped" in out, out  # sim-only tests are skipped
    finally:
        for _, _, sim, run in runs:
            if run.poll() is None:
                run.kill()
            sim.stop()


def test_recording_failure_names_channel_time_got_expected(tmp_path):
    pytest.importorskip("uprog.sim")
    reference = os.path.join(ROOT, "tests", "transcripts", "recorder", "first_steps.csv")
    (tmp_path / "test_twice_the_acceleration.py").write_text(f'''
from uprog.pytest_plugin import assert_recording_matches

def test_steps(sim_drive):
    d = sim_drive("gold")
    d.command("MO=1")
    d.run(0.03)
    d.command("SP=50000;AC=2000000;DC=2000000;PA=100000")
    d.record("DV[2],DV[3]", trigger="begin", length=8, gap=20)
    d.command("BG")
    d.run(0.01)
    assert_recording_matches(d.recording(), {reference!r})
''')
    done = subprocess.run(pytest_command(str(tmp_path)), capture_output=True, text=True,
                          timeout=120, check=False)
    assert done.returncode == 1, done.stdout
    # DV[2] at sample 0 (motion step 1 of 50 us) with a = 2e6 counts/s^2: 100; the reference's 50.
    assert "DV[2] at 0.000 ms (sample 0): 100, expected 50 (tolerance 0)" in done.stdout
