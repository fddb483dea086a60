#!/usr/bin/env bash
# scripts/apt_source_lines.sh on made-up apt configurations: deb-src lines for the release's own
# suites, from one-line and deb822 files alike, with their options and keyrings; other suites,
# comments, disabled stanzas and deb-src entries left out. Usage: test_apt_source_lines.sh SOURCE_DIR
set -u
src=${1:?usage: $0 SOURCE_DIR}
source "$(dirname "$0")/../cli/lib.sh"
etc=$PWD/etc
mkdir -p "$etc/sources.list.d"
cat >"$etc/sources.list" <<'LIST'
deb http://mirror.one.test/debian bookworm main contrib
# deb http://commented.test/debian bookworm main
deb-src http://already.test/debian bookworm main
deb [arch=amd64 signed-by=/k.gpg] http://mirror.two.test/debian-security bookworm-security main
deb https://vendor.test/apt cloud-sdk-bookworm main
LIST
cat >"$etc/sources.list.d/debian.sources" <<'SRC'
Types: deb
# a comment inside the stanza
URIs: http://mirror.three.test/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg

Types: deb
URIs: http://off.test/debian
Suites: bookworm
Components: main
Enabled: no

Types: deb
URIs: https://vendor.test/node
Suites: nodistro
Components: main
SRC
echo "deb http://ignored.test/debian bookworm main" >"$etc/sources.list.d/old.list.disabled"
cat >expected.txt <<'EXP'
deb-src http://mirror.one.test/debian bookworm main contrib
deb-src [arch=amd64 signed-by=/k.gpg] http://mirror.two.test/debian-security bookworm-security main
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://mirror.three.test/debian bookworm main
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://mirror.three.test/debian bookworm-updates main
EXP
if APT_ETC=$etc "$src/scripts/apt_source_lines.sh" bookworm >got.txt && diff -u expected.txt got.txt; then
  ok "deb-src lines from one-line and deb822 sources, the release's suites only"
else
  bad "deb-src lines differ from the expected ones"
fi
rm -f "$etc/sources.list" "$etc/sources.list.d/debian.sources"
if APT_ETC=$etc "$src/scripts/apt_source_lines.sh" bookworm >got.txt && [ ! -s got.txt ]; then
  ok "no Debian suite: no lines (sanitize.sh then stops with a message)"
else
  bad "lines printed without any Debian suite: $(cat got.txt)"
fi
finish test_apt_source_lines
