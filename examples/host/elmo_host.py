#!/usr/bin/python3
"""A small host driver for an Elmo Gold drive, run against `uprog sim`.

It talks as host software talks to a real drive over RS-232 or TCP: it turns the echo off
(EO=0), enables the motor and waits for SO, starts a function of the stored program with
XQ##, moves point to point and polls MS and SR until the move has settled, decodes SR and IP
bit by bit, and after a refused command reads the error code with EC.

  elmo_host.py --connect 127.0.0.1:5025          # a drive (or a uprog sim) already running
  elmo_host.py --sim build/bin/uprog --program examples/gold/first_move.ehl
                                                 # starts uprog sim itself, stops it at the end

Only the standard library is used. The exit status is 0 when every answer was what a drive
gives; otherwise the first surprise is printed and the status is 1.
"""

import argparse
import socket
import subprocess
import sys
import time

# SR bits (Elmo reference, SR - Status Register).
SR_DRIVE_PROBLEM = 1 << 0
SR_MOTOR_ON = 1 << 4
SR_MOTOR_FAILURE = 1 << 6
SR_HOMING = 1 << 11
SR_PROGRAM_RUNNING = 1 << 12
SR_STO = (1 << 14) | (1 << 15)  # Gold: both STO inputs permit enabling
SR_STOPPED_BY_LIMIT = 1 << 28
# IP bits as host drivers decode them (docs/dialects/gold.md, "IP and IB").
IP_LEVEL_SHIFT = 16


class DriveError(Exception):
    """A command the drive refused, with the code EC gave for it."""

    def __init__(self, line, code):
        super().__init__(f"{line!r} refused, EC={code}")
        self.line = line
        self.code = code


class Drive:
    """One connection, one command at a time, as a serial host works."""

    def __init__(self, host, port, timeout_s=5.0):
        self.sock = socket.create_connection((host, port), timeout=timeout_s)
        self.pending = b""

    def _answer(self):
        # An answer ends with ';'. Line ends (CR, LF) between answers carry nothing.
        while b";" not in self.pending:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise ConnectionError("the drive closed the connection")
            self.pending += chunk
        answer, self.pending = self.pending.split(b";", 1)
        return answer.decode("ascii").replace("\r", "").replace("\n", "").strip()

    def _send(self, line):
        self.sock.sendall(line.encode("ascii") + b"\r")
        answer = self._answer()
        # With the echo on the drive repeats the command before answering.
        if answer.startswith(line):
            answer = answer[len(line):].strip()
        return answer

    def command(self, line):
        """Sends one command; returns its answer, or raises DriveError with EC's code."""
        answer = self._send(line)
        if "?" in answer:
            code = int(self._send("EC"))
            raise DriveError(line, code)
        return answer

    def value(self, line):
        return int(self.command(line))

    def wait_for(self, line, wanted, timeout_s, poll_s=0.02):
        deadline = time.monotonic() + timeout_s
        while True:
            got = self.value(line)
            if got == wanted:
                return
            if time.monotonic() > deadline:
                raise TimeoutError(f"{line} stayed {got}, wanted {wanted}")
            time.sleep(poll_s)

    def close(self):
        self.sock.close()


def describe_sr(sr):
    bits = [name for name, bit in (("problem", SR_DRIVE_PROBLEM), ("motor on", SR_MOTOR_ON),
                                   ("motor failure", SR_MOTOR_FAILURE), ("homing", SR_HOMING),
                                   ("program running", SR_PROGRAM_RUNNING),
                                   ("stopped by limit", SR_STOPPED_BY_LIMIT)) if sr & bit]
    return (f"SR={sr:#010x}: UM={(sr >> 8) & 7}, STO={'permits' if (sr & SR_STO) == SR_STO else 'blocks'}"
            + (", " + ", ".join(bits) if bits else ""))


def expect(condition, what):
    if not condition:
        raise AssertionError(what)


def session(drive):
    drive.command("EO=0")  # no echo from here on: one answer per command
    print("vendor", drive.value("SN[1]"), "serial", drive.value("SN[4]"))

    # The stored program moves first: XQ## starts its function; the host waits for its end.
    drive.command("XQ##main")
    drive.wait_for("PS", 0, timeout_s=10)
    moves = drive.value("moves")
    expect(moves == 1, f"the program's move counter is {moves}")
    print("program: moves =", moves, "PX =", drive.value("PX"))

    # Enable (already on after the program; done again as a host does it) and wait for SO.
    if drive.value("MO") == 0:
        drive.command("UM=5")
        drive.command("MO=1")
    drive.wait_for("SO", 1, timeout_s=2)
    sr = drive.value("SR")
    print(describe_sr(sr))
    expect(sr & SR_MOTOR_ON, "SR says the motor is off")

    # A point-to-point move: MS is 2 while the profiler runs, 0 once settled within TR.
    drive.command("SP=200000")
    drive.command("AC=2000000")
    drive.command("DC=2000000")
    drive.command("PA=20000")
    drive.command("BG")
    drive.wait_for("MS", 0, timeout_s=5)
    px = drive.value("PX")
    expect(abs(px - 20000) <= drive.value("TR[1]"), f"PX={px} outside TR[1] of 20000")
    print("moved: PX =", px, describe_sr(drive.value("SR")))

    # Inputs by number: input 1's level is IP bit 16.
    ip = drive.value("IP")
    print(f"IP={ip:#x}: input 1 level {(ip >> IP_LEVEL_SHIFT) & 1}")

    # A refused command: the unit mode changes only with the motor off (EC 60).
    try:
        drive.command("UM=2")
    except DriveError as e:
        expect(e.code == 60, f"UM=2 with MO=1 gave EC={e.code}, not 60")
        print("refused as a drive refuses it:", e)
    else:
        raise AssertionError("UM=2 with the motor on was accepted")

    drive.command("MO=0")
    expect(drive.value("MS") == 3, "MS is not 3 with the motor off")  # Gold reference


def start_sim(uprog, program):
    sim = subprocess.Popen([uprog, "sim", "--listen", "127.0.0.1:0", "--program", program],
                           stdout=subprocess.PIPE, text=True)
    line = sim.stdout.readline()
    prefix = "listening on tcp 127.0.0.1:"
    if not line.startswith(prefix):
        sim.terminate()
        raise RuntimeError(f"uprog sim did not start: {line!r}")
    return sim, int(line[len(prefix):])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--connect", help="HOST:PORT of a running drive")
    parser.add_argument("--sim", help="the uprog binary: start `uprog sim` for the session")
    parser.add_argument("--program", help="the program uprog sim loads (with --sim)")
    args = parser.parse_args()
    sim = None
    try:
        if args.sim:
            sim, port = start_sim(args.sim, args.program)
            host = "127.0.0.1"
        elif args.connect:
            host, port = args.connect.rsplit(":", 1)
            port = int(port)
        else:
            parser.error("give --connect HOST:PORT or --sim UPROG --program FILE")
        drive = Drive(host, port)
        try:
            session(drive)
        finally:
            drive.close()
    except (AssertionError, DriveError, TimeoutError, ConnectionError, RuntimeError, OSError) as e:
        print("host: unexpected:", e, file=sys.stderr)
        return 1
    finally:
        if sim:
            sim.terminate()
            sim.wait(timeout=10)
    print("host: done")
    return 0


if __name__ == "__main__":
    sys.exit(main())
