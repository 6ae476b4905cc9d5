#!/usr/bin/env bash
# Runs a pvpython client script against a pvserver started here (inside the
# ParaView root, on the X display of the caller's xvfb-run), both on
# localhost. The server listens on a random port (passed to the client in
# PLUME_PV_SERVER_PORT) and exits when the client disconnects; it is ended
# by its id if it is still there afterwards.
#
# Usage: plume_client_server.sh RANKS CLIENT-SCRIPT
set -u
ranks="$1"
script="$2"
port=$((20000 + RANDOM % 20000))
if [ "$ranks" -gt 1 ]; then
  mpirun --allow-run-as-root --oversubscribe -np "$ranks" pvserver --disable-xdisplay-test --server-port="$port" &
else
  pvserver --disable-xdisplay-test --server-port="$port" &
fi
server=$!
rc=0
PLUME_PV_SERVER_PORT="$port" PLUME_PV_SERVER_RANKS="$ranks" pvpython "$script" || rc=$?
# the server leaves when its client disconnects; give it a few seconds
for _ in $(seq 1 20); do
  kill -0 "$server" 2>/dev/null || break
  sleep 0.5
done
if kill -0 "$server" 2>/dev/null; then
  echo "plume_client_server: server still running after the client left: ending it"
  kill "$server" 2>/dev/null
fi
wait "$server" 2>/dev/null
exit "$rc"
