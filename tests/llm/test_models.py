"""Model discovery and roles, the embedded default, `grove models list`, and `grove models pull`
against an HF-style server on loopback (verified download, corrupted download rejected)."""

from __future__ import annotations

import hashlib
import http.server
import threading
from pathlib import Path

import pytest
from click.testing import CliRunner
from helpers.tiny_qwen3 import build_tiny_qwen3

from grove_tui.cli import main as grove
from grove_tui.llm import pull as pull_module
from grove_tui.llm.embedded import EMBEDDED_MODEL, embedded_model_path
from grove_tui.errors import ModelError
from grove_tui.llm.gguf_info import read_gguf_info
from grove_tui.llm.pull import CatalogEntry, pull_model
from grove_tui.errors import SettingsError
from grove_tui.llm.registry import list_models, resolve_models


@pytest.fixture()
def user_dirs(tmp_path, monkeypatch):
    for name in ("GROVE_DATA_DIR", "GROVE_CONFIG_DIR", "GROVE_CACHE_DIR"):
        monkeypatch.setenv(name, str(tmp_path / name.lower()))
    for name in ("GROVE_MODEL", "GROVE_ROI_MODEL", "GROVE_BT_MODEL", "HF_ENDPOINT"):
        monkeypatch.delenv(name, raising=False)
    return tmp_path


@pytest.fixture(scope="module")
def small_and_large(tmp_path_factory):
    folder = tmp_path_factory.mktemp("ggufs")
    small = build_tiny_qwen3(folder / "small.gguf", context_length=1024)
    large = build_tiny_qwen3(folder / "large.gguf", context_length=4096, chat_template="{{ messages }}" * 400)
    assert large.stat().st_size > small.stat().st_size
    return small, large


# ---- embedded default --------------------------------------------------------------------------

def test_embedded_model_is_a_real_gguf():
    info = read_gguf_info(embedded_model_path())
    assert info.supported and info.chat_template and info.size_bytes > 50_000_000
    assert EMBEDDED_MODEL == "smollm2" and (info.architecture, info.quantization) == ("llama", "Q4_1")


# ---- role resolution ---------------------------------------------------------------------------

def test_both_roles_default_to_the_embedded_model(user_dirs):
    choices = resolve_models()
    assert choices["roi"].path == choices["bt"].path == embedded_model_path()
    assert choices["bt"].source.startswith("embedded")


def test_models_directory_gives_the_smallest_to_roi_and_the_largest_to_bt(user_dirs, small_and_large):
    small, large = small_and_large
    folder = user_dirs / "grove_data_dir" / "models"
    folder.mkdir(parents=True)
    (folder / "a.gguf").write_bytes(small.read_bytes())
    (folder / "b.gguf").write_bytes(large.read_bytes())
    (folder / ".partial.gguf").write_bytes(b"GGUF")
    choices = resolve_models()
    assert (choices["roi"].path.name, choices["bt"].path.name) == ("a.gguf", "b.gguf")


def test_config_file_then_environment_then_command_line(user_dirs, small_and_large, monkeypatch):
    small, large = small_and_large
    config = user_dirs / "grove_config_dir"
    config.mkdir()
    (config / "config.yaml").write_text(f"models:\n  roi: {small}\n  bt: {large}\n")
    choices = resolve_models()
    assert (choices["roi"].path, choices["bt"].path) == (small, large)
    assert "config.yaml models.bt" in choices["bt"].source
    monkeypatch.setenv("GROVE_MODEL", str(small))
    assert resolve_models()["bt"].path == small
    monkeypatch.setenv("GROVE_BT_MODEL", str(large))
    choices = resolve_models()
    assert (choices["roi"].source, choices["bt"].source) == ("GROVE_MODEL", "GROVE_BT_MODEL")
    choices = resolve_models(cli_roi=str(large), cli_bt=None, cli_model=str(small))
    assert (choices["roi"].path, choices["roi"].source, choices["bt"].source) == (large, "--roi-model", "--model")


def test_an_explicit_bad_path_is_an_error_not_a_fallback(user_dirs, tmp_path, monkeypatch):
    with pytest.raises(ModelError, match="--bt-model: .*does not exist"):
        resolve_models(cli_bt=str(tmp_path / "missing.gguf"))
    text = tmp_path / "notes.gguf"
    text.write_text("hello")
    monkeypatch.setenv("GROVE_ROI_MODEL", str(text))
    with pytest.raises(ModelError, match="GROVE_ROI_MODEL: .*is not a GGUF model"):
        resolve_models()
    monkeypatch.delenv("GROVE_ROI_MODEL")
    config = user_dirs / "grove_config_dir"
    config.mkdir()
    (config / "config.yaml").write_text("models:\n  planner: x.gguf\n")
    with pytest.raises(SettingsError, match="models.planner: Extra inputs are not permitted"):
        resolve_models()


