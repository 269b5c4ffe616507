#!/usr/bin/env python3
"""`uprog download` into `uprog sim` of an AG300: a program of any size (its chunks fit the
framer's 255-character line) and the manual's own Demo1.cup listing sent as it is (a CRC line of
`% 000000`, not checked). Usage: download_check.py UPROG BIG.pup DEMO1_LISTING.cup"""
import socket
import subprocess
import sys
import time

uprog, big, listing = sys.argv[1], sys.argv[2], sys.argv[3]
sim = subprocess.Popen([uprog, "sim", "--listen", "127.0.0.1:0", "--dialect", "pup"],
                       stdout=subprocess.PIPE, text=True)
try:
    address = sim.stdout.readline().rsplit(" ", 1)[1].strip()  # "listening on tcp 127.0.0.1:PORT"
    for program in (big, listing):
        done = subprocess.run([uprog, "download", address, program], capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"uprog download {program}: {done.stderr.strip()}")
    host, port = address.rsplit(":", 1)
    s = socket.create_connection((host, int(port)), timeout=5)
    s.sendall(b"AProgInfo\r")
    got, deadline = b"", time.time() + 5
    while not got.endswith(b"\r\n") and time.time() < deadline:
        got += s.recv(4096)
    # The listing's header: CRC 000000, date 13/01/14, name Demo1, an answer each.
    if got != b"000000;13/01/14;Demo1;\r\n":
        sys.exit(f"AProgInfo after the listing: {got!r}")
    print("ok")
finally:
    sim.kill()
    sim.wait()
