"""Compiling on the host with the `uprog` binary, and each dialect's download protocol: the
lines that carry a stored form into a drive and the line that loads it (what `uprog download`
sends: src/dialects/*/download*.cpp, docs/protocol.md "Download")."""

import json
import os
import shutil
import subprocess
import tempfile

from .errors import CompileError, Diagnostic, UprogError

# Stored form bytes per line: Gold's and PDL's `DL=` (254, download_protocol.h), the AG300's
# ADownloadUProg[2] within its 255-character line (118, pup/download.h), the S300's PLCDL (100).
_CHUNK_BYTES = {"gold": 254, "pdl": 254, "pup": 118, "st": 100}
LOAD_LINES = {"gold": "CC", "pdl": "reset", "pup": "", "st": "PLCRUN"}
# What a drive stores (`uprog dialects`): a file with this extension is downloaded as it is.
STORED_EXTENSIONS = {"gold": ".upi", "pdl": ".pdi", "pup": ".cup", "st": ".st"}




def is_stored_form(path, dialect):
    return str(path).endswith(STORED_EXTENSIONS.get(dialect, "\0"))


def is_image(path, dialect):
    """A compiled image (.upi, .pdi), not a source: the AG300's .cup and the S300's .st are
    sources as well as stored forms, and compiling them on the host gives their diagnostics."""
    return dialect in ("gold", "pdl") and is_stored_form(path, dialect)


def find_uprog(given=None):
    """The uprog binary: `given`, $UPROG, `uprog` on PATH, or this tree's build/bin/uprog."""
    candidates = [given, os.environ.get("UPROG"), shutil.which("uprog")]
    tree = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    candidates.append(os.path.join(tree, "build", "bin", "uprog"))
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    raise UprogError("no uprog binary: put it on PATH, set UPROG, or pass uprog=PATH")


def diagnostics_of(uprog, path, dialect):
    """Every diagnostic of `path`, from `uprog check --format json`."""
    done = subprocess.run([uprog, "check", "--format", "json", "--dialect", dialect, path],
                          capture_output=True, text=True, timeout=60, check=False)
    try:
        found = json.loads(done.stdout or "[]")
    except json.JSONDecodeError:
        found = []
    return [Diagnostic(d["file"], d["line"], d["column"], d["code"], d["message"],
                       d.get("severity", "error")) for d in found], done.stderr.strip()


def compile_file(path, dialect, uprog=None):
    """The stored form of a source file (bytes); a stored form (.upi, .cup) is read as it is.
    Raises CompileError with every diagnostic when it does not compile."""
    if is_stored_form(path, dialect):
        try:
            with open(path, "rb") as f:
                return f.read()
        except OSError as e:
            raise UprogError(f"{path}: {e.strerror}") from None
    uprog = find_uprog(uprog)
    with tempfile.TemporaryDirectory(prefix="uprog-") as tmp:
        out = os.path.join(tmp, "stored")
        done = subprocess.run([uprog, "build", "--dialect", dialect, "-o", out, path],
                              capture_output=True, text=True, timeout=60, check=False)
        if done.returncode == 0:
            with open(out, "rb") as f:
                return f.read()
    diagnostics, stderr = diagnostics_of(uprog, path, dialect)
    raise CompileError([d for d in diagnostics if d.severity == "error"] or diagnostics,
                       done.stderr.strip() or stderr)


def _hex_lines(prefix, stored, chunk):
    return [prefix + stored[at:at + chunk].hex().upper() for at in range(0, len(stored), chunk)]


def _declared_crc(cup):
    # An AG300 CUP file's first line is `% CRC8HEX` CR, or `% 000000` CR: not checked
    # (src/dialects/pup/cup_file.cpp).
    if cup.startswith(b"% 000000\r") or len(cup) < 11:
        return 0
    try:
        return int(cup[2:10], 16)
    except ValueError:
        return 0


def download_lines(dialect, stored):
    """The lines that download `stored` into a drive of `dialect`, in order."""
    chunk = _CHUNK_BYTES[dialect]
    if dialect in ("gold", "pdl"):
        return [f"DL##BEGIN={len(stored)}", *_hex_lines("DL=", stored, chunk), "DL##END"]
    if dialect == "pup":
        return [f"ADownloadUProg[1],{len(stored)}",
                *_hex_lines("ADownloadUProg[2],", stored, chunk),
                f"ADownloadUProg[3],0x{_declared_crc(stored):08X}"]
    if dialect == "st":
        return [f"PLCDL BEGIN {len(stored)}", *_hex_lines("PLCDL ", stored, chunk), "PLCDL END"]
    raise UprogError(f"no dialect {dialect!r}: gold, pdl, pup or st")
