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
        # Same composition as fixel::InputError (src/error.cpp).
        message = field + ":" + (" " + value if value else "") + (" " + reason if reason else "")
        return cls(message, field, value)


class ParseError(InputError):
    """Text that is not an exact number, or malformed JSON."""


class SceneError(InputError):
    """A well-formed scene that is physically invalid or degenerate."""


class UnsupportedError(InputError, NotImplementedError):
    """Valid input that fixel does not handle yet."""


class StoppedError(Error):
    """A long run stopped before its answer: its time limit (``max_seconds``)
    passed or it was cancelled. ``str(e)`` says how far it got."""
