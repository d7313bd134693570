#!/usr/bin/env bash
# Speed against error on the lent GPU machine (NVIDIA, headless EGL). Build natively
# here (cmake --build --preset native), then run there with build/native/pathtracer and
# .gl/ (libglvnd + tinyxml2 .debs, see docs/benchmarks.md) carried along:
#   bash tools/bench_device.sh cornell|scenes|speed|bvh|kernels|variants|wave2|accel|gltfms|adaptive|adaptivebound|fragment|flatkinds|denoise|denoiseeval|calibration
# Results (CSV, SVG, PNG, log) go to $OUT/results-PART.tar.gz.
set -uo pipefail
part="${1:?part: cornell, scenes, speed, bvh, kernels, variants, wave2, accel, gltfms, adaptive, adaptivebound, fragment, flatkinds, denoise, denoiseeval or calibration}"
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
nv=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[[ -f $nv ]] && export __EGL_VENDOR_LIBRARY_FILENAMES=$nv
out="${OUT:-out}"
w="/tmp/work-$part"
mkdir -p "$w"
exec > >(tee "$w/log-$part.txt") 2>&1
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv,noheader || true
date -u
B="${PT_BIN:-build/native/pathtracer}"  # PT_BIN: another carried build
S=1920x1080
SAMPLERS="sobol independent"
curves() {  # scene name ref-args...
  local scene=$1 name=$2; shift 2
  for nee in nee no-nee; do
    for smp in $SAMPLERS; do
      local flags=(--sampler "$smp")
      [[ $nee == no-nee ]] && flags+=(--no-nee)
      $B bench "$scene" --size $S --seconds "${SECS:-10}" "$@" "${flags[@]}" --label "$name $nee $smp" --csv "$w/$name-$nee-$smp.csv"
    done
  done
  $B plot "$w/$name-time.svg" --title "$name $S: relMSE against time" "$w/$name"-*.csv
  $B plot "$w/$name-spp.svg" --x spp --title "$name $S: relMSE against samples per pixel" "$w/$name"-*.csv
}
# A scene of n spheres and boxes in a 100-wide grid (the shader must not grow with n).
objects_scene() {
  local n=$1 f=$2
  {
    echo '<SceneLevel><Camera position="50 50 -150" up="0 1 0" yaw="270" pitch="0"/>'
    echo '<Light position="50 200 -100" radius="10" color="1 1 1" intensity="50"/><Objects>'
    for ((i = 0; i < n; ++i)); do
      x=$((i % 100)) y=$((i / 100))
      if ((i % 2)); then echo "<Sphere center=\"$x $y 0\" radius=\"0.4\"><Diffuse/></Sphere>"
      else echo "<Box min=\"$x $y 0\" max=\"$x.5 $y.5 0.5\"><Diffuse/></Box>"; fi
    done
    echo '</Objects></SceneLevel>'
  } > "$f"
}
case "$part" in
  cornell)
    SAMPLERS="${CORNELL_SAMPLERS:-sobol sobol-all independent}"
    $B render scenes/cornell-box.xml --size $S --spp 1000000 --seconds "${REF_SECS:-150}" --out "$w/cornell-ref.pfm" --out "$w/cornell-ref.png"
    curves scenes/cornell-box.xml cornell --reference "$w/cornell-ref.pfm"
    ;;
  scenes)
    for s in 0 1 2; do
      $B render scenes/reference/scene$s.xml --size $S --spp 1000000 --seconds 60 --out "$w/scene$s-ref.pfm" --out "$w/scene$s-ref.png"
      $B bench scenes/reference/scene$s.xml --size $S --seconds 10 --reference "$w/scene$s-ref.pfm" --label "scene$s" --csv "$w/scene$s.csv"
    done
    $B plot "$w/reference-scenes-time.svg" --title "Reference scenes $S: relMSE against time" "$w"/scene?.csv
    SECS=5 curves scenes/analytic/closed-room.xml room --bounces 64 --reference-value 2
    ;;
  speed)
    for s in scenes/reference/scene0.xml scenes/reference/scene1.xml scenes/reference/scene2.xml scenes/cornell-box.xml; do
      $B render "$s" --size 512x512 --spp 2048 --out "$w/$(basename "$s" .xml)-512.png"
    done
    ;;
  bvh)
    # One million triangles (1,310,720: scenes/bench/million.xml) at 1080p, every ray
    # counted (camera, bounce, shadow); the glTF scene; then the shader for 10 and for
    # 10,000 objects (spheres and boxes), which must be the same size and compile alike.
    $B render scenes/bench/million.xml --size $S --spp 64 --out "$w/million-1080p.png"
    $B render scenes/bench/million.xml --size $S --spp 64 --bounces 1 --out "$w/million-1080p-1bounce.png"
    $B render scenes/gltf-instances.xml --size $S --spp 64 --out "$w/gltf-1080p.png"
    for n in 10 10000; do
      f="$w/objects-$n.xml"
      objects_scene $n "$f"
      $B render "$f" --size $S --spp 64 --out "$w/objects-$n.png"
    done
    ;;
  kernels)
    # The fragment pass (what WebGL 2 runs) against the compute kernel (GL ES 3.1), same
    # code and estimate: each scene for at most 8 s at 1080p, then 16 spp of each kernel
    # compared byte for byte.
    for s in scenes/reference/scene0.xml scenes/reference/scene1.xml scenes/reference/scene2.xml scenes/cornell-box.xml \
             scenes/gltf-instances.xml scenes/bench/million.xml; do
      n=$(basename "$s" .xml)
      for k in fragment compute; do
        $B render "$s" --size $S --spp 100000 --seconds 8 --kernel $k --out "$w/$n-$k.png"
        $B render "$s" --size 640x360 --spp 16 --spp-per-pass 4 --kernel $k --out "$w/$n-$k-16.pfm" > /dev/null
      done
      if cmp -s "$w/$n-fragment-16.pfm" "$w/$n-compute-16.pfm"; then echo "$n: 16 spp identical (fragment, compute)"
      else echo "$n: 16 spp DIFFER: $(cmp "$w/$n-fragment-16.pfm" "$w/$n-compute-16.pfm" | head -1)"; fi
    done
    $B render scenes/bench/million.xml --size $S --spp 100000 --seconds 8 --bounces 1 --kernel compute --out "$w/million-1bounce.png"
    ;;
  variants)
    # Builds of different commits side by side (build/bench/pt-NAME, carried): the same
    # scenes, compute kernel, 1080p, 5 s each; then 16 spp of each compared byte for byte
    # with the first variant's (a traversal change must not change the image).
    objects_scene 10000 "$w/objects-10000.xml"
    for v in build/bench/pt-*; do
      for s in scenes/bench/million.xml scenes/gltf-instances.xml scenes/reference/scene0.xml "$w/objects-10000.xml"; do
        n=$(basename "$s" .xml)
        echo "== $(basename "$v") $n"
        $v render "$s" --size $S --spp 100000 --seconds 5 --out "$w/$n.png" | grep -E "BVH|rendered"
        $v render "$s" --size 640x360 --spp 16 --spp-per-pass 4 --out "$w/$n-$(basename "$v")-16.pfm" > /dev/null
      done
    done
    first=$(ls build/bench/ | head -1)
    for f in "$w"/*-16.pfm; do cmp -s "$f" "${f%-pt-*-16.pfm}-$first-16.pfm" && echo "$(basename "$f"): identical to $first" || echo "$(basename "$f"): differs from $first"; done
    rm -f "$w"/*.png
    last=$(ls build/bench/pt-* | tail -1)
    for flags in "--sampler independent" "--no-nee" "--bounces 1" "--kernel fragment"; do
      echo "== $(basename "$last") million $flags"
      $last render scenes/bench/million.xml --size $S --spp 100000 --seconds 5 $flags --out /tmp/m.png | grep -E "rendered"
    done
    ;;
  accel)
    # The traversal choice (issue 17, docs/benchmarks.md "Fragment-pass steps"): each scene
    # at 1080p for ACCEL_SECONDS (5) in both kernels with the BVH and flat, then 16 spp of
    # each kept as PFM (byte-compared with cmp: the same estimate).
    for s in ${ACCEL_SCENES:-scenes/reference/scene2.xml scenes/cornell-box.xml scenes/reference/scene0.xml scenes/bench/million.xml}; do
      for k in fragment compute; do
        for a in bvh flat; do
          [[ $a == flat && $s == *million* ]] && continue  # 1.3 M triangles in one loop: not a choice
          echo "== $(basename "$s" .xml) $k $a"
          $B render "$s" --size $S --spp 100000 --seconds "${ACCEL_SECONDS:-5}" --kernel $k --accel $a --out /tmp/w.png | grep -E "acceleration|rendered|non-finite"
          $B render "$s" --size 640x360 --spp 16 --spp-per-pass 4 --kernel $k --accel $a --out "$w/$(basename "$s" .xml)-$k-$a.pfm" >/dev/null
        done
        if [[ -f "$w/$(basename "$s" .xml)-$k-flat.pfm" ]]; then
          cmp -s "$w/$(basename "$s" .xml)-$k-bvh.pfm" "$w/$(basename "$s" .xml)-$k-flat.pfm" && echo "16 spp: bvh and flat byte-identical" || echo "16 spp: bvh and flat DIFFER"
        fi
      done
    done
    ;;
  gltfms)
    # The glTF BSDF's multiple-scattering compensation (issue 13, docs/gltf.md): each glTF
    # scene at 1080p for GLTFMS_SECONDS (5) in both kernels, --gltf-ms on and off.
    for s in ${GLTFMS_SCENES:-scenes/gltf/*.xml scenes/gltf-instances.xml}; do
      for k in compute fragment; do
        for ms in on off; do
          echo "== $(basename "$s" .xml) $k gltf-ms $ms"
          $B render "$s" --size $S --spp 100000 --seconds "${GLTFMS_SECONDS:-5}" --kernel $k --gltf-ms $ms --out /tmp/w.png | grep -E "shader|rendered|non-finite"
        done
      done
    done
    ;;
  adaptive)
    # Adaptive sampling against uniform at equal time (issue 14, tools/adaptive_eval.py):
    # compute kernel, 1080p, ADAPTIVE_SECONDS (10) per run, references of
    # ADAPTIVE_REF_SECONDS (60); then each build of ADAPTIVE_OTHERS (carried binaries)
    # adaptive only, against the same references.
    scenes=(${ADAPTIVE_SCENES:-scenes/cornell-box.xml scenes/reference/scene0.xml scenes/seed/05-cornell-blue-yellow.xml scenes/mesh-cube.xml})
    python3 -u tools/adaptive_eval.py --bin "$B" --size $S --kernel compute --seconds "${ADAPTIVE_SECONDS:-10}" \
      --ref-seconds "${ADAPTIVE_REF_SECONDS:-60}" --spp 0 --repeat "${ADAPTIVE_REPEAT:-1}" --work "$w" --csv "$w/adaptive.csv" "${scenes[@]}"
    for v in ${ADAPTIVE_OTHERS:-}; do
      for s in "${scenes[@]}"; do
        echo "== $(basename "$v") $(basename "$s" .xml) adaptive"
        $v bench "$s" --size $S --kernel compute --seconds "${ADAPTIVE_SECONDS:-10}" --adaptive on \
          --reference "$w/$(basename "$s" .xml)-$S-ref.pfm" --csv "$w/$(basename "$v")-$(basename "$s" .xml).csv" | grep -E "adaptive|spp/s"
      done
    done
    ;;
  adaptivebound)
    # The most adaptive sampling can gain per scene at equal samples (tools/adaptive_bound.py):
    # a uniform render of ADAPTIVE_BOUND_SPP (1024) at 1080p (compute kernel) with each
    # pixel's variance, then the ceilings per pixel, per 16x16 tile and with the floor.
    for s in ${ADAPTIVE_SCENES:-scenes/cornell-box.xml scenes/reference/scene0.xml scenes/seed/05-cornell-blue-yellow.xml scenes/mesh-cube.xml}; do
      n=$(basename "$s" .xml)
      $B render "$s" --size $S --kernel compute --spp "${ADAPTIVE_BOUND_SPP:-1024}" --out "$w/$n-mean.pfm" --out-variance "$w/$n-var.pfm" | grep -E "rendered"
      python3 tools/adaptive_bound.py --mean "$w/$n-mean.pfm" --variance "$w/$n-var.pfm" --spp "${ADAPTIVE_BOUND_SPP:-1024}"
    done
    ;;
  fragment)
    # The fragment pass (the page's) of builds side by side (FRAGMENT_BUILDS, carried):
    # each scene at 1080p for FRAGMENT_SECONDS (5), the BVH forced (a traversal change is
    # measured where it runs), builds interleaved per scene; then 16 spp of each build
    # compared byte for byte with the first's.
    for s in ${FRAGMENT_SCENES:-scenes/reference/scene2.xml scenes/cornell-box.xml scenes/reference/scene0.xml scenes/bench/million.xml}; do
      n=$(basename "$s" .xml)
      for v in ${FRAGMENT_BUILDS:?builds}; do
        echo "== $(basename "$v") $n fragment bvh"
        timeout 120 $v render "$s" --size $S --spp 100000 --seconds "${FRAGMENT_SECONDS:-5}" --kernel fragment --accel bvh --out /tmp/w.png |
          grep --line-buffered -E "shader|rendered|non-finite"
        timeout 120 $v render "$s" --size 640x360 --spp 16 --spp-per-pass 4 --kernel fragment --accel bvh --out "$w/$n-$(basename "$v").pfm" >/dev/null
      done
      first=$(set -- ${FRAGMENT_BUILDS}; basename "$1")
      for v in ${FRAGMENT_BUILDS}; do
        cmp -s "$w/$n-$first.pfm" "$w/$n-$(basename "$v").pfm" && echo "$n 16 spp: $(basename "$v") identical to $first" || echo "$n 16 spp: $(basename "$v") DIFFERS from $first"
      done
    done
    ;;
  flatkinds)
    # The flat loop kind by kind against the one loop (issue 17): builds (FLAT_BUILDS,
    # carried) interleaved, FLAT_REPEAT (2) times, on the scenes auto makes flat and on
    # rooms forced flat (FLAT_SCENES; gen_accel_scenes.py's rooms, carried), both kernels,
    # 1080p, FRAGMENT_SECONDS (5) each; then 16 spp of each build compared byte for byte.
    for s in ${FLAT_SCENES:-scenes/reference/scene2.xml}; do
      n=$(basename "$s" .xml)
      for ((rep = 0; rep < ${FLAT_REPEAT:-2}; ++rep)); do
        for k in fragment compute; do
          for v in ${FLAT_BUILDS:?builds}; do
            echo "== $(basename "$v") $n $k flat"
            timeout 120 $v render "$s" --size $S --spp 100000 --seconds "${FRAGMENT_SECONDS:-5}" --kernel $k --accel flat --out /tmp/w.png |
              grep --line-buffered -E "rendered|non-finite"
          done
        done
      done
      first=$(set -- ${FLAT_BUILDS}; basename "$1")
      for k in fragment compute; do
        for v in ${FLAT_BUILDS}; do
          timeout 120 $v render "$s" --size 640x360 --spp 16 --spp-per-pass 4 --kernel $k --accel flat --out "$w/$n-$k-$(basename "$v").pfm" >/dev/null
          cmp -s "$w/$n-$k-$first.pfm" "$w/$n-$k-$(basename "$v").pfm" && echo "$n $k 16 spp: $(basename "$v") identical to $first" ||
            echo "$n $k 16 spp: $(basename "$v") DIFFERS from $first"
        done
      done
    done
    ;;
  denoise)
    # The denoiser's cost (issue 14, docs/denoise.md): at 1080p, as the page runs it (the
    # fragment pass), below the regression's gate (16 spp: the a-trous filter alone) and
    # above it (32 spp: albedo term and regression); render prints the median of 3 timed
    # runs of the filter alone. A 10 s render first, so the clocks are up.
    $B render scenes/cornell-box.xml --size $S --spp 100000 --seconds 10 --kernel fragment --out /tmp/w.png | grep -E "rendered"
    for s in ${DENOISE_SCENES:-scenes/cornell-box.xml scenes/reference/scene0.xml scenes/gltf-instances.xml}; do
      for n in 16 32; do
        echo "== $(basename "$s" .xml) $n spp fragment"
        $B render "$s" --size $S --spp $n --kernel fragment --denoise --out /tmp/w.png --out-denoised "$w/$(basename "$s" .xml)-$n-denoised.png" |
          grep -E "rendered|denoised:"
      done
    done
    ;;
  denoiseeval)
    # The denoiser against references at a page's size (issue 14, docs/denoise.md):
    # tools/denoise_eval.py at DENOISE_SIZE (512x512), references of DENOISE_REF_SPP
    # (16384), the fragment pass; its table, and its PNGs in the results.
    # DENOISE_REF_KERNEL=compute: the references by the compute kernel first (the H100's and
    # H200's fragment pass runs on a few graphics-capable SMs: a 16384-spp reference of a
    # mesh scene took longer than a call); denoise_eval.py reuses them.
    if [[ -n ${DENOISE_REF_KERNEL:-} ]]; then
      mkdir -p "$w/denoise-eval"
      for s in ${DENOISE_SCENES:-scenes/cornell-box.xml scenes/reference/scene0.xml scenes/seed/03-balls-solid-table-wood.xml scenes/gltf-instances.xml}; do
        r="$w/denoise-eval/$(echo "${s#scenes/}" | sed 's/\.xml$//; s#/#-#g')-ref"
        $B render "$s" --size "${DENOISE_SIZE:-512x512}" --spp "${DENOISE_REF_SPP:-16384}" --spp-per-pass 16 --kernel "$DENOISE_REF_KERNEL" \
          --out "$r.pfm" --out "$r.png" --out-aux "$r" > "$r.txt"
        grep -E "rendered|estimated" "$r.txt"
      done
    fi
    python3 -u tools/denoise_eval.py --bin "$B" --size "${DENOISE_SIZE:-512x512}" --ref-spp "${DENOISE_REF_SPP:-16384}" \
      --kernel fragment --dir "$w/denoise-eval" ${DENOISE_SCENES:-}
    ;;
  calibration)
    # The error estimate against the truth (issue 14, docs/benchmarks.md "The renderer's own
    # error"): per scene a reference (compute kernel, CALIB_REF_SECONDS, 60), then `bench`
    # for CALIB_SECONDS (5) with each build of CALIB_BUILDS (carried; default PT_BIN),
    # whose CSV holds the true and the estimated relMSE at every power of two; the ratio
    # estimated / true per spp printed. CALIB_SIZE: 512x512.
    cs="${CALIB_SIZE:-512x512}"
    for s in ${CALIB_SCENES:-scenes/cornell-box.xml scenes/reference/scene0.xml scenes/seed/05-cornell-blue-yellow.xml scenes/analytic/closed-room.xml}; do
      n=$(basename "$s" .xml)
      if [[ $n == closed-room ]]; then ref=(--bounces 64 --reference-value 2)
      else
        $B render "$s" --size "$cs" --kernel compute --spp 1000000 --seconds "${CALIB_REF_SECONDS:-60}" --out "$w/$n-ref.pfm" | grep -E "rendered|estimated"
        ref=(--reference "$w/$n-ref.pfm")
      fi
      for v in ${CALIB_BUILDS:-$B}; do
        echo "== $(basename "$v") $n $cs"
        $v bench "$s" --size "$cs" --kernel compute --seconds "${CALIB_SECONDS:-5}" "${ref[@]}" --csv "$w/$(basename "$v")-$n.csv" | grep -E "spp/s"
        python3 -c 'import csv,sys
for r in csv.DictReader(open(sys.argv[1])):
    if r["est_rel_mse"] and int(r["spp"]) >= 4 and float(r["rel_mse"]) > 0:
        print("  %6s spp: true %.4g estimated %.4g ratio %.2f (iid alone %.2f, exponent %s)" % (r["spp"], float(r["rel_mse"]), float(r["est_rel_mse"]), float(r["est_rel_mse"]) / float(r["rel_mse"]), float(r["est_rel_mse_iid"]) / float(r["rel_mse"]), r["est_exponent"]))' "$w/$(basename "$v")-$n.csv"
      done
    done
    ;;
  wave2)
    # The second wave's costs, builds side by side (build/bench/pt-NAME, carried): each
    # scene at 1080p for 5 s in both kernels (the per-pixel variance target, the glTF
    # BSDF against the old stand-in on the glTF scenes, the per-kind records).
    # WAVE2_SCENES, WAVE2_SECONDS: a subset and a shorter time.
    for v in build/bench/pt-*; do
      for s in ${WAVE2_SCENES:-scenes/cornell-box.xml scenes/reference/scene2.xml scenes/reference/scene0.xml scenes/gltf-instances.xml \
               scenes/gltf/mr-grid.xml scenes/gltf/maps-quad.xml scenes/bench/million.xml}; do
        for k in compute fragment; do
          echo "== $(basename "$v") $(basename "$s" .xml) $k"
          # (line-buffered, so that a call stopped at its limit still shows what it measured;
          # a render that hangs is stopped after WAVE2_LIMIT s)
          timeout "${WAVE2_LIMIT:-120}" $v render "$s" --size $S --spp 100000 --seconds "${WAVE2_SECONDS:-5}" --kernel $k --out /tmp/w.png |
            grep --line-buffered -E "shader|rendered|non-finite|estimated"
        done
      done
    done
    ;;
esac
find "$w" -name "*.pfm" -delete
tar -czf "$out/results-$part.tar.gz" -C "$w" .
