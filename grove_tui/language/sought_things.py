"""What a purpose seeks (round 52): "to look for prom dresses", "to hunt for a charger", "to shop for
school shoes", "to search for her lost scarf". After a verb of seeking, "for" opens the thing sought,
which is the purpose's too ("to look for prom dresses": the purpose is the dresses), not a stay ("for a
while") nor a place. A phrase the world names as a place ("to look for the toilets") is left to the
places: people go there."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language.tokens import phrase_lemmas

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Verbs of seeking whose "for" opens what is sought, every form.
_SEEKING = frozenset(f"{v}{end}" for v in ("look", "hunt", "search", "shop", "browse", "forage", "rummage", "scout",
                                            "fish", "root", "dig", "scour")
                     for end in ("", "s", "es", "ing", "ping", "ed", "ped"))
# Words that start a stay, not a thing ("to look for a while", "to shop for an hour").
_STAY_HEADS = frozenset("while bit minute minutes hour hours moment moments second seconds time ages day".split())


def sought_object(s: Sentence, at: int) -> bool:
    """Whether "for" at `at`, right after a verb of seeking, opens the thing sought (module doc)."""
    if at < 1 or at + 1 >= s.n or s.low[at] != "for" or s.low[at - 1] not in _SEEKING:
        return False
    k = at + 1
    while k < s.n and k <= at + 3 and s.w[k].pos in ("DET", "ADJ", "NUM", "PRON"):
        k += 1
    if k < s.n and s.low[k] in _STAY_HEADS:
        return False
    said = phrase_lemmas([s.low[at + 1]])
    return not (said and s.index.knows(said[0]))
