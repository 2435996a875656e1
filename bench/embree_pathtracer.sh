#!/bin/sh
# Renders the same geometry (bench/scenarios/bare_volcano.toml: the default scene's terrain)
# with landsim and with Embree's own reference path tracer (`pathtracer` from Debian's
# embree-tools, reading landsim's OBJ export), same size and samples, 2 threads, and prints
# both times. Run from the repository root after a Release build.
set -eu
command -v pathtracer > /dev/null || { echo "install embree-tools (apt-get install embree-tools)"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
build/bin/landsim render bench/scenarios/bare_volcano.toml --out "$tmp/landsim" --threads 2 --json 2> /dev/null \
  | sed 's/.*"seconds":\([0-9.]*\).*"rays_per_second":\([0-9.e+]*\).*/landsim: \1 s, \2 rays\/s/; s/.*"rays_per_second":\([0-9.e+]*\).*"seconds":\([0-9.]*\).*/landsim: \2 s, \1 rays\/s/'
cmd=$(build/bin/landsim export-obj bench/scenarios/bare_volcano.toml --out "$tmp/scene.obj" --flatten --frame scene --print-pathtracer 2> /dev/null)
start=$(date +%s.%N)
# Sun (22 degrees up, azimuth 285) as a distant light of the sun's 0.53 degree disc, sky as
# an ambient light, paths of up to 5 vertices like landsim's 4 bounces.
$cmd --spp 16 --threads 2 --max-path-length 5 --distantlight -0.9 0.24 -0.37 3 3 3 0.53 \
  --ambientlight 0.3 0.35 0.45 -o "$tmp/pathtracer.ppm" > /dev/null 2>&1
cp "$tmp/pathtracer.ppm" "${EMBREE_PPM_OUT:-/dev/null}" 2> /dev/null || true
end=$(date +%s.%N)
echo "embree pathtracer (parse OBJ, build, render, write): $(echo "$end - $start" | bc) s"
