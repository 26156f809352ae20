#!/usr/bin/env bash
# The lab's end-to-end test (`make test-e2e`, part of `make test`): starts `pendulab serve --no-browser` on
# a free port in the background, waits until it answers, runs web/tests/e2e/smoke.mjs against it in
# Debian's headless chromium (playwright-core, never a downloaded browser) and stops the server on every
# exit path (success, failure, Ctrl-C). Screenshots go to web/test-results/ (gitignored).
#
# Environment: PENDULAB (default .venv/bin/pendulab), CHROMIUM (default: chromium on PATH),
# E2E_SERVER_TIMEOUT [s] to wait for the server (default 90: a loaded 2-core machine starts it slowly).
set -euo pipefail
cd "$(dirname "$0")/../../.."

PENDULAB=${PENDULAB:-.venv/bin/pendulab}
PY=${PY:-.venv/bin/python}
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

status=0
(cd web && CHROMIUM="$CHROMIUM" node tests/e2e/smoke.mjs "$base") || status=$?
if [ "$status" -ne 0 ]; then
  echo "-- server log:" >&2
  cat "$log" >&2
fi
exit "$status"
