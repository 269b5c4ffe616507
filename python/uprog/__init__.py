"""uprog for Python: test drive programs on the simulated drive (in process, virtual time) and on
a real drive or a `uprog sim` over the vendor's wire, with one API (docs/python.md)."""

from .drive import DIALECTS, Drive, connect
from .errors import (BadArgument, CompileError, ConnectionLost, Diagnostic, DriveError,
                     DriveTimeout, ProgramError, ProtocolError, UprogError)
from .recording import Recording, assert_recording_matches
from .recording import compare as compare_recordings
from .recording import read_csv as read_recording_csv

__all__ = ["DIALECTS", "BadArgument", "CompileError", "ConnectionLost", "Diagnostic", "Drive",
           "DriveError", "DriveTimeout", "ProgramError", "ProtocolError", "Recording", "SimDrive",
           "UprogError", "assert_recording_matches", "compare_recordings", "connect",
           "read_recording_csv"]


def __getattr__(name):
    # The in-process drive needs the C++ module (_uprog); the wire layer does not.
    if name == "SimDrive":
        from .sim import SimDrive
        return SimDrive
    raise AttributeError(name)
