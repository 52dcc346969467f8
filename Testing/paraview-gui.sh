#!/usr/bin/env bash
# Plays a recorded ParaView GUI test (Testing/GUI/*.xml, pqTestUtility's XML events) in the
# real `paraview` binary with the plugin found on PV_PLUGIN_PATH, compares the view with a
# baseline image, and checks what the session printed: no warning (a missing pipeline icon
# pops up the Output Messages window) and exactly the expected number of errors.
# Usage: paraview-gui.sh SCRIPT.xml BASELINE.png|- PLUGIN_DIR DATA_DIR OUTPUT_DIR ERRORS
#                        [PATTERN] [abort]
#   ERRORS   how many error lines the session must print; PATTERN, text each must contain.
#   abort    the script's last Apply starts a run of minutes: press the abort button beside
#            the progress bar (xdotool clicks along the status bar; ParaView drops clicks
#            anywhere else during a run) and require the session to end within a minute.
# Run under X (Testing/xvfb.sh run ...). CVT_UPDATE_BASELINES=1 rewrites the baseline.
set -u
SCRIPT=$1 BASELINE=$2 PLUGIN_DIR=$3 DATA=$4 OUT=$5 ERRORS=$6 PATTERN=${7:-} MODE=${8:-}
name=$(basename "$SCRIPT" .xml)
mkdir -p "$OUT"
log="$OUT/$name.log"
update=${CVT_UPDATE_BASELINES:-0}
[ "$BASELINE" = - ] && update=0
compare=()
if [ "$BASELINE" != - ]; then
  if [ "$update" = 1 ]; then
    rm -f "$BASELINE"; compare=(--test-baseline="$OUT/$name.png")
  else
    compare=(--test-baseline="$BASELINE")
  fi
fi
# --dr: no user settings; the test harness writes the view to OUT on a mismatch.
PV_PLUGIN_PATH="$PLUGIN_DIR" timeout 300 paraview --dr --data-directory="$DATA" \
  --test-script="$SCRIPT" "${compare[@]}" --test-directory="$OUT" --exit > "$log" 2>&1 &
pid=$!
if [ "$MODE" = abort ]; then
  start=$(date +%s)
  sleep 6
  while kill -0 $pid 2> /dev/null && [ $(( $(date +%s) - start )) -lt 60 ]; do
    for x in $(seq 260 8 470); do
      xdotool mousemove "$x" 747 click 1 2> /dev/null
    done
    sleep 0.5
  done
  kill -0 $pid 2> /dev/null && { echo "the run went on after the abort button was pressed"; kill $pid; }
fi
wait $pid
status=$?
if [ "$update" = 1 ]; then
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
