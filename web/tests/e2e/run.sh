#!/usr/bin/env bash
# The lab's end-to-end test (`make test-e2e`, part of `make test`), once per transport (issue 26 item 7):
# 1. server: starts `pendulab serve --no-browser` on a free port in the background, waits until it
#    answers, runs web/tests/e2e/smoke.mjs against it in Debian's headless chromium (playwright-core,
#    never a downloaded browser) and stops the server on every exit path (success, failure, Ctrl-C);
# 2. file: the same smoke.mjs against dist/pendulab-lab.html (`make lab-html`) opened from file:// with
#    every network request refused; what needs Python is skipped there, each with its reason printed.
# Screenshots go to web/test-results/ (gitignored; the file transport's end in -file.png).
#
# Environment: PENDULAB (default .venv/bin/pendulab), CHROMIUM (default: chromium on PATH),
# E2E_SERVER_TIMEOUT [s] to wait for the server (default 90: a loaded 2-core machine starts it slowly),
# E2E_TRANSPORTS (default "server file": which runs), LAB_HTML (default dist/pendulab-lab.html).
set -euo pipefail
cd "$(dirname "$0")/../../.."

PENDULAB=${PENDULAB:-.venv/bin/pendulab}
PY=${PY:-.venv/bin/python}
TRANSPORTS=${E2E_TRANSPORTS:-server file}
LAB_HTML=${LAB_HTML:-dist/pendulab-lab.html}
CHROMIUM=${CHROMIUM:-$(command -v chromium || command -v chromium-browser || true)}
if [ -z "$CHROMIUM" ] || [ ! -x "$CHROMIUM" ]; then
  echo "error: the end-to-end test needs Debian's chromium: 'apt-get install chromium' (.ci/run does it)," \
    "or set CHROMIUM=/path/to/chromium" >&2
  exit 1
fi
if [ ! -x "$PENDULAB" ]; then
  echo "error: $PENDULAB not found: run 'make build' first" >&2
  exit 1
fi
case " $TRANSPORTS " in
  *" file "*)
    if [ ! -f "$LAB_HTML" ]; then
      echo "error: $LAB_HTML not found (the e2e suite's file transport opens it): run 'make lab-html' first" >&2
      exit 1
    fi
    ;;
esac
status=0
started=$SECONDS
ABS_PY="$(cd "$(dirname "$PY")" && pwd)/$(basename "$PY")" # doclinks.mjs runs tools/lab_links.py with it

run_file() {
  local t0=$SECONDS
  echo "== e2e: the one-file lab $LAB_HTML from file://, network refused, chromium $CHROMIUM"
  (cd web && CHROMIUM="$CHROMIUM" PY="$ABS_PY" node tests/e2e/smoke.mjs "$(cd .. && realpath "$LAB_HTML")") || status=1
  echo "== e2e: file transport took $((SECONDS - t0)) s"
}

case " $TRANSPORTS " in
  *" server "*) ;;
  *)
    run_file
    exit "$status"
    ;;
esac

port=$("$PY" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
log=$(mktemp)
PENDULAB_NO_BROWSER=1 "$PENDULAB" serve --no-browser --host 127.0.0.1 --port "$port" >"$log" 2>&1 &
server=$!

stop_server() {
  if kill -0 "$server" 2>/dev/null; then
    kill -TERM "$server" 2>/dev/null || true
    for _ in $(seq 1 50); do # up to 5 s for a graceful stop, then kill
      kill -0 "$server" 2>/dev/null || break
      sleep 0.1
    done
    kill -KILL "$server" 2>/dev/null || true
  fi
  wait "$server" 2>/dev/null || true
  rm -f "$log"
}
trap stop_server EXIT
trap 'exit 130' INT TERM

base="http://127.0.0.1:$port"
deadline=$((SECONDS + ${E2E_SERVER_TIMEOUT:-90}))
until "$PY" -c "import urllib.request, sys; urllib.request.urlopen(sys.argv[1], timeout=2)" "$base/api/schema" \
  2>/dev/null; do
  if ! kill -0 "$server" 2>/dev/null; then
    echo "error: pendulab serve exited before answering:" >&2
    cat "$log" >&2
    exit 1
  fi
  if [ "$SECONDS" -ge "$deadline" ]; then
    echo "error: pendulab serve did not answer at $base within ${E2E_SERVER_TIMEOUT:-90} s:" >&2
    cat "$log" >&2
    exit 1
  fi
  sleep 0.3
done
echo "== e2e: pendulab serve at $base (pid $server), chromium $CHROMIUM"

(cd web && CHROMIUM="$CHROMIUM" PY="$ABS_PY" node tests/e2e/smoke.mjs "$base") || status=$?
if [ "$status" -ne 0 ]; then
  echo "-- server log:" >&2
  cat "$log" >&2
fi
echo "== e2e: server transport took $((SECONDS - started)) s"
stop_server
trap - EXIT
case " $TRANSPORTS " in
  *" file "*) run_file ;;
esac
exit "$status"
