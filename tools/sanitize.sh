#!/usr/bin/env bash
# The C++ test suite again, built with AddressSanitizer (LeakSanitizer included) and
# UndefinedBehaviorSanitizer, in build-asan/. tools/test.sh runs it after the normal suite.
# The gtests run here, the CLI tests through the sanitized `fabform`; left to the normal suite
# are the fuzz targets (built with their own sanitizers, tools/fuzz.sh), the Python tools'
# tests, which run build/fabform, and the slow tests listed below (minutes each under the
# sanitizers, on code smaller tests here run too). The first report ends the process and fails
# the pass. Only the test binary and the CLI it runs are built.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# -O1 -g1: AddressSanitizer's recommended optimisation, and line tables for its stack traces;
# it compiles in about 60 % of -O2 -g's time (CGAL's arrangement file: 80 s against 178 s).
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
      -DFABFORM_SANITIZE=address,undefined -DCMAKE_UNITY_BUILD=ON \
      -DFABFORM_TEST_PER_PROCESS=ON >/dev/null
cmake --build build-asan -j"$(nproc)" --target fabform_tests

# Leaks are checked at every process exit; tools/lsan.supp holds what third-party libraries keep
# on purpose, each line explained.
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:check_initialization_order=1:strict_init_order=1
export LSAN_OPTIONS="suppressions=$PWD/tools/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# The tests whose process starts MPI: BoomerAMG's own, and those that run it beside the lattice
# multigrid or in Newton's steps on an arc mesh (names they contain).
MPI_TESTS=(AmgConjugateGradient LinearSolver AlgebraicMultigrid)
# Left to the normal suite: the tests that take 15 s or more under the sanitizers (minutes of CI's
# time bounded at 15), each on code a smaller test here runs too, named after the pattern.
SLOW=(
  # multigrid: the 81 x 81 dome's distance, stagnating steps on the 61 x 61 dome, the iteration
  # count up to 129 x 129 (the V-cycle and Newton's multigrid steps on small domes stay)
  '*ThousandByThousand*' '*MultigridNewtonOnTheDome*' '*MultigridStepsThatStagnate*'
  '*LatticeMultigrid.IterationsDoNotGrowWithTheGrid*'
  # shipped scenes at full size (RunResume runs the mold at 30 x 30; torso stays; the terms each
  # have their own small tests)
  '*ConvergesOnTheBodyWithoutEnteringIt/mold*' '*ConvergesOnTheBodyWithoutEnteringIt/dome*'
  '*ConvergesOnTheBodyWithoutEnteringIt/pin' '*ConvergesOnTheBodyWithoutEnteringIt/cusick*'
  '*ConvergesOnTheBodyWithoutEnteringIt/fold' # ShippedFold runs the same scene
  '*ShippedCadPunch*' '*ShippedCadDie*' '*ShippedCadVacuum*' '*ShippedCup.*' '*ReproducibleForming.*'
  # mesh repair over the whole corpus (the other MeshRepairProperties repair every mesh of it)
  '*KeepsTheSurfaceAndTheBoundingBox*' '*TheWrittenFileIsWhatTheReportPromised*'
  '*RepairingTwiceIsRepairingOnce*'
  # relax's sweeps (RelaxC's other cases, the Extremes' other solvers and cases stay)
  '*StepDivisorC*' '*RelaxC.Converges/0*' '*Extremes.NearVerticalTableSegment/dynamic*'
  '*Extremes.HarshStartOver1000PercentStrain/relax*' '*Extremes.NodesStartingExactlyOnTheSurface/relax*'
  '*Relax.LockedNodesInContactKeepTheirLockedCoordinates*'
  # interrupts: Interrupt.StopsAtTheEndOfTheIterationAndResumesBitForBit reads and writes the
  # same checkpoint with the same handler
  '*RunResume.*/Sig*' '*RunResumeInSteps.*'
  # drapes and folds: the flat and shrunk circles on every mesh, the lobed outline on the others
  '*FoldCountComesFromTheFabricNotTheMesh*' '*LobedOutlineHasAFoldPerLobe/quadrangular80*'
  '*LobedOutlineHasAFoldPerLobe/triangular41*' '*FlatCircleHasDCOneAndNoFolds/quadrangular80*'
  '*CusickDrape.SoftKnitFoldsOverTheDisc*' '*CusickDrape.BucklingKeepsTheAreaThatTensionOnlyLoses*'
  '*PinDrape.DynamicsNeverGainsEnergy*' '*Cantilever.BendingFrictionHoldsTheTip*'
  # the same bits twice: ResultRecordsVersionSceneHashAndThreads runs every solver
  '*Reproducible.SameBitsTwiceAndOnEitherThreadCount*'
  # brute-force references over many points: the same queries' small cases stay
  '*EdgeContact.TheReachIsTheDeepestPointOfTheSegmentInTheWedge*'
  '*RigidBodyRealMeshes.TorsoClosestMatchesBruteForce*'
  # two bodies, the sphere against relax, the large fabric's huge pages (the other ModelBuilder,
  # Newton and HugePages tests stay)
  '*ModelBuilder.TwoBodiesInTheirOwnUnitsBothHoldTheFabric*' '*Newton.FabricOverSphereAgreesWithRelax*'
  '*HugePages.ALargeFabricRunsWithThem*' '*RunCommand.TheScenesLockingAngleJudgesTheShear*'
)
SLOW_TESTS=$(IFS=':'; echo "${SLOW[*]}")

# The rest run inside one process per core, gtest's shards: a process per test, as ctest runs
# them, spent about 0.55 s starting each sanitized process, and the pass took 27 minutes on CI's
# two cores against 11 in shards. Each shard's output goes to its log and is printed after; its
# last "[ RUN ]" line names the test a report interrupted. They run where ctest runs them, in
# build-asan/tests.
mpi_patterns=$(printf '*%s*:' "${MPI_TESTS[@]}")
shards=$(nproc)
pids=()
for ((shard = 0; shard < shards; ++shard)); do
  (cd build-asan/tests && GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard \
     exec timeout 3600 ./fabform_tests --gtest_filter="-$mpi_patterns$SLOW_TESTS") \
    >"build-asan/sanitize-shard-$shard.log" 2>&1 &
  pids+=($!)
done
status=0
for ((shard = 0; shard < shards; ++shard)); do
  wait "${pids[$shard]}" || status=$?
  echo "== sanitized shard $((shard + 1)) of $shards"
  cat "build-asan/sanitize-shard-$shard.log"
done
[[ $status -eq 0 ]] || { echo "sanitize.sh: a sanitized shard failed (exit status $status)" >&2; exit "$status"; }

# The tests that start MPI (hypre's multigrid runs on it) again, each in its own process as ctest
# runs them (MPI starts once per process), with LeakSanitizer unwinding every allocation's stack
# in full: Open MPI's plugins allocate from frames without frame pointers, whose leaks
# tools/lsan.supp can only match by library on a full stack (slower, so only here). Dynamic TLS
# is not tracked here: LeakSanitizer's tracer read a bogus dynamic-TLS range in these processes
# and crashed after the test had passed ("Tracer caught signal 11"); TLS it does not scan can
# only make a leak appear, never hide one.
ASAN_OPTIONS="$ASAN_OPTIONS:fast_unwind_on_malloc=0:intercept_tls_get_addr=0" \
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" \
        -R "$(IFS='|'; echo "${MPI_TESTS[*]}")" -E "^(fuzz|tools|goldens)\\."
