"""llama.cpp's OpenMP runtime must be tuned for llama.cpp, not inherit the package's passive wait.

The package sets OMP_WAIT_POLICY=PASSIVE for numba next to the UI. llama.cpp reads its OpenMP
settings once, when llama_cpp is first imported, so the model worker must set its own spin before
that import, and nothing the worker imports earlier may import llama_cpp.
"""

from __future__ import annotations

import json
import subprocess
import sys

from grove_tui.llm import worker


def run_fresh(code: str, env_extra: dict[str, str] | None = None) -> dict:
    import os

    env = {k: v for k, v in os.environ.items() if k not in ("GOMP_SPINCOUNT", "OMP_WAIT_POLICY")}
    env.update(env_extra or {})
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_the_model_modules_do_not_load_llama_cpp_on_import():
    # What the worker process imports before serve() runs: the package, models.* (to unpickle serve).
    seen = run_fresh(
        "import json, sys\n"
        "import grove_tui.llm.worker, grove_tui.llm.local, grove_tui.llm.registry\n"
        "import grove_tui.llm.chat_template, grove_tui.llm.embedded, grove_tui.llm.gguf_info\n"
        "maps = open('/proc/self/maps').read() if sys.platform.startswith('linux') else ''\n"
        "print(json.dumps({'llama_cpp': 'llama_cpp' in sys.modules, 'libgomp': 'libgomp' in maps}))"
    )
    assert seen == {"llama_cpp": False, "libgomp": False}


def test_the_worker_sets_a_short_spin_before_llama_cpp_loads():
    seen = run_fresh(
        "import json, os\n"
        "from grove_tui.llm.worker import tune_openmp_for_llama\n"
        "tune_openmp_for_llama()\n"
        "import llama_cpp\n"
        "print(json.dumps({'spin': os.environ.get('GOMP_SPINCOUNT'), 'policy': os.environ.get('OMP_WAIT_POLICY')}))"
    )
    assert seen["spin"] == worker.LLAMA_SPIN_COUNT
    assert seen["policy"] == "PASSIVE"  # the package's setting stays for everything else


def test_a_users_own_spin_setting_wins():
    seen = run_fresh(
        "import json, os\n"
        "from grove_tui.llm.worker import tune_openmp_for_llama\n"
        "tune_openmp_for_llama()\n"
        "print(json.dumps({'spin': os.environ.get('GOMP_SPINCOUNT')}))",
        {"GOMP_SPINCOUNT": "123"},
    )
    assert seen["spin"] == "123"
