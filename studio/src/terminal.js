// The terminal on the drive's command line (xterm.js), as `uprog term` is: a typed line goes to
// the drive on Enter, its answers come back one per line (errors as ?CODE TEXT), what the drive
// sends on its own is marked "<<". Up and down walk the history.
import { Terminal } from "@xterm/xterm";

export class DriveTerminal {
  constructor(parent, sendLine) {
    this.term = new Terminal({ convertEol: true, fontSize: 13, rows: 12, cursorBlink: true });
    this.term.open(parent);
    this.sendLine = sendLine;
    this.line = "";
    this.history = [];
    this.back = 0;
    this.term.onData((data) => this.typed(data));
    this.prompt();
  }
  prompt() {
    this.term.write("> ");
  }
  replaceLine(text) {
    this.term.write("\r\x1b[2K> " + text);
    this.line = text;
  }
  typed(data) {
    if (data.startsWith("\x1b")) return this.escape(data);
    for (const ch of data) {
      if (ch === "\r" || ch === "\n") {
        this.term.write("\r\n");
        const line = this.line;
        this.line = "";
        this.back = 0;
        if (line.trim() === "") {
          this.prompt();
          continue;
        }
        this.history.push(line);
        this.sendLine(line);
      } else if (ch === "\x7f" || ch === "\b") {
        if (this.line.length > 0) {
          this.line = this.line.slice(0, -1);
          this.term.write("\b \b");
        }
      } else if (ch >= " ") {
        this.line += ch;
        this.term.write(ch);
      }
    }
  }
  escape(data) {
    if (data === "\x1b[A" && this.back < this.history.length) {
      this.back += 1;
      this.replaceLine(this.history[this.history.length - this.back]);
    } else if (data === "\x1b[B" && this.back > 0) {
      this.back -= 1;
      this.replaceLine(this.back === 0 ? "" : this.history[this.history.length - this.back]);
    }
  }
  // The answers to a line: a line each.
  answers(list) {
    for (const a of list) {
      if (a.error) this.term.write(`\x1b[31m?${a.error} ${a.text}\x1b[0m\r\n`);
      else if (a.text !== "") this.term.write(a.text + "\r\n");
    }
    this.prompt();
  }
  // Text the drive sent on its own.
  unsolicited(text) {
    this.term.write("\r\x1b[2K<< " + text + "\r\n> " + this.line);
  }
}
