#!/usr/bin/env bash
# Plays a recorded ParaView GUI test (Testing/GUI/*.xml, pqTestUtility's XML events) in the
# real `paraview` binary with the plugin found on PV_PLUGIN_PATH, compares the view with a
# baseline image, and checks what the session printed: no warning (a missing pipeline icon
# pops up the Output Messages window) and exactly the expected number of errors.
# Usage: paraview-gui.sh SCRIPT.xml BASELINE.png PLUGIN_DIR DATA_DIR OUTPUT_DIR ERRORS [PATTERN]
#   ERRORS   how many error lines the session must print; PATTERN, text each must contain.
# Run under X (Testing/xvfb.sh run ...). CVT_UPDATE_BASELINES=1 rewrites the baseline.
set -u
SCRIPT=$1 BASELINE=$2 PLUGIN_DIR=$3 DATA=$4 OUT=$5 ERRORS=$6 PATTERN=${7:-}
name=$(basename "$SCRIPT" .xml)
mkdir -p "$OUT"
log="$OUT/$name.log"
baseline=$BASELINE
[ "${CVT_UPDATE_BASELINES:-0}" = 1 ] && { rm -f "$BASELINE"; baseline="$OUT/$name.png"; }
# --dr: no user settings; the test harness writes the view to OUT on a mismatch.
PV_PLUGIN_PATH="$PLUGIN_DIR" timeout 300 paraview --dr --data-directory="$DATA" \
  --test-script="$SCRIPT" --test-baseline="$baseline" --test-directory="$OUT" --exit \
  > "$log" 2>&1
status=$?
if [ "${CVT_UPDATE_BASELINES:-0}" = 1 ]; then
  cp "$OUT/$name.png" "$BASELINE" && echo "baseline rewritten: $BASELINE"; exit 0
fi
bad=0
[ $status -eq 0 ] || { echo "paraview exited with $status (image mismatch, failed event or timeout)"; bad=1; }
grep -q "Success =  true" "$log" || { echo "the test script did not finish"; bad=1; }
if grep -i "warning" "$log"; then echo "the session printed warnings (above)"; bad=1; fi
errors=$(grep -c "ERR|" "$log")
if [ "$errors" -ne "$ERRORS" ]; then
  echo "$errors error lines, expected $ERRORS:"; grep "ERR|" "$log"; bad=1
fi
if [ -n "$PATTERN" ] && [ "$ERRORS" -gt 0 ] && [ "$(grep "ERR|" "$log" | grep -c "$PATTERN")" -ne "$ERRORS" ]; then
  echo "the errors do not say '$PATTERN'"; bad=1
fi
[ $bad -eq 0 ] && echo "paraview gui $name: ok" || { echo "--- $log:"; cat "$log"; exit 1; }
