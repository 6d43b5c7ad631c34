#!/usr/bin/env bash
# Installs the Debian 12 packages skinlayer needs, then builds it.
#
#   ./setup.sh         install the packages only
#   ./setup.sh run     install, configure, build the command line, the previewer and the Python package
#                      (build/python: docs/guide/library.md) and start the previewer (build/skinlayer; without a
#                      display it says so and points to the headless `skinlayer render`)
#   ./setup.sh test    install, configure, build everything and run every test (with the glTF tools of npm in
#                      build-tools/; with SKINLAYER_BLENDER_CHROOTS=1 also Blender 4.3 and 5.2 in debootstrap chroots
#                      in build-blender/, 80 s and 1.0-1.35 GB each, and their render tests, 3-4 minutes each:
#                      docs/examples/blender); then build core, the command line's
#                      GL-free parsers, the readers' fuzz targets and their tests again with clang under
#                      AddressSanitizer + UndefinedBehaviorSanitizer (build-sanitize/: SKINLAYER_SANITIZE=address,
#                      SKINLAYER_FUZZ=ON, SKINLAYER_BUILD_APP=OFF), run those tests too but the slowest
#                      (sanitize_skipped), where any sanitizer report fails the test, and fuzz every reader for
#                      fuzz_seconds (tests/fuzz/run_fuzzers.sh); last, build the threaded code's tests under
#                      ThreadSanitizer (build-tsan/: SKINLAYER_SANITIZE=thread, target skinlayer_thread_tests) and
#                      run them (ctest -L threads), where any data race fails the test
#
# Idempotent: apt is skipped when every package is already installed, and an existing build folder is reused.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

readonly packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev libglm-dev libglfw3-dev libosmesa6-dev libimgui-dev libstb-dev
  nlohmann-json3-dev libpng-dev libpugixml-dev
  libgtest-dev libbenchmark-dev xvfb xauth fonts-dejavu-core python3-jsonschema
  clang libclang-rt-14-dev
  pybind11-dev python3-dev python3-numpy python3-pytest
  blender  # Blender 3.4: the exported Principled BSDF rendered in headless Cycles (tests/app/export, label blender)
  chromium  # three.js renders the glTF export in headless Chromium (tests/app/export/gltf_three_furnace.mjs)
  debootstrap  # Blender 4.3 and 5.2 from Debian 13 and unstable, in chroots (tests/app/export/make_blender_chroot.sh)
)
readonly tools_dir=build-tools
# Khronos' glTF-Validator, three.js and puppeteer-core (which drives Debian's chromium), pinned; puppeteer-core 25
# needs Node.js 22.
readonly npm_tools=(gltf-validator@2.0.0-dev.3.10 three@0.187.0 puppeteer-core@24.43.1)
readonly build_dir=build
readonly sanitize_dir=build-sanitize
readonly tsan_dir=build-tsan
readonly fuzz_seconds=12  # per reader, two readers at a time; their corpora are replayed first
# Any report stops the test with a stack trace. LeakSanitizer is on: it works in this VM (it needs ptrace-like
# thread suspension, which some containers forbid; there, add detect_leaks=0 to ASAN_OPTIONS).
readonly sanitizer_env=(
  ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:strict_string_checks=1
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
)
readonly tsan_env=(TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1)
# The sanitized builds keep line tables only (-g1): a report's stack still names file and line, and the builds take a
# quarter less time than with full debug information (-g: 36 s against 28 s for core's heaviest file under ASan).
readonly sanitized_flags=("-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
# The threaded tests are small (their solves on few ordinates), so ThreadSanitizer's build optimises less (-O1:
# core's heaviest file in 13 s instead of 16).
readonly tsan_flags=("-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG")

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
  local options=(-DCMAKE_BUILD_TYPE=Release "$@")
  if [[ -f "$build_dir/CMakeCache.txt" ]]; then
    cmake -S . -B "$build_dir" "${options[@]}"  # keep the generator the folder was made with
  else
    cmake -S . -B "$build_dir" -G Ninja "${options[@]}"
  fi
}

