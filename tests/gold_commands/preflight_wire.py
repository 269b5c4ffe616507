#!/usr/bin/python3
"""A Gold host's preflight over the wire, as a host written against the Gold Command Reference
sends it (issue 38, item 2): over TCP and over UDP (one command a datagram, one reply datagram),
every read answers a value and no error, on a fresh drive each, with the values that
docs/dialects/gold.md ("Preflight") decides and tests/transcripts/gold_drive/preflight.txt checks
on the command line; then the host's settings (RM=0, SF[1]=20, SF[2]=0, FS=0) are taken and read
back, the motor is enabled (SO=1) and turned off again (MS=3). Replies are the drive form of
docs/protocol.md: `value;`, `;` for a command without a value, and no echo after EO=0.

Usage: preflight_wire.py UPROG_BINARY
"""
import socket
import subprocess
import sys
import time

# Each read and what a fresh drive answers (docs/dialects/gold.md, "Preflight" and "The drive's
# commands"): SR 50432 is bits 14 and 15 (the STO inputs) and UM=5 in bits 8..10.
READS = [("RM", "0"), ("ID", "0.0")] + [("FC[%d]" % n, "1") for n in range(1, 13)] + [
    ("BP[1]", "0"), ("BP[2]", "0"), ("SC[13]", "0"), ("FS", "0"), ("SF[1]", "0"), ("SF[2]", "0"),
    ("OV[2]", "0"), ("LC", "0")] + [("CA[%d]" % n, "0") for n in range(54, 58)] + [
    ("MO", "0"), ("SO", "0"), ("MS", "3"), ("SR", "50432")]
SETTINGS = ["RM=0", "SF[1]=20", "SF[2]=0", "FS=0"]
READ_BACK = [("RM", "0"), ("SF[1]", "20"), ("SF[2]", "0"), ("FS", "0")]


def start_sim(uprog):
    sim = subprocess.Popen([uprog, "sim", "--dialect", "gold", "--safe-boot", "--listen",
                            "127.0.0.1:0", "--udp", "127.0.0.1:0"],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    ports = {}
    for _ in range(2):
        words = sim.stdout.readline().split()
        if len(words) != 4 or words[:2] != ["listening", "on"]:
            sim.kill()
            sys.exit("uprog sim did not report its ports: %r" % words)
        ports[words[2]] = int(words[3].rsplit(":", 1)[1])
    return sim, ports


class TcpHost:
    def __init__(self, port):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=2.0)

    def ask(self, line):
        self.sock.sendall((line + "\r").encode())
        reply = b""
        while not reply.endswith(b";"):
            chunk = self.sock.recv(4096)
            if not chunk:
                break
            reply += chunk
        return reply


class UdpHost:
    def __init__(self, port):
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.settimeout(2.0)
        self.to = ("127.0.0.1", port)

    def ask(self, line):
        self.sock.sendto((line + "\r").encode(), self.to)
        return self.sock.recv(65535)


def preflight(name, host, failures):
    def expect(line, reply):
        got = host.ask(line)
        if got != reply.encode():
            failures.append("%s %s: expected %r, got %r" % (name, line, reply, got))

    host.ask("EO=0")  # the answer may carry the echo of EO=0 itself
    for command, value in READS:
        expect(command, value + ";")
    for setting in SETTINGS:
        expect(setting, ";")
    for command, value in READ_BACK:
        expect(command, value + ";")
    expect("MO=1", ";")
    deadline = time.monotonic() + 5
    while host.ask("SO") != b"1;" and time.monotonic() < deadline:
        time.sleep(0.05)
    expect("SO", "1;")
    expect("MO=0", ";")
    expect("MS", "3;")


def main():
    failures = []
    # A fresh drive for each: the host's settings must not carry over.
    for name, host_class in (("tcp", TcpHost), ("udp", UdpHost)):
        sim, ports = start_sim(sys.argv[1])
        try:
            preflight(name, host_class(ports[name]), failures)
        except (OSError, socket.timeout) as e:
            failures.append("%s: no answer: %s" % (name, e))
        finally:
            sim.terminate()
            sim.wait()
    for f in failures:
        print(f)
    print("preflight over tcp and udp: %s" % ("FAILED" if failures else "ok"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
