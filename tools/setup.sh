#!/usr/bin/env bash
# Installs what the renderer needs from Debian/Ubuntu packages, then configures and builds it
# into build/. Safe to run again: apt and CMake skip what is already done.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
          libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools spirv-tools
          libglm-dev libglfw3-dev libtinygltf-dev libpng-dev libturbojpeg0-dev nlohmann-json3-dev libstb-dev libgtest-dev libimgui-dev
          xvfb xauth clang-format)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
fi

# Mesa's loader looks for a runtime directory; a shell without a session (CI, ssh) has none.
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp}"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-RelWithDebInfo}" ${CMAKE_ARGS:-}
cmake --build build --parallel
