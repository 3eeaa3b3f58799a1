"""Small readings of a follow-up's phrases that its clause readers share: where the subject ends, whether
words state an action or only who people are, definite and indefinite phrases, numbers and head counts,
and the word patterns edits are written with (the reader's own tables are in lexicon.py).

    split_subject("the nurses walk slowly")   # ("the nurses", "walk slowly")
    leading_number("two of the nurses")       # (2, "the nurses")
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.followup_context import FollowupContext
from grove_tui.language.tokens import verb_lemma, words

# regular-expression alternations of the words edits are written with
ROBOT_PATTERN = r"(?:robots?|bot|amr|droid)"
DETERMINER_PATTERN = r"(?:the|a|an|our|my|this|that|these|those|its|their)"
NUMBER_PATTERN = r"(?:\d+|" + "|".join(sorted(set(lx.UNITS) | set(lx.TENS), key=len, reverse=True)) + \
    r")(?:[\s-](?:" + "|".join(sorted(lx.UNITS, key=len, reverse=True)) + r"))?"

# words that mark a phrase as naming people already there ("everyone", "they")
EVERY_WORDS = frozenset({"everyone", "everybody", "all", "both", "every", "each", "whole", "entire"})
PRONOUNS = frozenset({"they", "them", "it", "he", "she", "him", "her", "those", "these", "that", "this"})

# words that end a subject as a verb does ("the nurses should ...", "the family keeps ...")
MODALS = frozenset("should must will shall would could can may might need needs has have had is are be "
                   "become becomes start starts begin begins keep keeps stay stays".split())


def split_subject(text: str) -> tuple[str, str]:
    """(subject phrase, predicate): the words before the first verb, and the rest."""
    ws = text.split()
    for k in range(1, len(ws)):
        w = ws[k].strip(",")
        before = ws[k - 1]
        if before in lx.DETERMINERS or before in lx.NP_MODIFIERS or before in ("of",):
            continue
        base = verb_lemma(w)
        if w in MODALS or base in lx.INTENT_VERBS or base in lx.ROBOT_VERBS or w in ("ignore", "ignores") or \
                (w.endswith("s") and base != w and base in lx.INTENT_VERBS):
            if before in lx.PLACE_PREPOSITIONS:
                continue
            return " ".join(ws[:k]), " ".join(ws[k:])
    return text, ""


def states_action(predicate: str) -> bool:
    """Whether words say what people do (a verb, phrase or feeling of the lexicon), not only who they are."""
    ws = words(predicate)
    lemmas = [verb_lemma(w) for w in ws]
    if any(v in lx.INTENT_VERBS or v in lx.ROBOT_VERBS for v in lemmas):
        return True
    if any(w in lx.EVACUATION_CUES or w in lx.ROBOT_FEELINGS for w in ws):
        return True
    joined = " ".join(lemmas)
    return any(" ".join(p) in joined for p in lx.PHRASAL_INTENTS) or any(" ".join(p) in joined for p in lx.ROBOT_PHRASES)


def says_together(predicate: str) -> bool:
    """Whether a predicate says the people keep together ("walk together", "as a group")."""
    ws = words(predicate)
    return bool(set(ws) & lx.TOGETHER_WORDS) or any(" ".join(p) in " ".join(ws) for p in lx.TOGETHER_PHRASES)


def is_definite(phrase: str) -> bool:
    """"the nurses", "they", "everyone": people already there."""
    ws = words(phrase)
    return bool(ws) and (ws[0] in ("the", "this", "that", "these", "those", "our", "my", "their", "his", "her",
                                   "its") or ws[0] in PRONOUNS or ws[0] in EVERY_WORDS)


def is_indefinite(phrase: str) -> bool:
    """"a nurse", "two nurses", "some visitors": people introduced, not people already there."""
    ws = words(phrase)
    return bool(ws) and (ws[0] in ("a", "an", "another", "some", "several", "few", "many") or ws[0].isdigit()
                         or ws[0] in lx.NUMBER_WORDS)


def count_in(phrase: str, ctx: FollowupContext) -> int | None:
    """A head count stated in a subject ("ten visitors", "the two nurses"), else None."""
    ws = words(phrase)
    if not any(w.isdigit() or w in lx.NUMBER_WORDS or w in lx.VAGUE_RANGES for w in ws):
        return None
    reading = ctx.read(phrase + " wait")
    return reading.groups[0].count.value if reading.groups else None


def leading_number(phrase: str) -> tuple[int | None, str]:
    """"two of the nurses" -> (2, "the nurses"); "three visitors" -> (3, "visitors")."""
    m = re.match(rf"^({NUMBER_PATTERN})\s+(?:of\s+)?(.+)$", phrase)
    if m is None:
        return None, phrase
    value = number_of(m.group(1))
    return value, m.group(2)


def number_of(text: str) -> int | None:
    """A number in digits or words ("12", "twenty-one"), else None."""
    text = text.strip().replace("-", " ")
    if text.isdigit():
        return int(text)
    total = 0
    for w in text.split():
        if w in lx.UNITS:
            total += lx.UNITS[w]
        elif w in lx.TENS:
            total += lx.TENS[w]
        else:
            return None
    return total or None


def listed_phrases(text: str) -> list[str]:
    """The phrases of a list ("the cleaner, the guard and the nurses")."""
    return [p.strip() for p in re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", text) if p.strip()]


def has_people(text: str, ctx: FollowupContext) -> bool:
    """Whether the reader reads people in the words."""
    return bool(ctx.read(text).groups)
