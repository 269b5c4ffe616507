"""Fixtures of the package's own tests: the repository's paths, the uprog binary, and a
`uprog sim` per test over TCP, UDP and a pty (started and stopped here)."""

import os
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def example(*parts):
    return os.path.join(ROOT, "examples", *parts)


@pytest.fixture(scope="session")
def uprog_binary():
    from uprog.compiler import find_uprog
    try:
        return find_uprog()
    except Exception as e:  # pylint: disable=broad-except
        pytest.skip(f"no uprog binary: {e}")


class Sim:
    """A `uprog sim` process and the addresses it printed."""

    def __init__(self, uprog, dialect, program=None, pty=False, udp=False, wire=None):
        args = [uprog, "sim", "--listen", "127.0.0.1:0", "--dialect", dialect]
        if program:
            args += ["--program", program]
        if pty:
            args.append("--pty")
        if udp:
            args += ["--udp", "127.0.0.1:0"]
        if wire:
            args += ["--wire", wire]
        self.process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                        text=True)
        self.urls = {}
        for _ in range(1 + pty + udp):
            line = self.process.stdout.readline()  # "listening on tcp 127.0.0.1:PORT"
            words = line.split()
            if len(words) != 4 or words[0] != "listening":
                self.stop()
                why = self.process.stderr.read()
                raise RuntimeError(f"uprog sim did not start: {line!r} {why}")
            scheme = "serial://" if words[2] == "pty" else f"{words[2]}://"
            self.urls[words[2]] = scheme + words[3]

    def stop(self):
        self.process.terminate()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


@pytest.fixture
def uprog_sim(uprog_binary):
    """uprog_sim(dialect, program=None, pty=False, udp=False) -> Sim; stopped after the test."""
    started = []

    def start(dialect, program=None, **options):
        sim = Sim(uprog_binary, dialect, program, **options)
        started.append(sim)
        return sim

    yield start
    for sim in started:
        sim.stop()
