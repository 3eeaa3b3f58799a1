"""Zones a sentence says are emptied, read with the place phrases (language/place_phrases.py): "the
cafeteria clears out", "the ticket hall has to be emptied", or whose own alarm goes off ("the café's
smoke alarm trips"). Everybody in them leaves, as in an evacuation."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.closed_zones import closing_end
from grove_tui.language.hazards import cue as hazard_cue
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, phrase_lemmas, verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place


class EmptiedZones:
    """The emptied-zone half of the place phrases: a mixin of PlacePhrases, which owns the sentence,
    its people and the zones read so far."""

    s: Sentence
    people: People
    context_zones: list[str]

    def passive_emptying(self, k: int) -> bool:
        """Whether the words from k say the subject before them is emptied: "(must|has to|is being)
        (be) cleared / emptied / vacated / evacuated"."""
        s = self.s
        j = k
        while j < s.n and j < k + 4 and (s.w[j].pos in ("AUX", "PART") or s.low[j] in ("to", "being", "be")
                                            or s.w[j].tag == "MD" or verb_lemma(s.low[j]) in ("have", "need")):
            j += 1
        return j > k and j < s.n and s.w[j].tag == "VBN" and verb_lemma(s.low[j]) in lx.ZONE_EMPTYING_VERBS

    def emptied_zones(self, tokens: Sequence[int]) -> list[Place]:
        """Zones that are the subject of an emptying verb used without an object: "the cafeteria
        clears out", "the whole boardroom empties into the corridor", "the kitchen empties in
        seconds". Everybody in them leaves (their start), as in an evacuation. "clear the tables"
        has an object and "the kitchen is clear" no verb: neither is one."""
        from grove_tui.language.place_phrases import Place  # the module that mixes this class in

        s = self.s
        out: list[Place] = []
        for i in tokens:
            emptied = self._emptied_subject_end(i) if s.low[i] not in ("'s", "’s") else self._hazard_owner_end(i)
            closing = closing_end(s, i) if emptied is None and s.low[i] not in ("'s", "’s") else None
            end = emptied if emptied is not None else closing
            if end is None:
                continue
            first = end
            while first > 0 and not s.is_punct(first - 1) and (
                    s.w[first - 1].pos in ("NOUN", "PROPN", "ADJ", "DET", "NUM")
                    or s.low[first - 1] in lx.PLACE_MODIFIERS) and s.low[first - 1] not in lx.CLAUSE_STARTERS:
                first -= 1
            words = tuple(s.low[first:end])
            lemmas = [t for t in phrase_lemmas(list(words)) if t not in lx.PLACE_MODIFIERS]
            match = s.index.match(lemmas) if lemmas else None
            if match is None or match.kind != "zone" or self.people.is_person_phrase(lemmas):
                continue
            if closing is not None and not match.exact:
                continue  # "when the clinic closes": the building's hours, not a room of it named
            self.context_zones.append(match.zone)
            out.append(Place("obj:start", first, words, match, end))
        return out

    def _hazard_owner_end(self, i: int) -> int | None:
        """The end of a zone that owns a hazard said right after it ("the common room's smoke detector
        trips", "the café's fire alarm goes off"): everybody in it leaves, as from an emptied zone."""
        return i if any(hazard_cue(self.s, k) for k in range(i + 1, min(i + 4, self.s.n))) else None

    def _emptied_subject_end(self, i: int) -> int | None:
        """The end of the subject an emptying verb at i empties, or None when it empties nothing."""
        s = self.s
        if i < 1 or verb_lemma(s.low[i]) not in lx.ZONE_EMPTYING_VERBS or s.low[i] == verb_lemma(s.low[i]):
            return None  # the base form is an imperative or infinitive ("clear the ward"), read elsewhere
        if s.w[i].tag == "VBN":
            # the passive, wherever it stands: "..., so the ticket hall has to be emptied"
            j = i - 1
            while j > 0 and (s.low[j] in ("be", "been", "being", "is", "are", "was", "were", "to", "has",
                                          "have", "had", "needs", "need", "got", "gets", "get")
                             or s.w[j].tag == "MD"):
                j -= 1
            return None if j == i - 1 else j + 1  # no auxiliary: "the emptied room"
        if s.w[i].pos == "VERB" or s.w[i].tag in ("VBZ", "VBD", "VBP", "NNS"):
            nxt = s.low[i + 1] if i + 1 < s.n else ""
            if nxt in lx.DETERMINERS or (nxt and s.index.knows(lemma(nxt)) and nxt != "out"):
                return None  # an object follows: "empties the bins"
            return i
        return None
