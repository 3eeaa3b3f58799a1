"""People who leave a place for an event said with its own place (round 69): "five developers abandon their
desks for the morning briefing at the whiteboard", "two analysts leave their desks for the weekly meeting in
the boardroom", "three nurses desert the nurses' station for the handover in the staff room". "Leave X for
the boardroom" is a walk there (place_contrast.py's left_for); for an event, the event was read as a place
to refuse and the event's place as where they stay. Said as leaving, then going to the event's place for
the event ("abandon their desks and go to the whiteboard for the morning briefing"), they walk from X to the
event's place, and the event is why they go.

Round 72: the place first, then the event after "and" ("leaves her office for network control and the
morning briefing", "quit the ward for the seminar room and the weekly teaching"): the same walk, said as
"leave X and go to <place> for the <event>"."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.event_names import EVENT_WORDS
from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import lemma, phrase_lemmas, verb_lemma, words

_LEFT_FOR_EVENT = re.compile(
    r"\b(?P<verb>(?:[Ll]eav|[Ll]eft|[Aa]bandon|[Dd]esert|[Qq]uit|[Ee]xit|[Vv]acat|[Ee]vacuat|[Ff]le|[Ee]scap|[Ff]orsak|"
    r"[Dd]itch|[Dd]epart)[a-z]*)\s+(?P<left>(?:(?:their|his|her|the|our|its|my)\s+)?[\w'’ -]{1,30}?)\s+for\s+"
    r"(?P<event>(?:the|a|an|their|his|her|our|this|today's|tonight's)\s+[\w'’ -]{1,40}?)\s+"
    r"(?P<prep>at|in|by|on|inside)\s+(?P<place>(?:the\s+)?[\w'’ -]{1,40}?)(?=\s*(?:[,.;!?]|$|\band\b|\bwhile\b|\bbut\b))")
_LEFT_FOR_PLACE_AND_EVENT = re.compile(
    r"\b(?P<verb>(?:[Ll]eav|[Ll]eft|[Aa]bandon|[Dd]esert|[Qq]uit|[Ee]xit|[Vv]acat|[Ff]orsak|[Dd]itch|[Dd]epart)[a-z]*)"
    r"\s+(?P<left>(?:(?:their|his|her|the|our|its|my)\s+)?[\w'’ -]{1,30}?)\s+for\s+"
    r"(?P<place>(?:the\s+)?[\w'’ -]{1,40}?)\s+and\s+"
    r"(?P<event>(?:the|a|an|their|his|her|our|this|today's|tonight's)\s+[\w'’ -]{1,40}?)"
    r"(?=\s*(?:[,.;!?]|$|\bwhile\b|\bbut\b))")
_EVENTS = EVENT_WORDS | frozenset("handover huddle standup stand-up catch-up debrief roll-call call demo review "
                                  "appraisal interview inspection induction training check-in weigh-in warm-up".split())
_LEAVING = lx.START_OBJECT_VERBS | lx.DEPARTURE_VERBS | frozenset({"forsake", "ditch"})


def with_events_left_for(text: str, index: PlaceIndex) -> str:
    """The text with "leave X for the <event> at <place>" said as "leave X and go to <place> for the <event>"."""
    def said(m: re.Match[str]) -> str:
        if verb_lemma(m.group("verb").lower()) not in _LEAVING:
            return m.group(0)
        event = words(m.group("event"))
        named = index.match(tuple(phrase_lemmas(event))) if event else None
        if not event or lemma(event[-1]) not in _EVENTS or named is not None and named.exact:
            return m.group(0)  # "leave the ward for the canteen at the back": a place, read as it is
        place = m.group("place")
        if index.match(tuple(phrase_lemmas(words(place)))) is None:
            return m.group(0)  # "for the meeting at nine": a time; a place the world lacks is refused as said
        return f"{m.group('verb')} {m.group('left')} and go to {place} for {m.group('event')}"
    def place_then_event(m: re.Match[str]) -> str:
        if verb_lemma(m.group("verb").lower()) not in _LEAVING:
            return m.group(0)
        event = words(m.group("event"))
        named = index.match(tuple(phrase_lemmas(event))) if event else None
        if not event or lemma(event[-1]) not in _EVENTS or named is not None and named.exact:
            return m.group(0)  # "leave the ward for the canteen and the shop": two places, read as said
        place = m.group("place")
        if index.match(tuple(phrase_lemmas(words(place)))) is None:
            return m.group(0)
        return f"{m.group('verb')} {m.group('left')} and go to {place} for {m.group('event')}"
    return _LEFT_FOR_PLACE_AND_EVENT.sub(place_then_event, _LEFT_FOR_EVENT.sub(said, text))
