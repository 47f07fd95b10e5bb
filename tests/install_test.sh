#!/usr/bin/env bash
# `cmake --install` into a temporary prefix gives a binary that runs from another working directory,
# finds its resources relative to itself, and prints its version; `cpack -G DEB` (when asked: any
# second argument) builds a package holding it, and docs/ci.md's CI commands run against it.
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

  # docs/ci.md's CI lines (GitHub's `- run:` and GitLab's `script:` items), run verbatim against this
  # package in a scratch repository: tools/ holds the .deb, shadows/check.json one case. An apt-get
  # first on PATH unpacks the package into the scratch folder instead of the system.
  doc="$(dirname "$0")/../docs/ci.md"
  ci="$tmp/ci"
  mkdir -p "$ci/repo/tools" "$ci/repo/shadows" "$ci/bin"
  cp "$deb" "$ci/repo/tools/"
  cat >"$ci/repo/shadows/check.json" <<'JSON'
{ "cases": [ { "name": "plane", "scene": "plane", "size": "96x64", "set": { "shadow_map.resolution": 256 },
               "expect": { "aliasing.p95": { "min": 0 } } } ] }
JSON
  cat >"$ci/bin/apt-get" <<SHIM
#!/usr/bin/env bash
# stand-in for the test: 'update' does nothing; 'install -y FILE.deb...' unpacks each into $ci/root
[ "\$1" = update ] && exit 0
[ "\$1" = install ] || { echo "apt-get stand-in: only update and install" >&2; exit 100; }
shift; [ "\${1:-}" = -y ] && shift
[ \$# -ge 1 ] || { echo "apt-get stand-in: nothing to install" >&2; exit 100; }
for p in "\$@"; do
  [ -f "\$p" ] || { echo "E: Unsupported file \$p given on commandline" >&2; exit 100; }
  dpkg-deb -x "\$p" "$ci/root"
done
SHIM
  chmod +x "$ci/bin/apt-get"
  # The single-job examples of "Adding it to a CI job" (the sharded ones run GitHub's ${{ }} syntax).
  section=$(sed -n '/^## Adding it to a CI job/,/^## Spreading/p' "$doc")
  github=$(echo "$section" | sed -n '/^```yaml/,/^```$/p' | sed -n 's/^ *- run: //p')
  gitlab=$(echo "$section" | sed -n '/^  script:/,/^  [a-z]*:$/p' | sed -n 's/^    - //p')
  [ "$(echo "$github" | wc -l)" -ge 2 ] && [ "$(echo "$gitlab" | wc -l)" -ge 2 ] ||
    { echo "FAIL: found no CI commands in docs/ci.md"; exit 1; }
  for flavour in github gitlab; do
    rm -rf "$ci/root" "$ci/repo/shadow-report"
    while IFS= read -r line; do
      (cd "$ci/repo" && PATH="$ci/bin:$ci/root/usr/bin:$PATH" bash -euo pipefail -c "$line") >"$ci/log" 2>&1 ||
        { echo "FAIL: docs/ci.md ($flavour): '$line' failed:"; tail -5 "$ci/log"; exit 1; }
    done <<<"${!flavour}"
    grep -q '<testcase name="plane"' "$ci/repo/shadow-report/junit.xml" ||
      { echo "FAIL: docs/ci.md ($flavour) wrote no JUnit case"; exit 1; }
  done
fi
echo "install test: ok ($version)"
