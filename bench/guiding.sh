#!/bin/sh
# Guided paths against unguided ones (issue 72, docs/PERFORMANCE.md "Guided paths"): one
# build, each scene rendered RUNS rounds alternating guiding off ("old") and on ("new"), two
# renders a round that differ in their sampling seed; the whole process timed (training
# included); the noise is bench/exr_noise's. Cost at equal error: time x noise^2.
#   sh bench/guiding.sh BUILD [RUNS]
# SCENES, SIZE, SPP as bench/haze_cost.sh's; TRAINING sets [render] guiding_training.
set -eu
BUILD=$1
RUNS=${2:-3}
EXTRA="--set render.guiding=true --set render.guiding_training=${TRAINING:-0.125}" \
  exec sh "$(dirname "$0")/haze_cost.sh" "$BUILD" "$BUILD" "$RUNS"
