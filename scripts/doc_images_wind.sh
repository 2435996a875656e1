#!/bin/sh
# Redraws docs/images/wind_{calm,breeze,strong}.png: quaking aspens on the volcano at
# t = 2 s, calm, in a breeze (speed 1.5, gust 1) and in a strong wind (speed 5, gust 3),
# one scenario and --set for the wind (docs/SPECIES.md "Wind").
set -eu
LANDSIM=${LANDSIM:-build/bin/landsim}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
cat > "$OUT/aspens.toml" <<TOML
[terrain]
elevation = "$(pwd)/data/terrain/volcano.asc"
[sun]
elevation = 40
azimuth = 220
[[species]]
bit = 0
file = "$(pwd)/data/species/quaking_aspen.toml"
variants = 3
density_per_ha = 60
cover = { rectangle = [50.0, 75.0, 90.0, 100.0] }
[[views]]
name = "v"
position = [70.0, 30.0, 110.0]
target = [70.0, 90.0, 118.0]
fov = 45
width = 480
height = 320
[render]
spp = 32
frames = [2.0]
TOML
for case in "calm 0 0" "breeze 1.5 1" "strong 5 3"; do
  set -- $case
  "$LANDSIM" render "$OUT/aspens.toml" --out "$OUT/$1" --set wind.speed="$2" --set wind.gust="$3" > /dev/null 2>&1
  cp "$OUT/$1/v.png" "docs/images/wind_$1.png"
done
