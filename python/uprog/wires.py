"""Each dialect's wire as its real hosts read it: where a line's answers end, which answer is an
error (with its code and text), and which text the drive sent on its own (program output).

- Gold (docs/protocol.md, "The drive form"; Elmo's MAN-SIMSW 3.1): a line ends with CR, every
  expression gets one answer ending with `;`, a refused one is its EC code as one byte then `?;`;
  while EO=1 the drive echoes the bytes of each expression before answering it.
- PDL and PUP (docs/protocol.md, "the readable form"): `value;`, `;`, `?CODE TEXT;`, CR LF after
  a line's answers; a line of its own that ends without `;` is the drive's output (PDL's `%P`,
  `%E`, `%L` events: docs/dialects/pdl.md).
- ST (S300, docs/dialects/st.md): with PROMPT 1 the drive echoes the line, answers a line each,
  errors as BEL `ERR n text`, and ends with the prompt `-->`.
"""

import time
from dataclasses import dataclass

from .errors import ConnectionLost, DriveTimeout, ProtocolError
from .error_texts import GOLD_EC_TEXTS

# A drive never sends an answer this long; past it the stream is garbage, not a slow answer.
MAX_ANSWER_BYTES = 1 << 16


@dataclass(frozen=True)
class Answer:
    text: str
    code: int = 0  # 0: a value or an empty answer; else the drive's error code

    @property
    def is_error(self):
        return self.code != 0


def parse_readable_error(text):
    """`?21 Value out of range` -> Answer("Value out of range", 21)."""
    body = text[1:]
    digits = body.split(" ", 1)
    if not digits[0].isdigit():
        raise ProtocolError(f"an error answer without a code: {text!r}")
    return Answer(digits[1] if len(digits) > 1 else "", int(digits[0]))


class Wire:
    """Reads what the drive sends; subclasses say where a line's answers end."""

    line_end = b"\r\n"

    def __init__(self, link):
        self.link = link
        self._pending = b""
        self._output = []
        self._skip_lf = False

    def start(self, timeout_s):
        """The wire's opening handshake, if it has one."""

    def _more(self, deadline):
        left = deadline - time.monotonic()
        if left <= 0:
            raise DriveTimeout("the drive did not answer within the timeout")
        data = self.link.receive(min(left, 0.5))
        self._pending += data
        if len(self._pending) > MAX_ANSWER_BYTES and not any(
                end in self._pending for end in (b";", b"\r", b"\n")):
            self._pending = b""
            raise ProtocolError("the drive sent more than 64 KiB without ending an answer")

    def resync(self):
        """Drops what is left of a garbled answer: the next line starts afresh."""
        self._pending = b""

    def keep_as_output(self, lines):
        self._output.extend(lines)

    def output(self):
        """Drains what the drive sent on its own: its lines, oldest first."""
        try:
            while True:
                data = self.link.receive(0)
                if not data:
                    break
                self._pending += data
                self._take_idle_output()
        except ConnectionLost:
            pass
        self._take_idle_output()
        out, self._output = self._output, []
        return out

    def _take_idle_output(self):
        """Complete lines that arrived outside an exchange, kept as output."""
        while True:
            cut = self._pending.find(b"\n")
            if cut < 0:
                return
            line = self._pending[:cut].rstrip(b"\r").decode("latin-1")
            self._pending = self._pending[cut + 1:]
            if line:
                self._output.append(line)


class SemicolonWire(Wire):
    """PDL, PUP, and Gold's readable form: answers end with `;`, CR LF ends a line's answers."""

    def exchange(self, line, timeout_s):
        if not line.strip():
            return []  # a blank line gets no answer, not even a line end
        self.link.send(line.encode("latin-1") + self.line_end)
        deadline = time.monotonic() + timeout_s
        answers = []
        while True:
            event = self._next_event()
            if event is None:
                self._more(deadline)
            elif event[0] == "answer":
                answers.append(self._answer(event[1]))
            elif event[0] == "output":
                self._output.append(event[1])
            else:
                return answers

    def _next_event(self):
        """("answer", text), ("output", line), ("end", None) or None when more must come."""
        if self._skip_lf and self._pending:
            self._skip_lf = False
            if self._pending.startswith(b"\n"):
                self._pending = self._pending[1:]
        cut = min((i for i in (self._pending.find(c) for c in (b";", b"\r", b"\n")) if i >= 0),
                  default=-1)
        if cut < 0:
            return None
        text = self._pending[:cut].decode("latin-1")
        end = self._pending[cut:cut + 1]
        self._pending = self._pending[cut + 1:]
        if end == b";":
            return ("answer", text)
        self._skip_lf = end == b"\r"
        return ("output", text) if text else ("end", None)

    def _take_idle_output(self):
        while True:
            event = self._next_event()
            if event is None or event[0] == "answer":
                return
            if event[0] == "output":
                self._output.append(event[1])

    @staticmethod
    def _answer(text):
        if text.startswith("?"):
            return parse_readable_error(text)
        return Answer(text)


