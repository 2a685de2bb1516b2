"""Running with Python's cyclic garbage collector paused.

A run allocates its fronts, regions, states and event records by the hundred thousand
and keeps every one of them to the end (they are the solution).  Python's cyclic
collector is triggered by allocations and, at each of its full passes, traverses
every tracked object alive: on the 20 µs Davison steel scene (``benchmarks/
run_length.py``, about 60 000 events) that traversal took a sixth to a fifth of the
run and found nothing to free, since nothing the engine drops is part of a
reference cycle.  Reference counting, which frees all the temporaries, is not
affected.  ``paused()`` switches the collector off for the duration of a run and back
on (if it was on) afterwards, so that any cycle left behind is collected then.
"""

from __future__ import annotations

import gc
from contextlib import contextmanager


@contextmanager
def paused():
    """Disable the cyclic garbage collector inside the block; restore its state after."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()
