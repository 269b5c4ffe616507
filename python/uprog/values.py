"""A drive's answer text as a Python number: `1234` -> 1234, `3.600000` -> 3.6, `5.4` -> 5.4."""

from .errors import ProtocolError


def number_of(text, asked=""):
    text = text.strip()
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        raise ProtocolError(f"{asked or 'the value'} answered {text!r}, not a number") from None
