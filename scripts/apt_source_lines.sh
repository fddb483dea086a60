#!/usr/bin/env bash
# Prints one-line `deb-src` entries for the Debian suites this machine's apt already uses: read
# from /etc/apt/sources.list and /etc/apt/sources.list.d/*.list (one-line format) and
# /etc/apt/sources.list.d/*.sources (deb822), so a source download goes to whatever mirror the
# machine is set up with, never to a host written into a script. Only entries of the release's
# own suites (CODENAME, CODENAME-updates, CODENAME-security, ...) are kept: a third-party
# repository on the machine may publish no sources, and apt-get update would fail on it.
# Usage: scripts/apt_source_lines.sh [CODENAME]   (default: VERSION_CODENAME of /etc/os-release)
# Env:   APT_ETC (default /etc/apt; for tests)
set -euo pipefail
codename=${1:-$(. /etc/os-release && echo "$VERSION_CODENAME")}
etc=${APT_ETC:-/etc/apt}

one_line_files=()
[ -f "$etc/sources.list" ] && one_line_files+=("$etc/sources.list")
for f in "$etc"/sources.list.d/*.list; do [ -f "$f" ] && one_line_files+=("$f"); done
deb822_files=()
for f in "$etc"/sources.list.d/*.sources; do [ -f "$f" ] && deb822_files+=("$f"); done

{
  if ((${#one_line_files[@]})); then
    # deb [opts] URI SUITE COMPONENT...  ->  deb-src [opts] URI SUITE COMPONENT...
    awk -v cn="$codename" '
      { sub(/#.*/, "") }
      $1 == "deb" {
        opts = ""; i = 2
        if ($2 ~ /^\[/) { while (i <= NF && $i !~ /\]$/) { opts = opts $i " "; i++ } opts = opts $i " "; i++ }
        suite = $(i + 1)
        if (suite != cn && index(suite, cn "-") != 1) next
        line = "deb-src " opts $i " " suite
        for (j = i + 2; j <= NF; j++) line = line " " $j
        print line
      }' "${one_line_files[@]}"
  fi
  if ((${#deb822_files[@]})); then
    # One stanza per blank-line-separated block; a stanza with Types including deb gives one
    # line per (URI, suite).
    awk -v cn="$codename" '
      function flush(   u, s, nu, ns, uris, suites, opts) {
        if (types ~ /(^| )deb( |$)/ && uri != "" && suite != "") {
          opts = (signed != "") ? "[signed-by=" signed "] " : ""
          nu = split(uri, uris, " "); ns = split(suite, suites, " ")
          for (u = 1; u <= nu; u++)
            for (s = 1; s <= ns; s++)
              if (suites[s] == cn || index(suites[s], cn "-") == 1)
                print "deb-src " opts uris[u] " " suites[s] " " comps
        }
        types = uri = suite = comps = signed = ""
      }
      BEGIN { flush() }
      /^[ \t]*#/ { next }
      /^[ \t]*$/ { flush(); next }
      {
        key = tolower($1); val = $0; sub(/^[^:]*:[ \t]*/, "", val); sub(/[ \t]+$/, "", val)
        if (key == "types:") types = val
        else if (key == "uris:") uri = val
        else if (key == "suites:") suite = val
        else if (key == "components:") comps = val
        else if (key == "signed-by:") signed = val
        else if (key == "enabled:" && tolower(val) == "no") types = ""
      }
      END { flush() }' "${deb822_files[@]}"
  fi
} | awk '!seen[$0]++'
