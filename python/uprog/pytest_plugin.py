"""The pytest plugin (entry point `pytest11: uprog`; in a tree, `-p uprog.pytest_plugin`):

- `sim_drive(dialect, program=None, **options)`: a fixture factory giving a SimDrive with the
  program loaded, or, with `--uprog-drive URL`, a Drive over that wire (a real drive or a
  running `uprog sim`) with the program downloaded: the same test runs on both.
- `--uprog-dialect NAME` says which dialect that drive speaks: tests of the others are skipped,
  so one run of a whole folder fits the drive on the bench.
- `@pytest.mark.uprog_sim_only`: a test that needs what only the simulation does (inputs,
  faults, the recorder) is skipped against a wire drive.
- `assert_recording_matches(recording, "ref.csv", tolerances={"PX": 2})`: the recorder's
  `--expect` comparison, failing with the channel, time, got and expected.
"""

import os

import pytest

from .recording import assert_recording_matches

__all__ = ["assert_recording_matches", "sim_drive"]


def pytest_addoption(parser):
    group = parser.getgroup("uprog")
    group.addoption("--uprog-drive", metavar="URL", default=None,
                    help="run sim_drive tests against this drive: tcp://HOST:PORT, "
                         "udp://HOST:PORT, serial:///dev/ttyUSB0?baud=115200")
    group.addoption("--uprog-dialect", metavar="NAME", default=None,
                    help="the dialect of the --uprog-drive drive: sim_drive tests of another "
                         "dialect are skipped")
    group.addoption("--uprog-binary", metavar="PATH", default=None,
                    help="the uprog binary that compiles programs for a wire drive")


def pytest_configure(config):
    config.addinivalue_line("markers", "uprog_sim_only: needs the simulated drive (inputs, "
                                       "faults, virtual time, the recorder)")


def pytest_collection_modifyitems(config, items):
    url = config.getoption("--uprog-drive")
    if not url:
        return
    skip = pytest.mark.skip(reason=f"needs the simulated drive, not {url}")
    for item in items:
        if "uprog_sim_only" in item.keywords:
            item.add_marker(skip)


def _resolve(request, path):
    """A program path as given, else relative to the working directory, the test's folder or
    one of its parents, or pytest's rootdir: `examples/gold/first_move.ehl` from anywhere."""
    if path is None or os.path.isabs(str(path)) or os.path.exists(str(path)):
        return path
    folder = os.path.dirname(str(request.node.fspath))
    while True:
        candidate = os.path.join(folder, str(path))
        if os.path.exists(candidate):
            return candidate
        parent = os.path.dirname(folder)
        if parent == folder:
            break
        folder = parent
    return os.path.join(str(request.config.rootpath), str(path))


@pytest.fixture
def sim_drive(request):
    """sim_drive(dialect, program=None, **SimDrive options) -> SimDrive, or a wire Drive with
    --uprog-drive; closed after the test."""
    config = request.config
    url = config.getoption("--uprog-drive")
    made = []

    def make(dialect, program=None, **options):
        program = _resolve(request, program)
        only = config.getoption("--uprog-dialect")
        if url and only and dialect != only:
            pytest.skip(f"a {dialect} test; the drive at {url} is {only}")
        if url:
            from .drive import connect
            drive = connect(url, dialect, uprog=config.getoption("--uprog-binary"))
        else:
            from .sim import SimDrive
            drive = SimDrive(dialect, **options)
        made.append(drive)
        if program:
            drive.load(program)
        return drive

    yield make
    for drive in made:
        drive.close()
