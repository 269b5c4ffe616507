// The studio's page: the drive's socket, and the editor, terminal, scope, run controls, debugger
// and panels around it. Every control carries the data-testid the issue lists (docs/studio.md).
import "./style.css";
import "@xterm/xterm/css/xterm.css";
import "uplot/dist/uPlot.min.css";
import { JsonSocket } from "./socket.js";
import { createEditor } from "./editor.js";
import { breakpointLines, setBreakpoint, showPausedLine } from "./breakpoints.js";
import { DriveTerminal } from "./terminal.js";
import { Scope } from "./scope.js";
import { DebugClient } from "./debugger.js";

const $ = (id) => document.getElementById(id);
const studio = { ready: false };
window.studio = studio;  // for the console and the browser tests

function appendOutput(text) {
  const out = $("output");
  out.textContent += text.endsWith("\n") ? text : text + "\n";
  out.scrollTop = out.scrollHeight;
}

function showDiagnostics(source, list) {
  studio.diagnostics[source] = list;
  const box = $("diagnostics");
  box.replaceChildren();
  for (const d of [...studio.diagnostics.build, ...studio.diagnostics.lsp]) {
    const li = document.createElement("li");
    li.className = `diagnostic ${d.severity}`;
    li.textContent = `${d.line}:${d.column}: ${d.severity}: ${d.message}`;
    li.onclick = () => {
      const line = studio.editor.state.doc.line(Math.min(d.line, studio.editor.state.doc.lines));
      studio.editor.dispatch({ selection: { anchor: line.from }, scrollIntoView: true });
      studio.editor.focus();
    };
    box.append(li);
  }
}

const kLspSeverity = { 1: "error", 2: "warning", 3: "note", 4: "note" };

function lspDiagnostics(params) {
  showDiagnostics("lsp", params.diagnostics.map((d) => ({
    line: d.range.start.line + 1, column: d.range.start.character + 1,
    severity: kLspSeverity[d.severity ?? 1], message: d.code != null ? `${d.message} [${d.code}]` : d.message,
  })));
}

function buildInputs(count) {
  const box = $("inputs");
  box.replaceChildren();
  const select = $("switch-input");
  select.replaceChildren();
  for (let n = 1; n <= count; ++n) {
    const label = document.createElement("label");
    label.className = "toggle";
    const box_ = document.createElement("input");
    box_.type = "checkbox";
    box_.dataset.testid = `input-${n}`;
    box_.onchange = () => studio.drive.send({ op: "input", n, high: box_.checked });
    label.append(box_, ` IN${n}`);
    box.append(label);
    select.append(new Option(`IN${n}`, n));
  }
}

function buildChannelPicker(signals) {
  const picker = $("channel-picker");
  picker.replaceChildren();
  const chosen = () => [...picker.querySelectorAll("input[type=checkbox]:checked")].map((c) => c.value);
  const add = (name, checked) => {
    const label = document.createElement("label");
    const box = document.createElement("input");
    box.type = "checkbox";
    box.value = name;
    box.checked = checked;
    box.dataset.testid = `channel-${name}`;
    box.onchange = () => studio.drive.send({ op: "scope", channels: chosen() });
    label.append(box, ` ${name}`);
    picker.insertBefore(label, picker.querySelector("form"));
  };
  const form = document.createElement("form");
  const more = document.createElement("input");
  more.placeholder = "a global or signal";
  more.dataset.testid = "channel-add";
  form.append(more);
  form.onsubmit = (e) => {
    e.preventDefault();
    if (more.value.trim()) add(more.value.trim(), true);
    more.value = "";
    studio.drive.send({ op: "scope", channels: chosen() });
  };
  picker.append(form);
  signals.forEach((s) => add(s, s === "position"));
  studio.drive.send({ op: "scope", channels: chosen() });
}

function showStatus(m) {
  $("time").textContent = `t = ${(m.time_us / 1e6).toFixed(3)} s`;
  const rows = m.threads.map((t) => `<tr><td>${t.name}</td><td class="st-${t.status}">${t.status}</td>` +
    `<td>${t.where}</td></tr>`);
  $("threads").innerHTML = `<tr><th>thread</th><th>status</th><th>where</th></tr>${rows.join("")}`;
  const held = m.threads.some((t) => /breakpoint/i.test(t.status));
  $("program-state").textContent = (held ? "held by the debugger" : m.running ? "running" : "not running") +
    (m.error ? ` — ${m.error}` : "");
  m.inputs.forEach((high, i) => {
    const box = document.querySelector(`[data-testid=input-${i + 1}]`);
    if (box && box.checked !== high && document.activeElement !== box) box.checked = high;
  });
  $("motor-fault").textContent = m.motor_fault ? `MF = 0x${m.motor_fault.toString(16)}` : "no fault";
  studio.status = m;
}

