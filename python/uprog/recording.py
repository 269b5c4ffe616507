"""Recordings on the Python side: the recorder's samples as numpy arrays with "time_s", the
recorder's CSV file (docs/recorder.md, "The CSV file") read back, and the comparison of
`uprog run --expect` (drive::compare in src/drive/recording.cpp) with its readable message."""

from dataclasses import dataclass

from .errors import UprogError


class Recording(dict):
    """Channel name -> values (numpy arrays), and "time_s": each sample's time from the trigger."""

    def __init__(self, channels, *, sample_period_us, trigger="", pretrigger_percent=0,
                 trigger_index=0, trigger_time_us=0, units=None, floats=None):
        import numpy as np
        super().__init__()
        self.sample_period_us = int(sample_period_us)
        self.trigger = trigger
        self.pretrigger_percent = int(pretrigger_percent)
        self.trigger_index = int(trigger_index)
        self.trigger_time_us = int(trigger_time_us)
        self.channels = list(channels)
        self.units = dict(units or {})
        self.floats = dict(floats or {})
        samples = len(next(iter(channels.values()))) if channels else 0
        self["time_s"] = (np.arange(samples) - self.trigger_index) * (self.sample_period_us / 1e6)
        for name, values in channels.items():
            self[name] = np.asarray(values, dtype=float)

    @property
    def samples(self):
        return len(self["time_s"])

    def time_us(self, i):
        return (i - self.trigger_index) * self.sample_period_us

    def to_csv(self, path):
        """Writes the recorder's CSV file (docs/recorder.md), a reference for later runs."""
        units = ",".join(self.units.get(n, "") for n in self.channels)
        types = ",".join("float" if self.floats.get(n) else "int" for n in self.channels)
        lines = ["# uprog recording 1", f"# sample_period_us: {self.sample_period_us}",
                 f"# trigger: {self.trigger}", f"# pretrigger_percent: {self.pretrigger_percent}",
                 f"# trigger_index: {self.trigger_index}",
                 f"# trigger_time_us: {self.trigger_time_us}", f"# units: {units}",
                 f"# types: {types}", ",".join(["time_us", *self.channels])]
        for i in range(self.samples):
            cells = [str(self.time_us(i))]
            cells += [_shown(self[n][i], self.floats.get(n)) for n in self.channels]
            lines.append(",".join(cells))
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(lines) + "\n")
        return path

    def dataframe(self):
        """The recording as a pandas DataFrame indexed by time_s (pandas needed)."""
        try:
            import pandas as pd
        except ImportError as e:
            raise UprogError("a DataFrame needs pandas (Debian: python3-pandas)") from e
        return pd.DataFrame({name: self[name] for name in self.channels},
                            index=pd.Index(self["time_s"], name="time_s"))


    to_dataframe = dataframe


def read_csv(path):
    """A recording from the recorder's CSV file (`uprog run --csv`, a transcript's reference)."""
    header = {}
    with open(path, encoding="utf-8") as f:
        lines = [line.rstrip("\r\n") for line in f]
    body = 0
    for body, line in enumerate(lines):
        if not line.startswith("#"):
            break
        key, _, value = line[1:].partition(":")
        header[key.strip()] = value.strip()
    else:
        raise UprogError(f"{path}: no column line")
    columns = lines[body].split(",")
    if not columns or columns[0] != "time_us":
        raise UprogError(f"{path}: line {body + 1}: the first column is time_us")
    names = columns[1:]
    values = {name: [] for name in names}
    # A float channel holds float32 values written in their shortest form: read back exactly.
    floats = dict(zip(names, (t == "float" for t in header.get("types", "").split(","))))
    import numpy as np
    for number, line in enumerate(lines[body + 1:], start=body + 2):
        if not line:
            continue
        cells = line.split(",")
        if len(cells) != len(columns):
            raise UprogError(f"{path}: line {number}: {len(cells)} values, expected {len(columns)}")
        for name, cell in zip(names, cells[1:]):
            try:
                value = float(cell)
                values[name].append(float(np.float32(value)) if floats.get(name) else value)
            except ValueError:
                raise UprogError(f"{path}: line {number}: {cell!r} is no number ({name})") from None
    try:
        return Recording(values, sample_period_us=int(header.get("sample_period_us", 0)),
                         trigger=header.get("trigger", ""),
                         pretrigger_percent=int(header.get("pretrigger_percent", 0)),
                         trigger_index=int(header.get("trigger_index", 0)),
                         trigger_time_us=int(header.get("trigger_time_us", 0)),
                         units=dict(zip(names, header.get("units", "").split(","))),
                         floats=floats)
    except ValueError as e:
        raise UprogError(f"{path}: a header value is not a number: {e}") from None


