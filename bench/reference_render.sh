# Sourced by bench/sampler.sh and bench/adaptive.sh (after BUILD is set): the default scene's
# converged reference at 320 x 180 (1024 spp, another sampling seed, independent samples) in
# $OUT/ref, and LANDSIM, ERROR (bench/image_error), OUT and SIZE for the renders compared.
LANDSIM="$BUILD/bin/landsim"
ERROR="$BUILD/bin/image_error"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
SIZE="--width 320"
"$LANDSIM" render $SIZE --spp 1024 --set render.seed=1 --set render.sampling_seed=99 \
  --out "$OUT/ref" > /dev/null 2>&1
