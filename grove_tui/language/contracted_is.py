"""A person's "'s" that is "is" or "has", not a possessive (round 40): "Dad's snoozing on the couch",
"Sarah's waiting at the nurse station", "Grandma's been sat in the cafeteria for hours", "Nan's asleep
in the lounge". The parser read "Dad's snoozing" as a possessive ("Dad's snooze") and the sentence
lost its person: one vague group of "people". Written out ("Dad is snoozing"), it is one person.

Only before a word a possessive is not followed by: an "-ing" word that is itself followed by a
preposition, an adverb, a determiner or the end ("Dad's walking stick" stays a stick), or "been",
"gone", "got", "asleep", a preposition of place. Pronouns and "let's" are left as they are."""

from __future__ import annotations

import re

_NOT_SUBJECTS = frozenset("it that there here what who where how when why let he she this everyone everybody "
                          "someone somebody nobody noone one each which".split())
# Words an "-ing" verb is followed by in a clause ("snoozing on", "waiting at", "cooking again"),
# never a noun it could modify ("walking stick", "waiting room").
_AFTER_ING = ("on|in|at|by|to|into|onto|from|towards?|through|around|round|about|near|outside|inside|behind|"
              "beside|past|up|down|out|off|over|under|across|along|with|for|after|away|again|still|quietly|"
              "alone|here|there|now|the|a|an|his|her|their|my|our|its|some|everywhere|nearby|upstairs|"
              "downstairs|home|together|happily|soundly|loudly")
_HAS = "been|gone|got"
_IS = ("asleep|awake|still|just|already|now|off|in|at|on|by|outside|inside|upstairs|downstairs|over|near|"
       "sat|stood|sitting|standing|lying|out\\s+in|out\\s+on|out\\s+by|out\\s+at|busy|dozing|fast\\s+asleep")
_CONTRACTED = re.compile(
    r"\b([A-Za-z][A-Za-z-]*)['\u2019]s\s+(?:"
    r"(?P<ing>[a-z]{2,}ing)(?=\s+(?:" + _AFTER_ING + r")\b|\s*[.,;:!?]|\s*$)"
    r"|(?P<has>" + _HAS + r")\b"
    r"|(?P<is>(?:" + _IS + r"))\b(?!-))")


def with_full_is(text: str) -> str:
    """The text with a person's contracted "is"/"has" written out (module doc)."""

    def full(m: re.Match[str]) -> str:
        if m.group(1).lower() in _NOT_SUBJECTS:
            return m.group(0)
        verb = "has" if m.group("has") else "is"
        word = m.group("ing") or m.group("has") or m.group("is")
        return f"{m.group(1)} {verb} {word}"

    return _CONTRACTED.sub(full, text)
