"""uprog.SimDrive, the drive in process and in virtual time, for every dialect: a program loaded
and run, its answers, its output, inputs, switches, faults, the recorder, and the errors it
raises. Expected values come from the manuals, the spec and the examples' own comments."""

import os

import pytest

import uprog
from conftest import ROOT, example

_uprog = pytest.importorskip("uprog.sim", reason="the C++ module _uprog is not built")
numpy = pytest.importorskip("numpy")
from uprog.recording import assert_recording_matches, read_csv  # noqa: E402


def transcripts(*parts):
    return os.path.join(ROOT, "tests", "transcripts", *parts)


# --- Gold

def test_gold_first_move():
    d = uprog.SimDrive("gold")
    d.load(example("gold", "first_move.ehl"))
    d.command("XQ##main")
    # examples/gold/first_move.txt: 100000 counts at SP=50000, AC=DC=1e6: 2.05 s of profile.
    d.run(1.0)
    assert d.query("moves") == 0
    assert d.query("MS") == 2  # the profiler runs
    took = d.run_until(lambda: d.query("PS") == 0, timeout=5)
    assert 1.0 < took + 1.0 < 2.2
    assert d.query("moves") == 1
    assert abs(d.query("PX") - 100000) <= 2


def test_gold_compile_error_lists_every_diagnostic(tmp_path):
    source = tmp_path / "bad.ehl"
    source.write_text("int a\nfunction main()\na = 1 +\nreturn\n")
    d = uprog.SimDrive("gold")
    with pytest.raises(uprog.CompileError) as failed:
        d.load(source)
    first = failed.value.diagnostics[0]
    # Gold's compile error 7, "Value is expected" (the manual's error table), at the end of line 3.
    assert (first.file, first.line, first.column, first.code) == (str(source), 3, 8, 7)
    assert first.message == "Value is expected"
    assert f"{source}:3:8" in str(failed.value)


def test_gold_run_time_error_raises_with_the_source_place():
    d = uprog.SimDrive("gold")
    d.load(transcripts("programs", "no_perr.ehl"))  # a = 100 / UI[2] on line 5, UI[2] = 0
    with pytest.raises(uprog.ProgramError) as stopped:
        d.command("XQ##main")
        d.run(0.01)
    e = stopped.value
    assert (e.code, e.text, os.path.basename(e.file), e.line) == (1, "division by zero",
                                                                  "no_perr.ehl", 5)
    assert d.query("PS") == 0 and d.query("reached") == 0  # the program stopped there


def test_gold_refused_command_has_its_ec():
    d = uprog.SimDrive("gold")
    with pytest.raises(uprog.DriveError) as refused:
        d.command("AC=-5")
    assert (refused.value.code, refused.value.text) == (21, "Value out of the command's range")


def test_gold_auto_perr_recovers_without_raising():
    # Manual 2.14.10: a run-time error lands in AUTO_PERR, which restarts main.
    d = uprog.SimDrive("gold")
    d.load(example("gold", "2_14_auto_perr.ehl"))
    d.command("XQ##main")
    d.run(0.01)
    d.command("IL[1]=1")
    d.set_input(1, 1)  # an active inhibit: MO=1 is refused in main
    d.command("UI[1]=-5000")
    start = d.time_s
    d.run(0.1)  # the error and AUTO_PERR come in it; the run goes on to its end all the same
    assert d.time_s - start == pytest.approx(0.1, abs=1e-6)
    assert "AUTO_PERR entered" in d.log[-1][1]
    assert d.query("UI[1]") == -5000  # AUTO_PERR waits 200 ms before it clears UI[1]
    d.run(0.3)
    assert d.query("MO") == 0 and d.query("UI[1]") == 0 and d.query("PS") == 1
    d.set_input(1, 0)
    d.command("UI[1]=-5000")
    d.run(2.0)
    assert abs(d.query("PX") + 5000) <= 2


def test_gold_inputs_start_moves():
    d = uprog.SimDrive("gold")
    d.load(example("gold", "moves_by_inputs.ehl"))
    d.command("XQ##main")
    d.run(0.1)
    d.set_input(2, 1)  # AUTO_I2 requests 9000 counts
    d.run(0.01)
    d.set_input(2, 0)
    d.run(1.5)  # 9000 counts at SP=10000, AC=DC=1e5: 1.0 s
    assert abs(d.query("PX") - 9000) <= 2
    assert d.query("done_count") == 1


