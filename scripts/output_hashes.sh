#!/bin/sh
# Hashes of everything landsim makes from the repository's examples: each example species'
# tree (OBJ and --json report), each example scene's images (EXR, 1 spp, 320 pixels wide),
# its info and degradation reports. A refactoring that must not change output compares the
# list before and after (issue 17):
#   sh scripts/output_hashes.sh > before.txt   # on the old build
#   sh scripts/output_hashes.sh > after.txt && diff before.txt after.txt
set -eu
LANDSIM=${LANDSIM:-build/bin/landsim}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
for species in data/species/*.toml data/species/*.xml; do
  name=$(basename "$species")
  "$LANDSIM" tree "$species" --seed 7 --obj "$OUT/tree.obj" --json |
    sed 's/"[a-z_]*_ms":[0-9.e+-]*,\{0,1\}//g' > "$OUT/tree.json"  # timings vary
  echo "$(sha256sum < "$OUT/tree.obj" | cut -c1-16) $(sha256sum < "$OUT/tree.json" | cut -c1-16) tree $name"
  "$LANDSIM" degrade "$species" --json > "$OUT/degrade.json"
  echo "$(sha256sum < "$OUT/degrade.json" | cut -c1-16) degrade $name"
done
for scenario in scenes/examples/default.toml scenes/examples/kagwene.toml \
  bench/scenarios/forest_100k.toml bench/scenarios/bare_volcano.toml; do
  name=$(basename "$scenario")
  rm -rf "$OUT/images"
  "$LANDSIM" render "$scenario" --spp 1 --width 320 --out "$OUT/images" > /dev/null 2>&1
  for image in "$OUT"/images/*.exr; do
    echo "$(sha256sum < "$image" | cut -c1-16) render $name $(basename "$image")"
  done
  "$LANDSIM" info "$scenario" --json | sed 's/"program":[0-9]*,\{0,1\}//; s/"memory_estimate_bytes":[0-9]*//' > "$OUT/info.json"
  echo "$(sha256sum < "$OUT/info.json" | cut -c1-16) info $name"
  "$LANDSIM" export-pov "$scenario" --out "$OUT/pov" > /dev/null 2>&1
  echo "$(cat "$OUT"/pov/* | sha256sum | cut -c1-16) export-pov $name"
done
