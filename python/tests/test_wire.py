"""The wire layer against `uprog sim` for every dialect: answers and errors as each dialect's
host reads them, a download through the dialect's own protocol, program output, and a wire
that breaks. Expected values come from the manuals, the spec and the examples' comments."""

import os
import socket
import time

import pytest

import uprog
from conftest import ROOT, example


def wait_for(drive, name, wanted, timeout_s=5.0):
    deadline = time.monotonic() + timeout_s
    while True:
        got = drive.query(name)
        if got == wanted or time.monotonic() > deadline:
            return got
        time.sleep(0.02)


# --- Gold: the drive form (MAN-SIMSW 3.1; docs/protocol.md "The drive form")

@pytest.mark.parametrize("scheme", ["tcp", "udp", "pty"])
def test_gold_answers_and_errors(uprog_sim, scheme):
    sim = uprog_sim("gold", pty=scheme == "pty", udp=scheme == "udp")
    with uprog.connect(sim.urls[scheme], "gold") as drive:
        # The echo is on after power-up (EO=1): it is taken out of the answers.
        assert drive.command("PX=7;PX-3") == ["", "4"]
        assert drive.command("3+4") == ["7"]
        assert drive.query("(3.2+4)/2") == pytest.approx(3.6)
        # AC must be positive: EC 21, "Value out of the command's range" (Elmo's EC table).
        with pytest.raises(uprog.DriveError) as refused:
            drive.command("AC=-5")
        assert refused.value.code == 21
        assert refused.value.text == "Value out of the command's range"
        assert drive.query("EC") == 21
        drive.command("EO=0")  # and without the echo
        assert drive.command("PX;MO") == ["7", "0"]


def test_gold_readable_wire(uprog_sim):
    sim = uprog_sim("gold", wire="readable")
    with uprog.connect(sim.urls["tcp"], "gold") as drive:
        assert drive.command("PX=7; PX-3") == ["", "4"]
        with pytest.raises(uprog.DriveError) as refused:
            drive.command("AC=-5")
        assert (refused.value.code, refused.value.text) == (21, "Value out of the command's range")


@pytest.mark.parametrize("scheme", ["tcp", "pty"])
def test_gold_load_and_move(uprog_sim, scheme):
    sim = uprog_sim("gold", pty=scheme == "pty")
    with uprog.connect(sim.urls[scheme], "gold") as drive:
        # examples/gold/2_06_globals.ehl has no motion; a download, CC and XQ## over the wire.
        size = drive.load(example("gold", "first_move.ehl"))
        assert size > 0
        # UM=5 with the motor off, then a move the manual's way (Gold reference: PA, BG, MS).
        for line in ("MO=0", "UM=5", "MO=1"):
            drive.command(line)
        assert wait_for(drive, "SO", 1) == 1
        for line in ("SP=400000", "AC=8000000", "DC=8000000", "PA=20000", "BG"):
            drive.command(line)
        assert wait_for(drive, "MS", 0) == 0  # 0: the move has settled
        assert abs(drive.query("PX") - 20000) <= drive.query("TR[1]")
        # UM changes only with the motor off: EC 60.
        with pytest.raises(uprog.DriveError) as refused:
            drive.command("UM=2")
        assert refused.value.code == 60


def test_gold_compile_error_names_every_place(uprog_sim, tmp_path):
    source = tmp_path / "bad.ehl"
    source.write_text("int a\nfunction main()\na = 1 +\nb = 2\nreturn\n")
    sim = uprog_sim("gold")
    with uprog.connect(sim.urls["tcp"], "gold") as drive:
        with pytest.raises(uprog.CompileError) as failed:
            drive.load(str(source))
    places = [(d.line, d.code) for d in failed.value.diagnostics]
    assert (3, 7) in places  # gold 7: "Value is expected" (the manual's compile error table)
    assert f"{source}:3:" in str(failed.value)


# --- PDL: `value;`, `?CODE TEXT;`, CR LF; `%P` events (pdl-drive.md, "Host protocol")

@pytest.mark.parametrize("scheme", ["tcp", "pty"])
def test_pdl_load_output_and_errors(uprog_sim, scheme):
    sim = uprog_sim("pdl", pty=scheme == "pty")
    with uprog.connect(sim.urls[scheme], "pdl") as drive:
        drive.load(example("pdl", "printl_report.pdl"))  # `reset` starts its #task tasks
        with pytest.raises(uprog.DriveError) as refused:
            drive.command("nosuch")
        assert (refused.value.code, refused.value.text) == (2, "no such variable")
        deadline = time.monotonic() + 5
        lines = []
        while len(lines) < 5 and time.monotonic() < deadline:
            lines += drive.output()
            time.sleep(0.02)
    # printl/103: task 2, mode 0x103 as 8 hex digits, mode2 0; step², ratio = level/25.
    assert lines[0] == "%P 2 00000103 00000000 ramp report : step=1 level=0001 ratio=0.04   "
    assert lines[4] == "%P 2 00000103 00000000 ramp report : step=5 level=0019 ratio=1   "


def test_pdl_move(uprog_sim):
    sim = uprog_sim("pdl")
    with uprog.connect(sim.urls["tcp"], "pdl") as drive:
        drive.load(example("pdl", "move_with_timeout.pdl"))
        # A move of 10000 counts at 20000 counts/s: about 0.6 s, within its 2 s timeout.
        assert wait_for(drive, "result", 1) == 1
        assert drive.query("ref_pos") == 10000


# --- PUP: the AG300's `value;` / `?CODE TEXT;` (akribis-drive.md)

