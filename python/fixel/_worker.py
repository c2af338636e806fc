"""The C++ core in a worker thread, so that the caller's thread stays free
to report progress and to take Ctrl-C (fixel.region, fixel.design)."""

import numbers
import os
import threading
from concurrent.futures import ThreadPoolExecutor, wait

# Reused worker threads: a fresh thread per call would also rebuild the
# core's per-thread workspaces (GMP limbs, tableaux), which cost more than
# the thread (docs/python.md). One pool per process: a child made by fork
# starts its own, the parent's threads do not exist there.
_pool, _pool_pid = None, None
_pool_lock = threading.Lock()


def _executor():
    global _pool, _pool_pid
    with _pool_lock:
        if _pool is None or _pool_pid != os.getpid():
            # Threads are made only when none is idle: as many as callers at once.
            _pool, _pool_pid = ThreadPoolExecutor(max_workers=64, thread_name_prefix="fixel"), os.getpid()
        return _pool


def in_worker(work, tick, interval=0.1, on_interrupt=None):
    """Runs ``work()`` (a C++ call that releases the GIL) in a worker thread
    and calls ``tick()`` every ``interval`` seconds while it runs. On
    KeyboardInterrupt, or any exception raised by ``tick()`` (a progress
    callback that raises to abort), ``on_interrupt()`` is called (a core that
    polls a control stops at its next poll), the worker is waited for (a
    core is never left running unseen), and the exception is raised again.
    An exception of ``work`` is raised in the caller's thread."""
    future = _executor().submit(work)
    try:
        while not wait([future], timeout=interval).done:
            tick()
    except BaseException:
        if on_interrupt is not None:
            on_interrupt()
        raise
    finally:
        wait([future])
    return future.result()

def seconds_limit(max_seconds):
    """``max_seconds`` as a float (None stays None); TypeError for a non-number.
    Any real number is taken (int, float, Fraction, numpy scalars); one that
    is not positive and finite is the core's InputError, and one beyond 10⁹
    s sets no limit (docs/python.md)."""
    if max_seconds is None:
        return None
    if isinstance(max_seconds, bool) or not isinstance(max_seconds, numbers.Real):
        raise TypeError(f"max_seconds: {max_seconds!r} ({type(max_seconds).__name__}) is not a number of seconds")
    try:
        return float(max_seconds)
    except OverflowError:  # an int or Fraction beyond doubles
        return float("inf") if max_seconds > 0 else float("-inf")


def stoppable(call, max_seconds=None, tick=None, interval=0.1):
    """``call(control)`` in a worker thread, ``control`` a fresh
    ``_fixel.Control`` that the core polls: past ``max_seconds`` the core
    stops and StoppedError is raised; Ctrl-C cancels it, waits for it and
    raises KeyboardInterrupt. ``tick(control)`` runs every ``interval``
    seconds while the core computes."""
    from . import _fixel

    control = _fixel.Control(seconds_limit(max_seconds))
    return in_worker(
        lambda: call(control),
        (lambda: tick(control)) if tick is not None else (lambda: None),
        interval,
        on_interrupt=control.cancel,
    )
