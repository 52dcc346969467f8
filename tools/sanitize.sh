#!/usr/bin/env bash
# The whole suite under AddressSanitizer and UndefinedBehaviorSanitizer (CI runs it after the
# README's test command; needs what tools/bootstrap.sh installs). Builds into build-asan/ and
# runs ctest there in two passes:
#  1. the project's own programs (tests, cvt, examples), with leak checking;
#  2. tests whose sanitized code runs inside a host built without sanitizers (python3,
#     pvpython, pvbatch, paraview, a downstream program): the runtime is preloaded into the
#     host and leaks are not checked, since the hosts leak at exit by themselves (Python about
#     1.8 MB) and LeakSanitizer suppressions by module would hide the project's leaks too.
# No suppressions: VTK 9.2's vtkStaticCleanPolyData leak is avoided in the code.
# Usage: tools/sanitize.sh [BUILD_DIR]   (default build-asan)
set -u
cd "$(dirname "$0")/.."
BUILD=${1:-build-asan}
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
link="-fsanitize=address,undefined"
mkdir -p "$BUILD"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$link" -DCMAKE_SHARED_LINKER_FLAGS="$link" \
  -DCMAKE_MODULE_LINKER_FLAGS="$link" > "$BUILD/sanitize-configure.log" 2>&1 ||
  { cat "$BUILD/sanitize-configure.log"; exit 1; }
cmake --build "$BUILD" -j"$(nproc)" > "$BUILD/sanitize-build.log" 2>&1 ||
  { tail -40 "$BUILD/sanitize-build.log"; exit 1; }

# abort_on_error: a sanitizer report ends the process with a signal, as a crash does (the CLI
# reads input files in a child first and reports a reader crash there as a clean error).
# intercept_tls_get_addr=0: gcc 12's LeakSanitizer otherwise sometimes dies in its own
# tracer ("Tracer caught signal 11", google/sanitizers#1322).
common=halt_on_error=1:abort_on_error=1:intercept_tls_get_addr=0:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
hosted='^(python-modules|example-stipple-python|example-remesh-python|paraview-plugin|paraview-client-server|example-paraview|example-pvbatch|paraview-mpi.*|paraview-gui-.*|install-downstream|x11-window-context)$'
# paraview-mpi and paraview-mpi-abort run in pvbatch under mpiexec. x11-window-context is hosted too: Mesa unloads its GLX driver before exit, so a leak of the
# driver shows as <unknown module> and cannot be told from the project's.
rc=0
echo "== sanitizers, pass 1: the project's programs, leak checking on"
ASAN_OPTIONS=detect_leaks=1:$common \
  ctest --test-dir "$BUILD" -E "standalone-vtk|$hosted" -j"$(nproc)" --output-on-failure || rc=1
echo "== sanitizers, pass 2: hosted in python3/pvpython/pvbatch/paraview, runtime preloaded"
# libstdc++ too: python3 does not link it, and the sanitizer's throw interceptor needs it.
LD_PRELOAD="$(g++ -print-file-name=libasan.so) $(g++ -print-file-name=libstdc++.so.6)" \
  ASAN_OPTIONS=detect_leaks=0:$common \
  ctest --test-dir "$BUILD" -R "$hosted" -j"$(nproc)" --output-on-failure || rc=1
[ $rc -eq 0 ] && echo "sanitizers: ok" || echo "sanitizers: FAILED"
exit $rc
