#!/usr/bin/env bash
# Resource faults of `cvt`: a full disk (simulated by a file-size limit), an output folder that
# cannot be written from the start, and one that becomes read-only during the run. Each must end
# in a clear error and a non-zero exit, leave no partial file (results are written under
# temporary names and renamed together at the end) and keep the previous run's results intact.
# The read-only cases run `cvt` as the user nobody when the suite runs as root (root ignores
# folder permissions); they are skipped, with a note, where neither is possible.
# Usage: resource-faults.sh PATH/TO/cvt
set -u
CVT=${1:?usage: resource-faults.sh PATH/TO/cvt}
T=$(mktemp -d)
chmod 755 "$T"
trap 'chmod -R u+w "$T"; rm -rf "$T"' EXIT
bad=0
fail() { echo "FAILED: $*"; bad=1; }
no_partials() { # no_partials DIR WHAT
  if find "$1" -name '.*.partial' | grep -q .; then fail "$2 left partial files: $(ls -A "$1")"; fi
}
job=(image --sites 200 --iterations 3 --engine cpu --quiet)

# 1. Full disk: the labels image (1.4 MB) goes past a 64 KiB file-size limit. The results of the
#    previous run in that folder stay as they were.
"$CVT" "${job[@]}" --output "$T/full" > /dev/null 2>&1 || fail "the first run did not succeed"
before=$(cd "$T/full" && md5sum ./* | md5sum)
if (ulimit -f 64; "$CVT" "${job[@]}" --seed 2 --output "$T/full") > "$T/log" 2>&1; then
  fail "a write past the file-size limit was not reported"
elif ! grep -q "cannot write '$T/full/labels.vti' (File too large)" "$T/log"; then
  fail "full disk: unclear message: $(cat "$T/log")"
fi
no_partials "$T/full" "full disk"
[ "$(cd "$T/full" && md5sum ./* | md5sum)" = "$before" ] || fail "full disk changed earlier results"

# 2 and 3 need a user whom folder permissions stop.
as_user=()
if [ "$(id -u)" = 0 ]; then
  if command -v setpriv > /dev/null && id nobody > /dev/null 2>&1; then
    as_user=(setpriv --reuid=nobody --regid="$(id -g nobody)" --clear-groups)
  else
    echo "note: read-only folder cases skipped (root, and no setpriv or no user nobody)"
    [ $bad = 0 ] && echo "resource faults: ok"
    exit $bad
  fi
fi
if ! "${as_user[@]}" "$CVT" --help > /dev/null 2>&1; then
  # The build is in a folder nobody cannot enter (a fresh clone under mktemp -d): run a copy of
  # the program and the project's libraries (found through LD_LIBRARY_PATH before RUNPATH).
  mkdir -p "$T/copy/lib"
  cp "$CVT" "$T/copy/cvt" && cp -P "$(dirname "$CVT")"/../lib/libcvt*.so* "$T/copy/lib/"
  chmod -R a+rX "$T/copy"
  CVT="$T/copy/cvt"
  export LD_LIBRARY_PATH="$T/copy/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  if ! "${as_user[@]}" "$CVT" --help > /dev/null 2>&1; then
    echo "note: read-only folder cases skipped (the user nobody cannot run cvt here)"
    [ $bad = 0 ] && echo "resource faults: ok"
    exit $bad
  fi
fi
owner=$(if [ ${#as_user[@]} -gt 0 ]; then id -u nobody; else id -u; fi)

# 2. A folder that cannot be written: refused before any work.
mkdir "$T/readonly" && chmod 555 "$T/readonly"
if "${as_user[@]}" "$CVT" "${job[@]}" --output "$T/readonly" > "$T/log" 2>&1; then
  fail "a read-only --output folder was accepted"
elif ! grep -q "cannot write in --output directory '$T/readonly' (Permission denied)" "$T/log"; then
  fail "read-only folder: unclear message: $(cat "$T/log")"
fi
[ -z "$(ls -A "$T/readonly")" ] || fail "files appeared in the read-only folder"

# 3. The folder turns read-only while the CVT runs (Lloyd's method for about 5 s on 2 cores:
# 4000 iterations took about 1 s, and the folder sometimes turned read-only while it wrote).
mkdir "$T/midrun" && chown "$owner" "$T/midrun"
"${as_user[@]}" "$CVT" image --sites 1000 --method lloyd --iterations 20000 --tolerance 0 \
  --engine cpu --quiet --output "$T/midrun" > "$T/log" 2>&1 &
pid=$!
sleep 1
chmod 555 "$T/midrun"
if wait $pid; then
  fail "the run finished before the folder turned read-only, or its writes were not reported"
elif ! grep -q "cannot write in --output directory '$T/midrun' (Permission denied)" "$T/log"; then
  fail "read-only mid-run: unclear message: $(cat "$T/log")"
fi
[ -z "$(ls -A "$T/midrun")" ] || fail "files left in the folder: $(ls -A "$T/midrun")"

[ $bad = 0 ] && echo "resource faults: ok"
exit $bad
