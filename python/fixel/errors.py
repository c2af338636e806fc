"""fixel's typed exceptions, raised by the C++ core and by the Python layer.

Each carries ``.field`` (the JSON path or argument name, e.g. ``fixels[1].normal``)
and ``.value`` (the offending value as text); ``str(e)`` is the CLI's message
without the ``fixel: error:`` prefix.
"""


class Error(Exception):
    """Base of every exception fixel raises on purpose."""

    def __init__(self, message, field=None, value=None):
        super().__init__(message)
        self.field = field
        self.value = value


class InputError(Error, ValueError):
    """Bad input: the message is "field: value reason"."""

    @classmethod
    def make(cls, field, value, reason):
        # Same composition as fixel::InputError (src/error.cpp): control
        # characters escaped, a part longer than 864 characters shown by its ends.
        message = _shown(field, 200, 40) + ":"
        message += (" " + _shown(value, 600, 200) if value else "") + (" " + _shown(reason, 600, 200) if reason else "")
        return cls(message, field, value)


def _shown(text, head, tail):
    text = str(text)
    if len(text) > head + tail + 64:
        text = text[:head] + f"…[{len(text) - head - tail} characters]…" + text[-tail:]
    out = []
    for c in text:
        if c == "\n":
            out.append("\\n")
        elif c == "\t":
            out.append("\\t")
        elif c == "\r":
            out.append("\\r")
        elif ord(c) < 0x20 or ord(c) == 0x7F:
            out.append(f"\\x{ord(c):02x}")
        else:
            out.append(c)
    return "".join(out)


class ParseError(InputError):
    """Text that is not an exact number, or malformed JSON."""


class SceneError(InputError):
    """A well-formed scene that is physically invalid or degenerate."""


class UnsupportedError(InputError, NotImplementedError):
    """Valid input that fixel does not handle yet."""


class StoppedError(Error):
    """A long run stopped before its answer: its time limit (``max_seconds``)
    passed or it was cancelled. ``str(e)`` says how far it got."""
