#!/usr/bin/env python3
"""`uprog sim` serving an AG300 drive over TCP, as a host program sees it: `value;`, `;`,
`?CODE TEXT;` and CR LF after each typed line; a program started over the line; a line the framer
refuses (a control byte) answered `?901` and latched as the communication error, event 23, which
the program's event function counts, and logged in AErrLog.
Usage: sim_check.py UPROG PROGRAM.pup (all_events.pup)"""
import socket
import subprocess
import sys
import time

uprog, program = sys.argv[1], sys.argv[2]
sim = subprocess.Popen([uprog, "sim", "--listen", "127.0.0.1:0", "--program", program],
                       stdout=subprocess.PIPE, text=True)
try:
    port = int(sim.stdout.readline().rsplit(":", 1)[1])  # "listening on tcp 127.0.0.1:PORT"
    s = socket.create_connection(("127.0.0.1", port), timeout=5)

    def ask(data):
        """Sends one line; returns all it got up to the CR LF that ends the answers."""
        s.sendall(data)
        got = b""
        deadline = time.time() + 5
        while not got.endswith(b"\r\n") and time.time() < deadline:
            s.settimeout(max(0.01, deadline - time.time()))
            try:
                chunk = s.recv(4096)
            except socket.timeout:
                break
            if not chunk:
                break
            got += chunk
        return got

    def talk(data, expected):
        got = ask(data)
        if got != expected:
            sys.exit(f"sent {data!r}: expected {expected!r}, got {got!r}")

    talk(b"AGenData[5]=7\r", b";\r\n")
    talk(b"AGenData[5]\r", b"7;\r\n")
    talk(b"agendata[5]; ASpeed\r", b"7;10000;\r\n")
    talk(b"ANoSuch\r", b"?1 unknown keyword;\r\n")
    talk(b"AWaitTime,10\r", b"?13 not over the line;\r\n")
    talk(b"AProgRun[1],1\r", b";\r\n")
    talk(b"AProgStatus[1]\r", b"2;\r\n")
    talk(b"AGenData[24]\r", b"0;\r\n")
    talk(b"AGen\x01Data[1]\r", b"?901 Bad character;\r\n")
    talk(b"AErrLog[1]\r", b"901,0,0;\r\n")  # the host's error, source 0, line 0
    # The event function runs within a few cycles of the next served line.
    deadline = time.time() + 5
    while ask(b"AGenData[24]\r") != b"1;\r\n":
        if time.time() > deadline:
            sys.exit("event 23 was not taken after the framing error")
        time.sleep(0.05)
    talk(b"AProgStatus[1]\r", b"2;\r\n")
    print("ok")
finally:
    sim.kill()
    sim.wait()
