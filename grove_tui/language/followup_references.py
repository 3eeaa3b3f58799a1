"""Which groups of a scenario a follow-up's phrase names: a `GroupRef` to their indices.

    resolve("the people at the pharmacy", ctx).targets   # the groups of the scenario that are there

"everyone"/"all"/"both" (every group, or every group the rest of the phrase names), a pronoun (the
groups the previous edit touched), "group 2" / "the second group", a person word against each group's
label and phrase ("the elderly patients"), an intent noun or participle ("the queue", "the people
chatting"), and a place inside the phrase ("the people at the pharmacy") to tell candidates apart.
Several candidates for one phrase are ambiguous.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.edits import GroupRef
from grove_tui.language.followup_context import FollowupContext
from grove_tui.language.followup_phrases import EVERY_WORDS, PRONOUNS
from grove_tui.language.model import GroupReading
from grove_tui.language.places import place_index
from grove_tui.language.tokens import lemma, verb_lemma, words

# Nouns and participles that name a group by what it does ("the queue", "those waiting").
INTENT_NOUNS: dict[str, str] = {
    "queue": "queue", "line": "queue", "queuer": "queue", "conversation": "converse", "chat": "converse",
    "circle": "converse", "talker": "converse", "evacuee": "evacuate", "walker": "walk", "wanderer": "wander",
    "follower": "follow", "stroller": "wander", "waiter": "wait",
}

# words that stand for a group already named ("the new ones", "that lot")
GROUP_WORDS = frozenset({"group", "groups", "ones", "one", "lot"})
ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7,
            "eighth": 8, "ninth": 9, "tenth": 10, "last": -1}


def resolve(phrase: str, ctx: FollowupContext, label: str | None = None) -> GroupRef:
    """The groups of the scenario a phrase can mean (module doc)."""
    ws = [w for w in words(phrase)]
    content = [w for w in ws if w not in lx.DETERMINERS and w not in ("of", "and")]
    count = ctx.group_count
    everyone = bool(set(ws) & EVERY_WORDS)
    every = everyone or "both" in ws
    # "group 2", "the second group", "the last group"
    for k, w in enumerate(ws):
        if w in ("group", "groups") and k + 1 < len(ws) and ws[k + 1].isdigit():
            n = int(ws[k + 1])
            return GroupRef(phrase, (n - 1,) if 1 <= n <= count else ())
        if w in ORDINALS and k + 1 < len(ws) and ws[k + 1] in ("group", "one"):
            n = ORDINALS[w]
            index = count - 1 if n < 0 else n - 1
            return GroupRef(phrase, (index,) if 0 <= index < count else ())
    if content and all(w in PRONOUNS or w in GROUP_WORDS or w in ("new", "same", "other", "last", "just", "added")
                       for w in content):
        if ctx.last:
            return GroupRef(phrase, ctx.last, every=True)
        return GroupRef(phrase, tuple(range(count)), every=count == 1)
    candidates = list(range(count))
    person_words = [lemma(w) for w in content if lemma(w) in lx.PERSON_NOUNS and lemma(w) not in lx.GENERIC_PEOPLE
                    and w not in EVERY_WORDS and lemma(w) not in ("group", "crowd", "everyone", "everybody")]
    if label and label not in lx.GENERIC_PEOPLE and label not in person_words and label != "group":
        person_words.append(label)
    narrowed = False
    generic = [lemma(w) for w in content if lemma(w) in lx.GENERIC_PEOPLE]
    if not person_words and generic:
        # "the people" of a scenario that has a group the sentence called people is that group
        named = [i for i in candidates if lemma(ctx.group(i).label) in lx.GENERIC_PEOPLE]
        if named:
            candidates, narrowed = named, True
    if person_words:
        candidates = [i for i in candidates if _names_group(person_words, ctx.group(i))]
        narrowed = True
        if not candidates:
            return GroupRef(phrase, ())
    intents = {INTENT_NOUNS[lemma(w)] for w in content if lemma(w) in INTENT_NOUNS}
    intents |= {lx.INTENT_VERBS[verb_lemma(w)] for w in content
                if w.endswith("ing") and verb_lemma(w) in lx.INTENT_VERBS}
    if intents:
        by_intent = [i for i in candidates if ctx.group(i).intent in intents or
                     (ctx.group(i).intent == "robot" and "wait" in intents)]
        if by_intent or not narrowed:
            candidates = by_intent
            narrowed = True
        if not candidates:
            return GroupRef(phrase, ())
    zones = _zones_in(phrase, ctx)
    if zones:
        here = [i for i in candidates if zones & _group_zones(ctx.group(i), ctx)]
        if here or not narrowed:
            candidates = here
            narrowed = True
    if not narrowed and not everyone and not (set(content) & {"people", "person", "crowd", "group", "everyone",
                                                              "everybody", "one", "ones", "others", "rest"}):
        return GroupRef(phrase, ())  # no word of it names people: "the corridor", "the lights"
    return GroupRef(phrase, tuple(candidates), every=every or len(candidates) == 1)


def _names_group(person_words: Sequence[str], group: GroupReading) -> bool:
    own = {lemma(group.label)} | {lemma(w) for w in words(group.who)} | {lemma(w) for w in group.label.split("_")}
    return any(w in own for w in person_words)


def _zones_in(phrase: str, ctx: FollowupContext) -> set[str]:
    """Zones named after a place preposition inside a phrase ("the people at the pharmacy")."""
    ws = words(phrase)
    index = place_index(ctx.world)
    found: set[str] = set()
    for k, w in enumerate(ws):
        if w in lx.PLACE_PREPOSITIONS and k + 1 < len(ws):
            lemmas = [lemma(x) for x in ws[k + 1:] if x not in lx.DETERMINERS]
            match = index.match(lemmas)
            if match is not None:
                found.add(match.zone)
    return found


def _group_zones(group: GroupReading, ctx: FollowupContext) -> set[str]:
    index = place_index(ctx.world)
    out: set[str] = set()
    for name in (group.start, group.location, group.destination, *group.via):
        entry = index.entry(name) if name else None
        if entry is not None:
            out.add(entry.zone)
    return out
