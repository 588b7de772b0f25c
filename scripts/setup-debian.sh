#!/usr/bin/env bash
# Installs what drycut needs to build and test, from Debian packages only (nothing is downloaded
# at build time). Safe to run again: installs only what is missing.
set -euo pipefail

packages=(cmake ninja-build g++ pkg-config
          libeigen3-dev nlohmann-json3-dev libspdlog-dev libfmt-dev libcli11-dev
          libgtest-dev libgmock-dev libbenchmark-dev
          libjs-three   # three.js, inlined into the HTML report for its 3D view
          help2man dpkg-dev)  # man page from --help; dpkg-shlibdeps for the .deb (CPack)
if [[ "${1:-}" == "--with-browser" ]]; then
  packages+=(chromium)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
