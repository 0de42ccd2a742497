#!/usr/bin/env bash
# Installs every dependency Insula needs on Debian 12: Debian packages with apt-get and the npm test
# tools into tools/node_modules. Idempotent: a second run only checks.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build pkg-config clang-format
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libpolyclipping-dev nlohmann-json3-dev libtinygltf-dev libcli11-dev libfmt-dev libtbb-dev
  libgtest-dev libgmock-dev libbenchmark-dev libstb-dev liblua5.4-dev libpugixml-dev libqhull-dev
  libgoogle-perftools-dev libproj-dev proj-bin libassimp-dev libsimdjson-dev
  libmeshoptimizer-dev  # glTF vertex optimisation and EXT_meshopt_compression
  libosmium2-dev libprotozero-dev zlib1g-dev libbz2-dev libexpat1-dev osmium-tool  # .osm/.osm.pbf input
  clang libclang-rt-dev llvm  # libFuzzer (scripts/fuzz.sh), llvm-symbolizer for sanitizer stacks
  assimp-utils libxml2-utils
  chromium  # the browser check of textured GLBs (tools/render_gltf_browser.mjs, three.js)
  blender python3-numpy  # opening OBJ and GLB as users do (tests/cli/blender_import.sh)
  openmpi-bin libopenmpi-dev  # mpirun insula mass ... -o DIR/tileset.json (docs/cluster.md)
  libcpp-httplib-dev curl  # insula studio's server (docs/studio.md), and its test
)
# Node.js may come from elsewhere (NodeSource ships npm inside nodejs); take Debian's only if absent.
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if [ ! -d tools/node_modules/gltf-validator ] || [ ! -d tools/node_modules/ajv ] ||
  [ ! -d tools/node_modules/playwright-core ] || [ ! -d tools/node_modules/three ] ||
  [ ! -d tools/node_modules/gltfpack ] || [ ! -d tools/node_modules/cesium ] ||
  [ ! -d tools/node_modules/@loaders.gl/tiles ]; then
  echo "setup: installing npm test tools (gltf-validator, ajv, playwright-core, three, gltfpack, cesium, loaders.gl)" >&2
  (cd tools && npm ci --no-audit --no-fund --silent 2>/dev/null || npm install --no-audit --no-fund --silent)
fi

# The studio's page (web/, docs/studio.md): CodeMirror, three.js and esbuild from npm, bundled
# into web/dist/ (a fraction of a second; always redone, so the page follows its sources).
if [ ! -x web/node_modules/.bin/esbuild ] || [ ! -d web/node_modules/codemirror ] ||
  [ ! -d web/node_modules/three ]; then
  echo "setup: installing the studio page's npm packages (codemirror, three, esbuild)" >&2
  (cd web && npm ci --no-audit --no-fund --silent 2>/dev/null || npm install --no-audit --no-fund --silent)
fi
(cd web && npm run --silent build >/dev/null)