@dataclass
class Difference:
    """The first place where a recording leaves its reference (None when it does not)."""

    text: str
    channel: str = ""
    time_s: float = 0.0
    sample: int = -1
    got: float = 0.0
    expected: float = 0.0
    tolerance: float = 0.0

    def __str__(self):
        return self.text


def _shown(v, is_float=False):
    """A value in its shortest exact form: an int32 as an integer, a float32 as float32 prints."""
    if float(v).is_integer():
        return str(int(v))
    if is_float:
        import numpy as np
        return str(np.float32(v))
    return repr(float(v))


def _tolerances(given):
    """{"PX": 2}, or the recorder's "PX=2" words (a list, or one string split at blanks/commas)."""
    if not given:
        return {}
    if isinstance(given, dict):
        return {str(k): float(v) for k, v in given.items()}
    words = given.replace(",", " ").split() if isinstance(given, str) else list(given)
    out = {}
    for word in words:
        name, eq, value = str(word).rpartition("=")
        try:
            out[name] = float(value)
        except ValueError:
            eq = ""
        if not eq or not name:
            raise UprogError(f"a tolerance is CH=VALUE, not {word!r}")
    return out


def compare(actual, expected, tolerances=None):
    """As `uprog run --expect` compares (docs/recorder.md, "Comparing"): the channels' names in
    order, the sampling period, the trigger index, then every sample in time order, the channels
    in order; the first value further from the reference than its channel's tolerance (0
    without one) is the Difference returned. None when they agree."""
    tolerances = _tolerances(tolerances)
    for name in tolerances:
        if name not in expected.channels:
            return Difference(f"tolerance {name}: the reference has no channel '{name}'")
    if len(actual.channels) != len(expected.channels):
        return Difference(f"{len(actual.channels)} channels, expected {len(expected.channels)}")
    for i, (a, e) in enumerate(zip(actual.channels, expected.channels)):
        if a != e:
            return Difference(f"channel {i + 1} is '{a}', expected '{e}'")
    if actual.sample_period_us != expected.sample_period_us:
        return Difference(f"sampling period {actual.sample_period_us} us, expected "
                          f"{expected.sample_period_us} us")
    if actual.trigger_index != expected.trigger_index:
        return Difference(f"the trigger is sample {actual.trigger_index}, expected sample "
                          f"{expected.trigger_index}")
    n = min(actual.samples, expected.samples)
    for i in range(n):
        for name in expected.channels:
            a, e = float(actual[name][i]), float(expected[name][i])
            tol = float(tolerances.get(name, 0.0))
            if abs(a - e) <= tol:
                continue
            t_ms = expected.time_us(i) / 1000.0
            return Difference(f"{name} at {t_ms:.3f} ms (sample {i}): {_shown(a)}, expected "
                              f"{_shown(e)} (tolerance {_shown(tol)})",
                              name, t_ms / 1000.0, i, a, e, tol)
    if actual.samples != expected.samples:
        return Difference(f"{actual.samples} samples, expected {expected.samples} (they agree up "
                          f"to {expected.time_us(n) / 1000.0:.3f} ms)")
    return None


def assert_recording_matches(actual, reference, tolerances=None):
    """Fails (AssertionError) with the first difference, named by channel, time, got and
    expected; `reference` is a Recording or the path of a recorder CSV file."""
    expected = read_csv(reference) if isinstance(reference, (str, bytes)) or hasattr(
        reference, "__fspath__") else reference
    difference = compare(actual, expected, tolerances)
    if difference is not None:
        where = f"{reference}: " if not isinstance(reference, Recording) else ""
        raise AssertionError(where + difference.text)


def plot(recording, path, title=""):
    """Draws a recording to `path` with matplotlib: a panel per unit, time in ms from the trigger
    (the layout of `uprog plot`, docs/recorder.md "Plots")."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise UprogError("plot() needs matplotlib (Debian: python3-matplotlib)") from e
    units = []
    for name in recording.channels:
        unit = recording.units.get(name) or "value"
        if unit not in units:
            units.append(unit)
    fig, axes = plt.subplots(len(units), 1, sharex=True, squeeze=False,
                             figsize=(10, 1.2 + 2.6 * len(units)))
    t_ms = recording["time_s"] * 1000.0
    for panel, unit in zip(axes[:, 0], units):
        for name in recording.channels:
            if (recording.units.get(name) or "value") == unit:
                panel.plot(t_ms, recording[name], label=name)
        panel.axvline(0.0, color="red", linestyle="--", linewidth=0.8)
        panel.set_ylabel(unit)
        panel.legend(loc="best")
        panel.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time from the trigger (ms)")
    fig.suptitle(title or f"trigger: {recording.trigger}, every {recording.sample_period_us} us")
    fig.savefig(path)
    plt.close(fig)
    return path
