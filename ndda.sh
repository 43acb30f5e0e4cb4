#!/usr/bin/env bash
# ndda: build and run.
#
#   ./ndda.sh                  install what is missing, build the program
#                              only (target ndda), run prm/default.prm
#   ./ndda.sh path/scene.prm   the same, running the given scene
#   ./ndda.sh test [ARGS]      install, build everything, and run the whole
#                              test suite (ctest ARGS, e.g. -L scene)
#   ./ndda.sh test-fast [ARGS] install, build only what the unit tests need
#                              (target ndda_unit_tests), run them (ctest -L
#                              unit ARGS; under a minute)
#   ./ndda.sh build            install and build everything (library,
#                              program, test programs, benchmarks)
#   ./ndda.sh validate         long: build everything, run every validation
#                              case and rewrite doc/validation.md, the
#                              gallery, the charts and the stability maps
#                              (not part of `test`)
#   ./ndda.sh sanitize [ARGS]  a Debug build with AddressSanitizer, LeakSanitizer
#                              and UndefinedBehaviorSanitizer in build-sanitize/
#                              (NDDA_SANITIZE_BUILD_DIR), the unit tests under
#                              them (ctest -L unit ARGS); fails on any report.
#                              About 32 min to build at -j1, 15 min of tests
#                              at -j1 (6 min with NDDA_SANITIZE_LEAKS=0, no
#                              leak check)
#
# Environment: NDDA_BUILD_DIR (default: build), NDDA_JOBS (default: number of
# cores; 2 for sanitize), NDDA_BUILD_TYPE (default: Release).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build_dir="${NDDA_BUILD_DIR:-$here/build}"
jobs="${NDDA_JOBS:-$(nproc 2>/dev/null || echo 2)}"
build_type="${NDDA_BUILD_TYPE:-Release}"

# OpenBLAS's Haswell kernels on every CPU that has AVX2 and FMA, whatever
# kernels it would pick (SkylakeX on an Intel CPU with AVX-512): results
# the same to the bit on AMD and Intel machines (CMakeLists.txt, which
# does the same for ctest). An OPENBLAS_CORETYPE already set is kept.
if [ -z "${OPENBLAS_CORETYPE:-}" ] && grep -qw avx2 /proc/cpuinfo 2>/dev/null &&
  grep -qw fma /proc/cpuinfo; then
  export OPENBLAS_CORETYPE=Haswell
fi

# Debian packages ndda needs to build and test. libopenblas0-serial:
# OpenBLAS (single-threaded), which Debian then makes the system's BLAS
# (update-alternatives); UMFPACK's factorization runs 3-5 times faster on
# it than on the reference BLAS (doc/performance.md). openmpi-bin: mpirun,
# for the tests that run on two MPI processes (libdeal.ii-dev's MPI is
# OpenMPI's).
packages=(cmake make g++ libdeal.ii-dev libcgal-dev numdiff python3 libopenblas0-serial openmpi-bin)
# And for ./ndda.sh validate's pictures (run with Debian's /usr/bin/python3).
plot_packages=(python3-numpy python3-matplotlib)

install_missing() {
  local missing=()
  for p in "${packages[@]}" "$@"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "ndda.sh: installing missing Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo="sudo"
    else
      echo "ndda.sh: not root and no sudo; please install: ${missing[*]}" >&2
      exit 1
    fi
  fi
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q "${missing[@]}"
}

# build TARGET [PACKAGES...]: install what is missing, configure if needed,
# and build TARGET (all: everything).
build() {
  local target="$1"
  shift
  install_missing "$@"
  if [ ! -f "$build_dir/CMakeCache.txt" ]; then
    echo "ndda.sh: configuring a $build_type build in $build_dir"
    cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type"
  fi
  echo "ndda.sh: building $target with $jobs jobs"
  cmake --build "$build_dir" --target "$target" -- -j"$jobs"
}

