#!/usr/bin/env bash
# Installs every Debian 12 package amrstream needs to build, test and run. Idempotent: when
# everything is already present it only checks and returns. Works as root or through sudo.
# Lavapipe with ray query / ray tracing pipelines needs Mesa from bookworm-backports, so this
# adds that suite when it is missing (see the README; scikit-build-core comes from there too).
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  # a compiler cache: a second build of the same sources (CI's fresh clone) compiles only changes
  ccache
  libglm-dev libgtest-dev libgmock-dev libcli11-dev libfmt-dev libtbb-dev nlohmann-json3-dev
  # VTK's Python modules come with python3-paraview (below), which conflicts with python3-vtk9
  python3 python3-numpy python3-pytest python3-yt python3-matplotlib pybind11-dev
  # the Python package: pip into a venv (python3-venv), with scikit-build-core (backports);
  # its stubs' check (mypy's stubtest)
  python3-venv mypy
  libvulkan-dev glslang-tools spirv-tools vulkan-validationlayers vulkan-tools
  libhdf5-dev libpng-dev zlib1g-dev liblz4-dev libdeflate-dev libexpat1-dev
  # text in rendered images: FreeType and the DejaVu Sans font
  libfreetype-dev fonts-dejavu-core
  libglfw3-dev libimgui-dev xvfb xauth
  # the ParaView plugin and its tests (pvpython, pvbatch); VTK's Python modules for the tests
  paraview python3-paraview
  # MPI: distributed tracing and its tests (mpirun)
  libopenmpi-dev openmpi-bin
  # the sources' format check (scripts/check_format.sh)
  clang-format
  # clang and its libFuzzer runtime (a recommendation, which --no-install-recommends skips)
  # for scripts/fuzz.sh
  clang libclang-rt-dev
)
backports_packages=(mesa-vulkan-drivers python3-scikit-build-core)

if [ "$(id -u)" -eq 0 ]; then
  as_root() { "$@"; }
elif command -v sudo >/dev/null 2>&1; then
  as_root() { sudo "$@"; }
else
  echo "install_deps: need root or sudo to install packages" >&2
  exit 1
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

backports_missing=()
for p in "${backports_packages[@]}"; do
  version=$(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || true)
  case "$version" in
    *bpo*) ;;
    *) backports_missing+=("$p") ;;
  esac
done

if [ ${#missing[@]} -eq 0 ] && [ ${#backports_missing[@]} -eq 0 ]; then
  echo "install_deps: all packages present"
  exit 0
fi

backports_file=/etc/apt/sources.list.d/amrstream-bookworm-backports.sources
if ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  echo "install_deps: adding the bookworm-backports suite ($backports_file)"
  as_root tee "$backports_file" >/dev/null <<'SRC'
Types: deb
URIs: http://deb.debian.org/debian
Suites: bookworm-backports
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
fi

export DEBIAN_FRONTEND=noninteractive
echo "install_deps: installing ${missing[*]} ${backports_missing[*]}"
as_root apt-get update -q
if [ ${#missing[@]} -gt 0 ]; then
  as_root apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
if [ ${#backports_missing[@]} -gt 0 ]; then
  as_root apt-get install -y -q --no-install-recommends -t bookworm-backports "${backports_missing[@]}"
fi
echo "install_deps: done"
