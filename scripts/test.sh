#!/usr/bin/env bash
# Installs what is missing, builds, checks that install_deps.sh installs every Debian package the
# build and the tests use, runs every test (gtest for the cores, rostest for the nodes, pytest,
# and the main job on the repository alone) and prints a summary that names every skipped test
# and why. Exits non-zero if the build meets a warning, the dependency, documentation, path,
# warning or format check fails, any test fails or none ran. Tests that need a public data set run when it is in $ARI_DATA_DIR (docs/data.md).
set -euo pipefail
source "$(dirname "$0")/prepare.sh"
rm -rf _build/test_results
cmake --build _build --target tests -j"$(nproc)"
# The benchmarks (bench/) are not run here, only built: nothing else compiles them, and an API
# change that broke one (bench_navigation) went unnoticed.
cmake --build _build --target benchmarks -j"$(nproc)"
# After the test binaries are built, so that their headers and libraries count too. A package this
# machine happens to have but install_deps.sh does not install would break a fresh machine only;
# the self-test shows the check catches a removed entry (libnlopt-dev, ...). Fails the run.
/usr/bin/python3 scripts/check_deps.py --build _build --self-test
# README.md and docs/ name only what the repository has: relative links and their #anchors, paths
# under its folders, citations defined in docs/references.md; neither they nor any tracked source,
# config, message, launch or test file cites the private material the project was written from.
# The self-test first shows that a broken link, anchor, path, a pointer outside the repository and
# private citations in documents and source files are each caught. Two commands, not `a && b`:
# set -e does not stop the script when the left side of && fails.
/usr/bin/python3 scripts/check_docs.py --self-test
/usr/bin/python3 scripts/check_docs.py
# No tracked file names a path outside the repository (a folder beside the checkout, a home or
# build folder); the self-test first shows each kind is caught.
/usr/bin/python3 scripts/check_paths.py --self-test
# The project's own code compiles without warnings: the build above treats them as errors
# (ARI_WARNINGS_AS_ERRORS); the check confirms every source had -Werror, after its self-test shows
# a file with a warning fails to compile with the project's flags.
/usr/bin/python3 scripts/check_warnings.py --self-test
# Every tracked C++ file is formatted as .clang-format says (clang-format 14), after the self-test
# shows a misformatted file fails.
bash scripts/check_format.sh --self-test
# clang-tidy's self-test only: it takes up to a minute a source on a loaded machine, hours over all
# of src/ (docs/contributing.md); run scripts/clang_tidy.sh on a change before its merge.
bash scripts/clang_tidy.sh --self-test
# Which public data sets are here (docs/data.md): tests that need a missing one are skipped and
# named in the summary; CI (ARI_REQUIRE_DATA_SETS=1) has them all and refuses such skips.
bash scripts/fetch_data.sh --check || true
# run_tests keeps going past failures; the summary below decides.
cmake --build _build --target run_tests -j1 || true
# The README's main job on the repository alone (no folder beside it, no data set), after its
# self-test shows that a path beside the repository is hidden; a JUnit result the summary counts.
/usr/bin/python3 scripts/check_alone.py --build _build \
  --junit _build/test_results/ari_social_sim/repository-alone.xml || true
summary_options=()
if [[ "${ARI_REQUIRE_DATA_SETS:-0}" == 1 ]]; then
  summary_options+=(--refuse-data-skips)
fi
exec /usr/bin/python3 scripts/test_summary.py "${summary_options[@]}" _build/test_results
