"""A count, a modifier the parser takes for a verb, a plural, then their own verb taken for a noun
(round 34): "Ten cub scouts bowl on the bumper lanes", "ten cub scouts pad to the pool". The parser
makes "cub" the verb of "ten", "scouts" its modifier and "bowl" its object, and the group of ten was
lost. A bare count, a word tagged a verb, a plural and a singular noun followed by a preposition, an
adverb, a comma or the end is a counted plural and its verb: "ten [cub scouts] [bowl] on ...". """

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word

_AFTER = frozenset({"ADP", "ADV", "PART", "PUNCT", "SCONJ", "CCONJ"})


def as_counted_modifiers(words: list[Word]) -> list[Word]:
    """The parse with a counted plural's modifier a noun and its verb a verb (module doc)."""
    out = list(words)
    for k in range(1, len(words) - 2):
        num, mod, plural, verb = words[k - 1], words[k], words[k + 1], words[k + 2]
        if num.pos != "NUM" or mod.pos != "VERB" or mod.tag not in ("VBP", "VB") or plural.tag != "NNS" or \
                verb.pos != "NOUN" or verb.tag != "NN" or not verb.lower.isalpha() or \
                len({num.sentence, mod.sentence, plural.sentence, verb.sentence}) != 1:
            continue
        if k - 2 >= 0 and words[k - 2].sentence == num.sentence and words[k - 2].pos not in ("DET", "PUNCT", "CCONJ", "ADV"):
            continue  # a count that is not the start of its phrase
        nxt = words[k + 3] if k + 3 < len(words) and words[k + 3].sentence == verb.sentence else None
        if nxt is not None and nxt.pos not in _AFTER:
            continue
        if any(x.pos in ("VERB", "AUX") and x.i > verb.i and x.sentence == verb.sentence and x.head == mod.i
               and x.dep not in ("conj",) for x in words):
            continue
        v = verb.i
        for j, x in enumerate(out):
            if x.head == mod.i and j not in (mod.i,):
                out[j] = replace(x, head=v)
        out[k - 1] = replace(out[k - 1], dep="nummod", head=plural.i)
        out[k] = replace(mod, pos="NOUN", tag="NN", lemma=mod.lower, dep="compound", head=plural.i)
        out[k + 1] = replace(out[k + 1], dep="nsubj", head=v)
        out[k + 2] = replace(verb, pos="VERB", tag="VBP", lemma=verb.lower, dep="ROOT", head=v)
        if mod.dep != "ROOT":  # "ten cub scouts bowl ..., two mums share nachos": the old root joins the verb
            for j, x in enumerate(out):
                if x.dep == "ROOT" and x.sentence == verb.sentence and j != v:
                    out[j] = replace(x, dep="conj", head=v)
    return out


def as_plural_verbs_before_a_clause(words: list[Word]) -> list[Word]:
    """"Six swimmers pad to the pool, a lifeguard watches": a plural the parser makes the modifier of a
    singular noun that hangs off a later clause's verb, that noun followed by a preposition: the
    plural's own verb, so the swimmers are read with it."""
    out = list(words)
    for k in range(1, len(words) - 2):
        plural, verb, nxt = words[k], words[k + 1], words[k + 2]
        if plural.tag != "NNS" or plural.dep != "compound" or plural.head != verb.i or verb.pos != "NOUN" or \
                verb.tag != "NN" or verb.dep not in ("dep", "nsubj", "appos", "ROOT") or not verb.lower.isalpha() or \
                nxt.pos != "ADP" or len({plural.sentence, verb.sentence, nxt.sentence}) != 1:
            continue
        before = words[k - 1]
        counted = before.pos == "NUM" or (k >= 2 and before.tag == "NN" and before.dep == "compound" and
                                          words[k - 2].pos == "NUM" and words[k - 2].sentence == plural.sentence)
        if before.sentence != plural.sentence or (before.pos not in ("NUM", "DET", "ADJ") and not counted):
            continue
        head = words[verb.head]
        if verb.dep == "ROOT":
            if not counted and not any(x.lower == "," and x.sentence == verb.sentence for x in words[verb.i + 1:]):
                continue  # "the swimmers pad to the pool." alone: read as before
        elif verb.head <= verb.i or head.pos not in ("VERB", "AUX") or \
                not any(x.lower == "," for x in words[verb.i + 1:verb.head]):
            continue  # only before a later clause of its own, after a comma
        out[k + 1] = replace(verb, pos="VERB", tag="VBP", lemma=verb.lower, dep="ROOT", head=verb.i)
        out[k] = replace(plural, dep="nsubj", head=verb.i)
        if verb.dep != "ROOT" and head.dep == "ROOT":
            out[verb.head] = replace(out[verb.head], dep="conj", head=verb.i)
        for j in range(k - 1, -1, -1):
            if words[j].sentence != plural.sentence:
                break
            if words[j].head == verb.i:
                out[j] = replace(out[j], head=plural.i)
    return out
