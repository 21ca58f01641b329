#!/usr/bin/env bash
# Installs every Debian package inbetween needs, then configures and builds (Release).
# Idempotent: safe to run twice. Usage: scripts/setup.sh [BUILD_DIR]   (default: build)
# INBETWEEN_WERROR=ON in the environment makes compiler warnings errors (.ci/run sets it);
# INBETWEEN_ENGINE=OFF installs and builds the solver alone (no Vulkan, GLFW, ImGui, Xvfb or Chromium).
# Both install the npm packages of the export's client checks (tests/clients, pinned by its
# package-lock.json) into tests/clients/node_modules. INBETWEEN_SETUP_ONLY=1 installs and stops
# there (scripts/sanitize.sh, scripts/fuzz.sh configure their own builds).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$here/build"}

packages=(
  build-essential cmake pkg-config git
  libeigen3-dev libmetis-dev libopenmesh-dev catch2 nlohmann-json3-dev
  libcgal-dev libpotrace-dev libpng-dev
  libtinygltf-dev libstb-dev libmeshoptimizer-dev
  clang-14 libclang-rt-14-dev libomp-14-dev  # the sanitizer and fuzz builds (scripts/sanitize.sh, fuzz.sh)
  strace  # the tests that kill a command in the middle of its writes
)
engine_packages=(
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools
  libglfw3-dev libglm-dev libimgui-dev
  xvfb xauth xdotool  # xdotool: real input events for the window tests
  chromium
)
[ "${INBETWEEN_ENGINE:-ON}" = "OFF" ] || packages+=("${engine_packages[@]}")
command -v npm >/dev/null || packages+=(nodejs npm)  # any Node.js with npm will do

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The client checks' npm packages, again whenever package-lock.json is newer than node_modules.
clients="$here/tests/clients"
if [ ! -d "$clients/node_modules" ] || [ "$clients/package-lock.json" -nt "$clients/node_modules" ]; then
  echo "setup: npm ci in tests/clients"
  (cd "$clients" && npm ci --no-audit --no-fund)
  touch "$clients/node_modules"
fi

[ -z "${INBETWEEN_SETUP_ONLY:-}" ] || exit 0

options=(-DCMAKE_BUILD_TYPE=Release)
[ -z "${INBETWEEN_WERROR:-}" ] || options+=("-DINBETWEEN_WERROR=$INBETWEEN_WERROR")
[ -z "${INBETWEEN_ENGINE:-}" ] || options+=("-DINBETWEEN_ENGINE=$INBETWEEN_ENGINE")
cmake -S "$here" -B "$build" "${options[@]}"
cmake --build "$build" -j "$(nproc)"
