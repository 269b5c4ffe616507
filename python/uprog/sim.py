"""uprog.SimDrive: the simulated drive in this process, in virtual time and deterministic, with
the API of the wire layer's Drive (command, query, load, output) and what only a simulation can
do: run time forward, set inputs, place switches, inject faults, record."""

import re

from .errors import (BadArgument, CompileError, Diagnostic, DriveError, DriveTimeout, ProgramError,
                     ProtocolError, UprogError)
from .compiler import is_image
from .drive import as_condition
from .recording import Recording
from .recording import plot as plot_recording
from .values import number_of

try:
    from . import _uprog  # an installed package carries the module inside it
except ImportError:
    import _uprog  # the build tree's (python/CMakeLists.txt), on PYTHONPATH

# How a firmware logs a run-time error (cmd_run.cpp relies on the words "run-time error"):
# "run-time error 1 (division by zero) at f.ehl:5", "task 1: run-time error 4 (call stack too
# deep at f.pdl:7)", "run-time error 30 at f.pup:5".
_RUN_TIME_ERROR = re.compile(r"run-time error (\d+)")
_PLACE = re.compile(r"\bat (\S+?):(\d+)")
_TEXT = re.compile(r"run-time error \d+ \(([^)]*)\)")
# An event routine that takes a run-time error (docs/python.md): Gold's AUTO_PERR ("...; AUTO_PERR
# entered", manual 2.14.10), the AG300's event 22 (the run-time error event).
_HANDLED = re.compile(r"AUTO_PERR entered|event 22 entered")

DEFAULT_STEP_S = 0.001  # run() and run_until() look at the drive every millisecond


