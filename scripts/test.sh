#!/usr/bin/env bash
# Installs what is missing, builds, runs every test (gtest for the cores, rostest for the nodes)
# and prints a summary. Exits non-zero if any test fails or none ran.
set -euo pipefail
source "$(dirname "$0")/prepare.sh"
rm -rf _build/test_results
cmake --build _build --target tests -j"$(nproc)"
# run_tests keeps going past failures; the summary below decides.
cmake --build _build --target run_tests -j1 || true
exec /usr/bin/python3 scripts/test_summary.py _build/test_results
