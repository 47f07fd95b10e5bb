#!/usr/bin/env bash
# scripts/check-layout passes on this repository and fails on planted upward includes.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
check="$repo/scripts/check-layout"

"$check" "$repo" >/dev/null || { echo "FAIL: the repository itself breaks the layering"; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
expect_failure() { # DIR WHAT: check-layout must fail on DIR and name WHAT
  local out
  if out=$("$check" "$1" 2>&1); then echo "FAIL: check-layout accepted $2"; exit 1; fi
  grep -q "$2" <<<"$out" || { echo "FAIL: the message does not name $2: $out"; exit 1; }
}

mkdir -p "$tmp/up/geometry/scene"
printf '#pragma once\n#include "geometry/shadow/shadow_plan.h"\n' >"$tmp/up/geometry/scene/scene.h"
expect_failure "$tmp/up" "geometry/scene/scene.h:2"

mkdir -p "$tmp/gl/geometry/shadow" "$tmp/gl/renderer"
printf '#include "renderer/renderer.h"\n' >"$tmp/gl/geometry/shadow/warp.cpp"
expect_failure "$tmp/gl" "geometry/shadow/warp.cpp:1"

mkdir -p "$tmp/rel/renderer" "$tmp/rel/ui"
printf '#pragma once\n' >"$tmp/rel/ui/dashboard.h"
printf '#include "../ui/dashboard.h"\n' >"$tmp/rel/renderer/renderer.cpp"
expect_failure "$tmp/rel" "renderer/renderer.cpp:1"

mkdir -p "$tmp/imgui/geometry/analysis"
printf '#include <imgui.h>\n' >"$tmp/imgui/geometry/analysis/heatmap.cpp"
expect_failure "$tmp/imgui" "<imgui.h>"

mkdir -p "$tmp/lod/geometry/lod" "$tmp/lod/geometry/shadow"
printf '#pragma once\n' >"$tmp/lod/geometry/shadow/warp.h"
printf '#include "geometry/shadow/warp.h"\n' >"$tmp/lod/geometry/lod/caster_lod.cpp"
expect_failure "$tmp/lod" "geometry/lod/caster_lod.cpp:1"
mkdir -p "$tmp/lodgl/geometry/lod"
printf '#include <GL/gl.h>\n' >"$tmp/lodgl/geometry/lod/caster_lod.cpp"
expect_failure "$tmp/lodgl" "<GL/gl.h>"

mkdir -p "$tmp/ok/ui/charts" "$tmp/ok/app" "$tmp/ok/renderer"
printf '#include "geometry/lod/caster_lod.h"\n' >"$tmp/ok/renderer/renderer.cpp"
printf '#include "geometry/shadow/warp.h"\n#include <imgui.h>\n' >"$tmp/ok/ui/charts/chart.cpp"
printf '#include "ui/charts/chart.h"\n#include "renderer/renderer.h"\n' >"$tmp/ok/app/main.cpp"
"$check" "$tmp/ok" >/dev/null || { echo "FAIL: check-layout refused allowed includes"; exit 1; }
echo "check-layout test: ok"
