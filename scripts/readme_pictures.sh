#!/bin/sh
# Redraws the README's three pictures from the repository's own scenarios and species:
#   docs/images/readme_kagwene.png  the Kagwene sanctuary from its highlands view (real DEM,
#                                   real vegetation map, its haze);
#   docs/images/readme_map.png      a north-up map of it with three of its truth layers beside
#                                   the picture (object class, species, depth);
#   docs/images/readme_cores.png    one tree of each core (Weber & Penn, Xu & Mould, self-organising,
#                                   London plane, Hoetzlein), each at its oldest default age.
# Needs the build (build/bin/landsim) and Debian's OpenImageIO Python binding (python3-openimageio,
# installed by scripts/install-deps.sh) to lay the panels side by side.
set -eu
LANDSIM=${LANDSIM:-build/bin/landsim}
PYTHON=${PYTHON:-/usr/bin/python3}
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

"$LANDSIM" render scenes/examples/kagwene.toml --view highlands --width 720 --spp 64 \
  --out "$OUT/kagwene" > /dev/null 2>&1
cp "$OUT/kagwene/highlands.png" docs/images/readme_kagwene.png

"$LANDSIM" render scenes/examples/kagwene_cameras.toml --view map --width 240 --spp 32 \
  --out "$OUT/map" > /dev/null 2>&1

for species in quaking_aspen graph_round_crown so_envelope london_plane harmonic_american_elm; do
  "$LANDSIM" grow "data/species/$species.toml" --width 180 --height 240 --spp 32 \
    --out "$OUT/$species" > /dev/null 2>&1
done

"$PYTHON" - "$OUT" <<'PY'
import colorsys
import glob
import sys

import numpy as np
import OpenImageIO as oiio

out = sys.argv[1]


def read(path, channels=None):
    buf = oiio.ImageBuf(path)
    pixels = buf.get_pixels(oiio.FLOAT)
    if channels is None:
        return pixels[:, :, :3]
    names = list(buf.spec().channelnames)
    return np.stack([pixels[:, :, names.index(c)] for c in channels], axis=-1)


def ids_in_colour(ids):
    # Each id its own hue (golden-ratio steps), 0 black: a truth layer as a person reads it.
    colours = np.zeros(ids.shape + (3,), np.float32)
    for i in np.unique(ids):
        if i == 0:
            continue
        colours[ids == i] = colorsys.hsv_to_rgb((i * 0.618034) % 1.0, 0.65, 0.9)
    return colours


def write(path, panels, gap=4):
    height = max(p.shape[0] for p in panels)
    row = []
    for p in panels:
        pad = np.ones((height, p.shape[1], 3), np.float32)
        pad[: p.shape[0]] = p
        row += [pad, np.ones((height, gap, 3), np.float32)]
    image = np.concatenate(row[:-1], axis=1)
    spec = oiio.ImageSpec(image.shape[1], image.shape[0], 3, oiio.UINT8)
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(), image)
    buf.write(path)


# The map: its preview, then what each pixel is (class, species) and how far it is (depth).
exr = out + "/map/map.exr"
truth = read(exr, ["object", "species", "Z"])
objects = np.rint(truth[:, :, 0] * 4294967295.0).astype(np.int64)  # 0 sky, 1 ground, 3 leaf...
species = np.rint(truth[:, :, 1] * 4294967295.0).astype(np.int64)
# Species are indices from 0, "none" is 2^32 - 1: shifted so that none is 0 (black).
species = np.where(species >= 1 << 20, 0, species + 1)
depth = truth[:, :, 2]
near, far = np.percentile(depth[np.isfinite(depth)], [1, 99])
shade = 1.0 - np.clip((depth - near) / max(far - near, 1e-6), 0.0, 1.0)
write("docs/images/readme_map.png",
      [read(out + "/map/map.png"), ids_in_colour(objects), ids_in_colour(species),
       np.repeat(shade[:, :, None], 3, axis=2)])

# The cores: each one's oldest tree.
trees = []
for name in [
    "quaking_aspen", "graph_round_crown", "so_envelope", "london_plane", "harmonic_american_elm"
]:
    # Without the age label along the top (the README says what each is).
    trees.append(read(sorted(glob.glob(out + "/" + name + "/age_*.png"))[-1])[24:])
write("docs/images/readme_cores.png", trees)
PY
