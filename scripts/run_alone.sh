#!/usr/bin/env bash
# Runs a command as a user who has a clone of this repository and nothing else would: in a private
# mount namespace where the repository's parent folder holds nothing but the repository (no
# folder beside it is in sight), with HOME and ARI_DATA_DIR empty temporary folders (no data set,
# no ~/.ros). The repository keeps its path, so the build's own paths still hold. Needs root (a
# mount namespace); exit 3 when it cannot make one, else the command's exit code.
#
#   scripts/run_alone.sh COMMAND [ARG ...]      (run from anywhere; COMMAND runs in the repository)
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
parent="$(dirname "$repo")"
if [[ "$parent" == "/" ]]; then
  echo "run_alone.sh: the repository is at the file system's root (clone it into a folder)" >&2
  exit 3
fi
home="$(mktemp -d)"
data="$(mktemp -d)"
trap 'rm -rf "$home" "$data"' EXIT
# Inside: keep the repository at a second place, hide the parent under an empty tmpfs, and put
# the repository back at its own path.
hide_siblings='
  keep="$(mktemp -d)"
  mount --bind "$REPO" "$keep"
  mount -t tmpfs ari_alone "$(dirname "$REPO")"
  mkdir -p "$REPO"
  mount --bind "$keep" "$REPO"
  cd "$REPO"
  exec "$@"'
if ! unshare --mount --propagation private true 2>/dev/null; then
  echo "run_alone.sh: cannot make a private mount namespace (needs root)" >&2
  exit 3
fi
set +e
REPO="$repo" HOME="$home" ARI_DATA_DIR="$data" \
  unshare --mount --propagation private bash -c "$hide_siblings" run_alone "$@"
status=$?
exit "$status"
