#!/bin/sh
# Builds landsim's libFuzzer targets with clang, AddressSanitizer and UBSan (build-fuzz/),
# lays out their seed corpora and dictionaries from the project's own files, and runs each
# target for SECONDS (default 30). A crash, leak, undefined behaviour, a hang past 10 s (30 s
# for tree_fuzz, which grows what it reads) or
# more than 2 GB is a finding: the target stops, its input is saved in build-fuzz/findings/,
# and this script exits non-zero. docs/RELIABILITY.md says how to run long campaigns.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]      e.g. scripts/fuzz.sh 600 species_fuzz
#
# With FUZZ_SEED set (CI: scripts/sanitize.sh), each target also stops after a fixed number of
# inputs (20000; 30 for tree_fuzz, which grows every tree it reads) from that seed: the same
# inputs every run, so a CI run cannot fail on an input no earlier run has tried.
set -eu
cd "$(dirname "$0")/.."
SECONDS_EACH="${1:-30}"
[ $# -gt 0 ] && shift
ALL="species_fuzz arbaro_fuzz class_mapping_fuzz scenario_fuzz elevation_fuzz vegetation_fuzz tree_fuzz band_response_fuzz mesh_fuzz image_fuzz pov_camera_fuzz manifest_fuzz"
TARGETS="${*:-$ALL}"
B=build-fuzz

cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_C_COMPILER=clang -DLANDSIM_FUZZ=ON -DLANDSIM_BUILD_BENCH=OFF >/dev/null
cmake --build "$B" --parallel "$(nproc)" --target landsim landsim_meshes landsim_images $ALL

# alloc_dealloc_mismatch off: OpenImageIO 2.4's OpenEXRCore reader frees new[] buffers with a
# sized delete (scripts/sanitize.sh).
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1:alloc_dealloc_mismatch=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$(pwd)/fuzz/lsan.supp:print_suppressions=0:use_tls=0"
export LANDSIM_MODULE_DIR="$(pwd)/$B/bin"

# Seed corpora: every input of the kind the project ships, and the regression inputs.
C="$B/corpus"
rm -rf "$C" && mkdir -p "$C" "$B/findings"
for t in $ALL; do mkdir -p "$C/$t"; done
cp data/species/*.toml "$C/species_fuzz/"
cp data/species/*.toml "$C/tree_fuzz/"
cp data/species/*.xml "$C/arbaro_fuzz/"
cp scenes/examples/*_classes.toml "$C/class_mapping_fuzz/"
for f in scenes/examples/*.toml; do
  case "$f" in *_classes.toml) ;; *) cp "$f" "$C/scenario_fuzz/" ;; esac
done
cp data/terrain/volcano.asc data/terrain/bei_elev.asc "$C/elevation_fuzz/"
cp data/bands/*.csv "$C/band_response_fuzz/"
# Mesh and image seeds carry the format in their first byte (the targets' choice of name).
seed() { { printf "$1"; cat "$2"; } > "$3"; }
for f in data/objects/*.obj; do seed '\000' "$f" "$C/mesh_fuzz/$(basename "$f")"; done
for f in data/objects/*.ply; do [ -f "$f" ] && seed '\001' "$f" "$C/mesh_fuzz/$(basename "$f")" || true; done
for f in data/objects/*.gltf; do [ -f "$f" ] && seed '\002' "$f" "$C/mesh_fuzz/$(basename "$f")" || true; done
for f in data/objects/*.glb; do [ -f "$f" ] && seed '\003' "$f" "$C/mesh_fuzz/$(basename "$f")" || true; done
gdal_translate -q -of PNG -ot Byte -scale -outsize 8 8 data/terrain/volcano.asc "$B/seed.png"
gdal_translate -q -of GTiff -outsize 8 8 data/terrain/volcano.asc "$B/seed.tif"
seed '\000' "$B/seed.png" "$C/image_fuzz/seed.png"
seed '\002' "$B/seed.tif" "$C/image_fuzz/seed.tif"
# One small image in each other format the image module reads (it finds the format by content).
/usr/bin/python3 - "$B" <<'PY'
import sys, OpenImageIO as oiio
for ext in ("exr", "jpg", "webp", "hdr", "bmp", "ppm", "tga"):
    buf = oiio.ImageBuf(oiio.ImageSpec(8, 8, 3, "uint8"))
    oiio.ImageBufAlgo.fill(buf, (0.1, 0.5, 0.9), (0.9, 0.2, 0.3), (0.0, 0.7, 0.1), (1.0, 1.0, 1.0))
    buf.write(f"{sys.argv[1]}/seed.{ext}")
PY
for f in "$B"/seed.exr "$B"/seed.jpg "$B"/seed.webp "$B"/seed.hdr "$B"/seed.bmp "$B"/seed.ppm "$B"/seed.tga; do
  seed '\001' "$f" "$C/image_fuzz/$(basename "$f")"
done
"$B/bin/landsim" export-pov scenes/examples/default.toml --out "$B/pov-seed" >/dev/null 2>&1 || true
# The export's head (settings, camera, the first tree declarations): the camera reader lexes
# the whole file, and the whole 2.6 MB scene would hold the fuzzer to a few inputs a second.
head -n 70 "$B/pov-seed/scene.pov" > "$C/pov_camera_fuzz/scene_head.pov" 2>/dev/null || true
printf '{"images": [{"path": "v.exr", "view": "v", "frame_index": 0}]}\n' > "$C/manifest_fuzz/one.json"
gdal_translate -q -of GTiff data/terrain/volcano.asc "$C/elevation_fuzz/volcano.tif"
gdal_translate -q -of PNG -ot UInt16 -scale data/terrain/volcano.asc "$C/elevation_fuzz/volcano.png"
"$B/bin/landsim" featuremap build data/featuremaps/volcano_landcover.asc \
  --map scenes/examples/volcano_classes.toml --out "$C/vegetation_fuzz/volcano.tif" >/dev/null
for t in $TARGETS; do
  [ -d "fuzz/regressions/$t" ] && cp fuzz/regressions/$t/* "$C/$t/" 2>/dev/null || true
done

# Dictionaries: the documented keys (backquoted names in the docs' tables) and TOML syntax.
D="$B/dict"
mkdir -p "$D"
keys() { grep -ho '`[A-Za-z0-9_]\+`' "$@" | tr -d '`' | sort -u | sed 's/.*/"&"/'; }
syntax='"=" "[" "]" "[[" "]]" "," "\"" "true" "false" "1e308" "-1" "nan" "inf" "#"'
{ keys docs/SPECIES.md docs/HARMONIC.md; echo "$syntax" | tr ' ' '\n'; } > "$D/toml_species.dict"
{ keys docs/SCENARIO.md; echo "$syntax" | tr ' ' '\n'; } > "$D/toml_scenario.dict"
printf '%s\n' '"<arbaro>"' '"<species"' '"<param"' '"name="' '"value="' '"/>"' '"</species>"' \
  '"Levels"' '"Shape"' '"0Branches"' '"LeafShape"' '"&amp;"' '"<!--"' > "$D/xml.dict"

status=0
for t in $TARGETS; do
  case "$t" in
    arbaro_fuzz) dict="$D/xml.dict" ;;
    scenario_fuzz) dict="$D/toml_scenario.dict" ;;
    elevation_fuzz|vegetation_fuzz|band_response_fuzz|mesh_fuzz|image_fuzz|pov_camera_fuzz|manifest_fuzz) dict="" ;;
    *) dict="$D/toml_species.dict" ;;
  esac
  log="$B/findings/$t.log"
  fixed=""
  # POV-Ray scenes: inputs up to 16 kB (the seed's head is 8 kB), not the longest seed's size.
  [ "$t" = pov_camera_fuzz ] && fixed="-max_len=16384"
  # tree_fuzz grows every species it reads: the largest shipped self-organising tree takes 8-12 s
  # under ASan with libFuzzer's tracing on this VM, so its limit is 30 s (a hang is still one).
  timeout=10
  [ "$t" = tree_fuzz ] && timeout=30
  if [ -n "${FUZZ_SEED:-}" ]; then
    runs=20000
    [ "$t" = tree_fuzz ] && runs=30
    fixed="$fixed -seed=$FUZZ_SEED -runs=$runs"
  fi
  # The image and mesh libraries keep no frame pointers: their allocations' stacks are
  # unwound fully, so that a library's own allocations are told from landsim's.
  asan="$ASAN_OPTIONS"
  case "$t" in image_fuzz|mesh_fuzz) asan="$asan:fast_unwind_on_malloc=0" ;; esac
  if ASAN_OPTIONS="$asan" "$B/bin/$t" "$C/$t" ${dict:+-dict=$dict} $fixed -max_total_time="$SECONDS_EACH" -timeout="$timeout" \
      -rss_limit_mb=2048 -malloc_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$B/findings/$t-" >"$log" 2>&1; then
    result=clean
  else
    result="FINDING (see $log)"
    status=1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  echo "$t: $runs runs, $cov edges, $result"
done
exit $status
