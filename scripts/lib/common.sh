# Shared by scripts/run, scripts/test and scripts/bench: install what the
# project needs from Debian (idempotent), then configure and build.
# Environment: VIBROTHERM_BUILD_DIR (default build), VIBROTHERM_BUILD_TYPE (Release).

VIBROTHERM_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
BUILD_DIR=${VIBROTHERM_BUILD_DIR:-$VIBROTHERM_ROOT/build}

DEBIAN_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  petsc-dev slepc-dev libhdf5-openmpi-dev openmpi-bin
  libmetis-dev libgmsh-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-numpy python3-h5py python3-matplotlib python3-scipy python3-pandas python3-xarray
)

log() { printf '[vibrotherm] %s\n' "$*" >&2; }

# What the project needs: the Debian packages, then `import vibrotherm` for Debian's python3.
install_dependencies() {
  install_debian_packages
  install_python_package
}

install_debian_packages() {
  local missing=()
  for pkg in "${DEBIAN_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  if [ ${#missing[@]} -eq 0 ]; then return 0; fi
  log "installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
}

# `import vibrotherm` in Debian's /usr/bin/python3 (the package scripts/vibrotherm): a
# vibrotherm.pth naming this checkout's scripts/ in Python's site directory
# (/usr/local/lib/python3.X/dist-packages as root, the user's site directory otherwise;
# VIBROTHERM_SITE_DIR overrides). Written when missing or when the checkout it names is gone;
# one naming another checkout that exists is left alone (a line says so). Idempotent.
install_python_package() {
  local site want="$VIBROTHERM_ROOT/scripts"
  if [ -n "${VIBROTHERM_SITE_DIR:-}" ]; then site=$VIBROTHERM_SITE_DIR
  elif [ "$(id -u)" -eq 0 ]; then site=$(/usr/bin/python3 -c 'import site; print(site.getsitepackages()[0])')
  else site=$(/usr/bin/python3 -m site --user-site); fi
  local pth="$site/vibrotherm.pth"
  if [ -f "$pth" ]; then
    local have
    have=$(head -n 1 "$pth")
    [ "$have" = "$want" ] && return 0
    if [ -f "$have/vibrotherm/__init__.py" ]; then
      log "import vibrotherm loads $have (another checkout; $pth): left as it is"
      return 0
    fi
  fi
  if mkdir -p "$site" 2>/dev/null && printf '%s\n' "$want" > "$pth.partial" 2>/dev/null && mv "$pth.partial" "$pth"; then
    log "import vibrotherm: $pth names $want"
  else
    log "could not write $pth: use PYTHONPATH=$want to import vibrotherm"
  fi
}

# build_project [TARGET...]: every target by default, or only the given ones.
build_project() {
  local generator=() targets=()
  for target in "$@"; do targets+=(--target "$target"); done
  command -v ninja >/dev/null && generator=(-G Ninja)
  if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
    cmake -S "$VIBROTHERM_ROOT" -B "$BUILD_DIR" "${generator[@]}" \
      -DCMAKE_BUILD_TYPE="${VIBROTHERM_BUILD_TYPE:-Release}" >/dev/null
  fi
  cmake --build "$BUILD_DIR" -j "$(nproc)" "${targets[@]}"
}

# Open MPI refuses to run as root unless told; CI and these machines run as root.
mpi_environment() {
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  export OMPI_MCA_rmaps_base_oversubscribe=1
}
