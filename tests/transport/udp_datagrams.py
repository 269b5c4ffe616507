#!/usr/bin/python3
"""`uprog sim --udp`: a host sends one command per datagram and reads one reply datagram, as Elmo
drives speak over Ethernet (issue 38). The replies are the drive form of docs/protocol.md (the
SimplIQ Software Manual, chapter 3): the echo while EO=1, `value;`, `;` for a command without a
value, the EC code as one byte then `?;` for a refusal, `0x13 ?;` (19) for a line too long or a
bad byte. Bad datagrams (empty, oversized, binary) do no harm: the drive answers the next one.
`uprog term udp:HOST:PORT` speaks to it too.

Usage: udp_datagrams.py UPROG_BINARY
"""
import socket
import subprocess
import sys


def start_sim(uprog):
    sim = subprocess.Popen([uprog, "sim", "--dialect", "gold", "--safe-boot", "--udp", "127.0.0.1:0"],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    line = sim.stdout.readline().strip()
    prefix = "listening on udp 127.0.0.1:"
    if not line.startswith(prefix):
        sim.kill()
        sys.exit("uprog sim did not report its UDP port: %r" % line)
    return sim, int(line[len(prefix):])


class Host:
    def __init__(self, port):
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.settimeout(2.0)
        self.to = ("127.0.0.1", port)

    def ask(self, datagram):
        self.sock.sendto(datagram, self.to)
        return self.sock.recv(65535)

    def no_reply(self, datagram):
        self.sock.sendto(datagram, self.to)
        self.sock.settimeout(0.5)
        try:
            extra = self.sock.recv(65535)
        except socket.timeout:
            return True
        finally:
            self.sock.settimeout(2.0)
        print("unexpected reply %r to %r" % (extra, datagram))
        return False


def main():
    sim, port = start_sim(sys.argv[1])
    failures = []

    def expect(host, datagram, reply):
        got = host.ask(datagram)
        if got != reply:
            failures.append("%r: expected %r, got %r" % (datagram[:40], reply, got))

    try:
        host = Host(port)
        # EO=1 after power-up: the bytes come back before the answer; the datagram's end ends
        # the line (no terminator sent)
        expect(host, b"EO=0", b"EO=0;")
        expect(host, b"PX=1234;", b";")
        expect(host, b"PX", b"1234;")
        expect(host, b"PX\r", b"1234;")
        expect(host, b"PX;MO", b"1234;0;")
        # a refusal: EC 21 as one byte, then ?; and EC reads it
        expect(host, b"AC=-5", b"\x15?;")
        expect(host, b"EC", b"21;")
        # an empty datagram carries no command: no reply
        if not host.no_reply(b""):
            failures.append("an empty datagram was answered")
        # oversized (beyond the 511 characters of a line) and binary: a syntax error, 19
        expect(host, b"A" * 2000, b"\x13?;")
        expect(host, b"P" * 65000, b"\x13?;")
        expect(host, b"\x00\x01\xff\xfe", b"\x13?;")
        # every other byte (CR, LF and `;` would end lines of their own)
        expect(host, bytes(b for b in range(256) if b not in (10, 13, 59)), b"\x13?;")
        # the drive runs on and keeps what it had
        expect(host, b"PX", b"1234;")
        # a second host has a session of its own; EO=0 is the drive's setting, so no echo for it
        other = Host(port)
        expect(other, b"PX", b"1234;")
        expect(other, b"UI[1]=7;UI[1]", b";7;")
        expect(host, b"UI[1]", b"7;")
        # `uprog term udp:HOST:PORT`: a line a datagram, the answers as over TCP (sim_test.cpp)
        term = subprocess.run([sys.argv[1], "term", "udp:127.0.0.1:%d" % port],
                              input="PX=7; PX-3\n(3.2+4)/2\nAC=-5\n", capture_output=True,
                              text=True, timeout=30)
        if not term.stdout.startswith("4\n3.600000\n?21"):
            failures.append("uprog term over UDP printed %r (stderr %r)" % (term.stdout, term.stderr))
    finally:
        sim.terminate()
        sim.wait(timeout=10)
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
