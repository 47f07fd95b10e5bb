#!/usr/bin/env bash
# scripts/check-format fails on a badly formatted file a change touches, and passes once it is formatted.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
command -v clang-format >/dev/null || { echo "clang-format missing"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/scripts" "$tmp/geometry/scene"
cp "$repo/.clang-format" "$tmp/"
cp "$repo/scripts/check-format" "$tmp/scripts/"
cd "$tmp"
git init -q . && git config user.email t@t && git config user.name t
printf 'int   f( int x ){return x;}\n' >geometry/scene/a.cpp
git add -A && git commit -qm bad
if out=$(scripts/check-format 2>&1); then echo "FAIL: accepted an unformatted file: $out"; exit 1; fi
grep -q "geometry/scene/a.cpp" <<<"$out" || { echo "FAIL: did not name the file: $out"; exit 1; }
clang-format -i geometry/scene/a.cpp
scripts/check-format >/dev/null || { echo "FAIL: refused a formatted file"; exit 1; }
echo "check-format test: ok"