@pytest.mark.parametrize("scheme", ["tcp", "pty"])
def test_pup_load_and_run(uprog_sim, scheme):
    sim = uprog_sim("pup", pty=scheme == "pty")
    with uprog.connect(sim.urls[scheme], "pup") as drive:
        drive.load(example("pup", "point_to_point.pup"))  # ADownloadUProg[3] stores and loads
        with pytest.raises(uprog.DriveError) as refused:
            drive.command("ANoSuch")
        assert (refused.value.code, refused.value.text) == (1, "unknown keyword")
        assert drive.command("AGenData[5]=7; AGenData[5]") == ["", "7"]
        drive.command("AProgRun[1],1")
        # Four moves of 20000 counts, 0.3 s each, after 20 ms: AGenData[1] counts them.
        assert wait_for(drive, "AGenData[1]", 4, timeout_s=6) == 4
        assert wait_for(drive, "AProgStatus[1]", 3) == 3
        # Back at target 0; over the wire time is the wall clock's and the host's lines take
        # servo cycles, so the loop is read within a few counts (examples/pup: exactly 0).
        assert abs(drive.query("APos")) <= 2


# --- ST: echo, a line per answer, BEL ERR, `-->` (the S300's ASCII reference, PROMPT 1)

@pytest.mark.parametrize("scheme", ["tcp", "pty"])
def test_st_load_output_and_errors(uprog_sim, scheme):
    sim = uprog_sim("st", pty=scheme == "pty")
    with uprog.connect(sim.urls[scheme], "st") as drive:
        with pytest.raises(uprog.DriveError) as refused:
            drive.command("NOSUCH")
        assert (refused.value.code, refused.value.text) == (1, "unknown command")
        drive.load(example("st", "init_parameters.st"))  # PLCDL lines, then PLCRUN
        # PLCINIT's XWRITEs: ACC 50, VLIM 2500, task 192's ORDER.
        assert drive.query("ACC") == 50
        assert drive.query("VLIM") == 2500
        assert drive.command("ORDER 192") == ["192 20000 5000 8192 10 10 0 0 0 0"]
        hello = str(__import__("pathlib").Path(example("..", "tests", "transcripts", "st",
                                                       "programs", "hello.st")))
        drive.load(hello)
        deadline = time.monotonic() + 3
        lines = []
        while not lines and time.monotonic() < deadline:
            lines = drive.output()
            time.sleep(0.02)
        assert drive.query("YEAR") == 2011
    # The PRINTF page's example: one line on the terminal.
    assert "Hello world in the year 2011" in lines


# --- bad input: a closed socket, a garbled answer, a silent drive

def fake_drive(replies):
    """A one-connection TCP server that sends `replies` whatever comes, then closes."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(1)

    def serve():
        conn, _ = server.accept()
        for reply in replies:
            conn.recv(4096)
            conn.sendall(reply)
        time.sleep(0.2)
        conn.close()
        server.close()

    import threading
    threading.Thread(target=serve, daemon=True).start()
    return f"tcp://127.0.0.1:{server.getsockname()[1]}"


def test_closed_connection_raises():
    url = fake_drive([b""])
    with uprog.connect(url, "pup", timeout_s=2) as drive:
        with pytest.raises(uprog.ConnectionLost):
            drive.command("AGenData[1]")
            drive.command("AGenData[1]")


def test_garbled_answers_raise():
    url = fake_drive([b"?x garbage;\r\n", b"abc;\r\n"])
    with uprog.connect(url, "pdl", timeout_s=2) as drive:
        with pytest.raises(uprog.ProtocolError):
            drive.command("a")
        with pytest.raises(uprog.ProtocolError):
            drive.query("a")


def test_silent_drive_times_out():
    url = fake_drive([b"", b""])
    with uprog.connect(url, "gold", timeout_s=0.3) as drive:
        with pytest.raises(uprog.DriveTimeout):
            drive.command("PX")


def test_nothing_listening():
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    port = server.getsockname()[1]
    server.close()
    with pytest.raises(uprog.ConnectionLost):
        uprog.connect(f"tcp://127.0.0.1:{port}", "gold")


def test_gold_image_downloads_as_it_is(uprog_sim, uprog_binary, tmp_path):
    import subprocess
    image = tmp_path / "first_move.upi"
    subprocess.run([uprog_binary, "build", example("gold", "first_move.ehl"), "-o", str(image)],
                   check=True, timeout=60)
    garbage = tmp_path / "garbage.upi"
    garbage.write_bytes(b"UPG\0" + bytes(100))
    sim = uprog_sim("gold")
    with uprog.connect(sim.urls["tcp"], "gold") as drive:
        assert drive.load(str(image)) == image.stat().st_size
        assert drive.query("moves") == 0  # CC loaded it: its global reads
        # docs/protocol.md: DL##END checks the image; a refused one is EC 213.
        with pytest.raises(uprog.DriveError) as refused:
            drive.load(str(garbage))
        assert refused.value.code == 213
        assert drive.query("moves") == 0  # the program stays


def test_pdl_run_time_error_event_raises(uprog_sim):
    # pdl-drive.md, "Events": a run-time error sends `%E task code text`; code 4 is the VM's
    # "call stack too deep" (src/vm/run_errors.def), on line 7 of the program.
    program = os.path.join(ROOT, "tests", "transcripts", "pdl", "programs", "stack_overflow.pdl")
    sim = uprog_sim("pdl")
    with uprog.connect(sim.urls["tcp"], "pdl") as drive:
        with pytest.raises(uprog.ProgramError) as stopped:
            drive.load(program)  # `reset` starts task 1
            drive.run_until(lambda: False, timeout=3)
        e = stopped.value
        assert (e.code, e.text) == (4, "call stack too deep")
        assert (e.file, e.line) == ("stack_overflow.pdl", 7)
        assert drive.output()[0].startswith("%E 1 4 call stack too deep")
