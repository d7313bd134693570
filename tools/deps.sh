#!/usr/bin/env bash
# Installs what the project needs on Debian bookworm, only what is missing.
#   tools/deps.sh native   compilers, GL/EGL (Mesa llvmpipe), header libraries, Catch2,
#                          clang + libclang-rt-dev (libFuzzer and clang's sanitizer runtimes)
#   tools/deps.sh web      + Emscripten, Dear ImGui / tinyxml2 sources (Debian source packages)
#   tools/deps.sh test     + Chromium and playwright-core (npm, test tooling only)
# Safe to re-run; a no-op when everything is present.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
want="${1:-test}"

native_pkgs=(cmake ninja-build g++ ccache pkg-config libglm-dev libtinyxml2-dev libstb-dev
             catch2 libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri libgbm1 libtinyobjloader-dev
             libtinygltf-dev nlohmann-json3-dev clang libclang-rt-dev python3)
web_pkgs=(emscripten dpkg-dev)
test_pkgs=(chromium nodejs npm)

pkgs=("${native_pkgs[@]}")
[[ "$want" == web || "$want" == test ]] && pkgs+=("${web_pkgs[@]}")
[[ "$want" == test ]] && pkgs+=("${test_pkgs[@]}")

SUDO=""; [[ $(id -u) -ne 0 ]] && SUDO="sudo"
missing=()
for p in "${pkgs[@]}"; do
  # node/npm may come from elsewhere (nodesource): accept the command
  if [[ "$p" == nodejs ]] && command -v node >/dev/null; then continue; fi
  if [[ "$p" == npm ]] && command -v npm >/dev/null; then continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done

ensure_deb_src() {
  if ! grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    echo "deps: enabling deb-src for Debian source packages"
    if [[ -f /etc/apt/sources.list.d/debian.sources ]]; then
      $SUDO sed -i 's/^Types: deb$/Types: deb deb-src/' /etc/apt/sources.list.d/debian.sources
    else
      grep -E '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' | $SUDO tee /etc/apt/sources.list.d/deb-src.list >/dev/null
    fi
    APT_UPDATED=""
  fi
}
APT_UPDATED=""
apt_update() { [[ -n "$APT_UPDATED" ]] || { $SUDO apt-get update -qq; APT_UPDATED=1; }; }

if [[ ${#missing[@]} -gt 0 ]]; then
  echo "deps: installing ${missing[*]}"
  apt_update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Sources compiled into the wasm build: Debian source packages, unpacked under third_party/ (ignored by git).
if [[ "$want" == web || "$want" == test ]]; then
  mkdir -p "$here/third_party"
  for src in imgui tinyxml2; do
    if ! ls -d "$here/third_party/$src"-*/ >/dev/null 2>&1; then
      ensure_deb_src; apt_update
      (cd "$here/third_party" && apt-get source -qq --download-only "$src" >/dev/null && \
         dpkg-source -x --skip-patches "$src"_*.dsc >/dev/null 2>&1 || dpkg-source -x "$src"_*.dsc >/dev/null)
      rm -f "$here/third_party/$src"_*
    fi
  done
fi

if [[ "$want" == test ]]; then
  if [[ ! -d "$here/tests/browser/node_modules/playwright-core" ]]; then
    (cd "$here/tests/browser" && npm install --no-audit --no-fund --silent)
  fi
fi
echo "deps: ok ($want)"
