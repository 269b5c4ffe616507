"""The exceptions of the uprog package: what a drive refused, what a program hit, what did not
compile, and a wire that broke. Every one carries the drive's code and text where there is one."""

from dataclasses import dataclass


class UprogError(Exception):
    """The base of every exception the package raises."""


class BadArgument(UprogError, ValueError):
    """An argument the drive has no use for: an unknown dialect, fault or channel, an input
    outside 1..6 (also a ValueError)."""


class DriveError(UprogError):
    """A line the drive refused: its error code and text, and the line sent."""

    def __init__(self, code, text, line=""):
        self.code = int(code)
        self.text = text
        self.line = line
        shown = f"{line!r} refused: " if line else ""
        super().__init__(f"{shown}error {self.code}" + (f" ({text})" if text else ""))


class ProgramError(UprogError):
    """The program stopped on a run-time error: its code and text, and the source place
    (`file`, `line`; None where the drive does not say) of the statement that hit it."""

    def __init__(self, code, text, file=None, line=None):
        self.code = int(code)
        self.text = text
        self.file = file
        self.line = line
        place = f" at {file}:{line}" if file else ""
        super().__init__(f"run-time error {self.code} ({text}){place}")


@dataclass(frozen=True)
class Diagnostic:
    """One compiler message, placed as gcc places it."""

    file: str
    line: int
    column: int
    code: int
    message: str
    severity: str = "error"

    def __str__(self):
        return (f"{self.file}:{self.line}:{self.column}: {self.severity}: {self.message} "
                f"[{self.code}]")


class CompileError(UprogError):
    """A program that did not compile: `diagnostics` lists every message."""

    def __init__(self, diagnostics, summary=""):
        self.diagnostics = list(diagnostics)
        text = ("\n".join(str(d) for d in self.diagnostics) or summary
                or "the program did not compile")
        super().__init__(text)


class ProtocolError(UprogError):
    """The drive sent something its wire does not allow (a garbled answer)."""


class ConnectionLost(UprogError, ConnectionError):
    """The drive closed the connection (or the port went away)."""


class DriveTimeout(UprogError, TimeoutError):
    """The drive did not answer within the timeout."""
