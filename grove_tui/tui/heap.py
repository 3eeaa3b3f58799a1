"""Keeping the UI thread's pauses for garbage collection short (issue 21: key response).

CPython's cyclic collector stops every thread while it runs, and a full (oldest generation)
collection walks every container object the process holds. After the warm-up the app holds about
560,000 of them (torch, sentence-transformers, ChromaDB, spaCy, numba), and a full collection took
0.37 s at load average 3 on 2 cores: one of those every few seconds of typing or streaming was the
p90 of the key response. Nearly all of those objects live as long as the process, so once they are
loaded they are collected one last time and frozen (`gc.freeze`, the permanent generation the
collector does not walk); later collections then walk only what the session creates after that.
"""

from __future__ import annotations

import gc
import time
from dataclasses import dataclass


@dataclass(frozen=True)
class FrozenHeap:
    """What one freeze did: objects moved out of the collector's sight and the collection's cost."""

    frozen: int
    collected: int
    seconds: float


def freeze_heap() -> FrozenHeap:
    """Collect everything once, then freeze the survivors.

    The collection first means no garbage is frozen with them (it would never be freed). What is
    frozen and later dropped is still freed by reference counting; only a reference cycle among
    frozen objects that becomes garbage later is kept, which is why this runs once the long-lived
    state (models, embedder, node index, reader) is loaded, not while screens come and go.
    """
    started = time.perf_counter()
    collected = gc.collect()
    gc.freeze()
    return FrozenHeap(gc.get_freeze_count(), collected, time.perf_counter() - started)


def drop_dead_widget_caches() -> None:
    """Forget Textual's memo of closed widgets' render caches.

    `StylesCache.get_inner_outer` is an `lru_cache(1024)` keyed by the widget's StylesCache, so it
    keeps up to 1,024 caches of widgets already removed alive, each with its rendered lines (about
    220 per F1/Escape). They are bounded but make every collection walk them; a dialog closing is a
    good moment to let them go (the cache refills with the few live widgets on the next paint).
    """
    from textual._styles_cache import StylesCache

    clear = getattr(getattr(StylesCache, "get_inner_outer", None), "cache_clear", None)
    if callable(clear):
        clear()
