"""The exactness boundary: Python values in, exact text to C++, Fractions out.

Inputs accept ``Fraction``, ``int`` (and numpy integers, ``decimal.Decimal``)
and strings such as ``"-3/7"`` or ``"0.1"`` (read as exactly 1/10). A
``float`` is refused: it is a binary approximation, and silently using it
would make "exact" results depend on rounding. ``exact(x)`` converts a float
deliberately, to the exact value of its binary representation.
"""

import collections.abc
import itertools
import decimal
import math
import numbers
from fractions import Fraction

from .errors import InputError


def exact(x):
    """The exact value of ``x`` as a Fraction; a float gives its binary value
    (``exact(0.1) == Fraction(3602879701896397, 36028797018963968)``).
    Strings are read as everywhere else in fixel (``"p/q"``, ``"0.1"``,
    ``"1e-3"``; ParseError otherwise)."""
    if isinstance(x, float) or _is_numpy_float(x):
        if getattr(getattr(x, "dtype", None), "kind", None) == "c":
            raise TypeError(f"x: {x!r} is a complex number")
        if not math.isfinite(float(x)):
            raise InputError.make("x", repr(float(x)), "is not a finite number")
        return Fraction(float(x))
    return parse(x, "x")


def _is_numpy_float(x):
    kind = getattr(getattr(x, "dtype", None), "kind", None)
    return kind in ("f", "c") and getattr(x, "ndim", 0) == 0


def text(x, field):
    """Exact text of one number ("p/q", an integer, or the user's string)."""
    return _text(x, field)


def _text(x, field):
    t = type(x)
    if t is str:
        return x
    if t is int:  # fast paths of the common exact types
        return int_text(x)
    if t is Fraction:
        return f"{int_text(x.numerator)}/{int_text(x.denominator)}"
    if x is None:
        raise TypeError(f"{field}: None is not a number")
    if isinstance(x, bool):
        raise TypeError(f"{field}: {x!r} is a bool, not a number")
    if isinstance(x, str):
        return x  # parsed by fixel::parse_rational: ParseError names the field
    if isinstance(x, Fraction):
        return f"{int_text(x.numerator)}/{int_text(x.denominator)}"
    if isinstance(x, numbers.Integral):
        return int_text(int(x))
    if isinstance(x, float) or _is_numpy_float(x) or isinstance(x, numbers.Real) and not isinstance(
        x, (numbers.Rational, decimal.Decimal)
    ):
        raise TypeError(
            f"{field}: {x!r} is a float, which is not exact input: fixel refuses every float, even one whose "
            "binary value is exact (0.1 is stored as "
            "3602879701896397/36028797018963968); pass a Fraction, an int or a string "
            "such as '1/10' or '0.1', or fixel.exact(x) for the float's exact binary value"
        )
    if isinstance(x, decimal.Decimal):
        if not x.is_finite():
            raise TypeError(f"{field}: {x!r} is not a finite number")
        # Its exact decimal text, so that the core's exponent limit applies
        # (Fraction(Decimal('1e1000000')) would build the integer first).
        return str(x)
    if isinstance(x, numbers.Rational):
        return f"{int_text(int(x.numerator))}/{int_text(int(x.denominator))}"
    raise TypeError(f"{field}: {x!r} ({type(x).__name__}) is not an exact number (Fraction, int or str)")


_MAX_VECTOR = 10000  # entries read from an iterator


