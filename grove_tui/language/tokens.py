"""The one tokenizer-level helper set and the one lemmatiser of the product.

`lemma` turns a word into the form the lexicon and the world index use: nouns singular
("nurses" -> "nurse", "pharmacies" -> "pharmacy", "people" -> "person") and verbs to their base
("waiting" -> "wait", "queued" -> "queue", "ran" -> "run", "leaves" -> "leave"). Verb forms are
resolved against the lexicon's verbs, so a suffix rule never invents a word the lexicon does not
know ("waiting" stays "waiting" when asked as a noun for a place name, "wait" as a verb).
Sentence parsing (spaCy) is in language/parser.py; this module is plain Python so the world index
needs no model.
"""

from __future__ import annotations

import re
from functools import lru_cache

from grove_tui.language.particle_names import joined
from grove_tui.language.lexicon import (EVACUATION_PHRASES, HUMAN_SUBJECT_VERBS, INTENT_VERBS, LEADING_VERBS,
                                        PERSON_NOUNS, ROBOT_CROSS_VERBS, ROBOT_FOLLOW_VERBS, ROBOT_PATROL_VERBS,
                                        ROBOT_PHRASES, ROBOT_VERBS, ROBOT_WAIT_VERBS, STOPWORDS, UNITS,
                                        URGENT_EXIT_PHRASES, ZONE_EMPTYING_VERBS)

_IRREGULAR_NOUNS = {
    "people": "person", "persons": "person", "children": "child", "men": "man", "women": "woman",
    "staff": "staff", "feet": "foot", "teeth": "tooth", "mice": "mouse", "geese": "goose",
    "elderly": "elderly", "police": "police", "series": "series", "news": "news", "kids": "kid",
    "policemen": "policeman", "policewomen": "policewoman", "gentlemen": "gentleman", "ladies": "lady",
    "passersby": "passerby", "passers": "passerby", "others": "other", "stairs": "stairs", "ones": "one",
    "families": "family", "parties": "party",
}
_IRREGULAR_VERBS = {
    "ran": "run", "went": "go", "gone": "go", "came": "come", "left": "leave", "sat": "sit", "stood": "stand",
    "met": "meet", "made": "make", "got": "get", "saw": "see", "seen": "see", "took": "take", "led": "lead",
    "fled": "flee", "is": "be", "are": "be", "was": "be", "were": "be", "has": "have", "had": "have",
    "does": "do", "did": "do", "goes": "go", "lay": "lie", "hung": "hang", "kept": "keep", "read": "read",
}
_KEEP_S = ("ss", "us", "is", "ous", "sis", "ics")
_KNOWN_VERBS = frozenset(INTENT_VERBS) | frozenset(ROBOT_VERBS) | frozenset(
    "look keep stay step back shy steer move get stand line form hang catch have sit mill take lead see "
    "register check pick buy pay order collect drop fetch grab use wash print board eat drink work serve help tag "
    "clean guard patrol deliver carry push wheel bring drive fill sign book "
    # cries and starts of fright ("a patient shrieks and bolts"): verbs, though each has a plural noun
    "scream shriek yell yelp squeal wail gasp flinch bolt".split()) | ZONE_EMPTYING_VERBS | \
    ROBOT_WAIT_VERBS | ROBOT_PATROL_VERBS | ROBOT_FOLLOW_VERBS | ROBOT_CROSS_VERBS | LEADING_VERBS | HUMAN_SUBJECT_VERBS | frozenset(
    # the verbs that open the lexicon's multi-word phrases ("shrink back", "empty out", "get out")
    phrase[0] for phrase in (*ROBOT_PHRASES, *EVACUATION_PHRASES, *URGENT_EXIT_PHRASES) if phrase[0].isalpha()
    and phrase[0] not in ("in", "at", "the", "a"))


# Nouns ending in "-ie", whose plural is no "-y" word's: "selfies", "zombies", "techies".
_IE_NOUNS = frozenset("selfie zombie movie cookie hippie rookie goalie techie newbie foodie auntie roomie bookie "
                      "groupie yuppie smoothie".split())


@lru_cache(maxsize=8192)  # a reading asks for some two thousand lemmas of a few dozen words
def lemma(word: str) -> str:
    """Plural nouns to singular by rule; enough to match "nurses" to "nurse" and "pharmacies" to "pharmacy"."""
    w = word.lower()
    if w in _IRREGULAR_NOUNS:
        return _IRREGULAR_NOUNS[w]
    if len(w) > 8 and w.endswith("children"):
        return w[:-3]  # "schoolchildren" -> "schoolchild"
    if len(w) > 5 and w.endswith(("men", "women")) and w[:-3] + "man" in PERSON_NOUNS:
        return w[:-3] + "man"  # "businessmen", "firemen"
    if len(w) <= 3 or not w.endswith("s") or (w.endswith(_KEEP_S) and w[:-1] not in PERSON_NOUNS):
        return w  # "physics", "bus"; but "paramedics" is more than one paramedic
    if w.endswith("ies") and len(w) > 4:
        return w[:-1] if w[:-1] in _IE_NOUNS else w[:-3] + "y"  # "selfies", "zombies"; "families"
    if w.endswith(("ches", "shes", "xes", "zes", "sses")):
        return w[:-2]
    return w[:-1]


# "queue" misspelt: a "q", then only "u"s and "e"s, then a verb's ending or none.
_QUEUE_TYPO = re.compile(r"q([ue]{1,5})(?:ing|in|ed|d|s)?")