// Whether a stack frame stands in the editor's document (not in an #include'd file).
function inEditor(frame) {
  const path = frame.source?.path;
  return !path || path === studio.file || path.split("/").pop() === studio.file.split("/").pop();
}

function showStopped({ frames, variables }) {
  const stack = $("call-stack");
  stack.replaceChildren(...frames.map((f) => {
    const li = document.createElement("li");
    const where = inEditor(f) ? `line ${f.line}` : `${f.source.name ?? f.source.path}:${f.line}`;
    li.textContent = `${f.name} — ${where}`;
    return li;
  }));
  const vars = $("variables");
  vars.replaceChildren();
  for (const scope of variables) {
    const h = document.createElement("h4");
    h.textContent = scope.scope;
    vars.append(h);
    for (const v of scope.items) {
      const row = document.createElement("div");
      row.className = "variable";
      row.dataset.name = v.name;
      row.textContent = `${v.name} = ${v.value}`;
      vars.append(row);
    }
  }
  // The paused line is highlighted only where the editor shows it (not inside an include).
  showPausedLine(studio.editor, frames.length && inEditor(frames[0]) ? frames[0].line : null);
  refreshWatches();
}

async function refreshWatches() {
  for (const li of $("watches").children) {
    const value = studio.debug?.attached ? await studio.debug.evaluate(li.dataset.expression) : "(not debugging)";
    li.textContent = `${li.dataset.expression} = ${value}`;
  }
}

function setDebugButtons(state) {
  const stopped = state === "stopped";
  for (const id of ["debug-continue", "debug-step-over", "debug-step-in", "debug-step-out"]) $(id).disabled = !stopped;
  $("debug-pause").disabled = state !== "running";
  $("debug-attach").textContent = state === "detached" ? "Debug" : "Debugging";
}

function download(name, href) {
  const a = document.createElement("a");
  a.href = href;
  a.download = name;
  a.click();
}

function build(run) {
  showDiagnostics("build", []);
  studio.building = studio.editor.state.doc.toString();
  studio.drive.send({ op: "build", source: studio.building, run });
}

async function hello(m) {
  studio.dialect = m.dialect;
  studio.file = m.file || "program";
  $("program-name").textContent = `${studio.file} (${m.dialect})`;
  document.title = `uprog studio — ${studio.file}`;
  if (!studio.editor) {
    studio.editor = await createEditor($("editor"), {
      source: m.source, file: studio.file, dialect: m.dialect,
      onDiagnostics: lspDiagnostics,
      onBreakpoints: () => studio.debug?.sendBreakpoints(),
      onBuild: () => build(false),
    });
  }
  buildInputs(m.inputs);
  $("fault-name").replaceChildren(...m.faults.map((f) => new Option(f, f)));
  $("speed").value = m.speed === -1 ? "max" : String(m.speed);
  buildChannelPicker(m.signals);
  studio.debug = new DebugClient({
    sourcePath: studio.file,
    breakpoints: () => breakpointLines(studio.editor),
    onStopped: showStopped,
    onContinued: () => {
      showPausedLine(studio.editor, null);
      $("call-stack").replaceChildren();
      $("variables").replaceChildren();
    },
    onOutput: appendOutput,
    onState: setDebugButtons,
  });
  studio.setBreakpoint = (line, spec) => {
    setBreakpoint(studio.editor, line, spec);
    return studio.debug.sendBreakpoints();
  };
  studio.ready = true;
}

// The next drive message of `type`.
function nextMessage(type) {
  return new Promise((resolve) => studio.waiting.push({ type, resolve }));
}

// Start the program with the debugger attached before any of its time passes: time is paused
// while the program starts and the debugger sets its breakpoints, then runs at the chosen speed.
// Run builds and downloads first when the editor's text is not what this page stored last.
async function runProgram() {
  if (studio.editor.state.doc.toString() !== studio.downloaded) {
    const built = nextMessage("build");
    build(false);
    if (!(await built).ok) return;
  }
  const speed = $("speed").value;
  studio.drive.send({ op: "speed", factor: 0 });
  const started = nextMessage("started");
  studio.drive.send({ op: "start" });
  if ((await started).ok) {
    studio.debug.detach();
    await studio.debug.attach();
  }
  studio.drive.send({ op: "speed", factor: speed === "max" ? "max" : Number(speed) });
}