# sanitize [CTEST ARGS]: configure (once) and build the unit tests with
# -fsanitize=address,undefined against deal.II's debug library (Assert on),
# run them under the sanitizers, and fail if a test fails or any test's
# output holds a sanitizer report. Every report aborts its process
# (abort_on_error), which fails its test; the check of ctest's log catches
# one that a pipe would hide (parameters_documented).
sanitize() {
  local dir="${NDDA_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
  local j="${NDDA_JOBS:-2}"
  install_missing
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    echo "ndda.sh: configuring a Debug + ASan/UBSan build in $dir"
    cmake -S "$here" -B "$dir" -DCMAKE_BUILD_TYPE=Debug \
      -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
      -DNDDA_BUILD_BENCHMARKS=OFF
  fi
  echo "ndda.sh: building ndda_unit_tests (sanitized) with $j jobs"
  cmake --build "$dir" --target ndda_unit_tests -- -j"$j"

  if [ "${NDDA_SANITIZE_LEAKS:-1}" = 1 ]; then
    # Full allocation stacks, or the suppressions cannot see OpenMPI's frames
    # (scripts/sanitize.lsan.supp); the tests take 2.6 times as long.
    export ASAN_OPTIONS="detect_leaks=1:fast_unwind_on_malloc=0:abort_on_error=1"
  else
    export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1"
  fi
  export LSAN_OPTIONS="suppressions=$here/scripts/sanitize.lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:abort_on_error=1:suppressions=$here/scripts/sanitize.ubsan.supp"
  # OpenMPI: keep its plugins loaded until exit (their leaks stay
  # attributable) and leave SIGABRT to the sanitizers (no second backtrace).
  export OMPI_MCA_mca_base_component_disable_dlclose=1
  export PMIX_MCA_mca_base_component_disable_dlclose=1
  export OMPI_MCA_opal_signal=""

  local status=0
  (cd "$dir" && ctest --output-on-failure -j"$j" -L unit "$@") || status=$?
  local log="$dir/Testing/Temporary/LastTest.log"
  local pattern='ERROR: (Address|Leak)Sanitizer|runtime error:'
  if [ -f "$log" ] && grep -Eq "$pattern" "$log"; then
    echo "ndda.sh: sanitizer reports (the tests' whole output: $log):" >&2
    awk -v p="$pattern" '/^[0-9]+\/[0-9]+ Test: /{t = $3} $0 ~ p {print t ": " $0}' \
      "$log" >&2
    status=1
  fi
  return "$status"
}

case "${1:-}" in
  test)
    build all
    cd "$build_dir"
    ctest --output-on-failure -j"$jobs" "${@:2}"
    ;;
  test-fast)
    build ndda_unit_tests
    cd "$build_dir"
    ctest --output-on-failure -j"$jobs" -L unit "${@:2}"
    ;;
  build)
    build all
    ;;
  validate)
    build all "${plot_packages[@]}"
    py=/usr/bin/python3
    echo "ndda.sh: running the test suite (every validation case)"
    (cd "$build_dir" && ctest --output-on-failure -j"$jobs" -E '^validation_page$')
    echo "ndda.sh: the long validation runs (finer meshes; about 20 minutes)"
    mkdir -p "$build_dir/tests/inclined_crack_fine"
    (cd "$build_dir/tests/inclined_crack_fine" &&
      ../test_inclined_crack 0.00125 > screen-output 2>&1)
    mkdir -p "$build_dir/tests/uniaxial_compression_fine"
    (cd "$build_dir/tests/uniaxial_compression_fine" &&
      ../test_uniaxial_compression 0.004 > screen-output 2>&1)
    echo "ndda.sh: the benchmarks whose figures the page quotes"
    for b in "step_vs_plain_solve 1e4 1e5 --repeat 5" "contact_step" "crack_event 1e4 1e5"; do
      set -- $b
      mkdir -p "$build_dir/tests/benchmark_$1"
      (cd "$build_dir/tests/benchmark_$1" &&
        "$build_dir/benchmarks/$1" "${@:2}" > screen-output 2>&1)
    done
    "$py" "$here/scripts/validation_page.py" --template "$here/doc/validation.md.in" \
      --values "$build_dir/tests" --out "$here/doc/validation.md"
    "$here/scripts/validate_pictures.sh" "$build_dir/ndda" "$py"
    ;;
  sanitize)
    sanitize "${@:2}"
    ;;
  -h|--help)
    sed -n '2,27p' "$0"
    ;;
  *)
    scene="${1:-$here/prm/default.prm}"
    if [ ! -f "$scene" ]; then
      echo "ndda.sh: no such scene file: $scene" >&2
      exit 1
    fi
    scene="$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")"
    build ndda
    "$build_dir/ndda" "$scene"
    ;;
esac
