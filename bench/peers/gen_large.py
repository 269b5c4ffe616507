#!/usr/bin/env python3
"""Writes a generated Gold program and a Lua program of the same shape and line count (100 000
lines by default) for the compile-speed comparison: uprog check vs luac5.4 -p.
Usage: gen_large.py OUT_DIR [LINES]"""
import sys

BODY_GOLD = """function [int r] = f{n}(int a, float b)
int x1, x2, x3
float y1, y2
x1 = a * 3 + {n} % 17
y1 = b * 0.5 + x1
y2 = sin(y1) * sqrt(abs(y1)) - 1.25e-3
if (x1 > 10 && y1 < 1000.0)
  x2 = x1 % 5 + (x1 >> 2)
elseif (x1 == 3)
  x2 = -x1
else
  x2 = x1 - 1
end
for x3 = 1:10
  x1 = x1 + x3 * 2
end
while (x2 < 100 && x2 > 0)
  x2 = x2 * 2 + 1
end
r = x1 + x2 + fix(y2)
return
"""

BODY_LUA = """function f{n}(a, b)
local x1, x2, x3
local y1, y2
x1 = a * 3 + {n} % 17
y1 = b * 0.5 + x1
y2 = math.sin(y1) * math.sqrt(math.abs(y1)) - 1.25e-3
if x1 > 10 and y1 < 1000.0 then
  x2 = x1 % 5 + (x1 >> 2)
elseif x1 == 3 then
  x2 = -x1
else
  x2 = x1 - 1
end
for x3 = 1, 10 do
  x1 = x1 + x3 * 2
end
while x2 < 100 and x2 > 0 do
  x2 = x2 * 2 + 1
end
return x1 + x2 + math.floor(y2)
end
"""


def write(path, head, body, tail, lines):
    per = body.count("\n")
    count = (lines - head.count("\n") - tail.count("\n")) // per
    text = head + "".join(body.format(n=n) for n in range(count)) + tail
    text += "\n" * (lines - text.count("\n"))  # pad to exactly `lines`
    with open(path, "w") as f:
        f.write(text)


def main():
    out = sys.argv[1]
    lines = int(sys.argv[2]) if len(sys.argv) > 2 else 100_000
    write(f"{out}/large.ehl", "function main()\nint r\nr = f0(1, 2.0)\nreturn\n", BODY_GOLD, "", lines)
    write(f"{out}/large.lua", "", BODY_LUA, "print(f0(1, 2.0))\n", lines)


if __name__ == "__main__":
    main()