# The npm tools of the glTF checks, in build-tools/node_modules; Node.js from Debian where the machine has none.
# Prints the CMake option that points the tests at them, or nothing where npm cannot install them (the tests are then
# left out, and configuring says so).
install_npm_tools() {
  if ! command -v npm > /dev/null; then
    echo "setup.sh: installing nodejs npm" >&2
    local as_root=()
    ((EUID == 0)) || as_root=(sudo)
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -o DPkg::Lock::Timeout=600 nodejs npm >&2 ||
      return 0
  fi
  if [[ ! -d "$tools_dir/node_modules/gltf-validator" || ! -d "$tools_dir/node_modules/puppeteer-core" ]]; then
    mkdir -p "$tools_dir"
    npm install --no-audit --no-fund --prefix "$tools_dir" "${npm_tools[@]}" >&2 ||
      { echo "setup.sh: npm could not install ${npm_tools[*]}; the glTF tool tests are left out" >&2; return 0; }
  fi
  echo "-DSKINLAYER_GLTF_TOOLS=$PWD/$tools_dir/node_modules"
}

# Debian's Blender 4.3 (trixie) and 5.2 (sid) in chroots, and their render tests, where SKINLAYER_BLENDER_CHROOTS=1
# asks for them (root and debootstrap needed; 80 s and 1.0-1.35 GB each). Not by default, nor in CI: their 60 renders
# (docs/examples/blender) do not fit CI's 45 minutes. Prints the CMake option that builds their tests, ON or OFF.
make_blender_chroots() {
  if [[ "${SKINLAYER_BLENDER_CHROOTS:-}" != 1 ]]; then
    echo "-DSKINLAYER_BLENDER_CHROOT_TESTS=OFF"
    return
  fi
  if ((EUID != 0)) || ! command -v debootstrap > /dev/null; then
    echo "setup.sh: the Blender 4.3 and 5.2 chroots need root and debootstrap; their tests are left out" >&2
    echo "-DSKINLAYER_BLENDER_CHROOT_TESTS=OFF"
    return
  fi
  local suite
  for suite in trixie sid; do
    tests/app/export/make_blender_chroot.sh "$suite" >&2 ||
      echo "setup.sh: no Blender chroot for $suite; its tests are left out" >&2
  done
  echo "-DSKINLAYER_BLENDER_CHROOT_TESTS=ON"
}