def test_models_list_shows_metadata_and_roles(user_dirs, small_and_large):
    small, _ = small_and_large
    folder = user_dirs / "grove_data_dir" / "models"
    folder.mkdir(parents=True)
    (folder / "tiny.gguf").write_bytes(small.read_bytes())
    found, choices = list_models()
    by_name = {model.path.name: model for model in found}
    assert by_name["tiny.gguf"].roles == ("roi", "bt")
    assert by_name["tiny.gguf"].info.architecture == "qwen3"
    assert by_name[embedded_model_path().name].roles == ()
    result = CliRunner().invoke(grove, ["--bt-model", str(embedded_model_path()), "models", "list"])
    assert result.exit_code == 0, result.output
    assert "qwen3" in result.output and "F32" in result.output and "1024" in result.output
    assert "Q4_1" in result.output and "8192" in result.output
    assert "bt: " + str(embedded_model_path()) in result.output.replace("\n", "")
    assert "from --bt-model" in result.output


# ---- pull against a loopback HF-style server ---------------------------------------------------

class _HubHandler(http.server.BaseHTTPRequestHandler):
    """Like the Hub: HEAD/GET on /{repo}/resolve/main/{file} answer 302 with the LFS sha256 and size,
    the storage URL serves the bytes."""

    files: dict[str, bytes] = {}
    published: dict[str, tuple[str | None, int]] = {}

    def log_message(self, *args) -> None:
        pass

    def _resolve(self, send_body: bool) -> None:
        name = self.path.rsplit("/", 1)[-1]
        if "/resolve/main/" in self.path:
            if name not in self.files:
                self.send_response(404)
                self.end_headers()
                return
            sha, size = self.published[name]
            self.send_response(302)
            if sha:
                self.send_header("X-Linked-Etag", f'"{sha}"')
            self.send_header("X-Linked-Size", str(size))
            self.send_header("Location", f"/storage/{name}")
            self.send_header("Content-Length", "0")
            self.end_headers()
            return
        body = self.files[name]
        self.send_response(200)
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        if send_body:
            self.wfile.write(body)

    def do_HEAD(self) -> None:  # noqa: N802
        self._resolve(False)

    def do_GET(self) -> None:  # noqa: N802
        self._resolve(True)


@pytest.fixture()
def hub(monkeypatch):
    for name in ("http_proxy", "https_proxy", "HTTP_PROXY", "HTTPS_PROXY", "all_proxy", "ALL_PROXY"):
        monkeypatch.delenv(name, raising=False)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), _HubHandler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    _HubHandler.files, _HubHandler.published = {}, {}
    yield f"http://127.0.0.1:{server.server_address[1]}", _HubHandler
    server.shutdown()
    server.server_close()


def _serve(handler, name: str, body: bytes, published_sha: str | None, published_size: int | None = None) -> None:
    handler.files[name] = body
    handler.published[name] = (published_sha, len(body) if published_size is None else published_size)


def _entry(payload: bytes, sha: str | None = None) -> dict[str, CatalogEntry]:
    return {"qwen3-test": CatalogEntry("qwen3-test", "Qwen/Qwen3-Test-GGUF", "Qwen3-Test-Q8_0.gguf", len(payload), sha, "test")}


def test_pull_downloads_verifies_and_writes_into_the_models_dir(user_dirs, hub, small_and_large):
    endpoint, handler = hub
    payload = small_and_large[0].read_bytes()
    _serve(handler, "Qwen3-Test-Q8_0.gguf", payload, hashlib.sha256(payload).hexdigest())
    progress: list[int] = []
    path = pull_model("qwen3-test", endpoint=endpoint, catalog=_entry(payload), on_progress=lambda got, total: progress.append(got))
    assert path == user_dirs / "grove_data_dir" / "models" / "Qwen3-Test-Q8_0.gguf"
    assert path.read_bytes() == payload and progress[-1] == len(payload)
    assert read_gguf_info(path).architecture == "qwen3"
    assert resolve_models()["bt"].path == path  # pulled models are picked up by the registry
    assert pull_model("qwen3-test", endpoint=endpoint, catalog=_entry(payload)) == path  # already there