def test_gold_fault_and_recovery():
    d = uprog.SimDrive("gold")
    d.load(example("gold", "p2p_with_recovery.ehl"))
    d.command("XQ##main")
    d.run(2.1)
    assert abs(d.query("PX") - 100000) <= 2
    d.inject_fault("feedback")  # MF bit 2 (4): feedback loss; AUTO_ER records it
    d.run(0.1)
    assert d.command("MO; MF; faults; last_fault") == ["0", "4", "1", "4"]
    d.run(0.7)  # main starts again 500 ms after the fault
    assert d.command("MO; PS; moves") == ["1", "1", "1"]


def test_gold_home_switch_is_placed():
    # A cam on input 3 over the motor's positions [1000, 2000]; input 3's level is IP bit 18
    # (docs/dialects/gold.md, "IP": bits 16-21 the levels of inputs 1-6).
    d = uprog.SimDrive("gold")
    d.place_switch(3, 1000, 2000)
    for line in ("UM=5", "MO=1"):
        d.command(line)
    d.run_until(lambda: d.query("SO") == 1, timeout=1)
    d.command("SP=100000;AC=1000000;DC=1000000;PA=1500;BG")
    d.run_until(lambda: d.query("MS") == 0, timeout=2)
    assert (d.query("IP") >> 18) & 1 == 1
    d.command("PA=3000;BG")
    d.run_until(lambda: d.query("MS") == 0, timeout=2)
    assert (d.query("IP") >> 18) & 1 == 0


def test_gold_recording_matches_the_trapezoid(tmp_path):
    # tests/transcripts/recorder/first_steps.csv is worked out by hand from the trapezoid:
    # DV[2] = a k TS, DV[3] = round(a (k TS)^2 / 2), sampled every 20 cycles from the trigger.
    d = uprog.SimDrive("gold")
    d.command("MO=1")
    d.run(0.03)
    d.command("SP=50000;AC=1000000;DC=1000000;PA=100000")
    d.record(["DV[2]", "DV[3]"], trigger="begin", length=8, gap=20)
    d.command("BG")
    d.run(0.01)
    r = d.recording()
    assert list(r["DV[2]"]) == [50 + 1000 * k for k in range(8)]
    assert r["time_s"][1] == pytest.approx(0.001)
    assert_recording_matches(r, transcripts("recorder", "first_steps.csv"))
    if pytest.importorskip("pandas"):
        assert list(r.dataframe().columns) == ["DV[2]", "DV[3]"]
    pytest.importorskip("matplotlib")
    assert os.path.getsize(d.plot(tmp_path / "steps.png")) > 0


def test_recording_difference_is_readable():
    # Twice the acceleration: DV[2] at sample 0 (motion step 1 of 50 us) is 2e6 * 50e-6 = 100,
    # at sample 7 (step 141) 14100 against 7050; DV[3] there round(2e6 * 0.00705^2 / 2) = 50,
    # against 25.
    d = uprog.SimDrive("gold")
    d.command("MO=1")
    d.run(0.03)
    d.command("SP=50000;AC=2000000;DC=2000000;PA=100000")
    d.record("DV[2],DV[3]", trigger="begin", length=8, gap=20)
    d.command("BG")
    d.run(0.01)
    reference = transcripts("recorder", "first_steps.csv")
    with pytest.raises(AssertionError) as differs:
        assert_recording_matches(d.recording(), reference)
    assert "DV[2] at 0.000 ms (sample 0): 100, expected 50 (tolerance 0)" in str(differs.value)
    # A tolerance is the largest difference allowed (`uprog run --expect`'s <=).
    assert_recording_matches(d.recording(), reference, tolerances={"DV[2]": 7050, "DV[3]": 25})
    with pytest.raises(AssertionError) as differs:
        assert_recording_matches(d.recording(), reference, tolerances={"DV[2]": 7050, "DV[3]": 24})
    assert "DV[3] at 7.000 ms (sample 7): 50, expected 25 (tolerance 24)" in str(differs.value)
    assert read_csv(reference).trigger == "begin"