# Left out of the sanitized run (each passes in the plain run before it): the slowest checks under the sanitizers,
# 40 s to 4 minutes each there, whose code a faster test of the same family still takes under them. Without them
# the whole of `./setup.sh test` stays inside CI's 45 minutes on 2 cores.
sanitize_skipped_tests=(
  'SolverEnergy\.ConservativeHalfSpaceWithoutInterfaceAtExtremeAsymmetry.*'  # the other SolverEnergy checks
  'SolverEnergy\.EveryPairOfExtremeParametersGivesFiniteNonNegativeBoundedValues'
  'SolverEnergy\.InteractingExtremeParametersGiveFiniteNonNegativeBoundedValues'
  'LayerTables\.BsdfIsNonNegativeBesideALobeNarrowerThanAGridStep'            # the other LayerTables checks
  'SolverPreview\.TablesAreFiniteAndSmallerThanTheFullSolves'                 # the other SolverPreview checks
  'SkinSpectrum\.AgreesWithMonteCarloAtStrongAndWeakAbsorption'               # the other SkinSpectrum checks
  'UnscatteredLight\.PublishedValuesAtTheSharpLobes'                          # the other UnscatteredLight ones
  'UnscatteredLight\.MatchedBottomWithoutScatteringIsTheClosedFormBetweenNodes'
  'MeasuredSkin\.TheNistSpectraAreFitWithinTheTargets'                        # SkinSpectrumFit, SkinColorMatch
  'SkinSpectrumFit\.RecoversASpectrumOfItsOwnModel'
  'SkinColorMatch\.RoundTripsFromRandomReachableParameters'
  'PointAccuracy\.SharpInterfacesAreWithinOnePercentAtEveryJudgedPoint'      # the other PointAccuracy ones
  'PointAccuracy\.AQuantityThatIsZeroUpToRoundOffIsNotJudged'
  'InterfaceAlbedo\.WithinOneInAMillionOfAnAdaptiveIntegration'              # InterfaceAlbedo's brute force
  'MonteCarlo\.DirectionalAlbedosAgreeWithSolver'                            # SkinSpectrum's Monte Carlo
  'MonteCarlo\.BinnedBsdfInPlaneOfIncidenceAgreesWithSolver.*'
  'MonteCarlo\.BinnedBsdfInRingsOfExitAngleAgreesWithSolver.*'
  'InterfaceDirections\..*'                                                  # MultipleScattering's walk checks
  'MultipleScatteringEstimate\..*'
  'StackSolver\.UnscatteredLightThroughAnInterfaceBetweenLayersIsExact'      # the other StackSolver ones
  'StackSolver\.StackBrdfIsReciprocal'
  'StackSolver\.CuttingASlabIntoIdenticalSlabsChangesNothing'
  'ReferenceTables\.DisortIntensities'                                       # the van de Hulst tables
  'LayerProfile\.HalfSpaceMatchesTheWalkInEveryAnnulus'                      # the other LayerProfile ones
  'LayerProfile\.SlabReflectionAndTransmissionMatchTheWalk'
  'LayerProfile\.AgreesWithMcmlsAnnuli'
  'LayerProfile\.PointValuesAverageToTheAnnuli'
  'LayerProfile\.FarFromTheSourceTheShapeIsTheDiffusionDipoles'
  'RoughTopProfile\.ForwardScatteringHalfSpaceMatchesTheWalk'                # the other RoughTopProfile ones
  'RoughTopProfile\.RoughTopOverAnAbsorbingHalfSpaceMatchesTheWalk'
  'RoughTopProfile\.PointValuesAverageToTheAnnuli'
  'RoughTopProfile\.TwoLayerStackInMillimetresMatchesTheWalk'
  'RoughTopProfile\.DiffuseIncidenceMatchesTheWalkAveragedOverTheHemisphere'
  'RoughTopProfile\.AdaptiveModesLeaveTheProfile'
  'RoughTopSingleScattering\.IsTheFirstOrderInTheAlbedoOfTheFullSolve'       # its other checks
  'LateralFrequencyResponse\.WeakScatteringIsTheClosedFormOfSingleScatteringAtEveryFrequency'  # its other checks
  'SmoothFacesProfile\.AgreesWithMcmlsPublishedThreeLayerSample'           # its closed-form check
  'FiniteStackTransmittance\.RoughTopOverAFiniteSlabMatchesTheWalk'        # its closed forms and k-space checks
  'FiniteStackTransmittance\.RougherTopOverAnAbsorbingSlabMatchesTheWalk'
  'FiniteStackTransmittance\.TwoLayerStackInMillimetresMatchesTheWalk'
  'InternalFacesProfile\.StackWithAnInterfaceMatchesTheWalk'                # its identity and refusals
  'BottomFacesProfile\.RoughBottomMatchesTheWalk'                          # its totals, refusals and the bounce's
  'BottomFacesProfile\.PapersRoughBottomMatchesTheWalkUnderItsInterfaces'  # closed form
  'BottomFacesProfile\.LambertBaseMatchesTheWalk'
  'BottomFacesProfile\.SharperRoughBottomMatchesTheWalk'
  'ConservativeProfile\.PapersLayerMatchesTheWalk'                        # its totals
  'app\.ProfileCommand\.FiniteLayerUnderARoughTopTransmitsOnFinerOrdinates'     # the other ProfileCommand ones
  'app\.ProfileCommand\.InterfaceBetweenLayersIsTheCoresProfile'
  'app\.ProfileCommand\.RoughBottomIsTheCoresProfile'
  'app\.ProfileCommand\.ThePapersConservativeLayerIsTheCoresProfile'
  'GltfFit\.FindsAClearcoatedSurfaceAgain'                                 # its albedo match, 7 s here each
  'GltfFit\.FindsItsOwnParametersAgain'
  'CyclesPrincipledFit\.FindsACoatedSurfaceAgain'                          # its other two
)
sanitize_skipped="^($(IFS='|'; echo "${sanitize_skipped_tests[*]}"))$"
readonly sanitize_skipped

