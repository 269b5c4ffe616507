#!/usr/bin/env python3
"""`uprog sim --input/--switch/--analog`: the world's inputs a host tester sets from the start
(docs/transcripts.md's `input`, `switch`, `analog`), read over the S300's own wire: IN1…IN4 the
digital levels, ANIN1/ANIN2 the analog levels in mV (the reference's ANIN1: -10000…10000, so a
level beyond it reads the limit). Bad values stop the sim with exit 2 and the option named; a
drive without analog inputs refuses --analog. Usage: sim_world_check.py UPROG"""
import socket
import subprocess
import sys
import time

uprog = sys.argv[1]


def refused(args, expected):
    r = subprocess.run([uprog, "sim", "--listen", "127.0.0.1:0", *args], capture_output=True,
                       text=True, timeout=30)
    if r.returncode != 2 or expected not in r.stderr:
        sys.exit(f"uprog sim {' '.join(args)}: expected exit 2 with {expected!r}, "
                 f"got {r.returncode}: {r.stderr!r}")


refused(["--dialect", "st", "--input", "7=1"], "--input 7=1: expected N=LEVEL, N 1..6")
refused(["--dialect", "st", "--input", "2=high"], "--input 2=high: expected N=LEVEL")
refused(["--dialect", "st", "--switch", "3=100:-100"], "--switch 3=100:-100: expected N=FROM:TO")
refused(["--dialect", "st", "--analog", "3=100"], "--analog 3=100: analog needs")
refused(["--dialect", "st", "--analog", "1=2.5V"], "--analog 1=2.5V: analog needs")
refused(["--dialect", "gold", "--analog", "1=100"], "--analog 1=100: the gold drive has no analog")

# Input 2 high, input 4 low; input 3 a cam over the motor's place (0 counts lies in it), input 1
# a cam away from it; SW1 at 2500 mV, SW2 at -12000 mV (beyond the ±10 V range).
sim = subprocess.Popen([uprog, "sim", "--dialect", "st", "--listen", "127.0.0.1:0",
                        "--input", "2=1", "--input", "4=0", "--switch", "3=-100:100",
                        "--switch", "1=5000:6000", "--analog", "1=2500", "--analog", "2=-12000"],
                       stdout=subprocess.PIPE, text=True)
try:
    line = sim.stdout.readline()  # "listening on tcp 127.0.0.1:PORT"
    port = int(line.rsplit(":", 1)[1])
    s = socket.create_connection(("127.0.0.1", port), timeout=5)

    def talk(command, answer):
        expected = command + b"\r\n" + answer + b"-->"
        s.sendall(command + b"\r")
        got = b""
        deadline = time.time() + 5
        while not got.endswith(b"-->") and time.time() < deadline:
            s.settimeout(max(0.01, deadline - time.time()))
            try:
                chunk = s.recv(4096)
            except socket.timeout:
                break
            if not chunk:
                break
            got += chunk
        if got != expected:
            sys.exit(f"sent {command!r}: expected {expected!r}, got {got!r}")

    talk(b"IN1", b"0\r\n")
    talk(b"IN2", b"1\r\n")
    talk(b"IN3", b"1\r\n")
    talk(b"IN4", b"0\r\n")
    talk(b"ANIN1", b"2500\r\n")
    talk(b"ANIN2", b"-10000\r\n")
    # The world outlives a cold start, as a real drive's wiring does.
    talk(b"COLDSTART", b"")
    talk(b"IN2", b"1\r\n")
    talk(b"ANIN1", b"2500\r\n")
    print("ok")
finally:
    sim.kill()
    sim.wait()
