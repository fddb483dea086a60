#!/usr/bin/env bash
# Installs the named Debian packages that are missing (apt-get, as root or with sudo); a no-op
# when all are present. Usage: scripts/apt_need.sh PACKAGE...
set -euo pipefail
missing=()
for p in "$@"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null) || status=
  [[ $status == "install ok installed" ]] || missing+=("$p")
done
((${#missing[@]})) || exit 0
echo "apt_need: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
retry=(-o Acquire::Retries=3)  # a dropped connection to the mirror should not fail a CI run
"${sudo[@]}" apt-get "${retry[@]}" update -qq
"${sudo[@]}" apt-get "${retry[@]}" install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
