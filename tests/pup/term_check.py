#!/usr/bin/env python3
"""`uprog term` to an AG300 drive (`uprog sim --program X.pup`): the A-prefixed keywords typed
line by line, a value per answer, an error as `?code text`, nothing for an empty answer; a
program started and its thread's status read. Usage: term_check.py UPROG PROGRAM.pup"""
import subprocess
import sys

uprog, program = sys.argv[1], sys.argv[2]
sim = subprocess.Popen([uprog, "sim", "--listen", "127.0.0.1:0", "--program", program],
                       stdout=subprocess.PIPE, text=True)
try:
    port = int(sim.stdout.readline().rsplit(":", 1)[1])
    lines = ["AGenData[3]=-42", "AGenData[3]", "ANoSuchThing", "AProgStatus[1]", "AProgRun[1],1",
             "AProgStatus[1]", "APushConstant,6; APushConstant,7; AMath[2]; APopParam,AGenData[4]",
             "AGenData[4]", "AErrLog[1]", "AProgHalt[1]", "AProgStatus[1]"]
    r = subprocess.run([uprog, "term", f"127.0.0.1:{port}"], input="\n".join(lines) + "\n",
                       capture_output=True, text=True, timeout=60)
    # AErrLog[1]: the refused ANoSuchThing, code 1 from the host (source 0, line 0)
    want = ["-42", "?1 unknown keyword", "0", "2", "42", "1,0,0", "3"]
    got = r.stdout.splitlines()
    if r.returncode != 0 or got != want:
        sys.exit(f"uprog term exited {r.returncode}\nexpected {want}\ngot      {got}\n{r.stderr}")
    print("ok")
finally:
    sim.kill()
    sim.wait()