def _leftovers(user_dirs: Path) -> list[str]:
    folder = user_dirs / "grove_data_dir" / "models"
    return sorted(p.name for p in folder.iterdir()) if folder.exists() else []


def test_a_corrupted_download_is_rejected_and_leaves_nothing(user_dirs, hub, small_and_large):
    endpoint, handler = hub
    payload = small_and_large[0].read_bytes()
    corrupted = payload[:1000] + bytes([payload[1000] ^ 0xFF]) + payload[1001:]
    _serve(handler, "Qwen3-Test-Q8_0.gguf", corrupted, hashlib.sha256(payload).hexdigest())
    with pytest.raises(ModelError, match="does not match the expected"):
        pull_model("qwen3-test", endpoint=endpoint, catalog=_entry(payload))
    assert _leftovers(user_dirs) == []


def test_catalog_hash_wins_over_the_servers(user_dirs, hub, small_and_large):
    endpoint, handler = hub
    payload = small_and_large[0].read_bytes()
    _serve(handler, "Qwen3-Test-Q8_0.gguf", payload, hashlib.sha256(payload).hexdigest())
    with pytest.raises(ModelError, match="does not match"):
        pull_model("qwen3-test", endpoint=endpoint, catalog=_entry(payload, sha="0" * 64))
    assert _leftovers(user_dirs) == []


@pytest.mark.parametrize("case", ["short body", "wrong announced size", "no published hash", "not gguf", "missing file"])
def test_bad_downloads_are_refused(user_dirs, hub, small_and_large, case):
    endpoint, handler = hub
    payload = small_and_large[0].read_bytes()
    body, sha, size, problem = payload, hashlib.sha256(payload).hexdigest(), None, ""
    if case == "short body":
        body, size, problem = payload[:-10], len(payload), "incomplete"
    elif case == "wrong announced size":
        size, problem = len(payload) + 1, "announces"
    elif case == "no published hash":
        sha, problem = None, "could not be verified"
    elif case == "not gguf":
        body = b"<html>" + payload[6:]
        sha, problem = hashlib.sha256(body).hexdigest(), "not a GGUF"
    elif case == "missing file":
        problem = "404"
    if case != "missing file":
        _serve(handler, "Qwen3-Test-Q8_0.gguf", body, sha, size)
    with pytest.raises(ModelError, match=problem):
        pull_model("qwen3-test", endpoint=endpoint, catalog=_entry(payload))
    assert _leftovers(user_dirs) == []


def test_pull_cli(user_dirs, hub, small_and_large, monkeypatch):
    endpoint, handler = hub
    payload = small_and_large[0].read_bytes()
    _serve(handler, "Qwen3-Test-Q8_0.gguf", payload, hashlib.sha256(payload).hexdigest())
    monkeypatch.setattr(pull_module, "CATALOG", {**pull_module.CATALOG, **_entry(payload)})
    result = CliRunner().invoke(grove, ["models", "pull", "qwen3-test", "--endpoint", endpoint])
    assert result.exit_code == 0, result.output
    assert "verified" in result.output and "100%" in result.output
    result = CliRunner().invoke(grove, ["models", "pull", "qwen9-huge"])
    assert result.exit_code != 0 and "qwen3-0.6b, qwen3-1.7b, qwen3-4b" in result.output


def test_pull_without_a_network_explains_what_to_do(user_dirs):
    payload = b"GGUF" + b"\0" * 60
    with pytest.raises(ModelError, match="cannot download|server answered"):
        pull_model("qwen3-test", endpoint="http://127.0.0.1:9", catalog=_entry(payload, sha="1" * 64), timeout=5)
    assert _leftovers(user_dirs) == []


def test_catalog_lists_the_official_qwen3_files():
    assert {name: (e.repo, e.filename, e.size) for name, e in pull_module.CATALOG.items()} == {
        "qwen3-0.6b": ("Qwen/Qwen3-0.6B-GGUF", "Qwen3-0.6B-Q8_0.gguf", 639_446_688),
        "qwen3-1.7b": ("Qwen/Qwen3-1.7B-GGUF", "Qwen3-1.7B-Q8_0.gguf", 1_834_426_016),
        "qwen3-4b": ("Qwen/Qwen3-4B-GGUF", "Qwen3-4B-Q4_K_M.gguf", 2_497_280_256),
    }
