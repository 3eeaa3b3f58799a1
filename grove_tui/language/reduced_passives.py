"""People taken somewhere by someone, said with a bare participle after them (round 71): "a baby carried
by her father to baggage claim", "an old lady pushed by her son heads to the café", "a patient, wheeled by
a porter, goes to radiology"; only verbs of moving someone who does not walk ("pushed", "carried"; not
"escorted by", "accompanied by": they walk). language/passive_escort.py reads the passive with "is"/"are"; with no
auxiliary the parser hangs the participle on the person as a clause describing them, and the taken
person was read walking on their own, or the taker lost. Said in the active ("her father carries a baby
to baggage claim", "her son pushes an old lady and heads to the café"), the taker walks and the taken
follow, as language/passive_order.py then puts back in the order said. Only when the taken person is
the subject, and the sentence's own verb, if any, is one of going somewhere ("an old lady pushed by her
son waits at the till" is left alone)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.passive_escort import _NOT_TAKERS, _ROUTE_WORDS, _span
from grove_tui.language.tokens import third_person, verb_lemma

# Verbs of moving someone who does not walk: "escorted", "accompanied", "helped by" someone, a person walks
# with them ("a defendant, accompanied by two guards, walks to the courtroom": the defendant walks).
_MOVING = frozenset("push wheel carry pull drag roll haul tow piggyback cradle transport ferry steer trundle".split())
_FINITE = frozenset({"VBZ", "VBP", "VBD"})
_GOING = frozenset({"walk", "evacuate"})
_TOWARDS = frozenset("to into towards toward onto through across up down over out".split())


def reduced_to_active(text: str, words: Sequence[Word]) -> str | None:
    """The text with a person "<verb>ed by <taker>" said as "<taker> <verb>s <person>" (module doc); None
    when there is none."""
    out = text
    for verb in sorted((w for w in words if w.tag == "VBN" and w.dep == "acl" and w.lemma in _MOVING),
                       key=lambda w: -w.i):
        found = _rewritten(text, words, verb)
        if found is not None:
            start, end, said = found
            out = out[:start] + said + out[end:]
    return None if out == text else out


def _rewritten(text: str, words: Sequence[Word], verb: Word) -> tuple[int, int, str] | None:
    taken = words[verb.head]
    if taken.i >= verb.i or taken.pos not in ("NOUN", "PROPN") or taken.dep not in ("nsubj", "ROOT") or \
            lx.PERSON_NOUNS.isdisjoint({taken.lemma, taken.lower}) and taken.pos != "PROPN" or \
            not _described(words, taken.i, verb.i):
        return None
    agent = words[verb.i + 1] if verb.i + 1 < len(words) else None
    if agent is None or agent.lower != "by":
        return None
    taker = next((w for w in words if w.head == agent.i and w.dep == "pobj"), None)
    verb_as_noun = taker is not None and taker.i > agent.i + 1 and words[taker.i - 1].dep == "compound" and \
        lx.INTENT_VERBS.get(verb_lemma(taker.lower)) in _GOING and verb_lemma(taker.lower) != taker.lower
    if verb_as_noun and taker is not None:
        taker = words[taker.i - 1]  # "by a volunteer heads for ...": the parser's compound noun is the taker and a verb
    if taker is None or taker.pos not in ("NOUN", "PROPN") or taker.lemma in _NOT_TAKERS or \
            lx.PERSON_NOUNS.isdisjoint({taker.lemma, taker.lower}) and taker.pos != "PROPN" and \
            taker.lemma not in lx.KIN_NAMES:
        return None
    first = taken.i
    while first > 0 and words[first - 1].dep not in ("advmod", "punct", "cc", "prep", "mark") and \
            _inside(words, first - 1, taken.i):
        first -= 1  # "an old lady", "two small kids": the words of the taken person's phrase
    _, taker_last = (0, taker.i) if verb_as_noun else _span(words, taker.i)
    taker_last = next((j - 1 for j in range(taker.i + 1, taker_last + 1)
                       if words[j].lower in _ROUTE_WORDS or words[j].lower in (",", "in", "on", "with")), taker_last)
    if taker_last < taker.i:
        return None
    sentence = [w for w in words if w.sentence == verb.sentence]
    last_word = sentence[-1]
    main = words[taker_last + 1] if verb_as_noun else \
        next((w for w in sentence if w.i > taker_last and w.tag in _FINITE and w.pos in ("VERB", "AUX")), None)
    opened = max((w.i for w in sentence if w.i < first and (w.lower in lx.CLAUSE_STARTERS or w.lower == ";")),
                 default=-1)
    if any(w.tag in _FINITE for w in sentence if opened < w.i < taken.i):
        return None  # "the robot passes a patient wheeled by a porter": the patient is its object
    singular = taker.tag in ("NN", "NNP") and not any(w.lower == "and" for w in words[agent.i + 1:taker_last + 1])
    taker_text = text[words[agent.i + 1].start:words[taker_last].end]
    taken_end = max((w.i for w in words[taken.i:verb.i] if w.lower != ","), default=taken.i)
    taken_text = text[words[first].start:words[taken_end].end]  # "a pupil with a broken leg"
    opening = first == sentence[0].i or words[first - 1].lower in (",", ";", ":")
    if opening:
        taker_text = taker_text[:1].upper() + taker_text[1:]
        if words[first].pos == "DET":
            taken_text = taken_text[:1].lower() + taken_text[1:]
    taking = third_person(verb.lemma) if singular else verb.lemma
    if main is None:
        rest = text[words[taker_last].end:last_word.end]
        return words[first].start, last_word.end, f"{taker_text} {taking} {taken_text}{rest}"
    intent = lx.INTENT_VERBS.get(verb_lemma(main.lower))
    if intent not in _GOING and not (intent is None and main.i + 1 < len(words) and words[main.i + 1].lower in _TOWARDS):
        return None  # "roll into the café": a way of going there
    if any(w.tag.startswith("VB") or w.lower in lx.CLAUSE_STARTERS for w in words[taker_last + 1:main.i]):
        return None
    between = text[words[taker_last].end:main.start].replace(",", " ")
    between = " ".join(between.split())
    going = third_person(verb_lemma(main.lower)) if singular else verb_lemma(main.lower)
    said = f"{taker_text} {taking} {taken_text}{' ' + between if between else ''} and {going}"
    return words[first].start, main.end, said


def _inside(words: Sequence[Word], k: int, head: int) -> bool:
    """Whether word k hangs, through its heads, on the word at `head`."""
    seen: set[int] = set()
    while k != head and k not in seen:
        seen.add(k)
        if words[k].head == k:
            return False
        k = words[k].head
    return k == head


def _described(words: Sequence[Word], taken: int, verb: int) -> bool:
    """Whether only commas and a "with" phrase describing the taken person ("a pupil with a broken leg,
    helped by ...") stand between them and the participle."""
    between = [w for w in words[taken + 1:verb] if w.lower != ","]
    return not between or (between[0].lower == "with" and between[0].head == taken and
                           all(_inside(words, w.i, taken) for w in between))
