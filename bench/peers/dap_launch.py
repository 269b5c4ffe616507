#!/usr/bin/env python3
"""bench/peers/dap_launch.py UPROG PROGRAM: runs PROGRAM to its end under `UPROG dap` (launch, no
breakpoints: the debugger attached and watching every cycle), for measuring what the debugger
costs against `UPROG run PROGRAM`, e.g. under `valgrind --tool=callgrind`. Prints the program's
exit code as the adapter reported it."""
import json
import subprocess
import sys


def frame(seq, command, arguments):
    body = json.dumps({"seq": seq, "type": "request", "command": command, "arguments": arguments})
    return f"Content-Length: {len(body)}\r\n\r\n{body}".encode()


def messages(stream):
    while True:
        header = b""
        while not header.endswith(b"\r\n\r\n"):
            c = stream.read(1)
            if not c:
                return
            header += c
        length = int(header.split(b"Content-Length:")[1].split(b"\r\n")[0])
        yield json.loads(stream.read(length))


def main():
    uprog, program = sys.argv[1], sys.argv[2]
    dap = subprocess.Popen([uprog, "dap"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    for seq, (command, arguments) in enumerate(
            [("initialize", {"adapterID": "uprog"}), ("launch", {"program": program}),
             ("configurationDone", {})], 1):
        dap.stdin.write(frame(seq, command, arguments))
    dap.stdin.flush()
    code = None
    for m in messages(dap.stdout):
        if m.get("type") == "response" and not m.get("success"):
            sys.exit(f"{m['command']}: {m.get('message')}")
        if m.get("event") == "exited":
            code = m["body"]["exitCode"]
        if m.get("event") == "terminated":
            break
    dap.stdin.write(frame(4, "disconnect", {}))
    dap.stdin.close()
    dap.wait()
    print(f"exit code {code}")


if __name__ == "__main__":
    main()
