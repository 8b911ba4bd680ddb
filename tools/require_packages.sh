# Sourced by iecoop's scripts: installs the Debian packages a command needs, if missing.
# shellcheck shell=sh

# iecoop_require_packages <package>...: apt-get installs the packages not yet installed
# (as root, or through sudo). On a system without dpkg it only checks for cmake.
iecoop_require_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    command -v cmake >/dev/null 2>&1 || { echo "iecoop: install cmake and: $*" >&2; return 1; }
    return 0
  fi
  missing=""
  for package in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      missing="$missing $package"
    fi
  done
  [ -z "$missing" ] && return 0
  echo "iecoop: installing$missing" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  # shellcheck disable=SC2086 # the package list is meant to split
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing
}

# iecoop_jobs: how many jobs a script's builds and tests run at once: CMAKE_BUILD_PARALLEL_LEVEL
# where it is set (CMake's own variable, so a shared machine's setting holds for every build),
# else the number of cores.
iecoop_jobs() {
  if [ -n "${CMAKE_BUILD_PARALLEL_LEVEL:-}" ]; then
    echo "$CMAKE_BUILD_PARALLEL_LEVEL"
  else
    nproc 2>/dev/null || echo 2
  fi
}
