"""The application layer's own rules: models once per role, inputs checked before any model loads."""

from __future__ import annotations

import pytest

from grove_tui.errors import BadInputError, OutputError, PromptError, WorldError
from grove_tui.services.session import GroveSession, ScenarioRequest


@pytest.mark.slow
def test_roles_naming_the_same_file_share_one_loaded_model():
    with GroveSession() as session:  # both roles default to the embedded model
        choices = session.model_choices()
        assert choices["roi"].path == choices["bt"].path
        models = session.load_models()
        assert models.roi is models.bt
        assert session.load_models() is models  # loaded once per session
        assert [status.loaded for status in session.model_status()] == [True, True]
    assert [status.loaded for status in session.model_status()] == [False, False]


@pytest.mark.parametrize(("request_", "error"), [
    (ScenarioRequest("hospital", "normal", "   "), PromptError),
    (ScenarioRequest("no_such_world", "normal", "two people walk"), WorldError),
])
def test_a_bad_request_is_refused_before_any_model_loads(tmp_path, request_, error):
    session = GroveSession()
    with pytest.raises(error):
        session.generate(request_, tmp_path / "bundle")
    assert session.model_status()[0].loaded is False
    assert not (tmp_path / "bundle").exists()


def test_a_folder_that_is_not_a_bundle_is_refused_before_any_model_loads(tmp_path):
    (tmp_path / "notes").mkdir()
    (tmp_path / "notes" / "thesis.tex").write_text("keep me", encoding="utf-8")
    session = GroveSession()
    with pytest.raises(OutputError):
        session.generate(ScenarioRequest("hospital", "normal", "two people walk"), tmp_path / "notes")
    assert session.model_status()[1].loaded is False
    assert (tmp_path / "notes" / "thesis.tex").read_text(encoding="utf-8") == "keep me"


def test_an_unknown_export_format_is_bad_input(tmp_path):
    with pytest.raises(BadInputError, match="unknown export format 'vrml'.*hunav, trajectories, rosbag, foxglove"):
        GroveSession().export("vrml", tmp_path, tmp_path / "out")
