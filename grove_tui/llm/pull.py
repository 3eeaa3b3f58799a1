"""`grove models pull`: fetch an official Qwen3 GGUF into models_dir(), verified, atomically.

This is the one place GROVE-TUI touches the network, and only when the user asks. The package sets
HF_HUB_OFFLINE=1 at import so no library phones home; that flag governs huggingface_hub's own
download functions, so pulling uses huggingface_hub only to build the official URL and fetches it
with a plain streaming HTTP GET. The endpoint is configurable (--endpoint, or HF_ENDPOINT as in
huggingface_hub) so mirrors work and tests can serve files from loopback.

Verification: the size must match the catalog and the server's announced size, the sha256 must match
the catalog or, where the catalog has none, the sha256 the Hub publishes for LFS files (X-Linked-Etag,
ETag), and the file must start with the GGUF magic. The download streams into a hidden file beside
the target and is renamed only after every check passed; on any failure nothing is left behind.
"""

from __future__ import annotations

import email.message
import hashlib
import os
import re
import tempfile
import urllib.error
import urllib.request
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import IO

from grove_tui.settings import models_dir
from grove_tui.errors import ModelError
from grove_tui.llm.gguf_info import GGUF_MAGIC

DEFAULT_ENDPOINT = "https://huggingface.co"
CHUNK_BYTES = 1 << 20
_SHA256 = re.compile(r"^[0-9a-f]{64}$")


@dataclass(frozen=True)
class CatalogEntry:
    name: str
    repo: str
    filename: str
    size: int
    sha256: str | None  # None: taken from the Hub's published LFS hash at download time
    description: str


# Official Qwen GGUF repositories (sizes from llm.md section 5; the Hub publishes each file's sha256).
CATALOG: dict[str, CatalogEntry] = {
    "qwen3-0.6b": CatalogEntry("qwen3-0.6b", "Qwen/Qwen3-0.6B-GGUF", "Qwen3-0.6B-Q8_0.gguf", 639_446_688, None,
                               "light model for RoI selection (the paper's local roi model)"),
    "qwen3-1.7b": CatalogEntry("qwen3-1.7b", "Qwen/Qwen3-1.7B-GGUF", "Qwen3-1.7B-Q8_0.gguf", 1_834_426_016, None,
                               "middle ground for slow machines"),
    "qwen3-4b": CatalogEntry("qwen3-4b", "Qwen/Qwen3-4B-GGUF", "Qwen3-4B-Q4_K_M.gguf", 2_497_280_256, None,
                             "stronger model for behavior-tree synthesis (the paper's local bt model)"),
}


class _NoRedirect(urllib.request.HTTPRedirectHandler):
    def redirect_request(self, req: urllib.request.Request, fp: IO[bytes], code: int, msg: str,
                         headers: email.message.Message, newurl: str) -> None:
        return None


def resolve_endpoint(endpoint: str | None = None) -> str:
    return (endpoint or os.environ.get("HF_ENDPOINT") or DEFAULT_ENDPOINT).rstrip("/")


def download_url(entry: CatalogEntry, endpoint: str | None = None, revision: str = "main") -> str:
    from huggingface_hub import hf_hub_url

    return hf_hub_url(entry.repo, entry.filename, revision=revision, endpoint=resolve_endpoint(endpoint))


def _published_hash_and_size(url: str, timeout: float) -> tuple[str | None, int | None]:
    """The Hub answers HEAD on a resolve URL with the LFS sha256 and size before redirecting to storage."""
    opener = urllib.request.build_opener(_NoRedirect)
    request = urllib.request.Request(url, method="HEAD", headers={"Accept-Encoding": "identity"})
    try:
        response = opener.open(request, timeout=timeout)
        headers = response.headers
        response.close()
    except urllib.error.HTTPError as error:
        if error.code in (301, 302, 303, 307, 308):
            headers = error.headers
        elif error.code in (401, 403, 404):
            raise ModelError(f"{url}: the server answered {error.code} {error.reason}") from None
        else:
            return None, None
    except (urllib.error.URLError, OSError):
        return None, None
    etag = (headers.get("X-Linked-Etag") or headers.get("ETag") or "").strip().strip('"').removeprefix("W/").strip('"')
    size_text = headers.get("X-Linked-Size") or headers.get("Content-Length")
    size = int(size_text) if size_text and size_text.isdigit() else None
    return (etag.lower() if _SHA256.match(etag.lower()) else None), size


