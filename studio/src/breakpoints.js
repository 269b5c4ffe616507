// The editor's breakpoint gutter and paused line (CodeMirror 6): a click on a line's gutter (or its
// number) sets or clears a breakpoint; a right click asks for its condition and hit count. The markers move
// with edits; the debugger reads them as line numbers.
import { StateField, StateEffect, RangeSet } from "@codemirror/state";
import { EditorView, GutterMarker, gutter, lineNumbers, Decoration } from "@codemirror/view";

const toggleBreakpoint = StateEffect.define({ map: (v, mapping) => ({ ...v, pos: mapping.mapPos(v.pos) }) });
const setPaused = StateEffect.define();

class BreakpointMarker extends GutterMarker {
  constructor(spec) {
    super();
    this.spec = spec;  // { condition, hitCondition }
  }
  eq(other) {
    return other.spec.condition === this.spec.condition &&
      other.spec.hitCondition === this.spec.hitCondition;
  }
  toDOM() {
    const dot = document.createElement("span");
    dot.className = this.spec.condition || this.spec.hitCondition ? "bp bp-conditional" : "bp";
    dot.textContent = "●";
    dot.title = [this.spec.condition && `when ${this.spec.condition}`,
      this.spec.hitCondition && `hit count ${this.spec.hitCondition}`].filter(Boolean).join(", ") ||
      "breakpoint";
    return dot;
  }
}

const breakpointField = StateField.define({
  create: () => RangeSet.empty,
  update(set, tr) {
    set = set.map(tr.changes);
    for (const e of tr.effects) {
      if (!e.is(toggleBreakpoint)) continue;
      const line = tr.state.doc.lineAt(e.value.pos);
      let had = false;
      set.between(line.from, line.from, () => { had = true; });
      set = set.update({ filter: (from) => from !== line.from });
      if (!had || e.value.spec) {
        set = set.update({ add: [new BreakpointMarker(e.value.spec ?? {}).range(line.from)] });
      }
    }
    return set;
  },
});

const pausedField = StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    deco = deco.map(tr.changes);
    for (const e of tr.effects) {
      if (!e.is(setPaused)) continue;
      if (e.value == null || e.value < 1 || e.value > tr.state.doc.lines) return Decoration.none;
      const line = tr.state.doc.line(e.value);
      deco = Decoration.set([Decoration.line({ class: "cm-paused-line" }).range(line.from)]);
    }
    return deco;
  },
  provide: (f) => EditorView.decorations.from(f),
});

// `onChange()` runs after every change of the breakpoints.
export function breakpointGutter(onChange) {
  const askAndSet = (view, pos) => {
    const condition = window.prompt("Stop only when (empty: always):", "") ?? "";
    const hitCondition = window.prompt("Stop from the n-th hit on (empty: every hit):", "") ?? "";
    view.dispatch({ effects: toggleBreakpoint.of({ pos, spec: { condition, hitCondition } }) });
    onChange();
  };
  const toggleAt = (view, line, event) => {
    if (event.button !== 0) return false;
    view.dispatch({ effects: toggleBreakpoint.of({ pos: line.from }) });
    onChange();
    return true;
  };
  return [
    // A click on a line's number toggles its breakpoint too, as in most editors.
    lineNumbers({ domEventHandlers: { mousedown: toggleAt } }),
    breakpointField,
    pausedField,
    gutter({
      class: "cm-breakpoint-gutter",
      markers: (v) => v.state.field(breakpointField),
      initialSpacer: () => new BreakpointMarker({}),
      domEventHandlers: {
        mousedown: toggleAt,
        contextmenu(view, line, event) {
          event.preventDefault();
          askAndSet(view, line.from);
          return true;
        },
      },
    }),
  ];
}

// The breakpoints as the debugger takes them: [{ line, condition?, hitCondition? }].
export function breakpointLines(view) {
  const out = [];
  const cursor = view.state.field(breakpointField).iter();
  for (; cursor.value; cursor.next()) {
    const b = { line: view.state.doc.lineAt(cursor.from).number };
    if (cursor.value.spec.condition) b.condition = cursor.value.spec.condition;
    if (cursor.value.spec.hitCondition) b.hitCondition = cursor.value.spec.hitCondition;
    out.push(b);
  }
  return out;
}

// Sets (or with `spec` replaces) the breakpoint on a line, for tests and the API.
export function setBreakpoint(view, lineNumber, spec) {
  const line = view.state.doc.line(lineNumber);
  view.dispatch({ effects: toggleBreakpoint.of({ pos: line.from, spec: spec ?? {} }) });
}

// Highlights the line the program stands at (1-based); null clears it.
export function showPausedLine(view, lineNumber) {
  const effects = [setPaused.of(lineNumber)];
  if (lineNumber != null && lineNumber >= 1 && lineNumber <= view.state.doc.lines) {
    effects.push(EditorView.scrollIntoView(view.state.doc.line(lineNumber).from, { y: "center" }));
  }
  view.dispatch({ effects });
}