# --- PDL

def test_pdl_printl_output():
    d = uprog.SimDrive("pdl")
    d.load(example("pdl", "printl_report.pdl"))  # `reset` starts the #task tasks
    d.run(0.1)
    lines = d.output()
    # printl/103 from task 2: mode 0x103 as 8 hex digits, mode2 0 (pdl-drive.md, "Events").
    assert lines[0].rstrip() == "%P 2 00000103 00000000 ramp report : step=1 level=0001 ratio=0.04"
    assert lines[4].rstrip() == "%P 2 00000103 00000000 ramp report : step=5 level=0019 ratio=1"


def test_pdl_move_and_host_error():
    d = uprog.SimDrive("pdl")
    d.load(example("pdl", "move_with_timeout.pdl"))
    d.run(1.0)  # 10000 counts at 20000 counts/s: about 0.6 s
    assert d.query("result") == 1 and d.query("ref_pos") == 10000
    with pytest.raises(uprog.DriveError) as refused:
        d.command("nosuch")
    assert (refused.value.code, refused.value.text) == (2, "no such variable")  # pdl-drive.md


# --- PUP

def test_pup_point_to_point():
    d = uprog.SimDrive("pup")
    d.load(example("pup", "point_to_point.pup"))
    d.command("AProgRun[1],1")
    d.run(0.3)
    assert d.query("AGenData[1]") == 0 and d.query("AInMotion") == 1
    d.run(1.5)  # four moves of 0.3 s after the 20 ms the motor takes to be ready
    assert d.query("AGenData[1]") == 4
    assert d.query("AProgStatus[1]") == 3
    assert d.query("APos") == 0


def test_pup_run_time_error():
    d = uprog.SimDrive("pup")
    d.load(os.path.join(ROOT, "tests", "cli", "run_time_error.pup"))
    with pytest.raises(uprog.ProgramError) as stopped:
        d.command("AProgRun[1],1")
        d.run(0.01)
    # akribis-drive.md: "÷0: 30"; the division is on line 5.
    assert stopped.value.code == 30 and stopped.value.line == 5


# --- ST

def test_st_init_parameters_and_printf():
    d = uprog.SimDrive("st")
    d.load(example("st", "init_parameters.st"))
    d.run(0.001)
    assert (d.query("ACC"), d.query("VLIM"), d.query("MTMUX")) == (50, 2500, 192)
    assert d.command("ORDER 192") == ["192 20000 5000 8192 10 10 0 0 0 0"]
    d2 = uprog.SimDrive("st")
    d2.load(transcripts("st", "programs", "hello.st"))
    d2.run(0.002)
    assert d2.output() == ["Hello world in the year 2011"]  # the PRINTF page's example
    assert d2.query("YEAR") == 2011


def test_bad_arguments_raise_not_crash():
    with pytest.raises(uprog.UprogError):
        uprog.SimDrive("cobol")
    d = uprog.SimDrive("gold")
    with pytest.raises(ValueError):
        d.set_input(9, 1)
    with pytest.raises(uprog.UprogError):
        d.inject_fault("gremlins")
    with pytest.raises(uprog.UprogError):
        d.record("NOSUCH")
    with pytest.raises(uprog.UprogError):
        d.recording()
    with pytest.raises(uprog.CompileError):
        d.load("/nonexistent/file.ehl")
    assert d.command("3+4") == ["7"]  # the drive still serves


