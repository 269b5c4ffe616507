// The editor: CodeMirror 6 with the language server over /ws/lsp (@codemirror/lsp-client:
// diagnostics, hover, completion, go to definition by F12 or Ctrl-click), the breakpoint gutter
// and the paused line.
// The server's diagnostics also reach `onDiagnostics` for the Problems panel.
import { basicSetup, EditorView } from "codemirror";
import { keymap } from "@codemirror/view";
import { LSPClient, jumpToDefinition, languageServerExtensions } from "@codemirror/lsp-client";
import { socketUrl } from "./socket.js";
import { breakpointGutter } from "./breakpoints.js";

// The transport lsp-client talks through: the WebSocket, with publishDiagnostics seen on the way.
function lspTransport(onDiagnostics) {
  const ws = new WebSocket(socketUrl("/ws/lsp"));
  let handlers = [];
  ws.onmessage = (e) => {
    const text = String(e.data);
    try {
      const m = JSON.parse(text);
      if (m.method === "textDocument/publishDiagnostics") onDiagnostics(m.params);
    } catch {
      // lsp-client reports what it cannot read
    }
    for (const h of handlers) h(text);
  };
  return new Promise((resolve, reject) => {
    ws.onerror = () => reject(new Error("the language server's socket failed"));
    ws.onopen = () => resolve({
      send: (message) => ws.readyState === WebSocket.OPEN && ws.send(message),
      subscribe: (h) => handlers.push(h),
      unsubscribe: (h) => { handlers = handlers.filter((x) => x !== h); },
    });
  });
}

// Ctrl-click (Cmd-click) on a name goes to its definition, as F12 does.
const definitionOnModClick = EditorView.domEventHandlers({
  mousedown(event, view) {
    if (event.button !== 0 || !(event.ctrlKey || event.metaKey)) return false;
    const pos = view.posAtCoords({ x: event.clientX, y: event.clientY });
    if (pos == null) return false;
    view.dispatch({ selection: { anchor: pos } });
    jumpToDefinition(view);
    event.preventDefault();
    return true;
  },
});

// The document's URI: the file's own (so the server finds its #include files beside it), or a
// name under a virtual folder for a program without an absolute path.
export function documentUri(file) {
  if (file?.startsWith("/")) return `file://${file.split("/").map(encodeURIComponent).join("/")}`;
  const name = (file || "program").split("/").pop();
  return `file:///studio/${encodeURIComponent(name)}`;
}

export async function createEditor(parent, { source, file, dialect, onDiagnostics, onBreakpoints,
  onBuild }) {
  const extensions = [
    basicSetup,
    breakpointGutter(() => onBreakpoints()),
    keymap.of([{ key: "Mod-b", run: () => { onBuild(); return true; } }]),
    definitionOnModClick,
    EditorView.lineWrapping,  // the pane is narrow; every word stays in view
    EditorView.theme({ "&": { height: "100%" }, ".cm-scroller": { overflow: "auto" } }),
  ];
  try {
    const transport = await lspTransport(onDiagnostics);
    const client = new LSPClient({ rootUri: documentUri(file).replace(/[^/]*$/, ""),
      extensions: languageServerExtensions() })
      .connect(transport);
    extensions.push(client.plugin(documentUri(file), dialect));
  } catch (e) {
    console.warn("no language server:", e);
  }
  return new EditorView({ doc: source, extensions, parent });
}
