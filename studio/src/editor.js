// The editor: CodeMirror 6 with the language server over /ws/lsp (@codemirror/lsp-client:
// diagnostics, hover, completion, go to definition), the breakpoint gutter and the paused line.
// The server's diagnostics also reach `onDiagnostics` for the Problems panel.
import { basicSetup, EditorView } from "codemirror";
import { keymap } from "@codemirror/view";
import { LSPClient, languageServerExtensions } from "@codemirror/lsp-client";
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

// The document's URI: the file's name under a virtual folder (the server compiles from memory).
export function documentUri(file) {
  const name = (file || "program").split("/").pop();
  return `file:///studio/${encodeURIComponent(name)}`;
}

export async function createEditor(parent, { source, file, dialect, onDiagnostics, onBreakpoints,
  onBuild }) {
  const extensions = [
    basicSetup,
    breakpointGutter(() => onBreakpoints()),
    keymap.of([{ key: "Mod-b", run: () => { onBuild(); return true; } }]),
    EditorView.theme({ "&": { height: "100%" }, ".cm-scroller": { overflow: "auto" } }),
  ];
  try {
    const transport = await lspTransport(onDiagnostics);
    const client = new LSPClient({ rootUri: "file:///studio/", extensions: languageServerExtensions() })
      .connect(transport);
    extensions.push(client.plugin(documentUri(file), dialect));
  } catch (e) {
    console.warn("no language server:", e);
  }
  return new EditorView({ doc: source, extensions, parent });
}
