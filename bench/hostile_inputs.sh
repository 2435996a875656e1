#!/bin/sh
# Hostile and careless inputs (issue 47, docs/RELIABILITY.md "What a hostile input can
# cost"): makes each input, runs the landsim command a user would, and prints its exit code,
# wall time and peak memory (GNU time's maximum resident set), with the first words of what
# landsim said. Every case must end in seconds under 500 MB.
# Run from the repository after a Release build:
#   sh bench/hostile_inputs.sh [BIN]
set -eu
BIN=${1:-build/bin}
ROOT=$(pwd)
W=$(mktemp -d /tmp/landsim-hostile-XXXXXX)
trap 'rm -rf "$W"' EXIT

scenario() {  # scenario NAME EXTRA: the volcano, a small view, and EXTRA
  cat > "$W/$1.toml" <<TOML
[terrain]
elevation = "$ROOT/data/terrain/volcano.asc"
[sun]
elevation = 30
azimuth = 200
[[views]]
name = "v"
position = [500.0, 900.0, 330.0]
target = [280.0, 280.0, 130.0]
width = 64
height = 36
[render]
spp = 1
$2
TOML
}
object() { printf '[[objects]]\nname = "x"\nfile = "%s"\nposition = [280.0, 280.0]\n' "$1"; }

# Meshes.
python3 - "$W" <<'PY'
import struct, sys, zlib, math
w = sys.argv[1]
with open(f"{w}/zero.obj", "w") as f:   # 10^6 zero-area faces on three vertices
    f.write("v 0 0 0\nv 1 0 0\nv 2 0 0\n" + "f 1 2 3\n" * 1000000)
with open(f"{w}/fan.obj", "w") as f:    # a 30,000-triangle fan round one vertex
    n = 30000
    f.write("v 0 0 0\n")
    for i in range(n + 1):
        a = 2 * math.pi * i / n
        f.write(f"v {math.cos(a):.6f} 0 {math.sin(a):.6f}\n")
    for i in range(n):
        f.write(f"f 1 {i + 2} {i + 3}\n")
with open(f"{w}/huge.glb", "wb") as f:  # a header claiming a 2 GB chunk
    f.write(b"glTF" + struct.pack("<II", 2, 100) + struct.pack("<I", 0x80000000) + b"JSON" + b" " * 80)
with open(f"{w}/faces.ply", "wb") as f:  # 2^31 faces claimed
    f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
            b"property float y\nproperty float z\nelement face 2147483648\n"
            b"property list uchar int vertex_indices\nend_header\n" + b"\0" * 36)
with open(f"{w}/outside.gltf", "w") as f:  # a buffer outside the model's folder
    f.write('{"asset": {"version": "2.0"}, "buffers": [{"uri": "../../../../etc/passwd", "byteLength": 36}]}')
def chunk(t, d):
    return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
with open(f"{w}/huge.png", "wb") as f:  # a 100000 x 100000 reference, header only
    f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 100000, 100000, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", b"\x78\x9c") + chunk(b"IEND", b""))
def one_strip_tiff(tags, data):  # little-endian, one strip, every entry a LONG
    tags = sorted(tags) + [(273, 8 + 2 + 12 * (len(tags) + 2) + 4), (279, len(data))]
    ifd = struct.pack("<H", len(tags)) + b"".join(struct.pack("<HHII", t, 4, 1, v) for t, v in tags)
    return b"II*\0" + struct.pack("<I", 8) + ifd + b"\0" * 4 + data
with open(f"{w}/lzw.tif", "wb") as f:  # 16000 x 16000 grey LZW (256 M values) in 300 bytes
    f.write(one_strip_tiff([(256, 16000), (257, 16000), (258, 8), (259, 5), (262, 1), (277, 1),
                            (278, 16000)], b"\x80" * 200))
with open(f"{w}/fax.tif", "wb") as f:  # CCITT fax of 314 channels (164 M values), 180 bytes
    f.write(one_strip_tiff([(256, 8), (257, 65272), (258, 8), (259, 3), (262, 1), (277, 314),
                            (278, 8)], b"\0" * 60))
with open(f"{w}/unknown.tif", "wb") as f:  # a codec libtiff lacks, 8 x 65307 x 260 claimed
    f.write(one_strip_tiff([(256, 8), (257, 65307), (258, 8), (259, 256), (262, 1), (277, 260),
                            (278, 8)], b"\0" * 60))
