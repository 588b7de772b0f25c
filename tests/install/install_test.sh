#!/usr/bin/env bash
# Installs the built tree into a temporary prefix (`cmake --install`) and runs the installed
# drycut on a program that calls a shipped cycle (CYCLE81): the binary must find the cycles under
# <prefix>/share/drycut/cycles, nothing from the build or source tree. Also checks the man page,
# docs, bash completion and --version. With --deb it builds the Debian package (CPack) instead
# and checks its contents.
#   install_test.sh CMAKE_COMMAND BUILD_DIR [--deb]
set -euo pipefail
cmake_cmd="$1"
build="$2"
mode="${3:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }

if [[ "$mode" == "--deb" ]]; then
  command -v dpkg-deb >/dev/null || { echo "dpkg-deb missing: skipped"; exit 77; }
  cpack_cmd="$(dirname "$cmake_cmd")/cpack"
  (cd "$work" && "$cpack_cmd" -G DEB --config "$build/CPackConfig.cmake" -B "$work/pkg" >"$work/cpack.log" 2>&1) ||
    { cat "$work/cpack.log"; fail "cpack -G DEB"; }
  deb="$(ls "$work"/pkg/*.deb)"
  contents="$(dpkg-deb -c "$deb")"
  for f in ./usr/bin/drycut ./usr/share/drycut/cycles/CYCLE81.SPF ./usr/share/man/man1/drycut.1 \
           ./usr/share/doc/drycut/README.md ./usr/share/bash-completion/completions/drycut; do
    grep -qF " $f" <<<"$contents" || fail "$f not in the package"
  done
  dpkg-deb -f "$deb" Package | grep -qx drycut || fail "package name"
  echo "package ok: $(basename "$deb")"
  exit 0
fi

prefix="$work/prefix"
"$cmake_cmd" --install "$build" --prefix "$prefix" >/dev/null
for f in bin/drycut share/drycut/cycles/CYCLE81.SPF share/man/man1/drycut.1 share/doc/drycut/README.md \
         share/doc/drycut/docs/guide.md share/bash-completion/completions/drycut; do
  [[ -e "$prefix/$f" ]] || fail "$f not installed"
done
grep -q "drycut profile" "$prefix/share/man/man1/drycut.1" || fail "man page lacks the subcommands"
"$prefix/bin/drycut" --version | grep -qE '^drycut [0-9.]+ \(.+\)$' || fail "--version: $("$prefix/bin/drycut" --version)"

# A program in a folder of its own calls the shipped CYCLE81 (drill from Z2 to Z-10).
mkdir "$work/job"
cat >"$work/job/DRILL.MPF" <<'MPF'
G17 G90 G94 F100
G0 X10 Y10 Z50
CYCLE81(50, 0, 2, -10)
M30
MPF
out="$(cd "$work/job" && "$prefix/bin/drycut" run DRILL.MPF 2>&1)" || { echo "$out"; fail "installed drycut run"; }
grep -q "time" <<<"$out" || fail "no summary: $out"
# The drill move is there: the path reaches Z-10.
(cd "$work/job" && "$prefix/bin/drycut" path DRILL.MPF --elements 2>&1) | grep -q -- "-10.000)" ||
  fail "the cycle's drill move is missing"
# The installed bash completion offers the subcommands and a subcommand's options.
completion="$(PATH="$prefix/bin:$PATH" bash -c '
  source "$1"
  COMP_WORDS=(drycut prof); COMP_CWORD=1; _drycut; echo "${COMPREPLY[*]}"
  COMP_WORDS=(drycut profile import --o); COMP_CWORD=3; _drycut; echo "${COMPREPLY[*]}"' _ \
  "$prefix/share/bash-completion/completions/drycut")"
[[ "$completion" == $'profile\n--output' ]] || fail "bash completion: $completion"
echo "install ok"
