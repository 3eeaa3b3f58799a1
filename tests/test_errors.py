"""The one error vocabulary: every error carries its title, hint and exit code; one printer shows them."""

from __future__ import annotations

import ast
import inspect
import io
from pathlib import Path

import pytest

from grove_tui import errors
from grove_tui.errors import (
    EXIT_BAD_INPUT,
    EXIT_CANCELLED,
    EXIT_MODEL_ERROR,
    EXIT_RUNTIME_FAILURE,
    BadInputError,
    Cancelled,
    GroveError,
    ModelError,
    RuntimeFailure,
    describe_error,
    print_error,
)

PACKAGE = Path(errors.__file__).resolve().parent
CATEGORIES = {BadInputError: EXIT_BAD_INPUT, RuntimeFailure: EXIT_RUNTIME_FAILURE, ModelError: EXIT_MODEL_ERROR,
              Cancelled: EXIT_CANCELLED}


def _error_classes() -> list[type[GroveError]]:
    return [value for value in vars(errors).values()
            if inspect.isclass(value) and issubclass(value, GroveError) and value is not GroveError]


@pytest.mark.parametrize("cls", _error_classes(), ids=lambda cls: cls.__name__)
def test_every_error_belongs_to_one_category_and_carries_its_exit_code_and_title(cls):
    categories = [category for category in CATEGORIES if issubclass(cls, category)]
    assert len(categories) == 1, f"{cls.__name__} is in {categories}"
    assert cls.exit_code == CATEGORIES[categories[0]]
    assert cls.title and cls.__doc__


def test_scenario_error_is_a_grove_error_and_not_a_plain_value_error():
    assert issubclass(errors.ScenarioError, BadInputError)
    assert not issubclass(errors.ScenarioError, ValueError)


def test_the_modules_that_raise_an_error_re_export_the_same_class():
    from grove_tui.generation.presets import GenerationError, PromptError
    from grove_tui.errors import ModelError as LlmModelError
    from grove_tui.scenario.model import ScenarioError
    from grove_tui.world import WorldError

    assert (PromptError, GenerationError, ScenarioError, WorldError, LlmModelError) == (
        errors.PromptError, errors.GenerationError, errors.ScenarioError, errors.WorldError, errors.ModelError)


def _bridges_a_library_error(node: ast.ClassDef) -> bool:
    """A class deriving from an errors.py class and from an optional library's own error (gymnasium's
    InvalidAction), so code catching either catches it: it lives where that library is imported, and
    keeps the errors.py class's title, hint and exit code."""
    def root(base: ast.expr) -> str:
        while isinstance(base, ast.Attribute):
            base = base.value
        return getattr(base, "id", "")

    names = {getattr(base, "id", "") for base in node.bases}
    return any(root(base) == "gymnasium" for base in node.bases) and bool(names & set(dir(errors)))


def test_no_module_outside_errors_defines_its_own_public_exception():
    # One vocabulary: an exception class elsewhere would miss the title, hint and exit code.
    offenders = []
    for path in PACKAGE.rglob("*.py"):
        if path.name == "errors.py" and path.parent == PACKAGE:
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ClassDef) and not node.name.startswith("_") and not _bridges_a_library_error(node):
                bases = {getattr(base, "id", getattr(base, "attr", "")) for base in node.bases}
                if bases & {"Exception", "ValueError", "RuntimeError", "GroveError"} or node.name.endswith("Error"):
                    offenders.append(f"{path.relative_to(PACKAGE)}:{node.lineno} {node.name}")
    assert offenders == []


def test_describe_error_gives_one_line_with_the_hint_and_the_exit_code():
    error = errors.WorldError("hospital.yaml: zones[0].doors[1].width: must be positive\nzones[2]: unknown key 'nme'")
    description = describe_error(error)
    assert description.exit_code == EXIT_BAD_INPUT
    assert "\n" not in description.line
    assert description.line.startswith("error: hospital.yaml: zones[0].doors[1].width: must be positive; zones[2]")
    assert "grove worlds check" in description.line


def test_an_instance_hint_overrides_the_class_hint():
    assert describe_error(errors.PromptError("too many", hint="lower the counts")).hint == "lower the counts"
    assert describe_error(errors.PromptError("too many")).hint == errors.PromptError.hint


def test_print_error_writes_one_line_and_returns_the_exit_code():
    stream = io.StringIO()
    assert print_error(ModelError("qwen.gguf: not a GGUF file"), file=stream) == EXIT_MODEL_ERROR
    lines = stream.getvalue().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: qwen.gguf: not a GGUF file")


def test_keyboard_interrupt_is_cancelled_and_an_unexpected_exception_is_a_runtime_failure():
    assert describe_error(KeyboardInterrupt()).exit_code == EXIT_CANCELLED
    unexpected = describe_error(ZeroDivisionError("division by zero"))
    assert unexpected.exit_code == EXIT_RUNTIME_FAILURE
    assert unexpected.message == "ZeroDivisionError: division by zero" and "bug" in unexpected.hint
