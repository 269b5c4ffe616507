// A WebSocket to the studio's server on this page's host: JSON texts in and out, binary messages
// (the scope's samples) as ArrayBuffers. It says when it opens and closes; no reconnection (the
// page is reloaded instead, so that a half-known state never lingers).
export function socketUrl(path) {
  const scheme = location.protocol === "https:" ? "wss:" : "ws:";
  return `${scheme}//${location.host}${path}`;
}

export class JsonSocket {
  constructor(path, { onMessage, onBinary, onOpen, onClose } = {}) {
    this.ws = new WebSocket(socketUrl(path));
    this.ws.binaryType = "arraybuffer";
    this.open = new Promise((resolve) => {
      this.ws.onopen = () => {
        onOpen?.();
        resolve();
      };
    });
    this.ws.onmessage = (e) => {
      if (typeof e.data !== "string") return onBinary?.(e.data);
      let message;
      try {
        message = JSON.parse(e.data);
      } catch {
        return;
      }
      onMessage?.(message);
    };
    this.ws.onclose = (e) => onClose?.(e);
  }
  send(message) {
    if (this.ws.readyState === WebSocket.OPEN) {
      this.ws.send(typeof message === "string" ? message : JSON.stringify(message));
    }
  }
  close() {
    this.ws.close();
  }
}
