# SPDX-License-Identifier: BSL-1.0
# Shared by the project's commands: installing what they need, configuring and building.
# Sourced, not run.

# The Debian packages the builds for other processors need (scripts/test.sh i386, aarch64
# and armv7; scripts/determinism-report.sh): g++ -m32, and clang's ARM targets under qemu.
POINTMASS_CROSS_PACKAGES=(g++-multilib
                          qemu-user binutils-aarch64-linux-gnu libc6-dev-arm64-cross
                          libstdc++-12-dev-arm64-cross libgcc-12-dev-arm64-cross
                          binutils-arm-linux-gnueabihf libc6-dev-armhf-cross
                          libstdc++-12-dev-armhf-cross libgcc-12-dev-armhf-cross)

# The Debian packages a full build and test run needs.
POINTMASS_PACKAGES=(cmake ninja-build g++ clang libclang-rt-14-dev libboost-dev doctest-dev
                    libbenchmark-dev libtbb-dev gnuplot-nox doxygen pkg-config
                    libglm-dev libeigen3-dev  # test-only (tests/packaging/user_vectors)
                    libxxhash-dev  # test-only: the state hash against XXH64 (tests/system)
                    libtrilinos-kokkos-dev  # pointmass::kokkos and tests/kokkos (Serial backend)
                    clang-format-14 clang-tidy-14  # tests/lint (POINTMASS_LINT)
                    "${POINTMASS_CROSS_PACKAGES[@]}")

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

# The benchmark scripts' steps.

# CMake arguments for a build of the benchmarks alone (no tests, no examples).
POINTMASS_BENCHMARKS_ONLY=(-DPOINTMASS_BUILD_TESTS=OFF -DPOINTMASS_BUILD_EXAMPLES=OFF
                           -DPOINTMASS_BUILD_BENCHMARKS=ON)

# build_release BUILD_DIR "TARGET..." [cmake arguments...]: configures BUILD_DIR (Ninja,
# Release, -march=native, or the compiler flags in RELEASE_CXX_FLAGS) and builds the named
# targets, quietly.
build_release() {
  local dir=$1 targets=$2
  shift 2
  cmake -S "$POINTMASS_ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" \
    -DCMAKE_CXX_FLAGS="${RELEASE_CXX_FLAGS:--march=native}" >/dev/null
  # shellcheck disable=SC2086  # the targets are words
  cmake --build "$dir" --target $targets >/dev/null
}

# run_repetitions JSON PROGRAM REPETITIONS MIN_TIME [arguments...]: runs the Google Benchmark
# PROGRAM with REPETITIONS interleaved repetitions of at least MIN_TIME seconds each, and
# writes the aggregates (medians among them) as JSON to the file JSON.
run_repetitions() {
  local json=$1 program=$2 repetitions=$3 min_time=$4
  shift 4
  "$program" "$@" --benchmark_repetitions="$repetitions" \
    --benchmark_enable_random_interleaving=true --benchmark_min_time="$min_time" \
    --benchmark_report_aggregates_only=true --benchmark_format=json >"$json"
}

# processor_name: the processor's model, as /proc/cpuinfo names it, with its family and model
# numbers and the first core's caches, for the tables' Machine line (a model name such as
# "AMD EPYC" covers several generations, whose caches and vector units differ), e.g.
# "AMD EPYC (family 25, model 17; L1d 32 KiB, L2 1 MiB, L3 32 MiB)"; "unknown
# processor" where /proc/cpuinfo does not name it.
processor_name() {
  local name family model caches="" index level type size
  name=$(sed -n '/^model name/{s/^[^:]*:[[:space:]]*//p;q;}' /proc/cpuinfo 2>/dev/null || true)
  family=$(sed -n '/^cpu family/{s/^[^:]*:[[:space:]]*//p;q;}' /proc/cpuinfo 2>/dev/null || true)
  model=$(sed -n '/^model[[:space:]]*:/{s/^[^:]*:[[:space:]]*//p;q;}' /proc/cpuinfo 2>/dev/null || true)
  for index in /sys/devices/system/cpu/cpu0/cache/index*; do
    [[ -r $index/level && -r $index/type && -r $index/size ]] || continue
    level=$(<"$index/level") type=$(<"$index/type") size=$(<"$index/size")
    [[ $type == Instruction ]] && continue
    size=${size/%K/ KiB}
    [[ $size == *" KiB" && $((${size% KiB} % 1024)) == 0 ]] && size="$((${size% KiB} / 1024)) MiB"
    case $level in
      1) caches+="${caches:+, }L1d $size" ;;
      2) caches+="${caches:+, }L2 $size" ;;
      *) caches+="${caches:+, }L$level $size" ;;
    esac
  done
  local details="${family:+family $family, model $model}"
  [[ -n $caches ]] && details+="${details:+; }$caches"
  echo "${name:-unknown processor}${details:+ ($details)}"
}

# median_table JSON REPETITIONS [MORE...] <<'PY' ... PY: runs the Python script on standard
# input with sys.argv[1:] = JSON REPETITIONS [MORE...] and, defined before it, `data` (the
# JSON report), `ctx` (its context), `rate` (run name -> median items_per_second, in
# millions) and `processor` (processor_name). Then noisy_note's sentence, if any, under the
# tables.
median_table() {
  POINTMASS_PROCESSOR=$(processor_name) python3 - "$@" <<<"import json, os, sys
data = json.load(open(sys.argv[1]))
rate = {b['run_name']: b['items_per_second'] / 1e6
        for b in data['benchmarks'] if b.get('aggregate_name') == 'median'}
ctx = data['context']
processor = os.environ['POINTMASS_PROCESSOR']
$(cat)"
  local note
  note=$(noisy_note "$1" items_per_second)
  if [[ -n $note ]]; then printf '\n%s\n' "$note"; fi
}

# noisy_note JSON METRIC: if the repetitions of any benchmark of the report JSON varied by more
# than POINTMASS_NOISY_CV (0.10: the coefficient of variation of METRIC, items_per_second or
# cpu_time), prints a sentence saying so, on standard output and on standard error: another
# load on the machine for part of the run (here every loop ran at about half its speed for
# seconds at a time, with nothing of the project's running), so that loops timed in different
# parts of it may compare wrongly, and the command is worth running again. Quiet: nothing.
noisy_note() {
  python3 - "$1" "$2" <<'PY'
import json, os, sys
data, metric = json.load(open(sys.argv[1])), sys.argv[2]
cv = {b['run_name']: b[metric]
      for b in data['benchmarks'] if b.get('aggregate_name') == 'cv' and metric in b}
limit = float(os.environ.get('POINTMASS_NOISY_CV', '0.10'))
noisy = sorted(((v, k) for k, v in cv.items() if v > limit), reverse=True)
if noisy:
    note = (f'Not a quiet run: the repetitions of {len(noisy)} of the {len(cv)} benchmarks '
            f'varied by more than {limit:.0%} (the most, {noisy[0][0]:.0%}, {noisy[0][1]}), so '
            'loops timed in different parts of the run may compare wrongly; run the command '
            'again on a quiet machine.')
    print(note)
    print(note, file=sys.stderr)
PY
}

# publish_table DOC NAME FILE: prints FILE and writes it into DOC between the NAME markers.
publish_table() {
  cat "$3"
  replace_between_markers "$1" "$2" "$3"
  echo "updated ${1#"$POINTMASS_ROOT"/}"
}
