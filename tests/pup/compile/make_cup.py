#!/usr/bin/env python3
# Writes a CUP file from its program lines by the spec's header rules (akribis-drive.md, "The CUP
# file"), independently of the C++ writer: the oracle the expected .cup files here were made with.
# usage: make_cup.py NAME OUT.cup [--info S]... [--event ID,F]... < program-lines
import sys, zlib

def cup(name, lines, info=(), events=(), date="01/01/00"):
    tasks = [(l[len("AProgTask["):-1], i + 1) for i, l in enumerate(lines) if l.startswith("AProgTask[")]
    i_part = "".join("%I " + s + "\r" for s in info)
    t_part = "".join("%%T %s,%d\r" % t for t in tasks)
    e_part = "".join("%E " + e + "\r" for e in events)
    body = "".join(l + "\r" for l in lines)
    head = "% " + date + "\r% " + name + "\r"
    at = 11 + len(head) + 5 * 9
    offsets = [at, at + len(i_part), at + len(i_part) + len(t_part)]
    offsets.append(offsets[2] + len(e_part))
    offsets.append(offsets[3] + len(body))
    head += "".join("%% %06d\r" % o for o in offsets)
    rest = head + i_part + t_part + e_part + body
    return "%% %08X\r" % zlib.crc32(rest.encode()) + rest

if __name__ == "__main__":
    args = sys.argv[1:]
    name, out = args[0], args[1]
    info, events, k = [], [], 2
    while k < len(args):
        (info if args[k] == "--info" else events).append(args[k + 1])
        k += 2
    lines = [l.rstrip("\n") for l in sys.stdin if l.strip()]
    open(out, "w", newline="").write(cup(name, lines, info, events))
