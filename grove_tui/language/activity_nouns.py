"""Activities said by a noun after a light verb ("have a natter", "take a break", "swap stories",
round 17). The verb ("have", "take", "do") says nothing of what people do; the noun after it does, so
each noun of talk is conversing and each noun of a pause is waiting wherever they are.
"""

from __future__ import annotations

# Nouns of talk after "have": "have a natter", "have a quick chat", "have their catch-up".
_TALK_NOUNS = ("chat", "natter", "gossip", "catch-up", "catchup", "chinwag", "word", "conversation",
               "discussion", "chatter", "talk", "debate", "argument", "heart-to-heart", "banter", "yarn", "confab")
# Nouns of a pause or refreshment after "have"/"take"/"grab": people stay where they are.
_PAUSE_NOUNS = ("coffee", "cuppa", "tea", "drink", "break", "breather", "rest", "sit-down", "snack", "bite",
                "sandwich", "smoke", "pause", "nap", "doze", "breakfast", "lunch")
PAUSE_NOUNS = frozenset(_PAUSE_NOUNS)
# What may stand between the light verb and its noun ("a quick", "their").
_BEFORE = (("a",), ("an",), ("a", "quick"), ("a", "little"), ("a", "good"), ("a", "long"), ("a", "short"),
           ("a", "bit", "of", "a"), ("their",), ("his",), ("her",), ("some",), ("a", "friendly"), ("a", "brief"))

ACTIVITY_PHRASES: dict[tuple[str, ...], str] = {
    **{("have", *before, noun): "converse" for before in _BEFORE for noun in _TALK_NOUNS},
    **{(verb, *before, noun): "wait" for verb in ("have", "take", "grab", "enjoy")
       for before in _BEFORE for noun in _PAUSE_NOUNS},
    **{("have", noun): "wait" for noun in ("lunch", "breakfast", "dinner", "coffee", "tea")},
    # Talk said by what is swapped: "swap stories", "compare notes", "shoot the breeze".
    **{(verb, what): "converse" for verb in ("swap", "exchange", "trade", "share", "compare")
       for what in ("stories", "notes", "gossip", "news", "anecdotes", "jokes", "tales")},
    ("shoot", "the", "breeze"): "converse", ("chew", "the", "fat"): "converse",
    ("deep", "in", "conversation"): "converse", ("deep", "in", "discussion"): "converse",
    ("catch", "up"): "converse",
}
