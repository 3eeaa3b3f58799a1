"""What caught someone's eye or feelings, said by a participle set off before them (issue 29):
"Intrigued by the flashing LEDs, a toddler wobbles ...", "a boy, fascinated by the spinning wheels,
...". After "by" such a participle names what drew or stirred them, not a place beside which they are:
never a place of the world to read, nor one to refuse. A participle of position ("Seated by the window,
...") is not one of these, so "by" there stays a place."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs whose participle says what drew, caught or stirred someone: the "by" phrase is the cause.
_STIRRED = frozenset(
    "intrigue fascinate draw attract startle scare frighten puzzle amaze astonish distract charm delight "
    "captivate spook alarm unnerve worry bore annoy tempt lure surprise bemuse mesmerise mesmerize transfix "
    "enchant entrance excite thrill bewilder baffle confuse dazzle rattle irritate entice intimidate "
    "disturb upset terrify petrify impress enthral enthrall fluster panic spur prompt lure beguile".split())
_OPENERS = frozenset({",", ";", ":", ".", "(", "—", "–", "-", "and", "but"})


def caught_by(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k after "by" at `at` is what a set-off participle before it was stirred by."""
    if prep != "by" or at < 1 or k >= s.n:
        return False
    x = at - 1
    if verb_lemma(s.low[x]) not in _STIRRED and s.lemma(x) not in _STIRRED and s.w[x].lemma not in _STIRRED:
        return False
    x -= 1
    while x >= 0 and s.w[x].pos == "ADV":  # "Slightly puzzled by", "clearly intrigued by"
        x -= 1
    return x < 0 or s.low[x] in _OPENERS
