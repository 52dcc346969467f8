#!/usr/bin/env bash
# One X server (Xvfb) for every test that needs X, as a CTest fixture:
#   xvfb.sh start STATE_DIR        the setup test: start Xvfb on a free display and wait until it
#                                  accepts connections (three tries, each up to 15 s)
#   xvfb.sh run STATE_DIR CMD...   run CMD with DISPLAY set, once the server answers (again,
#                                  up to three times, when the server refused its connection)
#   xvfb.sh stop STATE_DIR         the cleanup test
# A test never gets a display that is still starting, or one another run is shutting down.
set -u
action=${1:?usage: xvfb.sh start|run|stop STATE_DIR [CMD...]}
state=${2:?usage: xvfb.sh start|run|stop STATE_DIR [CMD...]}
shift 2

answers() { # answers DISPLAY: whether an X client can open it (libX11 through Python)
  /usr/bin/python3 -c '
import ctypes, sys
x = ctypes.cdll.LoadLibrary("libX11.so.6")
x.XOpenDisplay.restype = ctypes.c_void_p
d = x.XOpenDisplay(sys.argv[1].encode())
if d:
    x.XCloseDisplay(ctypes.c_void_p(d))
sys.exit(0 if d else 1)' "$1" 2>/dev/null
}

case $action in
start)
  mkdir -p "$state"
  for attempt in 1 2 3; do
    n=""
    for candidate in $(seq 90 199); do
      if [ ! -e "/tmp/.X$candidate-lock" ] && [ ! -e "/tmp/.X11-unix/X$candidate" ]; then
        n=$candidate; break
      fi
    done
    [ -n "$n" ] || { echo "no free X display number in 90..199"; exit 1; }
    # Detached, its output in a file: CTest must not wait for the server to end. -noreset: by
    # default an X server resets when its last client disconnects and refuses connections
    # while it does, so a client that starts just as another ends (our own readiness check
    # included) is refused now and then (3 of 300 open-close-open cycles here, none with it).
    setsid Xvfb ":$n" -screen 0 1280x1024x24 -nolisten tcp -noreset < /dev/null > "$state/xvfb.log" 2>&1 &
    pid=$!
    for _ in $(seq 1 150); do
      if answers ":$n"; then
        echo "$n" > "$state/display"
        echo "$pid" > "$state/pid"
        echo "Xvfb :$n ready (attempt $attempt)"
        exit 0
      fi
      kill -0 "$pid" 2> /dev/null || break
      sleep 0.1
    done
    kill "$pid" 2> /dev/null
    echo "Xvfb :$n did not accept connections (attempt $attempt):"
    tail -n 3 "$state/xvfb.log"
  done
  echo "Xvfb never came up after 3 attempts"
  exit 1
  ;;
run)
  if [ ! -f "$state/display" ]; then
    echo "no X server: the xvfb-start test (fixture xvfb) did not run or failed"
    exit 1
  fi
  export DISPLAY=":$(cat "$state/display")"
  # Should the server still refuse a connection ("bad X server connection" from VTK, "cannot
  # connect to the X server" from vtkCVTOpenGLContext), that start alone is tried again, up to
  # three times; any other failure is the test's own.
  for attempt in 1 2 3; do
    # The server refuses a connection now and then while it is busy: wait up to 10 s for it.
    ready=0
    for _ in $(seq 1 40); do
      if answers "$DISPLAY"; then
        ready=1
        break
      fi
      sleep 0.25
    done
    if [ "$ready" -eq 0 ]; then
      echo "xvfb.sh: the X server $DISPLAY no longer accepts connections; see $state/xvfb.log"
      exit 1
    fi
    log=$(mktemp)
    "$@" 2>&1 | tee "$log"
    status=${PIPESTATUS[0]}
    refused=0
    grep -q "bad X server connection\|cannot connect to the X server" "$log" && refused=1
    rm -f "$log"
    if [ "$status" -ne 0 ] && [ "$refused" -eq 1 ] && [ "$attempt" -lt 3 ]; then
      echo "xvfb.sh: the X server refused the connection (attempt $attempt of 3); starting again"
      sleep 1
      continue
    fi
    [ "$refused" -eq 1 ] && [ "$status" -ne 0 ] &&
      echo "xvfb.sh: the X server refused the connection three times"
    exit "$status"
  done
  ;;
stop)
  if [ -f "$state/pid" ]; then
    kill "$(cat "$state/pid")" 2> /dev/null
  fi
  rm -f "$state/display" "$state/pid"
  echo "Xvfb stopped"
  ;;
*)
  echo "usage: xvfb.sh start|run|stop STATE_DIR [CMD...]"
  exit 2
  ;;
esac
