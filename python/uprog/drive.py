"""A drive over its vendor's wire: `uprog.connect(url, dialect)` gives a Drive whose command(),
query(), load() and output() speak to a real drive or a `uprog sim` as the dialect's own host
software does. Pure Python: nothing here needs the C++ module."""

import inspect
import re
import time

from . import compiler
from .errors import BadArgument, DriveError, DriveTimeout, ProgramError, ProtocolError
from .links import open_link
from .values import number_of
from .wires import WIRES

DIALECTS = tuple(WIRES)

# A PDL drive reports a task's run-time error to every host: `%E task code text` (pdl-drive.md,
# "Events"), the text ending with the source place ("call stack too deep at f.pdl:7").
_PDL_ERROR_EVENT = re.compile(r"^%E \d+ (-?\d+) (.*?)\s*$")
_PLACE = re.compile(r"^(.*) at (\S+):(\d+)$")


def program_error_of(dialect, line):
    """The ProgramError an output line reports, or None."""
    found = _PDL_ERROR_EVENT.match(line) if dialect == "pdl" else None
    if not found:
        return None
    text = found.group(2)
    place = _PLACE.match(text)
    if place:
        return ProgramError(int(found.group(1)), place.group(1), place.group(2),
                            int(place.group(3)))
    return ProgramError(int(found.group(1)), text)


class Drive:
    """One connection to one drive; one line at a time, as a serial host works."""

    def __init__(self, link, dialect, timeout_s=5.0, uprog=None):
        if dialect not in WIRES:
            raise BadArgument(f"no dialect {dialect!r}: {', '.join(DIALECTS)}")
        self.dialect = dialect
        self.timeout_s = timeout_s
        self.uprog = uprog
        self._link = link
        self._wire = WIRES[dialect](link)
        self._wire.start(timeout_s)
        self._output = []

    # --- the command line
    def command(self, line, timeout_s=None):
        """Sends one line; its answers as the drive sends them (`""` for a command that shows
        nothing). The first refused expression raises DriveError with its code and text."""
        try:
            answers = self._wire.exchange(line, self.timeout_s if timeout_s is None else timeout_s)
        except ProtocolError:
            self._wire.resync()  # the rest of a garbled line is no answer to the next one
            raise
        self._check_program()
        for a in answers:
            if a.is_error:
                raise DriveError(a.code, a.text, line)
        return [a.text for a in answers]

    def query(self, name):
        """A value: a parameter (`PX`), an array element (`AGenData[3]`), a program global."""
        answers = self.command(name)
        if len(answers) != 1:
            raise ProtocolError(f"{name} answered {len(answers)} times, not once: {answers}")
        return number_of(answers[0], name)

    def output(self):
        """The lines the drive sent on its own since the last call (printl, PRINTF, events)."""
        self._output += self._wire.output()
        out, self._output = self._output, []
        return out

    def _check_program(self):
        """ProgramError when the drive reported that its program stopped (PDL's `%E`); the
        line stays in output()."""
        new = self._wire.output()
        self._output += new
        for line in new:
            error = program_error_of(self.dialect, line)
            if error:
                raise error

    # --- programs
    def load(self, path, *, uprog=None, start=True):
        """Compiles `path` on this host (with the uprog binary), downloads it with the dialect's
        download lines and, with `start`, loads it as the dialect's host does (Gold CC, PDL
        reset, S300 PLCRUN; the AG300's last download line loads it already)."""
        stored = compiler.compile_file(path, self.dialect, uprog or self.uprog)
        for line in compiler.download_lines(self.dialect, stored):
            self.command(line)
        load_line = compiler.LOAD_LINES[self.dialect]
        if start and load_line:
            # The load line shows nothing (Gold CC, PDL reset, S300 PLCRUN); what comes with it
            # is the drive's own text: the S300's MSG compile report, the program's first PRINTF.
            self._wire.keep_as_output(text for text in self.command(load_line) if text)
        return len(stored)

    # --- time: a real drive's is the wall clock's
    def run(self, seconds):
        """Lets `seconds` pass (a real drive runs on its own: this waits); ProgramError when the
        drive reports a stopped program meanwhile."""
        time.sleep(seconds)
        self._check_program()

    def run_until(self, predicate, timeout=10.0, *, step_s=0.02):
        """Polls predicate() (or predicate(drive), or a drive expression) every `step_s` until
        it is true; DriveTimeout
        after `timeout` seconds. The time it took."""
        call = as_condition(predicate, self)
        start = time.monotonic()
        while not call():
            self._check_program()
            if time.monotonic() - start >= timeout:
                raise DriveTimeout(f"still false after {timeout} s")
            time.sleep(step_s)
        return time.monotonic() - start

    # --- the connection
    def close(self):
        self._link.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def connect(url, dialect, *, timeout_s=5.0, uprog=None):
    """A Drive over tcp://HOST:PORT, udp://HOST:PORT (Gold's Ethernet) or
    serial:///dev/ttyUSB0?baud=115200 (pyserial)."""
    if dialect not in WIRES:
        raise BadArgument(f"no dialect {dialect!r}: {', '.join(DIALECTS)}")
    link = open_link(url, timeout_s)
    try:
        return Drive(link, dialect, timeout_s, uprog)
    except BaseException:
        link.close()
        raise


def as_condition(predicate, drive):
    """predicate() or predicate(drive), whichever it takes; a string is an expression the drive
    evaluates (`"MS==0"`, `"PS"`): true when its value is not 0."""
    if isinstance(predicate, str):
        return lambda: drive.query(predicate) != 0
    try:
        takes_drive = len(inspect.signature(predicate).parameters) >= 1
    except (TypeError, ValueError):
        takes_drive = False
    return (lambda: predicate(drive)) if takes_drive else predicate
