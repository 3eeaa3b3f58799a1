"""A verb after the "to" of a purpose is no place (issue 29): "wanders round to goods in to sign for a
pallet", "hurries to reception to collect her badge", "a nurse comes over to check it". The parser tags
the infinitive "to" TO and the bare verb after it VB, while the "to" of a place is a preposition (IN);
a word the parser reads so is what they go to do, never a place of the world to read, nor an unknown
one to refuse. The parser also tags place words so ("to gate B.", "to left luggage"), so a word the
world's places are called by is a verb only with a particle or an object that is no place ("to sign for
a pallet": "sign" of the sign-in desk; "to check it": "check" of the check-in kiosk). A word with a place's number after it or nothing at all
("to gate C4", "to gate.") is left to the place reader."""

from __future__ import annotations

from grove_tui.language.sentence import IDENTIFIER, Sentence

_OBJECT_PRONOUNS = frozenset("it them him her me us everyone everybody something".split())
# Words after a verb that no place's name goes on with ("to sign for a pallet", "to tidy up"); not "in":
# "go to check in" may mean the check-in desk.
_PARTICLES = frozenset("for on with about up off out over down after".split())


def infinitive_verb(s: Sentence, k: int, at: int) -> bool:
    """Whether the bare word at k, right after a "to" (the preposition at `at` or its last word), is the verb of
    an infinitive."""
    if not (0 <= at < k < s.n) or s.low[k - 1] != "to":  # "in to sign": "to" ends the preposition at `at`
        return False
    if k + 1 >= s.n or s.is_punct(k + 1) or any(IDENTIFIER.fullmatch(w) and not w.isalpha() for w in s.low[k + 1:k + 4]):
        return False  # "walk to gate C4", "to gate.": the parser's verb is a place's word, its number or nothing after
    if s.w[k - 1].tag != "TO" or s.w[k].tag != "VB":
        return False
    return not s.index.knows(s.low[k]) or s.low[k + 1] in _PARTICLES or _object_no_place(s, k)


def _object_no_place(s: Sentence, k: int) -> bool:
    """Whether the verb at k has an object that names no place: a pronoun ("check it", "check on them") or a
    noun it governs that no place of the world is called by ("check the robot"; not "gate B", "left luggage")."""
    nxt = k + 2 if s.low[k + 1] == "on" and k + 2 < s.n else k + 1
    if s.low[nxt] in _OBJECT_PRONOUNS:
        return True
    return any(s.w[x].dep in ("dobj", "pobj") and s.w[x].head in (k, k + 1) and s.w[x].pos == "NOUN"
               and not s.index.knows(s.low[x]) and not s.index.knows(s.lemma(x)) for x in range(k + 1, min(k + 5, s.n)))
