#!/usr/bin/env python3
"""A real host's session with `uprog sim --dialect st` over TCP, on the drive's own wire with its
default echo (PROMPT 1): the host syncs with a bare CR and waits for `-->`, sends each command,
reads its echo line, then the answer lines up to the prompt, as Kollmorgen's host tools do
(docs/dialects/st.md, "Echo" and "The command line"). Usage: host_session_check.py UPROG"""
import socket
import subprocess
import sys
import time

uprog = sys.argv[1]
sim = subprocess.Popen([uprog, "sim", "--dialect", "st", "--listen", "127.0.0.1:0"],
                       stdout=subprocess.PIPE, text=True)
try:
    port = int(sim.stdout.readline().rsplit(":", 1)[1])
    s = socket.create_connection(("127.0.0.1", port), timeout=5)
    pending = b""

    def read_to_prompt():
        global pending
        deadline = time.time() + 5
        while b"-->" not in pending:
            if time.time() > deadline:
                sys.exit(f"no prompt; got {pending!r}")
            s.settimeout(max(0.01, deadline - time.time()))
            chunk = s.recv(4096)
            if not chunk:
                sys.exit(f"connection closed; got {pending!r}")
            pending += chunk
        got, pending = pending.split(b"-->", 1)
        return got

    def ask(command, end=b"\r"):
        """The answer lines of one command, after its echo; an error line starts with BEL."""
        s.sendall(command.encode() + end)
        got = read_to_prompt()
        echo = command.encode() + b"\r\n"
        if not got.startswith(echo):
            sys.exit(f"{command!r}: expected the echo {echo!r} first, got {got!r}")
        lines = got[len(echo):].split(b"\r\n")
        if lines[-1] != b"":
            sys.exit(f"{command!r}: the answer does not end with CR LF: {got!r}")
        return [line.decode() for line in lines[:-1]]

    def expect(command, *answer, end=b"\r"):
        got = ask(command, end)
        if got != list(answer):
            sys.exit(f"{command!r}: expected {list(answer)!r}, got {got!r}")

    def number(command):
        got = ask(command)
        if len(got) != 1:
            sys.exit(f"{command!r}: expected one number, got {got!r}")
        return float(got[0])

    # The host finds the drive: a bare CR gives CR LF and the prompt (the reference's PROMPT=1).
    s.sendall(b"\r")
    if read_to_prompt() != b"\r\n":
        sys.exit("a bare CR did not give CR LF and the prompt")
    expect("VER", "uprog S300 sim 1.0")
    # Its first jog: CLRFAULT, OPMODE 0, EN, J 500 back to back (issue 39), then the reads.
    for command in ("CLRFAULT", "OPMODE 0", "EN", "J 500"):
        expect(command)
    time.sleep(0.5)
    expect("ERRCODE", "no error")
    if number("V") != 500.0:
        sys.exit("J 500 does not run at 500 rpm")
    first = number("PFB")
    time.sleep(0.2)
    if number("PFB") <= first:
        sys.exit("PFB does not grow while jogging")
    if number("I") < 0:
        sys.exit("I is negative (the reference: always positive)")
    expect("STATUS", "00000000 00000000 00000000 00000000 00000001")  # word 5 bit 0: moving
    # A bad command is one BEL ERR line before the prompt; the drive goes on.
    expect("J", "\aERR 2 syntax error")
    expect("OPMODE 8", "\aERR 5 needs disabled")
    expect("STOP")
    expect("DIS")
    expect("ACTIVE", "0")
    # Parameters: a write answers nothing, a read its value; lines may end with LF alone.
    expect("VLIM 2000")
    expect("VLIM", "2000", end=b"\n")
    expect("vlim", "2000", end=b"\r\n")
    # A motion task in user units (c = 8192), started with MOVE, polled with INPOS.
    expect("OPMODE 8")
    expect("ORDER 192 10000 100000 8192 50 50 0 0 0 0")
    expect("EN")
    expect("MOVE 192")
    deadline = time.time() + 10
    while ask("INPOS") != ["1"]:
        if time.time() > deadline:
            sys.exit("task 192 never in position")
        time.sleep(0.05)
    # In position is within PEINPOS of the target: the axis may still settle by a count then.
    deadline = time.time() + 2
    while ask("PFB") != ["10000"]:
        if time.time() > deadline:
            sys.exit("task 192 never ends at PFB 10000")
        time.sleep(0.05)
    expect("MOVE", "192")
    expect("DIS")
    expect("SAVE")
    expect("ERRCODE", "no error")
    print("ok")
finally:
    sim.kill()
    sim.wait()