function driveMessage(m) {
  const waiting = studio.waiting.filter((w) => w.type === m.type);
  studio.waiting = studio.waiting.filter((w) => w.type !== m.type);
  for (const w of waiting) w.resolve(m);
  switch (m.type) {
    case "hello": return hello(m);
    case "status":
      // The speed the drive runs at, unless the page holds it while the debugger attaches.
      if (!studio.waiting.length && document.activeElement !== $("speed")) {
        $("speed").value = m.speed === -1 ? "max" : String(m.speed);
      }
      return showStatus(m);
    case "answers": return studio.terminal.answers(m.answers);
    case "output":
      for (const line of m.lines) {
        appendOutput(line);
        studio.terminal.unsolicited(line);
      }
      return;
    case "build":
      if (m.ok) studio.downloaded = studio.building;
      showDiagnostics("build", m.diagnostics);
      appendOutput(m.ok ? "build: downloaded" : `build failed${m.error ? ": " + m.error : ""}`);
      return;
    case "started": return appendOutput(m.ok ? "program started" : `start: ${m.error}`);
    case "stopped": return appendOutput("program stopped");
    case "reset": return appendOutput(["drive reset", ...m.messages].join("\n"));
    case "scope": return studio.scope.reset(m.channels, m.period_us);
    case "error": return appendOutput(`studio: ${m.message}`);
    default:
  }
}

function wireControls() {
  $("build").onclick = () => build(false);
  $("run").onclick = () => runProgram();
  $("stop").onclick = () => studio.drive.send({ op: "stop" });
  $("reset").onclick = () => studio.drive.send({ op: "reset" });
  $("speed").onchange = (e) => studio.drive.send({
    op: "speed", factor: e.target.value === "max" ? "max" : Number(e.target.value),
  });
  $("switch-place").onclick = () => studio.drive.send({
    op: "switch", n: Number($("switch-input").value), from: Number($("switch-from").value), to: Number($("switch-to").value),
  });
  $("switch-remove").onclick = () => studio.drive.send({ op: "switch", n: Number($("switch-input").value) });
  $("fault-inject").onclick = () => studio.drive.send({ op: "fault", name: $("fault-name").value });
  $("debug-attach").onclick = () => studio.debug?.attach();
  $("debug-continue").onclick = () => studio.debug?.go("continue");
  $("debug-pause").onclick = () => studio.debug?.go("pause");
  $("debug-step-over").onclick = () => studio.debug?.go("next");
  $("debug-step-in").onclick = () => studio.debug?.go("stepIn");
  $("debug-step-out").onclick = () => studio.debug?.go("stepOut");
  $("watch-form").onsubmit = (e) => {
    e.preventDefault();
    const expression = $("watch-input").value.trim();
    if (!expression) return;
    const li = document.createElement("li");
    li.dataset.expression = expression;
    li.textContent = expression;
    $("watches").append(li);
    $("watch-input").value = "";
    refreshWatches();
  };
  const scope = studio.scope;
  const trigger = () => {
    scope.trigger = {
      mode: $("trigger-mode").value, channel: Number($("trigger-channel").value || 0),
      level: Number($("trigger-level").value), pretrigger: Math.min(100, Math.max(0, Number($("pretrigger").value))) / 100,
    };
    scope.triggerAt = -1;
    scope.candidate = null;
    scope.dirty = true;
  };
  for (const id of ["trigger-mode", "trigger-channel", "trigger-level", "pretrigger"]) $(id).onchange = trigger;
  $("window").onchange = () => { scope.windowS = Math.max(0.01, Number($("window").value)); scope.dirty = true; };
  $("scope-pause").onclick = () => {
    scope.paused = !scope.paused;
    $("scope-pause").textContent = scope.paused ? "Resume" : "Pause";
  };
  $("export-csv").onclick = () => download("scope.csv", URL.createObjectURL(new Blob([scope.csv()], { type: "text/csv" })));
  $("export-png").onclick = () => download("scope.png", scope.png());
}

function start() {
  studio.diagnostics = { build: [], lsp: [] };
  studio.waiting = [];
  studio.scope = new Scope($("scope"), $("cursors"));
  const resetScope = studio.scope.reset.bind(studio.scope);
  studio.scope.reset = (channels, periodUs) => {
    resetScope(channels, periodUs);
    $("trigger-channel").replaceChildren(...channels.map((c, i) => new Option(c.name, i)));
  };
  studio.terminal = new DriveTerminal($("terminal"), (line) => studio.drive.send({ op: "line", text: line }));
  studio.drive = new JsonSocket("/ws/drive", {
    onMessage: driveMessage,
    onBinary: (b) => studio.scope.add(b),
    onOpen: () => { $("connection").textContent = "connected"; },
    onClose: () => {
      $("connection").textContent = "disconnected: reload the page";
      $("connection").classList.add("lost");
    },
  });
  wireControls();
}

start();