class GoldWire(Wire):
    """Gold's drive form: answers counted per expression, the echo taken out, `<code>?;`."""

    line_end = b"\r"

    @staticmethod
    def expressions(line):
        """How many answers the drive sends: one per `;`-ended expression and one for the
        CR-ended rest (empty ones too); a line of `**` comments alone gets none."""
        code = line.split("**", 1)[0]
        if not code.strip() and "**" in line:
            return 0
        return code.count(";") + 1

    def exchange(self, line, timeout_s):
        count = self.expressions(line)
        if count == 0:
            return []
        # The readable form's line end after the last line's answers is no echo.
        self._pending = self._pending.lstrip(b"\r\n")
        sent = line.encode("latin-1") + self.line_end
        echo = EchoFilter(sent)
        self.link.send(sent)
        deadline = time.monotonic() + timeout_s
        answers = []
        partial = bytearray()
        while True:
            data, self._pending = echo.feed(self._pending), b""
            for i, byte in enumerate(data):
                c = bytes((byte,))
                if c == b";":
                    answers.append(self._answer(bytes(partial)))
                    partial.clear()
                    if len(answers) == count:
                        self._pending = data[i + 1:]
                        return answers
                elif c in (b"\r", b"\n") and not partial:
                    continue  # the readable form's line end
                elif c in (b"\r", b"\n"):
                    self._output.append(partial.decode("latin-1"))
                    partial.clear()
                else:
                    partial += c
            if len(partial) > MAX_ANSWER_BYTES:
                raise ProtocolError("the drive sent more than 64 KiB without ending an answer")
            self._more(deadline)

    @staticmethod
    def _answer(raw):
        # MAN-SIMSW 3.1: "{<value>}{<error code>}<terminator>": the code as one byte, then `?`.
        if len(raw) == 2 and raw[1:] == b"?" and raw[:1] != b"?":
            code = raw[0]
            return Answer(GOLD_EC_TEXTS.get(code, ""), code)
        text = raw.decode("latin-1")
        if text == "?":
            raise ProtocolError("an error answer without its code byte")
        if text.startswith("?"):
            return parse_readable_error(text)
        return Answer(text.strip())


class EchoFilter:
    """Takes a Gold drive's echo (EO=1) out of its answers, as src/transport/echo_filter.h does:
    each expression's bytes come back before its answer; whether the drive echoes is learnt
    from the first bytes after each piece (they repeat it or start an answer)."""

    def __init__(self, sent, ends=b";\r\n"):
        self.pieces = []
        piece = b""
        for byte in sent:
            piece += bytes((byte,))
            if byte in ends:
                self.pieces.append(piece)
                piece = b""
        if piece:
            self.pieces.append(piece)
        self.piece = 0
        self.matched = 0
        self.in_answer = False
        self.held = b""

    def feed(self, data):
        out = bytearray()
        for byte in data:
            if self.piece >= len(self.pieces):
                out.append(byte)
                continue
            if self.in_answer:
                out.append(byte)
                if byte == ord(";"):
                    self.piece += 1
                    self.in_answer = False
                continue
            expected = self.pieces[self.piece]
            if byte == expected[self.matched]:
                self.held += bytes((byte,))
                self.matched += 1
                if self.matched == len(expected):
                    self.held = b""
                    self.matched = 0
                    self.in_answer = True
                continue
            out += self.held
            out.append(byte)
            self.held = b""
            self.pieces = []
        return bytes(out)


class PromptWire(Wire):
    """The S300's wire with PROMPT 1: echo, a line per answer, BEL `ERR n text`, `-->`."""

    line_end = b"\r"
    prompt = b"-->"
    error_prefix = "\aERR "

    def start(self, timeout_s):
        # As `uprog download` does (src/transport/drive_client.cpp): PROMPT 1, then its prompt.
        self.exchange("PROMPT 1", timeout_s, handshake=True)

    def exchange(self, line, timeout_s, handshake=False):
        self._take_idle_output()
        self.link.send(line.encode("latin-1") + self.line_end)
        deadline = time.monotonic() + timeout_s
        answers = []
        echo_seen = False
        while True:
            if self._pending.startswith(self.prompt):
                self._pending = self._pending[len(self.prompt):]
                return answers
            cut = self._pending.find(b"\r")
            prompt_at = self._pending.find(self.prompt)
            if prompt_at > 0 and (cut < 0 or prompt_at < cut):
                # Text before the prompt without a line end: an answer all the same.
                answers.append(Answer(self._pending[:prompt_at].decode("latin-1")))
                self._pending = self._pending[prompt_at:]
                continue
            if cut < 0:
                self._more(deadline)
                continue
            text = self._pending[:cut].decode("latin-1")
            self._pending = self._pending[cut + 1:].removeprefix(b"\n")
            if handshake:
                continue  # the echo of PROMPT 1, or whatever a drive said before it
            if not echo_seen:
                # The echo opens the line's answers; a line before it is the program's text.
                echo_seen = text == line
                if not echo_seen:
                    self._output.append(text)
            elif text.startswith(self.error_prefix):
                answers.append(self._error(text))
            else:
                answers.append(Answer(text))

    def _error(self, text):
        rest = text[len(self.error_prefix):]
        code, _, message = rest.partition(" ")
        if not code.isdigit():
            raise ProtocolError(f"an error line without a code: {text!r}")
        return Answer(message, int(code))

    def _take_idle_output(self):
        # Lines the program printed while no line was open; a lone prompt carries nothing.
        while self._pending.startswith(self.prompt):
            self._pending = self._pending[len(self.prompt):]
        super()._take_idle_output()


WIRES = {"gold": GoldWire, "pdl": SemicolonWire, "pup": SemicolonWire, "st": PromptWire}