def test_hostile_inputs_raise_and_the_drive_keeps_serving(tmp_path):
    junk = tmp_path / "junk.ehl"
    junk.write_bytes(bytes(range(256)) * 8)
    image = tmp_path / "junk.upi"
    image.write_bytes(b"UPG\0" + bytes(100))
    spin = tmp_path / "spin.ehl"
    spin.write_text("function main()\nwhile(1)\nend\nreturn\n")
    deep = tmp_path / "deep.ehl"
    deep.write_text("function f()\nf()\nreturn\nfunction main()\nf()\nreturn\n")
    d = uprog.SimDrive("gold")
    with pytest.raises(uprog.CompileError) as failed:
        d.load(junk)
    assert failed.value.diagnostics and all(x.file == str(junk) for x in failed.value.diagnostics)
    with pytest.raises(uprog.DriveError):  # the image is refused before anything is stored
        d.load(image)
    d.load(spin)  # a program that never ends: virtual time still passes, the line still answers
    d.command("XQ##main")
    d.run(1.0)
    assert d.command("3+4") == ["7"] and d.query("PS") == 1
    with pytest.raises(uprog.DriveError) as refused:
        d.load(deep)  # stored, but CC loads no program over a running one: EC 203
    assert refused.value.code == 203
    d.command("KL")
    d.load(deep)  # endless recursion: the VM's "call stack too deep" (run_errors.def, 4)
    with pytest.raises(uprog.ProgramError) as stopped:
        d.command("XQ##main")
        d.run(0.1)
    e = stopped.value
    assert (e.code, e.text, e.line) == (4, "call stack too deep", 2)


def test_plot_script(tmp_path):
    pytest.importorskip("matplotlib")
    import runpy
    import sys
    out = tmp_path / "move.png"
    argv = sys.argv
    sys.argv = ["plot_move.py", str(out)]
    try:
        script = os.path.join(ROOT, "examples", "python", "plot_move.py")
        runpy.run_path(script, run_name="__main__")
    finally:
        sys.argv = argv
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_recording_round_trip_and_its_forms(tmp_path):
    d = uprog.SimDrive("gold")
    d.command("MO=1")
    d.run_until("SO==1", timeout=1)  # a drive expression as the condition
    d.command("SP=50000;AC=1000000;DC=1000000;PA=100000")
    d.record("DV[2],DV[3],IQ", trigger="begin", length=8, gap=20)
    d.command("BG")
    d.run(0.01)
    r = d.recording()
    again = uprog.read_recording_csv(r.to_csv(tmp_path / "again.csv"))
    assert uprog.compare_recordings(again, r) is None  # export, import: the same samples
    assert again.units == {"DV[2]": "counts/s", "DV[3]": "counts", "IQ": "A"}  # docs/recorder.md
    uprog.assert_recording_matches(r, again, "DV[2]=0 DV[3]=0")  # the recorder's CH=V words
    pytest.importorskip("pandas")
    frame = d.recording(dataframe=True)
    assert list(frame.columns) == ["DV[2]", "DV[3]", "IQ"] and frame.index.name == "time_s"
    assert frame["DV[2]"].iloc[0] == 50  # a k TS for k = 1 (first_steps.csv)
    with pytest.raises(uprog.UprogError):
        uprog.assert_recording_matches(r, again, ["DV[2]"])  # a tolerance is CH=VALUE


def test_deterministic_bit_for_bit():
    # DESIGN.md: "The same program, inputs and scenario give the same result bit for bit."
    def one_run():
        d = uprog.SimDrive("gold")
        d.load(example("gold", "first_move.ehl"))
        d.record("PX,VX,PE,IQ", trigger="begin", length=500, gap=40)
        d.command("XQ##main")
        d.run(2.5)
        return d.recording()
    first, second = one_run(), one_run()
    assert uprog.compare_recordings(first, second) is None
    assert all((first[name] == second[name]).all() for name in first)


def test_state_dir_keeps_the_program_across_drives(tmp_path):
    d = uprog.SimDrive("gold", state_dir=tmp_path)
    d.load(example("gold", "first_move.ehl"))
    d.close()
    with pytest.raises(uprog.UprogError):
        d.command("PX")  # a closed drive says so
    again = uprog.SimDrive("gold", state_dir=tmp_path)  # boots with the stored program
    assert again.boot_messages == []
    again.command("XQ##main")
    again.run_until("PS==0", timeout=5)
    assert again.query("moves") == 1
    # A flash whose program was damaged: the drive boots without it and says why.
    with open(tmp_path / "program.upi", "r+b") as flash:
        flash.write(b"XXXX")
    damaged = uprog.SimDrive("gold", state_dir=tmp_path)
    assert "refused" in damaged.boot_messages[0]
    with pytest.raises(uprog.DriveError) as refused:
        damaged.command("XQ##main")
    assert refused.value.code == 201  # "No program is loaded" (interpreter_errors.def)
