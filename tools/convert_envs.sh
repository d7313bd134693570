#!/usr/bin/env bash
# Converts three CC0 HDR environments shipped by Debian's blender-data package (Greg Zaal,
# HDRI Haven; see assets/env/README.md) from OpenEXR to Radiance .hdr under assets/env/.
# Run once by hand; its output is committed, so neither CI nor the builds need
# blender-data or openimageio-tools. The seed had morning, afternoon and night skies:
#   sunrise.exr -> morning.hdr, city.exr -> afternoon.hdr, night.exr -> night.hdr
set -euo pipefail
cd "$(dirname "$0")/.."
src=/usr/share/blender/datafiles/studiolights/world
need=()
[ -d "$src" ] || need+=(blender-data)
command -v oiiotool >/dev/null || need+=(openimageio-tools)
if [ ${#need[@]} -gt 0 ]; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${need[@]}"
fi
grep -q CC0 "$src/license.txt"  # the licence the package ships beside the files
mkdir -p assets/env
for pair in sunrise:morning city:afternoon night:night; do
  in="$src/${pair%%:*}.exr" out="assets/env/${pair##*:}.hdr"
  oiiotool "$in" -d float -o "$out"   # 1024 x 512, equirectangular, linear
  echo "$in -> $out ($(stat -c %s "$out") bytes)"
done
