# Sourced by bench/sampler.sh, bench/adaptive.sh and bench/haze_truth.sh (after BUILD is
# set): a converged reference at 320 x 180 (REF_SPP samples, default 1024, another sampling
# seed) in $OUT/ref, of SCENE (a scenario file; unset: the embedded default scene), and
# LANDSIM, ERROR (bench/image_error), OUT and SIZE for the renders compared.
LANDSIM="$BUILD/bin/landsim"
ERROR="$BUILD/bin/image_error"
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
SIZE="--width 320"
# shellcheck disable=SC2086
"$LANDSIM" render ${SCENE:-} $SIZE --spp "${REF_SPP:-1024}" --set render.seed=1 \
  --set render.sampling_seed=99 --out "$OUT/ref" > /dev/null 2>&1
