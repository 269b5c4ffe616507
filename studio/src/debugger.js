// The debugger over DAP on /ws/dap, attached to the studio's drive: breakpoints from the gutter
// (conditions, hit counts), continue, pause and steps, the call stack, variables and watches of
// the stopped thread, the paused line in the editor.
import { JsonSocket } from "./socket.js";

export class DebugClient {
  constructor({ sourcePath, breakpoints, onStopped, onContinued, onOutput, onState }) {
    this.sourcePath = sourcePath;
    this.breakpoints = breakpoints;  // () => [{ line, condition?, hitCondition? }]
    this.onStopped = onStopped;
    this.onContinued = onContinued;
    this.onOutput = onOutput;
    this.onState = onState;
    this.seq = 1;
    this.pending = new Map();
    this.threadId = null;
    this.attached = false;
  }

  // Attaches to the program the drive runs; it ends when the program ends (DAP's terminated).
  async attach() {
    if (this.socket) return;
    this.socket = new JsonSocket("/ws/dap", {
      onMessage: (m) => this.message(m),
      onClose: () => this.detach(),
    });
    await this.socket.open;
    await this.request("initialize", { adapterID: "uprog", linesStartAt1: true, columnsStartAt1: true });
    await this.request("attach", {});
    await this.sendBreakpoints();
    await this.request("setExceptionBreakpoints", { filters: ["error"] });
    await this.request("configurationDone", {});
    this.attached = true;
    this.onState("running");
  }

  detach() {
    if (!this.socket) return;
    this.socket.close();
    this.socket = null;
    this.attached = false;
    this.threadId = null;
    for (const done of this.pending.values()) done({ success: false, message: "detached" });
    this.pending.clear();
    this.onContinued();
    this.onState("detached");
  }

  request(command, args) {
    const seq = this.seq++;
    this.socket?.send({ seq, type: "request", command, arguments: args });
    return new Promise((resolve) => this.pending.set(seq, resolve));
  }

  message(m) {
    if (m.type === "response") {
      const done = this.pending.get(m.request_seq);
      this.pending.delete(m.request_seq);
      if (!m.success) this.onOutput(`debugger: ${m.command}: ${m.message}\n`);
      done?.(m);
    } else if (m.type === "event") {
      if (m.event === "stopped") this.stopped(m.body);
      else if (m.event === "continued") this.continued();
      else if (m.event === "output") this.onOutput(m.body.output);
      else if (m.event === "terminated") this.detach();
    }
  }

  async sendBreakpoints() {
    if (!this.socket) return;
    const breakpoints = this.breakpoints();
    const r = await this.request("setBreakpoints", {
      source: { path: this.sourcePath, name: this.sourcePath.split("/").pop() },
      breakpoints, lines: breakpoints.map((b) => b.line),
    });
    const set = r.body?.breakpoints ?? [];
    set.forEach((b, i) => {
      if (!b.verified) this.onOutput(`breakpoint at line ${breakpoints[i].line}: ${b.message ?? "not set"}\n`);
    });
    return set;
  }

  async stopped(body) {
    this.threadId = body.threadId ?? 1;
    this.onState("stopped");
    const trace = await this.request("stackTrace", { threadId: this.threadId, startFrame: 0, levels: 20 });
    const frames = trace.body?.stackFrames ?? [];
    const scopes = frames.length ? await this.request("scopes", { frameId: frames[0].id }) : null;
    const variables = [];
    for (const scope of scopes?.body?.scopes ?? []) {
      const v = await this.request("variables", { variablesReference: scope.variablesReference });
      variables.push({ scope: scope.name, items: v.body?.variables ?? [] });
    }
    this.onStopped({ reason: body.reason, frames, variables });
  }

  continued() {
    this.threadId = null;
    this.onState("running");
    this.onContinued();
  }

  async evaluate(expression) {
    const r = await this.request("evaluate", { expression, context: "watch", frameId: 0 });
    return r.success ? r.body.result : `(${r.message})`;
  }

  // continue, next, stepIn, stepOut (of the stopped thread) or pause.
  async go(command) {
    if (this.threadId == null && command !== "pause") return;
    const threadId = this.threadId ?? 1;
    if (command !== "pause") this.continued();
    await this.request(command, { threadId });
  }
}
