#!/bin/sh
# Installs the Debian packages thinlight needs, and only those that are missing.
# Run as root (or with sudo available). Safe to run again: it does nothing when all are there.
set -eu
PACKAGES="cmake make gcc g++ pkg-config python3 python3-glad libosmesa6-dev libegl-dev libegl-mesa0 libgl-dev libglfw3-dev libembree-dev \
libtinygltf-dev nlohmann-json3-dev libopenimageio-dev gnuplot-nox glslang-tools doxygen \
clang libclang-rt-14-dev valgrind libimgui-dev xvfb xauth"
missing=""
for p in $PACKAGES; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed"; then
    missing="$missing $p"
  fi
done
if [ -z "$missing" ]; then
  echo "install-deps: all packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" != 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "install-deps: missing packages:$missing; run this script as root" >&2
    exit 1
  fi
fi
echo "install-deps: installing$missing"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
# shellcheck disable=SC2086
$SUDO apt-get install -y -q --no-install-recommends $missing
