#!/usr/bin/env bash
# `pathtracer watch`: start it on a scene in a temporary folder, then edit the scene, edit
# the mesh it references (a dependency, not the scene file), write a broken edit, and fix
# it again. Each good edit must produce a new generation whose image differs (and whose
# mean radiance says what the edit did); the broken edit must print file:line, keep the
# last image untouched and leave the process running.
#   bash tests/cli_watch.sh BIN WORKDIR
set -uo pipefail
BIN=$1
dir=$2
rm -rf "$dir" && mkdir -p "$dir"
log=$dir/out.log err=$dir/err.log img=$dir/img.png
pid=
fail() {
  echo "FAIL: $*"
  echo "--- stdout"; cat "$log"; echo "--- stderr"; cat "$err"
  [[ -n "$pid" ]] && kill "$pid" 2>/dev/null
  exit 1
}
# Editors save in place or by rename; rename makes the new content appear at once.
put() { printf '%s\n' "$2" > "$1.tmp" && mv "$1.tmp" "$1"; }
scene() {  # $1: environment colour
  put "$dir/scene.xml" "<SceneLevel>
  <Camera position=\"0 0 6\" yaw=\"90\" pitch=\"0\"/>
  <Environment color=\"$1\"/>
  <Objects>
    <Mesh src=\"quad.obj\"><Attenuate color=\"0.2 0.2 0.2\"><Diffuse/></Attenuate></Mesh>
  </Objects>
</SceneLevel>"
}
quad() {  # $1: half-size of a square facing the camera
  put "$dir/quad.obj" "v -$1 -$1 0
v $1 -$1 0
v $1 $1 0
v -$1 $1 0
f 1 2 3 4"
}
# Waits until stdout has a write of generation $1 at the sample target; prints its line.
wait_gen() {
  for _ in $(seq 1 600); do
    line=$(grep -E "wrote .*: 4 spp \(generation $1\)" "$log" | tail -1)
    [[ -n "$line" ]] && { echo "$line"; return 0; }
    kill -0 "$pid" 2>/dev/null || fail "watch exited"
    sleep 0.1
  done
  fail "no image of generation $1"
}
mean() { sed -E 's/.*mean radiance: ([^ ]+) ([^ ]+) ([^ ]+)/\1 \2 \3/' <<<"$1"; }

quad 1
scene "0.5 0.5 0.5"
"$BIN" watch "$dir/scene.xml" --out "$img" --size 32x32 --spp 4 --seconds 300 >"$log" 2>"$err" &
pid=$!

l1=$(wait_gen 1) || exit 1
h1=$(md5sum <"$img")
read -r r1 g1 b1 < <(mean "$l1")

# 1. The scene file: a red sky.
scene "1 0 0"
l2=$(wait_gen 2) || exit 1
h2=$(md5sum <"$img")
read -r r2 g2 b2 < <(mean "$l2")
[[ "$h2" != "$h1" ]] || fail "image unchanged after editing the scene"
awk -v r="$r2" -v g="$g2" 'BEGIN { exit !(r > 3 * g) }' || fail "red sky not red: $l2"

# 2. A referenced file: a larger quad covers more of the sky.
quad 2
l3=$(wait_gen 3) || exit 1
h3=$(md5sum <"$img")
read -r r3 g3 b3 < <(mean "$l3")
[[ "$h3" != "$h2" ]] || fail "image unchanged after editing the mesh"
awk -v a="$r3" -v b="$r2" 'BEGIN { exit !(a < b) }' || fail "a larger quad should hide red sky: $l2 -> $l3"

# 3. A broken edit: an error with file and line, no new image, still running.
put "$dir/scene.xml" "<SceneLevel>
  <Camera position=\"0 0 6\" yaw=\"90\"/>
  <Objects>
    <Sphere center=\"0 0\" radius=\"1\"><Diffuse/></Sphere>
  </Objects>
</SceneLevel>"
for _ in $(seq 1 100); do grep -q "scene.xml:4: <Sphere>" "$err" && break; sleep 0.1; done
grep -q "^pathtracer: .*scene.xml:4: <Sphere>: attribute 'center'" "$err" || fail "no file:line error for the broken edit"
sleep 1
kill -0 "$pid" 2>/dev/null || fail "watch died on a broken edit"
[[ "$(md5sum <"$img")" == "$h3" ]] || fail "the last good image was replaced after a broken edit"
grep -q "generation 4" "$log" && fail "a broken edit made a generation"

# 4. Fixed again: rendering resumes.
scene "0 0 1"
l4=$(wait_gen 4) || exit 1
read -r r4 g4 b4 < <(mean "$l4")
awk -v r="$r4" -v b="$b4" 'BEGIN { exit !(b > 3 * r) }' || fail "blue sky not blue: $l4"

kill "$pid"
wait "$pid"
echo "ok: generations 1-4: $l1 | $l2 | $l3 | $l4"
