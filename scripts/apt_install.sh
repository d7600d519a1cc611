# Sourced by install_deps.sh and install_extras.sh once they have set `packages` (Debian package
# names) and `installer` (their name, for messages): installs those that are missing, without
# recommends. Safe to run again: nothing is installed twice.
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "$installer: installing ${#missing[@]} missing packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
echo "$installer: all ${#packages[@]} packages present"
