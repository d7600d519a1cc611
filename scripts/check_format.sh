#!/usr/bin/env bash
# Fails when a tracked C++ file (or each FILE given) is not formatted as the repository's
# .clang-format says, with Debian's clang-format 14: the diff a reviewer would otherwise point out
# by hand. Prints each offending place; `clang-format-14 -i FILE` fixes it.
#
# usage: scripts/check_format.sh [--self-test] [FILE...]
#   --self-test  first shows that a misformatted file fails the check and a formatted one passes
set -euo pipefail
cd "$(dirname "$0")/.."
readonly style_file="$PWD/.clang-format"
clang_format=clang-format-14
command -v "$clang_format" > /dev/null || clang_format=clang-format

# Exit 0 when every file is formatted, 1 otherwise (clang-format's own messages say where).
check() {
  printf '%s\0' "$@" | xargs -0 "$clang_format" --style="file:$style_file" --dry-run --Werror
}

self_test() {
  local dir
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' RETURN
  # Two statements on a line, a 4-space indent and a missing space: three violations.
  printf 'int f(int x){\n    return x+1; }\n' > "$dir/bad.cpp"
  printf 'int f(int x) {\n  return x + 1;\n}\n' > "$dir/good.cpp"
  if check "$dir/bad.cpp" 2> "$dir/bad.log"; then
    echo "check_format self-test: FAILED, a misformatted file passed" >&2
    return 1
  fi
  if ! check "$dir/good.cpp"; then
    echo "check_format self-test: FAILED, a formatted file failed" >&2
    return 1
  fi
  echo "check_format self-test: a misformatted file fails ($(grep -c 'error:' "$dir/bad.log")" \
    "places reported, first at $(grep -m1 -o "bad.cpp:[0-9]*:[0-9]*" "$dir/bad.log")), a formatted one passes"
}

if [[ "${1:-}" == --self-test ]]; then
  shift
  self_test
fi
files=("$@")
if [[ ${#files[@]} -eq 0 ]]; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc')
fi
if check "${files[@]}"; then
  echo "check_format: ${#files[@]} C++ files formatted as .clang-format says"
else
  echo "check_format: files above are not formatted, clang-format-14 -i fixes them" >&2
  exit 1
fi
