#!/usr/bin/env bash
# Speed figures on the lent GPU machine (NVIDIA, headless EGL). Run there from the repo
# root with build/native/pathtracer and .gl/ (glvnd + tinyxml2 .debs) carried along:
#   bash tools/device_bench.sh        results in $OUT (or out/) and on stdout
set -uo pipefail
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
nv=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[[ -f $nv ]] && export __EGL_VENDOR_LIBRARY_FILENAMES=$nv
out="${OUT:-out}"
mkdir -p "$out"
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv,noheader || true
bin=build/native/pathtracer
run() { echo "## $*"; "$bin" render "$@" 2>&1 | grep -vE '^(scene|wrote)'; }
for s in 0 1 2; do
  run scenes/reference/scene$s.xml --spp 1024 --size 512x512 --out "$out/scene$s-512.png"
done
run scenes/reference/scene2.xml --spp 256 --size 1920x1080 --out "$out/scene2-1080p.png"
run scenes/reference/scene2.xml --spp 256 --size 512x512 --no-nee --out "$out/scene2-512-nonee.png"