class SimDrive:
    """SimDrive(dialect, *, axes=1, state_dir=None, safe_boot=False, servo_period_us=0)."""

    def __init__(self, dialect, *, axes=1, state_dir=None, safe_boot=False, servo_period_us=0):
        try:
            self._core = _uprog.Core(dialect, int(axes), str(state_dir or ""), bool(safe_boot),
                                     int(servo_period_us))
        except (ValueError, TypeError) as e:
            raise BadArgument(str(e)) from None
        self.dialect = dialect
        self.warnings = []
        self.log = []  # (time_us, text): what the firmware noted (auto-routines, errors)
        self._partial_output = ""
        self._output = []

    # --- the command line, as on the wire
    def command(self, line):
        """Sends one line on the drive's command line (it takes the line's virtual time); its
        answers. A refused expression raises DriveError; a program that stopped on a run-time
        error meanwhile raises ProgramError."""
        answers = self._core.send(line)
        self._check_program()
        for text, code in answers:
            if code:
                raise DriveError(code, text, line)
        return [text for text, _ in answers]

    def query(self, name):
        """A value (`PX`, `AGenData[3]`, a global), read without taking virtual time."""
        answers = self._core.query(name)
        for text, code in answers:
            if code:
                raise DriveError(code, text, name)
        if len(answers) != 1:
            raise ProtocolError(f"{name} answered {len(answers)} times, not once")
        return number_of(answers[0][0], name)

    def output(self):
        """The lines the drive sent on its own since the last call (printl, PRINTF, MSG)."""
        self._collect_output()
        out, self._output = self._output, []
        return out

    # --- programs
    def load(self, path):
        """Compiles `path` in the drive's dialect, downloads it and loads it as the dialect's
        host does (Gold CC, PDL reset, S300 PLCRUN; the AG300's download loads it). Raises
        CompileError listing every diagnostic."""
        path = str(path)
        if is_image(path, self.dialect):
            self._download_stored(path)
        else:
            ok, found = self._core.download(path)
            diagnostics = [Diagnostic(d["file"], d["line"], d["column"], d["code"], d["message"],
                                      d["severity"]) for d in found]
            if not ok:
                raise CompileError([d for d in diagnostics if d.severity == "error"] or diagnostics)
            self.warnings = [d for d in diagnostics if d.severity != "error"]
        load_line = self._core.load_line()
        if load_line:
            # As a transcript's `load` does: the load line takes no time.
            for text, code in self._core.query(load_line):
                if code:
                    raise DriveError(code, text, load_line)
        self._check_program()

    def _download_stored(self, path):
        try:
            with open(path, "rb") as f:
                stored = f.read()
        except OSError as e:
            raise UprogError(f"{path}: {e.strerror}") from None
        why = self._core.download_stored(stored)
        if why:
            raise DriveError(0, why, f"download {path}")

    # --- time
    @property
    def time_s(self):
        """The drive's virtual time in seconds."""
        return self._core.now_us() / 1e6

    def run(self, seconds, *, step_s=DEFAULT_STEP_S):
        """Lets `seconds` of virtual time pass; ProgramError at the step the program stopped."""
        target = self._core.now_us() + _microseconds(seconds)
        step = max(_microseconds(step_s), 1)
        # The core stops at a step with a run-time error; one the program takes goes on.
        while self._core.now_us() < target:
            self._core.advance(target - self._core.now_us(), step)
            self._check_program()

    def run_until(self, predicate, timeout=10.0, *, step_s=DEFAULT_STEP_S):
        """Runs until predicate() (or predicate(drive), or a drive expression such as "MS==0")
        is true, checking every `step_s` of virtual time; DriveTimeout after `timeout` seconds
        of it. The virtual time it took."""
        call = as_condition(predicate, self)
        start = self._core.now_us()
        limit = start + _microseconds(timeout)
        step = max(_microseconds(step_s), 1)
        while not call():
            now = self._core.now_us()
            if now >= limit:
                raise DriveTimeout(f"still false after {timeout} s of virtual time")
            self._core.advance(min(step, limit - now), step)
            self._check_program()
        return (self._core.now_us() - start) / 1e6

    # --- the world
    def set_input(self, n, level):
        """Digital input n (1..6) high (1, True) or low."""
        try:
            self._core.set_input(int(n), bool(level))
        except ValueError as e:
            raise BadArgument(str(e)) from None

    def place_switch(self, n, lo, hi):
        """Input n is high while the motor's position (counts) lies in [lo, hi]: a cam, a home
        or limit switch (the transcripts' `switch`)."""
        try:
            self._core.place_switch(int(n), float(lo), float(hi))
        except ValueError as e:
            raise BadArgument(str(e)) from None

    def inject_fault(self, name, persistent=False):
        """Latches a drive fault by name (feedback, overcurrent, undervoltage, ...)."""
        try:
            self._core.inject_fault(name, persistent)
        except ValueError as e:
            raise BadArgument(str(e)) from None

    # --- the recorder
    def record(self, channels, *, trigger="immediate", pretrigger=0, length=1000, gap=1):
        """Arms the recorder: `channels` ("PX,VX" or a list; signals or globals), `trigger`
        (immediate, begin, rising:CH:LEVEL, falling:CH:LEVEL, leave:CH:LO:HI, enter:CH:LO:HI,
        input:N:rise|fall), `pretrigger` percent, `length` samples, `gap` servo cycles a sample."""
        if not isinstance(channels, str):
            channels = ",".join(channels)
        try:
            self._core.record(channels, trigger, int(pretrigger), int(length), int(gap))
        except ValueError as e:
            raise BadArgument(f"record: {e}") from None

    def recording(self, *, dataframe=False):
        """The finished recording: a dict of numpy arrays with "time_s" (a Recording, whose
        .dataframe() is a pandas DataFrame), or that DataFrame with dataframe=True. UprogError
        while there is none."""
        r = self._core.recording()
        if r is None:
            raise UprogError("no finished recording (not triggered yet, or still recording)")
        recording = Recording({c[0]: c[3] for c in r["channels"]},
                         sample_period_us=r["sample_period_us"], trigger=r["trigger"],
                         pretrigger_percent=r["pretrigger_percent"],
                         trigger_index=r["trigger_index"], trigger_time_us=r["trigger_time_us"],
                         units={c[0]: c[1] for c in r["channels"]},
                              floats={c[0]: c[2] for c in r["channels"]})
        return recording.dataframe() if dataframe else recording

    def plot(self, path, title=""):
        """Draws the finished recording to `path` (PNG, SVG, PDF: matplotlib's formats)."""
        return plot_recording(self.recording(), str(path), title)

    # --- state
    @property
    def program_running(self):
        return self._core.program_running()

    @property
    def boot_messages(self):
        """What the drive said at power-up: a refused stored program, unreadable parameters."""
        return list(self._core.boot_messages())

    def close(self):
        self._core = _Closed()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _collect_output(self):
        for text in self._core.take_output():
            for c in text:
                if c == "\r":
                    continue
                if c != "\n":
                    self._partial_output += c
                    continue
                self._output.append(self._partial_output)
                self._partial_output = ""

    def _check_program(self):
        """ProgramError when the log since the last look holds a run-time error that no event
        routine took (Gold's AUTO_PERR, the AG300's event 22)."""
        self._collect_output()
        entries = self._take_log()
        errors = [text for _, text in entries if _RUN_TIME_ERROR.search(text)]
        if not errors or any(_HANDLED.search(text) for _, text in entries):
            return
        if self._core.program_running():
            # The routine that takes the error is entered a few cycles after it: look once more.
            self._core.advance(_microseconds(DEFAULT_STEP_S), _microseconds(DEFAULT_STEP_S))
            if any(_HANDLED.search(text) for _, text in self._take_log()):
                return
        raise _program_error(errors[-1], self._core.program_error_text())

    def _take_log(self):
        entries = self._core.take_log()
        self.log.extend(entries)
        return entries


def _program_error(text, fallback_text):
    """The ProgramError a log entry describes: its code, text and last FILE:LINE."""
    code = int(_RUN_TIME_ERROR.search(text).group(1))
    place = _PLACE.findall(text)
    described = _TEXT.search(text)
    message = described.group(1) if described else fallback_text
    if place:
        message = message.replace(f" at {place[-1][0]}:{place[-1][1]}", "")
    return ProgramError(code, message, place[-1][0] if place else None,
                        int(place[-1][1]) if place else None)

class _Closed:
    """Stands for the drive after close(): every use says so."""

    def __getattr__(self, name):
        raise UprogError("the drive is closed")


def _microseconds(seconds):
    if seconds < 0:
        raise ValueError("a time is 0 or more seconds")
    return int(round(seconds * 1e6))

