"""What people work on, and where that puts them (round 27).

A verb of work with its particle ("hoses down the scrap cars", "wipes down the benches", "mops up the
spill") acts on its object: the particle is no way through ("down the corridor"), and the thing worked
on is where they are. A thing worked on and then the room it is done in ("folds tunics in the kit
room", "lays tables in the restaurant"): the room said is where they are, not the fixture the thing
happens to be called after."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.parser import Word
    from grove_tui.language.place_phrases import Place
    from grove_tui.language.places import PlaceIndex

# Verbs of work on a thing and the particles they take ("hose down", "wipe off", "tidy up", "clean out").
_CLEANING = frozenset("hose wipe scrub wash rinse spray dust polish clean mop tidy hoover vacuum sponge swab "
                      "sluice jetwash disinfect sanitise sanitize spruce".split())
_WORK_PARTICLES: dict[str, frozenset[str]] = {
    **{v: frozenset({"down", "off", "up", "out"}) for v in _CLEANING},
    **{v: frozenset({"up", "out"}) for v in "lay set stack tidy straighten clear".split()},
}
_AFTER = frozenset({"the", "a", "an", "all", "some", "every", "each", "both", "those", "these", "his", "her",
                    "their", "its", "our", "my"})


def work_particles(words: list[Word]) -> list[Word]:
    """The parse with the particle of a verb of work ("hoses down the scrap cars") marked as its
    particle, not a preposition of a way through."""
    out = list(words)
    for k in range(1, len(words) - 1):
        w, verb, nxt = words[k], words[k - 1], words[k + 1]
        if w.lower not in _particles(verb):
            continue
        if words[k - 2].pos == "DET" if k >= 2 else False:
            continue  # "the hoses down the corridor": a thing, no verb
        if nxt.lower in _AFTER or nxt.pos in ("NOUN", "PROPN", "NUM", "ADJ"):
            out[k] = replace(w, pos="ADP", tag="RP", dep="prt", head=k - 1)
            if verb.pos != "VERB":  # "a student scrubs down the bench": a verb, not the scrubs worn
                tag = "VBZ" if verb.lower.endswith("s") else "VBG" if verb.lower.endswith("ing") else \
                    "VBD" if verb.lower.endswith("ed") else "VBP"
                out[k - 1] = replace(verb, pos="VERB", tag=tag)
    return out


def is_work_particle(words: list[Word], i: int) -> bool:
    """Whether the word at `i` is a verb of work's particle marked by `work_particles`."""
    return 0 < i < len(words) and words[i].tag == "RP" and words[i].dep == "prt" and \
        words[i].lower in _particles(words[i - 1])


def _particles(verb: Word) -> frozenset[str]:
    """The particles of a verb of work, whatever its form ("hoses", "wiping", "scrubbed")."""
    low = verb.lower
    for base in (verb_lemma(low), verb.lemma, low[:-2] if low.endswith("es") else low, low[:-1] if low.endswith("s") else low,
                 low[:-3] if low.endswith("ing") else low, low[:-3] + "e" if low.endswith("ing") else low,
                 low[:-1] if low.endswith("ed") else low, low[:-2] if low.endswith("ed") else low):
        if base in _WORK_PARTICLES:
            return _WORK_PARTICLES[base]
    return frozenset()


def room_worked_in(index: PlaceIndex, current: Place | None, room: Place) -> str | None:
    """The room said after the thing people work on ("folds tunics in the kit room"): that room, when
    the thing was read as a fixture of it; None otherwise."""
    if current is None or current.match is None or room.match is None or current.prep != "obj:at":
        return None
    if room.match.kind != "zone" or room.written not in ("in", "inside") or room.index <= current.index:
        return None
    entry = index.entry(current.match.name)
    if entry is None or entry.kind == "zone" or entry.zone != room.match.name:
        return None
    return room.match.name