def vector(p, field):
    """Exact texts of a flat sequence; C++ checks the length against dof."""
    if p is None:
        raise TypeError(f"{field}: None is not a vector")
    if isinstance(p, (str, bytes, bytearray, memoryview)) or not hasattr(p, "__iter__"):
        raise TypeError(f"{field}: {p!r} is not a sequence of exact numbers")
    if isinstance(p, (collections.abc.Set, collections.abc.Mapping)):
        raise TypeError(
            f"{field}: a {type(p).__name__} has no order of its entries; pass a list, tuple or 1-D numpy array"
        )
    dtype = getattr(p, "dtype", None)
    if dtype is not None:
        if dtype.kind in ("f", "c"):
            raise TypeError(
                f"{field}: a numpy {dtype} array is not exact; pass ints, Fractions or strings "
                "(e.g. a list, or an array of dtype object or int)"
            )
        if getattr(p, "ndim", 1) != 1:
            raise InputError.make(field, f"shape {p.shape}", "must be a flat vector")
    elif not isinstance(p, (list, tuple)):
        # An iterator can be read only once, and the slow path reads again;
        # an endless one is read no further than a vector can be long.
        p = list(itertools.islice(p, _MAX_VECTOR + 1))
        if len(p) > _MAX_VECTOR:
            raise InputError.make(field, "an iterator", f"has more than {_MAX_VECTOR} entries")
    out = []
    try:
        for x in p:
            t = type(x)  # fast paths inline: this runs on every contains() call
            if t is int or t is str:
                out.append(str(x))
            elif t is Fraction:
                out.append(f"{x.numerator}/{x.denominator}")
            else:
                raise _Slow
    except (_Slow, ValueError):
        slow = True
    else:
        slow = False
    if slow:  # outside the except block: an error here is not chained to _Slow
        return [text(x, f"{field}[{i}]") for i, x in enumerate(p)]  # names the entry on error
    return out


class _Slow(Exception):
    """A vector entry needs the general conversion."""


def frac(s):
    """Fraction from the core's exact text ("p/q" or an integer)."""
    if len(s) <= _DIGITS:
        return Fraction(s)
    num, _, den = s.partition("/")
    return Fraction(_int(num), _int(den) if den else 1)


# Python refuses int(str) and str(int) beyond 4300 digits (a guard against
# slow conversions, sys.set_int_max_str_digits). Exact values may be longer:
# they are converted in halves of at most _DIGITS digits each.
_DIGITS = 4000


def _int(s):
    """int of a decimal integer text of any length."""
    if len(s) <= _DIGITS:
        return int(s)
    negative = s.startswith("-")
    body = s[1:] if negative else s
    m = len(body) // 2
    value = _int(body[:-m]) * 10**m + _int(body[-m:])
    return -value if negative else value


def int_text(n):
    """Decimal text of an int of any size."""
    if n.bit_length() <= 13000:  # below 4300 digits
        return str(n)
    if n < 0:
        return "-" + int_text(-n)
    m = int(n.bit_length() * 0.30103) // 2  # about half the digits
    high, low = divmod(n, 10**m)
    return int_text(high) + int_text(low).rjust(m, "0")


def fracs(v):
    return tuple(frac(s) for s in v)


def parse(x, field):
    """``x`` (an exact number or a string) as the core reads it, as a
    Fraction; ParseError naming ``field`` for text the core refuses."""
    from . import _fixel

    return frac(_fixel.parse_rational(text(x, field), field))


# The C++ core's int: a count beyond it would reach pybind11 as an
# unreadable "incompatible function arguments".
INT_MIN, INT_MAX = -(2**31), 2**31 - 1


def engine_settings(steps_per_h, velocity_iterations, position_iterations):
    """The engine's accuracy as whole numbers (the core checks the ranges)."""
    return (
        whole(steps_per_h, "steps_per_h"),
        whole(velocity_iterations, "velocity_iterations"),
        whole(position_iterations, "position_iterations"),
    )


def whole(x, field):
    """``x`` (an int or a numpy integer, not a bool) as a Python int within
    the core's int range; TypeError for a non-integer, InputError naming
    ``field`` for one out of range. Lower limits of meaning (at least 1, ...)
    are the core's to check and name."""
    if isinstance(x, bool) or not isinstance(x, numbers.Integral):
        raise TypeError(f"{field}: {x!r} is not an int")
    v = int(x)
    if v > INT_MAX:
        raise InputError.make(field, str(v), f"is too large (at most {INT_MAX})")
    if v < INT_MIN:
        raise InputError.make(field, str(v), f"is too small (at least {INT_MIN})")
    return v
