#!/usr/bin/env bash
# Installs the named Debian packages that are missing (apt-get, as root or with sudo); a no-op
# when all are present. Usage: scripts/apt_need.sh PACKAGE...
# Env: AGVBENCH_APT_UNSAFE_IO=1 lets dpkg skip its fsync after every file it unpacks
#      (--force-unsafe-io: a crash mid-install may leave a package to reinstall). .ci/run sets it:
#      its machines are thrown away after the run, and on a bare Debian 12 the syncs cost a
#      third of the installs' time.
set -euo pipefail
missing=()
for p in "$@"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null) || status=
  [[ $status == "install ok installed" ]] || missing+=("$p")
done
((${#missing[@]})) || exit 0
echo "apt_need: installing ${missing[*]}" >&2
start=$(date +%s)
if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
opts=(-o Acquire::Retries=3)  # a dropped connection to the mirror should not fail a CI run
[ "${AGVBENCH_APT_UNSAFE_IO:-0}" = 1 ] && opts+=(-o Dpkg::Options::=--force-unsafe-io)
install() { "${sudo[@]}" apt-get "${opts[@]}" install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; }
# Package lists fetched in the last hour (an earlier call of this script, say) are used as they
# are; if the install then fails, the lists are fetched again and it is tried once more.
lists=/var/lib/apt/lists
if [ -n "$(find "$lists" -maxdepth 1 -name '*_Packages*' -mmin -60 -print -quit 2>/dev/null)" ] &&
  install 2>/dev/null; then
  :
else
  "${sudo[@]}" apt-get "${opts[@]}" update -qq
  install
fi
echo "apt_need: installed ${#missing[@]} packages in $(($(date +%s) - start)) s" >&2
