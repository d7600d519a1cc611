#!/usr/bin/env bash
# Runs Debian's clang-tidy 14 with the repository's .clang-tidy over the C++ sources of src/ that a
# change touches (against a base, default origin/main or else main), or over all of them (--all).
# Fails on any finding (.clang-tidy makes every warning an error). A changed header is checked
# through the source of the same name under src/ and, by the header filter, through every source
# checked that includes it.
#
# It reads the compile commands of a configured build (scripts/build.sh exports them): the nodes'
# sources also need the generated message headers, so build once first.
#
# usage: scripts/clang_tidy.sh [--self-test] [--all | --base REF] [--build DIR] [-j N] [FILE...]
#   --self-test  first shows that a function over 80 lines and a needless copy fail, and a clean
#                file passes (needs no build); alone, only that
#   --all        every source under src/ (about 240 files: long, see docs/contributing.md)
#   --base REF   what the change is measured against (default origin/main, else main)
#   --build DIR  the build folder with compile_commands.json (default _build)
#   -j N         files checked at once (default 1)
#   FILE...      these sources instead
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
clang_tidy=clang-tidy-14
command -v "$clang_tidy" > /dev/null || clang_tidy=clang-tidy
# Only this repository's headers: the messages catkin generates into the build folder are not ours.
header_filter="^$root/(include/ari_social_sim/[a-z_]+|src)/"

self_test() {
  local dir
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' RETURN
  # 81 statements in a row: one over readability-function-size's 80 lines; a string taken by value
  # and only read: performance-unnecessary-value-param.
  {
    echo '#include <string>'
    echo 'int count(std::string text) { return static_cast<int>(text.size()); }'
    echo 'int long_function(int x) {'
    for i in $(seq 1 81); do echo "  x += $i;"; done
    echo '  return x;'
    echo '}'
  } > "$dir/bad.cpp"
  printf '#include <string>\nint count(const std::string& text) {\n  return static_cast<int>(text.size());\n}\n' \
    > "$dir/good.cpp"
  if "$clang_tidy" --quiet --config-file="$root/.clang-tidy" "$dir/bad.cpp" -- -std=c++17 \
    > "$dir/bad.log" 2>&1; then
    echo "clang_tidy self-test: FAILED, a bad file passed" >&2
    return 1
  fi
  local check
  for check in readability-function-size performance-unnecessary-value-param; do
    if ! grep -q "\[$check" "$dir/bad.log"; then
      echo "clang_tidy self-test: FAILED, $check not reported:" >&2
      cat "$dir/bad.log" >&2
      return 1
    fi
  done
  if ! "$clang_tidy" --quiet --config-file="$root/.clang-tidy" "$dir/good.cpp" -- -std=c++17 \
    > "$dir/good.log" 2>&1; then
    echo "clang_tidy self-test: FAILED, a clean file failed:" >&2
    cat "$dir/good.log" >&2
    return 1
  fi
  echo "clang_tidy self-test: a bad file fails ($(grep -o 'error: [^[]*\[[a-z-]*' "$dir/bad.log" |
    sed 's/.*\[//' | sort -u | tr '\n' ' ')reported), a clean one passes"
}

mode=changed
base=""
build=_build
jobs=1
ran_self_test=false
files=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --self-test) self_test; ran_self_test=true ;;
    --all) mode=all ;;
    --base) base="$2"; shift ;;
    --build) build="$2"; shift ;;
    -j) jobs="$2"; shift ;;
    -j[0-9]*) jobs="${1#-j}" ;;
    -*) echo "clang_tidy: unknown option $1" >&2; exit 2 ;;
    *) files+=("$1"); mode=files ;;
  esac
  shift
done
if [[ "$ran_self_test" == true && "$mode" == changed && -z "$base" ]]; then
  exit 0
fi

if [[ ! -f "$build/compile_commands.json" ]]; then
  echo "clang_tidy: $build/compile_commands.json not found: run scripts/build.sh first" >&2
  exit 2
fi
if [[ "$mode" == all ]]; then
  mapfile -t files < <(git ls-files 'src/*.cpp')
elif [[ "$mode" == changed ]]; then
  if [[ -z "$base" ]]; then
    base=main
    git rev-parse --verify --quiet origin/main > /dev/null && base=origin/main
  fi
  fork=$(git merge-base "$base" HEAD)
  # Committed and uncommitted changes since the branch left the base; deleted files are gone.
  mapfile -t changed < <(git diff --name-only --diff-filter=d "$fork" -- src include)
  for path in "${changed[@]}"; do
    case "$path" in
      src/*.cpp) files+=("$path") ;;
      include/ari_social_sim/*.hpp) source_file="src/${path#include/ari_social_sim/}" ;&
      src/*.hpp)
        source_file="${source_file:-$path}"
        [[ -f "${source_file%.hpp}.cpp" ]] && files+=("${source_file%.hpp}.cpp")
        source_file="" ;;
    esac
  done
  mapfile -t files < <(printf '%s\n' "${files[@]}" | sort -u | sed '/^$/d')
  echo "clang_tidy: ${#files[@]} sources changed since $base"
fi
if [[ ${#files[@]} -eq 0 ]]; then
  exit 0
fi
# clang's count of the warnings it computed in system headers, which clang-tidy then hides.
drop_counts() { grep -v '^[0-9]* warnings\? generated\.$' || true; }
start=$(date +%s)
# The Python module's flags (from pybind11) include GCC's -fno-fat-lto-objects, which clang lacks.
if printf '%s\0' "${files[@]}" | xargs -0 -n1 -P"$jobs" "$clang_tidy" --quiet -p "$build" \
  --header-filter="$header_filter" --extra-arg=-Wno-ignored-optimization-argument \
  2> >(drop_counts >&2); then
  echo "clang_tidy: ${#files[@]} sources clean ($(($(date +%s) - start)) s)"
else
  echo "clang_tidy: findings above ($(($(date +%s) - start)) s)" >&2
  exit 1
fi
