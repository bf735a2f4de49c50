# Shared by the project's commands: installing what they need, configuring and building.
# Sourced, not run.

# The Debian packages a full build and test run needs.
POINTMASS_PACKAGES=(cmake ninja-build g++ clang libclang-rt-14-dev libboost-dev doctest-dev
                    libbenchmark-dev libtbb-dev gnuplot-nox doxygen pkg-config
                    libglm-dev libeigen3-dev  # test-only (tests/packaging/user_vectors)
                    libtrilinos-kokkos-dev)  # pointmass::kokkos and tests/kokkos (Serial backend)

# Installs those of the named Debian packages that are missing (apt-get update first, once).
ensure_packages() {
  local missing=() package
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' ||
      missing+=("$package")
  done
  ((${#missing[@]} == 0)) && return 0
  local sudo=()
  [[ $(id -u) -ne 0 ]] && sudo=(sudo)
  echo "== installing: ${missing[*]}"
  "${sudo[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
}

# configure_and_build BUILD_DIR [cmake arguments...]: configure with Ninja and build all.
configure_and_build() {
  local dir=$1
  shift
  cmake -S "$POINTMASS_ROOT" -B "$dir" -G Ninja "$@"
  cmake --build "$dir" --parallel "$(nproc)"
}

POINTMASS_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# replace_between_markers DOC NAME FILE: replaces what stands between the lines
# <!-- NAME:begin --> and <!-- NAME:end --> of DOC with the contents of FILE.
replace_between_markers() {
  local doc=$1 name=$2 file=$3
  grep -q "<!-- $name:begin -->" "$doc" && grep -q "<!-- $name:end -->" "$doc" ||
    { echo "$doc has no <!-- $name:begin --> ... <!-- $name:end --> markers" >&2; return 1; }
  awk -v table="$file" -v begin="<!-- $name:begin -->" -v end="<!-- $name:end -->" '
    $0 == end { skipping = 0 }
    !skipping { print }
    $0 == begin { while ((getline line < table) > 0) print line; skipping = 1 }
  ' "$doc" > "$doc.new" && mv "$doc.new" "$doc"
}
