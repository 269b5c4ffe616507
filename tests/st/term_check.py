#!/usr/bin/env python3
"""`uprog term` to an S300 drive (`uprog sim --wire readable`, the form uprog's hosts read):
each line's answers, a BEL ERR error as `?code text`, the MSG=2 compile report on PLCRUN and at
boot (COLDSTART with MSG=2 saved) and the program's PRINTF text as what the drive sent on its
own (`<< `). Usage: term_check.py UPROG PROGRAM.st"""
import subprocess
import sys

uprog, program = sys.argv[1], sys.argv[2]
sim = subprocess.Popen([uprog, "sim", "--listen", "127.0.0.1:0", "--wire", "readable", "--program", program],
                       stdout=subprocess.PIPE, text=True)
REPORT = ["<< PLC compile", "<< PLCMAIN (size=4)", "<< load factor 0", "<< PLC start",
          "<< Hello world in the year 2011"]
try:
    port = int(sim.stdout.readline().rsplit(":", 1)[1])
    lines = ["VER", "NOSUCH", "MSG 2", "PLCRUN", "SAVE", "COLDSTART", "MSG", "YEAR"]
    r = subprocess.run([uprog, "term", "--dialect", "st", f"127.0.0.1:{port}"], input="\n".join(lines) + "\n",
                       capture_output=True, text=True, timeout=60)
    want = ["uprog S300 sim 1.0", "?1 unknown command"] + REPORT + REPORT + ["2", "2011"]
    got = r.stdout.splitlines()
    # What the program printed when the drive started may have come before the connection.
    if got and got[0] == REPORT[-1]:
        got = got[1:]
    if r.returncode != 0 or got != want:
        sys.exit(f"uprog term exited {r.returncode}\nexpected {want}\ngot      {got}\n{r.stderr}")
    print("ok")
finally:
    sim.kill()
    sim.wait()
