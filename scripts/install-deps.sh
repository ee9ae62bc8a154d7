#!/usr/bin/env bash
# Installs the Debian packages and npm tools the build and the tests need, only when missing.
set -euo pipefail
packages=(
  build-essential cmake ccache pkg-config
  libboost-dev libeigen3-dev libtinygltf-dev libstb-dev libopenmesh-dev libcli11-dev
  catch2 libnanoflann-dev libtbb-dev libzstd-dev
  python3 python3-numpy python3-pywt python3-scipy nodejs
  nlohmann-json3-dev  # JSON of the language server (lsp/): header only, keeps integer ids exact
  chromium  # headless browser: three.js loads the pieces outputs (tests/pieces/browser)
  libdraco-dev libmeshoptimizer-dev  # --compress draco|meshopt (gltf_compress)
  # Blender's and Godot's glTF importers load the demo tree (scripts/check-engines.sh); with Xvfb
  # for Godot's editor, which imports assets. ~63 s to install on the project machine.
  blender godot3 xvfb xauth
  parallel  # GNU parallel: scripts/run-tiles.sh runs a tiled plot's tiles (tests/forest)
  # em++ (3.1.6, with its prebuilt libc/libc++): the runtime as WebAssembly (runtime/wasm/),
  # grown in headless Chromium by tests/runtime/test_wasm.cpp
  emscripten
  # clang with its sanitizer and libFuzzer runtimes: CI's ASan+UBSan build and the clang side of
  # the byte comparison (scripts/ci-extra.sh), and the fuzz preset
  clang libclang-rt-14-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  echo "installing: ${missing[*]}"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# npm tools used by the test suite live in tools/node_modules (not committed).
# Installs again when a package the list names is missing (the list grew since the last install).
npm_missing=0
for p in gltf-validator three playwright-core laz-perf; do
  [ -d "tools/node_modules/$p" ] || npm_missing=1
done
if [ -f tools/package.json ] && [ "$npm_missing" -eq 1 ]; then
  (cd tools && npm install --no-audit --no-fund --silent)
fi