with open(f"{w}/claims.webp", "wb") as f:  # 20 bytes of lossless WebP claiming 3085 x 12337
    f.write(bytes.fromhex("2f0c0c0c0c0c0cf3f30c0c0000000000ab2f2f2f"))
PY
for m in zero.obj fan.obj huge.glb faces.ply outside.gltf; do scenario "mesh_$m" "$(object "$W/$m")"; done
scenario plain ""
# image_fuzz findings kept in the regressions (their first byte is the target's choice of name).
tail -c +2 fuzz/regressions/image_fuzz/timeout-rla-1x1-38-channels-rle > "$W/hang.rla"
tail -c +2 fuzz/regressions/image_fuzz/slow-exr-attribute-beyond-file-1 > "$W/attribute.exr"
tail -c +2 fuzz/regressions/image_fuzz/oom-exr-string-attribute-after-damaged-chlist > "$W/string.exr"
tail -c +2 fuzz/regressions/image_fuzz/slow-tiff-zstd-strip-byte-count-0 > "$W/zstd.tif"
tail -c +2 fuzz/regressions/image_fuzz/slow-tiff-lerc-strip-byte-count-0 > "$W/lerc.tif"
tail -c +2 fuzz/regressions/image_fuzz/oom-tiff-lerc-long-float-rows > "$W/rows.tif"
tail -c +2 fuzz/regressions/image_fuzz/slow-tiff-tiles-8192-square-on-8x8 > "$W/tiles.tif"
tail -c +2 fuzz/regressions/image_fuzz/slow-webp-alpha-claiming-3085x6193 > "$W/alpha.webp"
for t in lzw.tif fax.tif claims.webp unknown.tif hang.rla attribute.exr string.exr zstd.tif lerc.tif rows.tif tiles.tif alpha.webp; do scenario "texture_$t" "$(printf '[ground]\ntextures = { soil = "%s" }' "$W/$t")"; done
printf 'camera { location <0, 1, -3> right x*image_width/image_height look_at <0, 0, 0> }\n#include "self.pov"\n' > "$W/self.pov"

# Species.
cat > "$W/harmonic.toml" <<'TOML'
core = "harmonic"
name = "explosive"
general = [400, 0.13, 4, 0.0013, 0.003, 0.3, 0.05, 0.0]
hierarchy = [[2, 1.0, 1.0, 25, 137, 400, 1.0, 0, 1.0], [2, 1.0, 1.0, 30, 137, 400, 0.75, 0, 1.0],
             [2, 1.0, 1.0, 40, 137, 400, 0.6, 0, 0.7], [2, 1.0, 1.0, 45, 137, 400, 0.6, 0, 0.5]]
TOML
{
  printf 'core = "self_organizing"\n[growth]\nage = 200\n'
  for k in 1 2 3; do
    printf '[[stroke]]\npoints = [%s[0, 0, 2, 1]]\nmarkers_per_step = 100000\nmax_age = 300\n' \
      "$(for i in $(seq 1 99); do printf '[0, 0, 2, 1], '; done)"
  done
} > "$W/strokes.toml"
# Self-organising internodes that multiply: fast (shoots of 20 metamers in a 20 m brush) and
# slow (a 15 m brush crawling up, the tree filling it over some 70 steps).
stroke_species() {  # stroke_species FILE MAX_SHOOT RADIUS1 RADIUS2 TOP PER_STEP MARKERS AGE
  printf 'core = "self_organizing"\n[growth]\nsteps = 300\ninternode_length = 0.12\n' > "$1"
  printf '[vigour]\nmax_shoot = %s\n[[stroke]]\npoints = [[0, 0, 0.4, %s], [0, 0, %s, %s]]\n' \
    "$2" "$3" "$5" "$4" >> "$1"
  printf 'points_per_step = %s\nmarkers_per_step = %s\nmax_age = %s\n' "$6" "$7" "$8" >> "$1"
}
stroke_species "$W/internodes_fast.toml" 20 10 20 40 0.1 100000 150
stroke_species "$W/internodes_slow.toml" 3 15 15 30 0.01 50000 100
printf 'core = "self_organizing"\n[growth]\nsteps = 100\ninternode_length = 0.12\n[space]\nautonomous_markers = 100\n[vigour]\nmax_shoot = 20\n' > "$W/autonomous.toml"
sed 's/^spacing = .*//' data/species/graph_rooted.toml > "$W/roots.toml"
python3 - "$W/roots.toml" <<'PY'
import re, sys
p = sys.argv[1]; s = open(p).read()
s = re.sub(r"(\[roots\]\n)", r"\1spacing = 0.005\n", s, count=1)
open(p, "w").write(s)
PY

