"""Places by meaning (language/meaning.py, PlaceIndex.by_meaning): where words do not decide, the
phrase is read against the world's names with the packaged MiniLM, run in numpy; absent places stay
refused; a place's own kind of person decides "her office"; reading never imports torch."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from grove_tui.language.meaning import MiniLM, PhraseVectors, model_dir
from grove_tui.language.model import UNSURE_BELOW
from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world
from helpers.paths import REPO


@pytest.mark.slow
def test_the_numpy_encoder_gives_sentence_transformers_vectors():
    from sentence_transformers import SentenceTransformer

    texts = ["big meeting room", "the ticket office windows", "a", "ten patients queue at the pharmacy counter "
             "and then walk slowly to the cafeteria for a coffee"]
    ours = MiniLM.shared().encode(texts)
    theirs = SentenceTransformer(str(model_dir()), device="cpu", local_files_only=True).encode(
        texts, normalize_embeddings=True)
    assert ours.dtype == np.float32 and ours.shape == theirs.shape
    assert np.abs(ours - theirs).max() < 1e-4


@pytest.mark.parametrize("world,prompt,field,want", [
    # an adjective no name has, before words several places share
    ("office", "Four engineers chat in the big meeting room.", "location", "boardroom"),
    ("office", "Two developers wait in the computer room.", "location", "server_room"),
    # a word the world has for another place, where the meaning is nearer one
    ("hospital", "Three visitors eat in the dining hall.", "location", "cafeteria"),
    # no word of the phrase names a place
    ("hospital", "A nurse walks to the storeroom.", "destination", "supply_room"),
    ("station", "A man buys a paper at the news stand.", "location", "newsagent"),
    # a thing's name inside a phrase headed by a word for rooms is the room
    ("museum", "A guard walks to the mummy gallery.", "destination", "egyptian_gallery"),
])
def test_places_words_do_not_decide_are_read_by_meaning(worlds, world, prompt, field, want):
    group = read_prompt(prompt, worlds[world]).groups[0]
    assert getattr(group, field) == want, group
    conf = group.confidence_of(field)
    assert conf is not None and conf.score < 1.0 and "meaning" in conf.reason


@pytest.mark.parametrize("world,place", [
    ("hospital", "swimming pool"), ("hospital", "chapel"), ("office", "bowling alley"), ("station", "observatory"),
    ("residential", "greenhouse"), ("museum", "helipad"), ("airport", "aquarium"),
])
def test_places_the_world_lacks_are_still_refused(worlds, world, place):
    reading = read_prompt(f"Five people walk to the {place}.", worlds[world])
    assert reading.unknown_places == (place,)


@pytest.mark.parametrize("world,prompt,field,want", [
    ("office", "The director paces around his office.", "location", "manager_office"),
    ("museum", "The curator waits in her office.", "location", "curator_office"),
    ("museum", "Two guards rest in their room.", "location", "security_office"),
    ("residential", "Two teenagers play in their room.", "location", "child_bedroom"),
    ("hospital", "Three nurses chat in their station.", "location", "nurse_station"),
    ("hospital", "The doctors walk from their office to the cafeteria.", "start", "doctors_office"),
])
def test_a_person_s_own_room_is_a_room_of_that_kind_of_person(worlds, world, prompt, field, want):
    group = read_prompt(prompt, worlds[world]).groups[0]
    assert getattr(group, field) == want, group
    conf = group.confidence_of(field)
    assert conf is None or conf.score >= UNSURE_BELOW


def test_a_world_s_name_vectors_are_kept_on_disk_and_a_torn_file_is_recomputed(tmp_path, monkeypatch):
    monkeypatch.setenv("GROVE_CACHE_DIR", str(tmp_path))
    model = MiniLM.shared()
    first = PhraseVectors(["ticket hall", "concourse", "waiting room"])
    vectors = first.vectors(model)
    assert first.path.is_file() and first.path.is_relative_to(tmp_path)
    again = PhraseVectors(["ticket hall", "concourse", "waiting room"])
    assert np.array_equal(again.vectors(model), vectors)
    first.path.write_bytes(b"torn")
    assert np.array_equal(PhraseVectors(["ticket hall", "concourse", "waiting room"]).vectors(model), vectors)
    assert PhraseVectors(["another", "world"]).path != first.path


@pytest.mark.slow
def test_reading_by_meaning_never_imports_torch():
    code = ("import sys\nfrom grove_tui.language.reading import read_prompt\nfrom grove_tui.world import load_world\n"
            "r = read_prompt('Four engineers chat in the big meeting room.', load_world('office'))\n"
            "assert r.groups[0].location == 'boardroom', r\nprint('torch' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"
