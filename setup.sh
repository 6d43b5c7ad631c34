#!/usr/bin/env bash
# Installs the Debian 12 packages skinlayer needs, then builds it.
#
#   ./setup.sh         install the packages only
#   ./setup.sh run     install, configure, build and start the previewer (build/skinlayer; without a display it
#                      says so and points to the headless `skinlayer render`)
#   ./setup.sh test    install, configure, build everything and run every test
#
# Idempotent: apt is skipped when every package is already installed, and an existing build folder is reused.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

readonly packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev libglm-dev libglfw3-dev libosmesa6-dev libimgui-dev libstb-dev
  libgtest-dev libbenchmark-dev xvfb xauth fonts-dejavu-core
)
readonly build_dir=build

install_packages() {
  local missing=()
  local package
  for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed'; then
      missing+=("$package")
    fi
  done
  if ((${#missing[@]} == 0)); then
    return
  fi
  echo "setup.sh: installing ${missing[*]}"
  local as_root=()
  if ((EUID != 0)); then
    as_root=(sudo)
  fi
  "${as_root[@]}" apt-get update
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -o DPkg::Lock::Timeout=600 "${packages[@]}"
}

configure() {
  if [[ -f "$build_dir/CMakeCache.txt" ]]; then
    cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release  # keep the generator the folder was made with
  else
    cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release
  fi
}

install_packages
case "${1:-}" in
  "")
    ;;
  run)
    configure
    cmake --build "$build_dir" -j2 --target skinlayer skinlayer-window
    exec "$build_dir/skinlayer" "${@:2}"
    ;;
  test)
    configure
    cmake --build "$build_dir" -j2
    ctest --test-dir "$build_dir" --output-on-failure -j2
    ;;
  *)
    echo "usage: ./setup.sh [run|test]" >&2
    exit 2
    ;;
esac