@lru_cache(maxsize=4096)
def verb_lemma(word: str) -> str:
    """The base form of a verb the lexicon knows ("queuing" -> "queue", "stares" -> "stare"); else `word`."""
    w = word.lower()
    if w in _IRREGULAR_VERBS:
        return _IRREGULAR_VERBS[w]
    if w in _KNOWN_VERBS:
        return w
    typo = _QUEUE_TYPO.fullmatch(w)
    if typo is not None and "u" in typo.group(1):
        return "queue"  # "queing", "qeueing", "queuin": "queue" misspelt, its vowels shuffled
    candidates: list[str] = []
    if w.endswith("ing") and len(w) > 4:
        stem = w[:-3]
        candidates += [stem, stem + "e"]
        if len(stem) > 2 and stem[-1] == stem[-2]:
            candidates.append(stem[:-1])  # "chatting" -> "chat"
        if stem.endswith("y"):
            candidates.append(stem[:-1] + "ie")  # "lying" -> "lie"
    if w.endswith("ed") and len(w) > 3:
        stem = w[:-2]
        candidates += [stem, stem + "e", w[:-1]]
        if len(stem) > 2 and stem[-1] == stem[-2]:
            candidates.append(stem[:-1])
        if stem.endswith("i"):
            candidates.append(stem[:-1] + "y")
    if w.endswith("s") and len(w) > 2:
        candidates += [w[:-1]]
        if w.endswith("es"):
            candidates.append(w[:-2])
        if w.endswith("ies"):
            candidates.append(w[:-3] + "y")
    for c in candidates:
        if c in _KNOWN_VERBS:
            return c
    return w


_WORD = re.compile(r"[a-z]&[a-z]\b|[a-z0-9]+(?:[,'][0-9]{3})*")  # "a&e" is one word, as the parser keeps it


def third_person(verb: str) -> str:
    """The present tense for one subject of a verb's base form, or of a phrase's first word: "takes",
    "pushes", "carries", "goes", "mans up"."""
    first, _, rest = verb.partition(" ")
    if first.endswith("y") and first[-2:-1] not in ("a", "e", "i", "o", "u", ""):
        first = first[:-1] + "ies"
    else:
        first += "es" if first.endswith(("ch", "sh", "s", "x", "z", "o")) else "s"
    return f"{first} {rest}" if rest else first


def words(text: str) -> list[str]:
    """Lowercased words and numbers of a text; hyphens split ("check-in" -> "check", "in")."""
    return _WORD.findall(text.lower().replace("-", " "))


def name_tokens(text: str) -> list[str]:
    """The lemmatised words of a world name or alias ("doctor's office" -> doctor, office)."""
    text = re.sub(r"'s\b", "", text.replace("_", " "))
    return phrase_lemmas(words(text))


# Stopwords that are a noun at the start of a place's name ("the still house", "the still room").
_NOUN_STOPWORDS = frozenset({"still"})


def phrase_lemmas(ws: list[str] | tuple[str, ...]) -> list[str]:
    """Lemmas of the words of a place phrase as names are indexed: stopwords out, except a single
    letter after the first word, which tells places apart ("ward a", "check-in counter b"), and a
    number word after it, read as its digits ("platform one" is "platform 1", not any platform), and
    "it" before another word, which is information technology there ("the IT room"), not a pronoun."""
    out: list[str] = []
    skip = 0
    for k, w in enumerate(ws):
        if k < skip or w == "-":
            continue  # "check-in": the hyphen is no word of the name
        if (one := joined(ws, k)) is not None:
            out.append(one[0])  # "make-up room": one word "makeup" (language/particle_names.py)
            skip = one[1]
        elif k > 0 and w in UNITS and UNITS[w] > 0:
            out.append(str(UNITS[w]))
        elif w == "it" and k + 1 < len(ws):
            out.append(w)
        elif w not in STOPWORDS or (k > 0 and len(w) == 1 and w.isalpha()) or \
                (k == 0 and w in _NOUN_STOPWORDS and len(ws) > 1 and ws[1] != "-"):  # "the still house": a name's word
            out.append(lemma(w))
    return out


# ---- crude stems for matching node-document phrases against a prompt (generation/retrieval.py) ----
# Deliberately cruder than `lemma`: both sides are stemmed the same way, so "queueing", "queued" and
# "queue" meet halfway; it never has to produce a real word.

MATCH_STOP_WORDS = frozenset(
    "a an the to of at in on into onto by for from with and or as is are be being was were it its their them "
    "they he she his her who that this these those some any each every all one two three four five six seven "
    "eight nine ten few several many while then than there here up down out over under about around near "
    "until when where which do does not no".split()
)
_MATCH_IRREGULAR = {"people": "person", "men": "man", "women": "woman", "children": "child", "kids": "kid",
              "feet": "foot", "lying": "lie", "left": "leave", "leaves": "leave", "stood": "stand"}
_MATCH_WORD = re.compile(r"[a-z0-9]+")


def match_stem(word: str) -> str:
    """Crude suffix stripping, applied identically to prompts and phrases so both meet halfway."""
    word = _MATCH_IRREGULAR.get(word, word)
    for suffix, keep in (("ies", "y"), ("ing", ""), ("ed", ""), ("es", ""), ("s", "")):
        if word.endswith(suffix) and len(word) - len(suffix) >= 3 and not word.endswith("ss"):
            word = word[: len(word) - len(suffix)] + keep
            break
    if len(word) > 3 and word[-1] == word[-2] and word[-1] not in "aeiouls":
        word = word[:-1]  # queueing/queued -> queu, running -> run
    return word.rstrip("e") if len(word) > 3 else word


def match_tokens(text: str) -> list[str]:
    """The content words of a text, lower-cased and stemmed for phrase matching."""
    return [match_stem(w) for w in _MATCH_WORD.findall(text.lower()) if w not in MATCH_STOP_WORDS]
