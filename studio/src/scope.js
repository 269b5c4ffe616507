// The live scope (uPlot): the drive streams every servo cycle's sample of the chosen channels;
// the page keeps the last seconds at full rate (for the trigger and for CSV export) and draws the
// window decimated to the plot's width (min and max per pixel, so no peak is lost on screen).
import uPlot from "uplot";

const kKeepSeconds = 20;
const kMaxKeep = 1 << 19;  // samples per channel kept
const kColors = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"];

export class Scope {
  constructor(parent, cursorsBox) {
    this.parent = parent;
    this.cursorsBox = cursorsBox;
    this.channels = [];
    this.periodUs = 0;
    this.paused = false;
    this.trigger = { mode: "free", channel: 0, level: 0, pretrigger: 0.1 };
    this.windowS = 2;
    this.cursorMarks = [];
    this.received = 0;  // samples received since the channels were chosen
    this.reset([], 0);
    requestAnimationFrame(() => this.frame());
  }

  // New channels ({name, unit}) at `periodUs`: the kept samples start afresh.
  reset(channels, periodUs) {
    this.channels = channels;
    this.periodUs = periodUs;
    this.capacity = periodUs > 0 ? Math.min(kMaxKeep, Math.ceil(kKeepSeconds * 1e6 / periodUs)) : 1;
    this.times = new Float64Array(this.capacity);
    this.values = channels.map(() => new Float64Array(this.capacity));
    this.total = 0;  // samples ever stored; the ring holds the last `capacity`
    this.scanned = 1;
    this.triggerAt = -1;  // the sample index of the trigger on display
    this.shown = null;
    this.dirty = true;
    this.makePlot();
  }

  makePlot() {
    this.plot?.destroy();
    this.readout?.remove();
    this.readout = null;
    const series = [{ label: "time (s)" }];
    this.channels.forEach((c, i) => series.push({
      label: c.unit ? `${c.name} (${c.unit})` : c.name, stroke: kColors[i % kColors.length], width: 1,
    }));
    const width = Math.max(300, this.parent.clientWidth || 600);
    this.plot = new uPlot({
      width, height: 260, series,
      scales: { x: { time: false } },
      axes: [{ label: "drive time (s)" }, { size: 80 }],
      cursor: { drag: { x: true, y: false } },
      hooks: { ready: [(u) => u.over.addEventListener("click", () => this.markCursor(u))] },
    }, [[], ...this.channels.map(() => [])], this.parent);
  }

  // A binary block from the drive: [first_time_us, period_us, channels, samples, values...].
  add(buffer) {
    const words = new Float64Array(buffer);
    const [firstUs, periodUs, channels, samples] = words;
    if (channels !== this.channels.length || periodUs !== this.periodUs) return;
    for (let i = 0; i < samples; ++i) {
      const slot = this.total % this.capacity;
      this.times[slot] = (firstUs + i * periodUs) / 1e6;
      for (let c = 0; c < channels; ++c) this.values[c][slot] = words[4 + i * channels + c];
      this.total += 1;
    }
    this.received += samples;
    this.dirty = true;
  }

  at(c, index) {
    return this.values[c][index % this.capacity];
  }
  oldest() {
    return Math.max(0, this.total - this.capacity);
  }

  // The window on display: [from, to) sample indexes; null when nothing is to be shown yet.
  window() {
    const n = Math.max(2, Math.round(this.windowS * 1e6 / Math.max(1, this.periodUs)));
    if (this.trigger.mode === "free") {
      return this.total === 0 ? null : [Math.max(this.oldest(), this.total - n), this.total];
    }
    const pre = Math.round(n * this.trigger.pretrigger);
    const c = Math.min(this.trigger.channel, this.channels.length - 1);
    if (c < 0) return null;
    const level = this.trigger.level;
    // New crossings since the last look; the latest whose window is complete is shown.
    for (let i = Math.max(this.scanned, this.oldest() + 1); i < this.total; ++i) {
      const a = this.at(c, i - 1), b = this.at(c, i);
      const hit = this.trigger.mode === "rising" ? a < level && b >= level : a > level && b <= level;
      if (hit) this.candidate = i;
    }
    this.scanned = this.total;
    if (this.candidate != null && this.candidate + (n - pre) <= this.total) {
      this.triggerAt = this.candidate;
      this.candidate = null;
    }
    if (this.triggerAt < 0 || this.triggerAt - pre < this.oldest()) return null;
    return [this.triggerAt - pre, Math.min(this.total, this.triggerAt - pre + n)];
  }

