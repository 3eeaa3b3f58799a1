"""A plural place noun that names several rooms of one kind together ("everyone in the galleries",
"both platforms", "the wards"): no one of them is meant, so the phrase reads no place (and refuses none),
rather than the first room of that kind. A plural that is one place's own name ("the toilets", "the lifts")
and a plural narrowed to one room by its other words ("the Egyptian galleries") keep their reading."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch

# Words that tell a pair of rooms apart by who uses them: their plural is the pair's common name.
_PAIRED = frozenset("men women mens womens male female boys girls ladies gents staff public".split())


def several_zones(index: PlaceIndex, phrase: Sequence[str], lemmas: Sequence[str], match: PlaceMatch | None) -> bool:
    """Whether the phrase is a plural noun naming two or more of the world's rooms alike, none above the rest."""
    if match is None or match.exact or match.kind != "zone" or not phrase or not lemmas:
        return False
    word, head = phrase[-1].lower(), lemmas[-1]
    if word == head or not word.endswith("s") or any(w.isdigit() for w in lemmas):
        return False
    if any(word in said.lower().split() for e in index.entries for said in e.said):
        return False  # "the toilets", "the stairs": the plural is a place's own name
    found = index.candidates(tuple(lemmas))
    if not found:
        return False
    top = found[0].score
    tied = [m for m in found if m.kind == "zone" and m.score >= top - 1e-9 and not m.exact]
    if len(tied) < 2 or match.name not in {m.name for m in tied}:
        return False
    if any(set(m.name.split("_")) & _PAIRED for m in tied):
        return False  # "the changing rooms": the men's and women's, said as one place
    # each of them is a room of the head's kind: its type or its name ends in the head word
    kinds = [e for e in index.entries if e.name in {m.name for m in tied} and e.kind == "zone"]
    return sum(1 for e in kinds if any(head == p[-1] for p in e.phrases) or
               any(head == t.split()[-1] for t in e.types)) >= 2