run() {  # run NAME COMMAND...
  name=$1; shift
  /usr/bin/time -f "%e %M" -o "$W/time" timeout "${LIMIT:-600}" "$@" > "$W/out" 2> "$W/err" && code=0 || code=$?
  set -- $(cat "$W/time" | tail -1)
  said=$(grep -v "^landsim: info" "$W/err" | head -1 | cut -c1-110)
  printf '%-28s exit %s  %6.2f s  %5d MB  %s\n' "$name" "$code" "$1" $(( $2 / 1024 )) "$said"
}
echo "case                         exit   wall      peak  message"
for m in zero.obj fan.obj huge.glb faces.ply outside.gltf; do
  run "mesh $m" "$BIN/landsim" info "$W/mesh_$m.toml"
done
run "reference 100000^2 PNG" "$BIN/landsim" crosscheck "$W/plain.toml" --out "$W/c1" --reference "$W/huge.png"
run "texture: LZW TIFF claiming 256M values" "$BIN/landsim" render "$W/texture_lzw.tif.toml" --out "$W/t1"
run "texture: fax TIFF of 314 channels" "$BIN/landsim" render "$W/texture_fax.tif.toml" --out "$W/t2"
run "texture: WebP of 20 bytes claiming 38M pixels" "$BIN/landsim" render "$W/texture_claims.webp.toml" --out "$W/t3"
run "texture: TIFF of an unknown codec, 136M values" "$BIN/landsim" render "$W/texture_unknown.tif.toml" --out "$W/t4"
run "texture: Wavefront RLA of 797 bytes (OpenImageIO's reader hung)" "$BIN/landsim" render "$W/texture_hang.rla.toml" --out "$W/t5"
run "texture: EXR of 373 bytes with a 1.6 GB attribute" "$BIN/landsim" render "$W/texture_attribute.exr.toml" --out "$W/t6"
run "texture: EXR of 312 bytes, a 1.7 GB string past a damaged channel list" "$BIN/landsim" render "$W/texture_string.exr.toml" --out "$W/t7"
run "texture: Zstandard TIFF of 185 bytes, 8 rows of 51 MB, no strip bytes" "$BIN/landsim" render "$W/texture_zstd.tif.toml" --out "$W/t8"
run "texture: the same in LERC (no ratio bound)" "$BIN/landsim" render "$W/texture_lerc.tif.toml" --out "$W/t9"
run "texture: LERC TIFF of 8 rows of 128 MB floats, no strip bytes" "$BIN/landsim" render "$W/texture_rows.tif.toml" --out "$W/t10"
run "texture: 8 x 8 TIFF in tiles of 8192 x 8192" "$BIN/landsim" render "$W/texture_tiles.tif.toml" --out "$W/t11"
run "texture: WebP of 21 bytes with alpha claiming 19M pixels" "$BIN/landsim" render "$W/texture_alpha.webp.toml" --out "$W/t12"
run "reference garbage" "$BIN/landsim" crosscheck "$W/plain.toml" --out "$W/c2" --reference "$W/strokes.toml"
run "pov includes itself" "$BIN/landsim" crosscheck "$W/plain.toml" --out "$W/c3" --pov "$W/self.pov"
run "harmonic explosive" "$BIN/landsim" tree "$W/harmonic.toml"
run "strokes of 3e7 markers" "$BIN/landsim" tree "$W/strokes.toml"
run "internodes multiply fast" "$BIN/landsim" tree "$W/internodes_fast.toml"
run "internodes multiply slowly" "$BIN/landsim" tree "$W/internodes_slow.toml"
run "autonomous markers multiply" "$BIN/landsim" tree "$W/autonomous.toml"
run "graph [roots] too fine" "$BIN/landsim" tree "$W/roots.toml"
