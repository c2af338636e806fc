"""The C++ core in a worker thread, so that the caller's thread stays free
to report progress and to take Ctrl-C (fixel.region, fixel.design)."""

import threading


def in_worker(work, tick, interval=0.1, on_interrupt=None, name="fixel"):
    """Runs ``work()`` (a C++ call that releases the GIL) in a worker thread
    and calls ``tick()`` every ``interval`` seconds while it runs. On
    KeyboardInterrupt, ``on_interrupt()`` is called (a core that polls a
    control stops at its next poll), the worker is waited for (a core is
    never left running unseen), and the interrupt is raised again. An
    exception of ``work`` is raised in the caller's thread."""
    result, error = [], []

    def target():
        try:
            result.append(work())
        except BaseException as e:  # re-raised in the caller's thread
            error.append(e)

    worker = threading.Thread(target=target, name=name, daemon=True)
    worker.start()
    try:
        while worker.is_alive():
            worker.join(interval)
            if worker.is_alive():
                tick()
    except KeyboardInterrupt:
        if on_interrupt is not None:
            on_interrupt()
        raise
    finally:
        worker.join()
    if error:
        raise error[0]
    return result[0]
