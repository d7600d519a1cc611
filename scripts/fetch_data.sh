#!/usr/bin/env bash
# Fetches the public data sets that some tests and tools use (docs/data.md) into one folder:
# $ARI_DATA_DIR, by default ~/.local/share/ari_social_sim/data. Nothing the product needs by
# default is in them: without them the data-dependent tests are skipped, with the reason.
#
#   scripts/fetch_data.sh [--check] [SET ...]     SET: fformation, mpgt (default: both)
#
# Each set is downloaded into a temporary folder beside its place, every file is checked against
# the sha256 listed in scripts/data/SET.sha256, and only then is the folder moved into place, so a
# set that is there is complete. A set already there is checked again, not downloaded. --check
# only reports what is there. Prints each set's source and licence. Exit 0 when every set asked
# for is present and checked, 1 when one could not be fetched or failed its check, 2 on bad usage.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
data_dir="${ARI_DATA_DIR:-$HOME/.local/share/ari_social_sim/data}"

# MPGT (Addlesee et al., SIGDIAL 2023): the annotated conversations, as published.
readonly mpgt_source="https://raw.githubusercontent.com/AddleseeHQ/mpgt-eval/e32c2861993db9f22d1041df39be61ee11a8354d"
readonly mpgt_licence="MIT licence (its LICENSE file is fetched with it), cite Addlesee et al., SIGDIAL 2023"
# The F-formation recordings (Cristani et al., BMVC 2011) as GCFF distributes them, converted to CSV.
readonly fformation_source="https://raw.githubusercontent.com/vrichter/group-assignment-datasets/eeb630e0e2785f7a3ebd02eb460692ee9715a480/data/octave"
readonly fformation_licence="free for scientific research, cite Cristani et al., BMVC 2011 and Setti et al., PLOS ONE 2015"

usage() {
  echo "usage: scripts/fetch_data.sh [--check] [fformation] [mpgt]" >&2
  exit 2
}

folder_of() {
  case "$1" in
    fformation) echo "$data_dir/fformation" ;;
    mpgt) echo "$data_dir/dialogue/mpgt" ;;
  esac
}

# Checks every file listed for set $1 in folder $2; prints the first mismatch.
verify() {
  (cd "$2" && sha256sum --quiet --strict -c "$here/data/$1.sha256")
}

download() {
  curl --fail --silent --show-error --location --retry 2 --max-time 120 -o "$2" "$1"
}

fetch_mpgt() {
  local into="$1" file
  download "$mpgt_source/LICENSE" "$into/LICENSE"
  for file in $(awk '$2 ~ /^convo/ {print $2}' "$here/data/mpgt.sha256"); do
    download "$mpgt_source/Preprocessing/data/dialogues/dst-and-goals/$file" "$into/$file"
  done
}

fetch_fformation() {
  local into="$1" mat="$1/mat" sequence name
  for sequence in Synth CoffeeBreak/Seq1 CoffeeBreak/Seq2; do
    name="${sequence//\//_}"
    mkdir -p "$mat/$name"
    download "$fformation_source/$sequence/features.mat" "$mat/$name/features.mat"
    download "$fformation_source/$sequence/groundtruth.mat" "$mat/$name/groundtruth.mat"
    /usr/bin/python3 "$here/data/fformation_to_csv.py" "$mat/$name/features.mat" \
      "$mat/$name/groundtruth.mat" "$into" "$name"
  done
  rm -rf "$mat"
}

# Fetches set $1 unless it is there; returns non-zero when it cannot be had whole.
fetch() {
  local set="$1" folder partial source licence
  folder="$(folder_of "$set")"
  source="${set}_source"
  licence="${set}_licence"
  echo "$set: from ${!source}"
  echo "$set: licence: ${!licence}"
  if [[ -d "$folder" ]]; then
    verify "$set" "$folder" && { echo "$set: present and checked in $folder"; return 0; }
    echo "$set: $folder does not match scripts/data/$set.sha256 (move it away to fetch again)" >&2
    return 1
  fi
  if ((check_only)); then
    echo "$set: missing ($folder)"
    return 1
  fi
  mkdir -p "$(dirname "$folder")"
  partial="$(mktemp -d "$folder.partial.XXXXXX")"
  if "fetch_$set" "$partial" && verify "$set" "$partial"; then
    mv "$partial" "$folder"
    echo "$set: fetched and checked into $folder"
    return 0
  fi
  rm -rf "$partial"
  echo "$set: could not be fetched whole, nothing was left in $folder" >&2
  return 1
}

check_only=0
sets=()
for argument in "$@"; do
  case "$argument" in
    --check) check_only=1 ;;
    fformation) sets+=(fformation) ;;
    mpgt) sets+=(mpgt) ;;
    *) echo "fetch_data.sh: unknown argument '$argument'" >&2; usage ;;
  esac
done
((${#sets[@]})) || sets=(fformation mpgt)
if ((!check_only)); then
  packages=(curl python3-scipy)
  installer=fetch_data
  source "$here/apt_install.sh"
fi
status=0
for set in "${sets[@]}"; do
  fetch "$set" || status=1
done
exit "$status"
