"""Verbs of leaving in everyday English the lexicon lacks (round 14): "leg it", "bail", "scarper",
"make a run for it", "clear off", "head for the exits". Each is a walk away from where the people
are; said with a hazard (`hazards.py`) or with urgency, the clause's evacuation cues make it an
evacuation, as for "leave" and "get out"."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.bound_for import bound_verbs
from grove_tui.language.chore_verbs_tagged import as_chore_verbs
from grove_tui.language.event_causes import shutting_verbs
from grove_tui.language.going_idioms import as_going_verbs
from grove_tui.language.parser import Word
from grove_tui.language.pushed_things import as_pushing_verbs
from grove_tui.language.till_words import with_till_nouns
from grove_tui.language.worked_things import work_particles
from grove_tui.language.walk_nouns import as_walk_verbs
from grove_tui.language.idle_idioms import as_idle_verbs

# One-word verbs of leaving (base forms): a walk.
LEAVING_VERBS = frozenset("bail scarper skedaddle scram bolt vamoose decamp depart".split())
# Leaving for the day or to be out of the way, no hazard said (round 18): "knock off for the day",
# "make themselves scarce", "head off home", "call it a day".
_SELVES = ("themselves", "himself", "herself", "ourselves", "myself", "yourself", "yourselves")
_LEAVING_FOR_HOME: tuple[tuple[str, ...], ...] = (
    *(("make", own, "scarce") for own in _SELVES), ("knock", "off"), ("clock", "off"), ("clock", "out"),
    ("sign", "off"), ("call", "it", "a", "day"), ("call", "it", "a", "night"), ("head", "home"), ("go", "home"),
    ("push", "off"), ("shove", "off"), ("buzz", "off"), ("hit", "the", "road"), ("slope", "off"),
    ("slip", "away"), ("sneak", "off"), ("sneak", "away"), ("take", "their", "leave"), ("take", "his", "leave"),
    ("take", "her", "leave"), ("pack", "up"), ("bug", "out"))
# Phrasal verbs of leaving: (base form, words after it).
LEAVING_PHRASES: dict[tuple[str, ...], str] = {
    **{phrase: "walk" for phrase in (
        ("leg", "it"), ("clear", "off"), ("make", "tracks"), ("make", "off"), ("head", "off"), ("take", "off"),
        ("make", "a", "run", "for", "it"), ("make", "a", "break", "for", "it"), ("make", "a", "dash", "for", "it"),
        ("head", "for", "the", "exits"), ("head", "for", "the", "exit"), ("make", "for", "the", "exits"),
        ("make", "for", "the", "exit"), ("run", "for", "it"), ("run", "for", "the", "exits"),
        ("get", "out"), ("clear", "out"), ("pile", "out"), ("bail", "out"), ("file", "out"), ("stream", "out"),
        ("pour", "out"), ("spill", "out"), ("get", "away"))},
    **{phrase: "walk" for phrase in _LEAVING_FOR_HOME},
}
# Phrasal verbs of leaving that are an evacuation when the prompt names a hazard ("legs it", "bails").
HAZARD_EXIT_PHRASES: tuple[tuple[str, ...], ...] = (
    ("leg", "it"), ("clear", "off"), ("make", "tracks"), ("make", "off"), ("run", "for"), ("make", "a"),
    ("head", "for"), ("make", "for"), ("get", "away"), ("file", "out"), ("stream", "out"), ("spill", "out"))


# Forms of the leaving verbs the small parser tags as nouns after a noun ("the carers in the lounge
# leg it": "lounge leg", a compound; "the passengers bail"): with what follows them, they are verbs.
_LEG_FORMS = frozenset({"leg", "legs", "legged", "legging"})
_BARE_FORMS = frozenset(f"{v}{end}" for v in ("bail", "scarper", "skedaddle", "scram", "bolt", "decamp")
                        for end in ("", "s", "ed", "ing", "d")) - {"bolts", "bolt", "scrams"}
_AFTER_BARE = frozenset({"", ".", "!", ",", ";", ":", "from", "out", "off", "away", "and", "through", "via", "towards",
                         "toward", "to", "immediately", "now", "fast", "quickly"})


def as_verbs(words: list[Word]) -> list[Word]:
    """The parse with leaving verbs the parser took for nouns tagged as verbs ("lounge leg it")."""
    words = as_chore_verbs(with_till_nouns(words))  # "a keeper preps fish": a verb; "a pair of till staff": the shop's till, not "until"
    out = list(words)
    for k, w in enumerate(words):
        nxt = words[k + 1].lower if k + 1 < len(words) else ""
        leaving = (w.lower in _LEG_FORMS and nxt == "it") or (w.lower in _BARE_FORMS and nxt in _AFTER_BARE and k > 0
                                                               and words[k - 1].pos in ("NOUN", "PROPN", "PRON"))
        if leaving and w.pos != "VERB":
            out[k] = replace(w, pos="VERB", tag="VBP" if not w.lower.endswith(("ed", "ing")) else "VBD",
                             dep="ROOT", head=k)
            prev = out[k - 1] if k > 0 else None
            if prev is not None and prev.dep == "compound" and prev.head == k:
                out[k - 1] = replace(prev, dep=w.dep, head=w.head)  # "the lounge": the noun the verb was taken for
    return as_idle_verbs(as_walk_verbs(as_going_verbs(as_pushing_verbs(work_particles(bound_verbs(shutting_verbs(out)))))))  # "a pair of teens mess about": a verb; "mums wheel prams", "the toy store shuts and ...", "bound for Leeds queue at ..."
