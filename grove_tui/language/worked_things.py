"""What people work on, and where that puts them (round 27).

A verb of work with its particle ("hoses down the scrap cars", "wipes down the benches", "mops up the
spill") acts on its object: the particle is no way through ("down the corridor"), and the thing worked
on is where they are. A thing worked on and then the room it is done in ("folds tunics in the kit
room", "lays tables in the restaurant"): the room said is where they are, not the fixture the thing
happens to be called after."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.filled_things import FILLING_PARTICLES
from grove_tui.language.gerund_loads import load_gerund
from grove_tui.language.tokens import verb_lemma
from grove_tui.language.used_fixtures import uses_fixture

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
    **FILLING_PARTICLES,
}
# Verbs whose object is what people are among, not a thing they handle ("browse the shelves").
_BEING_AMONG = lx.LOCATION_OBJECT_VERBS - lx.THING_OR_PLACE_VERBS
_AFTER = frozenset({"the", "a", "an", "all", "some", "every", "each", "both", "those", "these", "his", "her",
                    "their", "its", "our", "my"})


# What people are "on" while they work ("two teenagers on work experience stack growbags", "nurses on
# duty wipe ..."), and the words that may come before it ("the night shift", "their lunch break").
_STATUS = frozenset("duty shift experience placement patrol break call standby secondment rota watch nights lates "
                    "earlies days".split())
_STATUS_BEFORE = frozenset("the a their his her our work night day early late evening morning afternoon lunch tea "
                           "coffee weekend overnight graveyard split double long short".split())
_AFTER_VERB = frozenset({"DET", "NOUN", "ADJ", "NUM", "PRON"})


def status_verbs(words: list[Word]) -> list[Word]:
    """The parse with the verb after what people are on taken for a verb, not the last word of that
    noun phrase: "two teenagers on work experience stack growbags" (the parser's "experience stack
    growbags")."""
    out = list(words)
    for o, on in enumerate(words[:-3]):
        if on.lower != "on" or o == 0 or words[o - 1].pos not in ("NOUN", "PROPN"):
            continue
        t = o + 1
        while t < len(words) and words[t].lower in _STATUS_BEFORE and words[t].lemma not in _STATUS:
            t += 1
        v = t + 1
        if v + 1 >= len(words) or words[t].lemma not in _STATUS and words[t].lower not in _STATUS:
            continue
        verb, nxt = words[v], words[v + 1]
        if verb.pos not in ("NOUN", "ADJ", "PROPN") or not verb.lower.isalpha() or verb.lower in _STATUS or \
                not (nxt.pos in _AFTER_VERB or nxt.lower in ("down", "up", "out", "off")):
            continue
        tag = "VBZ" if verb.lower.endswith("s") and not verb.lower.endswith("ss") else "VBP"
        out[v] = replace(verb, pos="VERB", tag=tag, dep="ROOT", head=v)
        out[t] = replace(words[t], dep="pobj", head=o)
    return out


def work_particles(words: list[Word]) -> list[Word]:
    """The parse with the particle of a verb of work ("hoses down the scrap cars") marked as its
    particle, not a preposition of a way through; and the verb after what people are on a verb."""
    words = status_verbs(words)
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
        words[i].lower in _particles(words[i - 1]) and not load_gerund(words, i - 1)  # "a basket of washing off X"


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
    if verb_lemma(current.written) in _BEING_AMONG or uses_fixture(current.written):
        return None  # "browse the perfume shelves in the duty free": among the shelves, not only in the room
    if room.match.kind != "zone" or room.written not in ("in", "inside") or room.index <= current.index:
        return None
    entry = index.entry(current.match.name)
    if entry is None or entry.kind == "zone" or entry.zone != room.match.name:
        return None
    return room.match.name