  frame() {
    requestAnimationFrame(() => this.frame());
    if (this.paused || !this.dirty || this.channels.length === 0) return;
    this.dirty = false;
    const w = this.window();
    if (!w) return;
    this.shown = w;
    this.plot.setData(this.decimated(w[0], w[1], this.plot.width));
    this.showReadout();
  }

  // At most two points (min and max of each channel) per pixel column.
  decimated(from, to, width) {
    const count = to - from;
    const buckets = Math.max(1, Math.min(count, width));
    const per = count / buckets;
    const xs = [], ys = this.channels.map(() => []);
    for (let b = 0; b < buckets; ++b) {
      const start = from + Math.floor(b * per), end = from + Math.max(Math.floor((b + 1) * per), Math.floor(b * per) + 1);
      if (per <= 2) {
        for (let i = start; i < end; ++i) {
          xs.push(this.times[i % this.capacity]);
          ys.forEach((y, c) => y.push(this.at(c, i)));
        }
        continue;
      }
      xs.push(this.times[start % this.capacity], this.times[(end - 1) % this.capacity]);
      ys.forEach((y, c) => {
        let lo = Infinity, hi = -Infinity;
        for (let i = start; i < end; ++i) {
          const v = this.at(c, i);
          if (v < lo) lo = v;
          if (v > hi) hi = v;
        }
        y.push(lo, hi);
      });
    }
    return [xs, ...ys];
  }

  // The samples on display at full rate, as CSV: time_s and every channel.
  csv() {
    const w = this.shown;
    const head = ["time_s", ...this.channels.map((c) => c.name)].join(",");
    if (!w) return head + "\n";
    const rows = [head];
    for (let i = Math.max(w[0], this.oldest()); i < w[1]; ++i) {
      rows.push([this.times[i % this.capacity], ...this.channels.map((_, c) => this.at(c, i))].join(","));
    }
    return rows.join("\n") + "\n";
  }

  png() {
    return this.plot.ctx.canvas.toDataURL("image/png");
  }

  // A click on the plot places cursor A, the next B; the box shows both and their difference.
  markCursor(u) {
    const idx = u.cursor.idx;
    if (idx == null) return;
    const x = u.data[0][idx];
    const values = this.channels.map((c, i) => `${c.name}=${u.data[i + 1][idx]}`);
    this.cursorMarks = this.cursorMarks.length >= 2 ? [] : this.cursorMarks;
    this.cursorMarks.push({ x, values });
    const [a, b] = this.cursorMarks;
    let text = `A: t=${a.x.toFixed(6)} s ${a.values.join(" ")}`;
    if (b) text += ` | B: t=${b.x.toFixed(6)} s ${b.values.join(" ")} | Δt=${(b.x - a.x).toFixed(6)} s`;
    this.cursorsBox.textContent = text;
  }

  // The latest value of every channel, as text under the plot.
  showReadout() {
    if (!this.readout) {
      this.readout = document.createElement("div");
      this.readout.className = "readout";
      this.readout.dataset.testid = "scope-readout";
      this.parent.append(this.readout);
    }
    this.readout.textContent = this.channels.map((c) =>
      `${c.name} = ${this.latest(c.name)}${c.unit ? " " + c.unit : ""}`).join("   ");
  }

  // The last value of a channel by name (the tests' and the page's readout).
  latest(name) {
    const c = this.channels.findIndex((ch) => ch.name === name);
    return c < 0 || this.total === 0 ? null : this.at(c, this.total - 1);
  }
}
