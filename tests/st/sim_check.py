#!/usr/bin/env python3
"""`uprog sim` serving an S300 drive over TCP, as `uprog term` or a host program sees it: the
prompt and echo with PROMPT=1, BEL ERR errors, the MSG=2 compile report on PLCRUN and at boot
(COLDSTART with MSG=2 saved) and PRINTF text between answers. Usage: sim_check.py UPROG PROGRAM.st"""
import socket
import subprocess
import sys
import time

uprog, program = sys.argv[1], sys.argv[2]
sim = subprocess.Popen([uprog, "sim", "--listen", "127.0.0.1:0", "--program", program],
                       stdout=subprocess.PIPE, text=True)
try:
    line = sim.stdout.readline()  # "listening on tcp 127.0.0.1:PORT"
    port = int(line.rsplit(":", 1)[1])
    s = socket.create_connection(("127.0.0.1", port), timeout=5)

    def talk(data, expected, also=b""):
        s.sendall(data)
        got = b""
        deadline = time.time() + 5
        while not got.endswith(expected[-3:]) and time.time() < deadline:
            s.settimeout(max(0.01, deadline - time.time()))
            try:
                chunk = s.recv(4096)
            except socket.timeout:
                break
            if not chunk:
                break
            got += chunk
        # `also`, what the program loaded at start prints, may come anywhere among the answer's
        # lines: the program runs in wall-clock time beside the command line.
        if got != expected and (not also or got.replace(also, b"", 1) != expected):
            sys.exit(f"sent {data!r}: expected {expected!r}, got {got!r}")

    # A fresh drive echoes and prompts (PROMPT's default is 1, the SERVOSTAR-family reference).
    talk(b"PROMPT 1\r", b"PROMPT 1\r\n-->", also=b"Hello world in the year 2011\r\n")
    talk(b"VER\r", b"VER\r\nuprog S300 sim 1.0\r\n-->")
    talk(b"NOSUCH\r", b"NOSUCH\r\n\aERR 1 unknown command\r\n-->")
    talk(b"MSG 2\r", b"MSG 2\r\n-->")
    talk(b"PLCRUN\r", b"PLCRUN\r\nPLC compile\r\nPLCMAIN (size=4)\r\nload factor 0\r\nPLC start\r\n"
                      b"Hello world in the year 2011\r\n-->")
    # MSG=2 saved, then a cold start: the drive compiles its stored source at boot and prints
    # the same report before the program's PRINTF; PROMPT=1 was saved too.
    talk(b"SAVE\r", b"SAVE\r\n-->")
    talk(b"COLDSTART\r", b"COLDSTART\r\nPLC compile\r\nPLCMAIN (size=4)\r\nload factor 0\r\nPLC start\r\n"
                         b"Hello world in the year 2011\r\n-->")
    talk(b"MSG\r", b"MSG\r\n2\r\n-->")
    # A real host's first jog (issue 39, item 1) on the drive's own wire: CLRFAULT, OPMODE 0,
    # EN, J 500 back to back; the jog waits for the loops and nothing faults (VLIM 3000,
    # VOSPD 3600). A download's END without BEGIN is the spec's 12.
    for command in (b"CLRFAULT", b"OPMODE 0", b"EN", b"J 500"):
        talk(command + b"\r", command + b"\r\n-->")
    time.sleep(0.5)
    talk(b"ERRCODE\r", b"ERRCODE\r\nno error\r\n-->")
    talk(b"ACTIVE\r", b"ACTIVE\r\n1\r\n-->")
    talk(b"DIS\r", b"DIS\r\n-->")
    talk(b"PLCDL END\r", b"PLCDL END\r\n\aERR 12 no download in progress (PLCDL BEGIN first)\r\n-->")
    # `uprog download` on the drive's own wire (issue 39): it reads the echo, BEL ERR and `-->`.
    size = len(open(program, "rb").read())
    r = subprocess.run([uprog, "download", f"127.0.0.1:{port}", program], capture_output=True,
                       text=True, timeout=30)
    if r.returncode != 0 or f"downloaded {size} bytes" not in r.stdout:
        sys.exit(f"uprog download: exit {r.returncode}: {r.stdout!r} {r.stderr!r}")
    print("ok")
finally:
    sim.kill()
    sim.wait()
