"""A fronted participle that moves someone (round 32): "Pushing her father's wheelchair, a woman brings
him from the cloakroom to the gallery", "Wheeling his mum in, a man heads to the pharmacy", "Guiding a
blind visitor, a guide walks to the café". The fronted clause has no subject of its own, so the person
pushed, wheeled or guided was lost with it. Said as the mover's own clause ("a woman brings her father
from ...", "a guide guides a blind visitor and walks to the café"), the person moved is read like any
object of a leading verb: a second group that goes along. A thing pushed ("Pushing a trolley, ...")
reads as before: the object of a leading verb that is no person makes no group. Round 46: an aid pushed
before a clause that takes someone somewhere ("Pushing a wheelchair, a porter takes a patient from X to Y")
is how the one taken goes: the fronted clause is left out, so the porter keeps the way (pushed_aids.py)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import parse
from grove_tui.language.pushed_aids import after_is_someone
from grove_tui.language.tokens import third_person, verb_lemma

_PARTICIPLES = {"pushing": "push", "wheeling": "wheel", "guiding": "guide", "leading": "lead",
                "escorting": "escort", "helping": "help", "steering": "steer", "shepherding": "shepherd",
                "ushering": "usher", "supporting": "support", "accompanying": "accompany", "towing": "tow",
                "pulling": "pull", "dragging": "drag", "carrying": "carry", "chaperoning": "chaperone",
                "walking": "walk", "assisting": "assist", "ferrying": "ferry", "bringing": "bring",
                "taking": "take"}
_PARTICLES = "in|out|along|over|through|round|around|back|away|up|down|across|inside|outside"
_FRONTED = re.compile(rf"^(?P<part>{'|'.join(_PARTICIPLES)})\s+(?P<obj>[^,.;:!?]+?)"
                      rf"(?:\s+(?:{_PARTICLES}))?\s*,\s+(?P<rest>.+)$", re.IGNORECASE | re.DOTALL)
_OWNED_THING = re.compile(r"^(?P<owner>.+?)(?:'s|s')\s+(?:\w+\s+)?(?P<thing>\w+)$")
_PRONOUNS = frozenset({"him", "her", "them"})
_NOT_OBJECTS = frozenset({"the way", "a break", "a look", "a seat", "their time", "his time", "her time",
                          "a moment", "part", "care", "charge", "place", "turns", "a photo", "photos"})


def _person(obj: str) -> str:
    """The person moved: "her father's wheelchair" is her father; "a blind visitor" is themselves."""
    owned = _OWNED_THING.match(obj)
    if owned is not None and owned.group("thing").lower() in lx.CARRYING_THINGS:
        return owned.group("owner")
    return obj


def _aid(obj: str) -> bool:
    """Whether the thing pushed is an aid that carries someone ("a wheelchair", "one of the store
    wheelchairs"), not a person."""
    words = obj.lower().split()
    return bool(words) and (words[-1] in lx.CARRYING_THINGS or words[-1].rstrip("s") in lx.CARRYING_THINGS)


def with_fronted_movers(text: str) -> str:
    """The text with a fronted participle that moves someone said as the mover's own clause (module doc)."""
    m = _FRONTED.match(text)
    if m is None:
        return text
    obj = " ".join(m.group("obj").split())
    if len(obj.split()) > 6 or obj.lower() in _NOT_OBJECTS:
        return text
    rest = m.group("rest")
    words = parse(rest)
    root = next((w for w in words if w.dep == "ROOT"), None)
    if root is None or root.i == 0 or root.sentence != 0:
        return text
    if root.pos not in ("VERB", "AUX") and not (root.tag == "NNS" and verb_lemma(root.lower) != root.lower):
        return text  # "a mum walks": the small parser's plural noun, a verb the lexicon knows
    if any(w.text in (",", ";", ":") for w in words[:root.i]):
        return text
    subject = rest[:root.start].rstrip()
    tail = rest[root.start:]
    person = _person(obj)
    if person == obj and _aid(obj) and verb_lemma(root.lower) in lx.LEADING_VERBS and after_is_someone(words, root.i):
        return rest[:1].upper() + rest[1:]  # "Pushing a wheelchair, a porter takes a patient to X": the patient goes
    after = words[root.i + 1] if root.i + 1 < len(words) else None
    if verb_lemma(root.lower) in lx.LEADING_VERBS and after is not None and after.lower in _PRONOUNS:
        said = f"{subject} {rest[root.start:after.start]}{person}{rest[after.end:]}"  # "brings him": her father
    else:
        verb = _PARTICIPLES[m.group("part").lower()]
        said = f"{subject} {verb if root.tag == 'VBP' else third_person(verb)} {person} and {tail}"
    return said[:1].upper() + said[1:]
