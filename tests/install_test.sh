#!/usr/bin/env bash
# `cmake --install` into a temporary prefix gives a binary that runs from another working directory,
# finds its resources relative to itself, and prints its version; `cpack -G DEB` (when asked: any
# second argument) builds a package holding it.
# Usage: install_test.sh BUILD_DIR [deb]
set -euo pipefail
build=$(cd "$1" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
unset SHADOWSCOPE_RESOURCES DISPLAY WAYLAND_DISPLAY
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
exe="$tmp/prefix/bin/shadowscope"
[ -x "$exe" ] || { echo "FAIL: no $exe"; exit 1; }
[ -f "$tmp/prefix/share/shadowscope/resources/presets/paper.json" ] || { echo "FAIL: presets not installed"; exit 1; }

mkdir "$tmp/elsewhere" && cd "$tmp/elsewhere"
version=$("$exe" --version)
[[ $version =~ ^shadowscope\ [0-9]+\.[0-9]+\ \(.+\)$ ]] || { echo "FAIL: --version printed '$version'"; exit 1; }

"$exe" render --backend osmesa --scene plane --size 96x64 --shadow-res 256 --out plane >/dev/null
[ -s plane/eye.png ] && [ -s plane/metrics.json ] || { echo "FAIL: render plane wrote nothing"; exit 1; }
# resources/... names resolve against the installed resources, not the working directory.
"$exe" render --backend osmesa --scene resources/scenes/plane.json --preset resources/presets/paper.json \
  --size 96x64 --shadow-res 256 --out paper >/dev/null
grep -q '"filter.type": "pcf"' paper/metrics.json || { echo "FAIL: the installed paper preset was not applied"; exit 1; }

if [ $# -ge 2 ]; then
  (cd "$tmp" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$tmp/deb" >/dev/null 2>&1)
  deb=$(ls "$tmp"/deb/*.deb)
  dpkg-deb -c "$deb" >"$tmp/contents"
  dpkg-deb -f "$deb" Depends >"$tmp/depends"
  grep -q "usr/bin/shadowscope$" "$tmp/contents" || { echo "FAIL: the package lacks usr/bin/shadowscope"; exit 1; }
  grep -q "presets/paper.json$" "$tmp/contents" || { echo "FAIL: the package lacks the presets"; exit 1; }
  grep -q "libosmesa6" "$tmp/depends" || { echo "FAIL: the package does not depend on OSMesa: $(cat "$tmp/depends")"; exit 1; }
fi
echo "install test: ok ($version)"