def pull_model(name: str, dest_dir: Path | None = None, endpoint: str | None = None,
               catalog: dict[str, CatalogEntry] | None = None, force: bool = False,
               on_progress: Callable[[int, int], None] | None = None, timeout: float = 60.0) -> Path:
    """Download catalog model `name` into `dest_dir` (models_dir()) and return the verified file's path."""
    table = CATALOG if catalog is None else catalog
    entry = table.get(name)
    if entry is None:
        raise ModelError(f"unknown model {name!r}; available: {', '.join(table)}")
    folder = models_dir() if dest_dir is None else Path(dest_dir)
    target = folder / entry.filename
    if target.exists() and not force:
        if target.stat().st_size == entry.size:
            return target
        raise ModelError(f"{target} exists with {target.stat().st_size} bytes instead of {entry.size}; "
                         "pass --force to download it again")
    url = download_url(entry, endpoint)
    published_hash, published_size = _published_hash_and_size(url, timeout)
    expected_hash = entry.sha256 or published_hash
    if expected_hash is None:
        raise ModelError(f"{url}: the server publishes no sha256 for {entry.filename} and the catalog has none, "
                         "so the download could not be verified; not downloading")
    if published_size is not None and published_size != entry.size:
        raise ModelError(f"{url}: the server announces {published_size} bytes but {entry.name} has {entry.size}; "
                         "the repository changed or the mirror is wrong")
    folder.mkdir(parents=True, exist_ok=True)
    fd, staging_name = tempfile.mkstemp(prefix=f".{entry.filename}.", suffix=".part", dir=folder)
    staging = Path(staging_name)
    try:
        digest = hashlib.sha256()
        received = 0
        head = b""
        request = urllib.request.Request(url, headers={"Accept-Encoding": "identity", "User-Agent": "grove-tui"})
        try:
            with os.fdopen(fd, "wb") as out, urllib.request.urlopen(request, timeout=timeout) as response:
                while True:
                    block = response.read(CHUNK_BYTES)
                    if not block:
                        break
                    if len(head) < 4:
                        head += block[:4 - len(head)]
                    received += len(block)
                    if received > entry.size:
                        raise ModelError(f"{url}: the download is larger than the expected {entry.size} bytes; rejected")
                    digest.update(block)
                    out.write(block)
                    if on_progress is not None:
                        on_progress(received, entry.size)
                out.flush()
                os.fsync(out.fileno())
        except urllib.error.HTTPError as error:
            raise ModelError(f"{url}: the server answered {error.code} {error.reason}") from None
        except (urllib.error.URLError, TimeoutError, ConnectionError) as error:
            raise ModelError(f"cannot download {url}: {getattr(error, 'reason', error)}. Without a network, copy "
                             f"{entry.filename} from {entry.repo} into {folder} by hand") from None
        if received != entry.size:
            raise ModelError(f"{url}: received {received} bytes, expected {entry.size}; the download was incomplete and was removed")
        actual = digest.hexdigest()
        if actual != expected_hash:
            raise ModelError(f"{url}: sha256 {actual} does not match the expected {expected_hash}; "
                             "the download is corrupted and was removed")
        if head != GGUF_MAGIC:
            raise ModelError(f"{url}: the file is not a GGUF model (starts with {head!r}); removed")
        os.replace(staging, target)
    except BaseException:
        staging.unlink(missing_ok=True)
        raise
    return target