# The second build of `test`: core, the GL-free parsers and the readers' fuzz targets with their tests, with clang
# (libFuzzer) under ASan + UBSan; then each reader fuzzed for fuzz_seconds.
sanitize_test() {
  local options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "${sanitized_flags[@]}" -DSKINLAYER_SANITIZE=address
                 -DSKINLAYER_FUZZ=ON -DSKINLAYER_BUILD_APP=OFF -DSKINLAYER_BUILD_BENCH=OFF)
  # A folder configured before with another compiler (g++ until issue 28) cannot switch: it is made anew.
  if [[ -f "$sanitize_dir/CMakeCache.txt" ]] &&
     ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' "$sanitize_dir/CMakeCache.txt"; then
    echo "setup.sh: $sanitize_dir/ was configured with another compiler than clang; configuring it anew"
    rm -rf "$sanitize_dir"
  fi
  if [[ -f "$sanitize_dir/CMakeCache.txt" ]]; then
    cmake -S . -B "$sanitize_dir" "${options[@]}"
  else
    CC=clang CXX=clang++ cmake -S . -B "$sanitize_dir" -G Ninja "${options[@]}"
  fi
  # The build runs the test executables too (gtest_discover_tests lists their tests), so it gets the options.
  env "${sanitizer_env[@]}" cmake --build "$sanitize_dir" -j2
  env "${sanitizer_env[@]}" ctest --test-dir "$sanitize_dir" --output-on-failure -j2 -E "$sanitize_skipped"
  env "${sanitizer_env[@]}" tests/fuzz/run_fuzzers.sh "$sanitize_dir" "$fuzz_seconds"
}

# The third build of `test`: the threaded code's tests (the solver's parallel paths, the parallel-for, the solve
# worker, the export job: tests/CMakeLists.txt labels them `threads`) under ThreadSanitizer, with g++.
thread_sanitize_test() {
  local options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "${tsan_flags[@]}" -DSKINLAYER_SANITIZE=thread
                 -DSKINLAYER_BUILD_BENCH=OFF)
  if [[ -f "$tsan_dir/CMakeCache.txt" ]]; then
    cmake -S . -B "$tsan_dir" "${options[@]}"
  else
    cmake -S . -B "$tsan_dir" -G Ninja "${options[@]}"
  fi
  env "${tsan_env[@]}" cmake --build "$tsan_dir" -j2 --target skinlayer_thread_tests
  env "${tsan_env[@]}" ctest --test-dir "$tsan_dir" --output-on-failure -j2 -L threads
}

install_packages
case "${1:-}" in
  "")
    ;;
  run)
    configure
    cmake --build "$build_dir" -j2 --target skinlayer skinlayer-window skinlayer_python
    exec "$build_dir/skinlayer" "${@:2}"
    ;;
  test)
    chroot_option=$(make_blender_chroots)
    gltf_tools_option=$(install_npm_tools)
    configure "$chroot_option" ${gltf_tools_option:+"$gltf_tools_option"}
    cmake --build "$build_dir" -j2
    ctest --test-dir "$build_dir" --output-on-failure -j2
    sanitize_test
    thread_sanitize_test
    ;;
  *)
    echo "usage: ./setup.sh [run|test]" >&2
    exit 2
    ;;
esac
