"""Shutting oneself in a place (round 41): "storms out of the boardroom and locks himself in the gents",
"shuts herself in the staff room", "barricade themselves into the stockroom". A person who locks or shuts
themselves in a room goes into it; the room is where they go, not where they already are. The reader
knows "head into" well, so the phrase is said that way before the sentence is read, in the verb's own
form ("locks himself in" -> "heads into", "locking themselves inside" -> "heading into").
A thing or another person locked in ("locks the bikes in the shed", "shuts the dog in the kitchen") is
left alone: only a reflexive pronoun makes it the person's own going. So is shutting oneself in with no
going said before it in the sentence ("the manager shuts herself in her office for the afternoon"): the
person is there, and stays."""

from __future__ import annotations

import re

_SHUT_IN = re.compile(
    r"\b(?P<verb>lock|shut|barricade?|closet|bolt)(?P<end>s|es|ed|d|ted|ting|ing)?"
    r"\s+(?:him|her|them|my|your|our|one)sel(?:f|ves)(?:\s+away)?\s+(?:in|into|inside)\s+(?=(?:the|a|an|their|our|his|her|its|this|that|one)\b)",
    re.IGNORECASE)
# Going said before it, and joined to it: "storms out of the boardroom and", "stomps upstairs, then".
_GONE_BEFORE = re.compile(r"\b(?:out\s+of|from|off|leaves?|left|leaving|upstairs|downstairs|away|across|back|out)\b"
                          r"[^.;!?]*?(?:,\s*|\s)(?:and|then|before)(?:\s+then)?\s*$", re.IGNORECASE)
_ENDS = {"s": "s", "es": "s", "ed": "ed", "d": "ed", "ted": "ed", "ing": "ing", "ting": "ing"}


def as_going_in(text: str) -> str:
    """The text with shutting oneself in a place said as heading into it."""
    def say(m: re.Match[str]) -> str:
        sentence = re.split(r"[.;!?]", text[:m.start()])[-1]
        if not _GONE_BEFORE.search(sentence):
            return m.group(0)
        head = "Head" if m.group("verb")[0].isupper() else "head"
        return f"{head}{_ENDS.get(m.group('end') or '', '')} into "
    return _SHUT_IN.sub(say, text)
