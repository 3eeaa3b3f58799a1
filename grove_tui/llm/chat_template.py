"""Chat prompts rendered from the GGUF's own `tokenizer.chat_template`, Qwen3 in non-thinking mode.

Qwen3 must not think under a grammar: the grammar constrains from the first generated token, so a
model that wants to open `<think>` fights it. The switch is in the template (`enable_thinking=False`
appends an empty think block); `/no_think` in the text is not enough. Qwen3-4B-Instruct-2507 never
thinks and its template has no such switch, so nothing is appended there.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from grove_tui.errors import ModelError

QWEN3_EMPTY_THINK = "<think>\n\n</think>\n\n"
QWEN3_ASSISTANT_START = "<|im_start|>assistant\n"
# Used only when a GGUF carries no template (base models converted without one).
PLAIN_TEMPLATE = (
    "{% for message in messages %}{{ message['role'] | capitalize }}: {{ message['content'] }}\n\n{% endfor %}"
    "{% if add_generation_prompt %}Assistant: {% endif %}"
)


@dataclass(frozen=True)
class Sampling:
    temperature: float
    top_p: float
    top_k: int
    min_p: float
    presence_penalty: float


# Qwen3 model cards, non-thinking mode; presence_penalty 1.5 as in Qwen's GGUF cards.
QWEN3_NON_THINKING = Sampling(temperature=0.7, top_p=0.8, top_k=20, min_p=0.0, presence_penalty=1.5)
# Models under ~1B parameters wander at Qwen's temperature; a grammar keeps them valid, this keeps them on topic.
TINY_MODEL = Sampling(temperature=0.2, top_p=0.9, top_k=20, min_p=0.05, presence_penalty=0.0)
DEFAULT = Sampling(temperature=0.5, top_p=0.9, top_k=40, min_p=0.05, presence_penalty=0.0)
TINY_MODEL_BYTES = 700 * 1024 * 1024


def default_sampling(architecture: str, size_bytes: int) -> Sampling:
    """Sampling settings for a model: Qwen's non-thinking values for Qwen3 beyond tiny sizes."""
    if size_bytes < TINY_MODEL_BYTES:
        if architecture in ("qwen3", "qwen3moe"):
            return Sampling(temperature=0.3, top_p=0.8, top_k=20, min_p=0.0, presence_penalty=1.5)
        return TINY_MODEL
    if architecture in ("qwen3", "qwen3moe"):
        return QWEN3_NON_THINKING
    return DEFAULT


def template_supports_thinking_switch(template: str) -> bool:
    return "enable_thinking" in template


def render_chat(template: str | None, messages: Sequence[dict[str, str]], *, bos_token: str, eos_token: str,
                architecture: str) -> str:
    """The prompt text for `messages`, ending where the assistant's reply starts."""
    for index, message in enumerate(messages):
        if not isinstance(message, dict) or set(message) - {"role", "content"} or "role" not in message:
            raise ModelError(f"chat message {index} must be a dict with 'role' and 'content', got {message!r}")
    # Imported here: importing llama_cpp loads llama.cpp and its OpenMP runtime, which reads its
    # settings once; the model worker tunes them first (worker.tune_openmp_for_llama).
    from llama_cpp.llama_chat_format import Jinja2ChatFormatter

    formatter = Jinja2ChatFormatter(template=template or PLAIN_TEMPLATE, eos_token=eos_token, bos_token=bos_token)
    try:
        prompt = formatter(messages=list(messages), enable_thinking=False).prompt  # type: ignore[arg-type]  # plain role/content dicts are llama_cpp's TypedDicts
    except Exception as error:  # a template is user data: any Jinja failure is a problem with the file
        raise ModelError(f"the model's chat template failed to render: {error}") from None
    if (architecture in ("qwen3", "qwen3moe") and template and template_supports_thinking_switch(template)
            and prompt.endswith(QWEN3_ASSISTANT_START)):
        # Some Qwen3 template revisions ignore the flag when rendered outside transformers.
        prompt += QWEN3_EMPTY_THINK
    return prompt
