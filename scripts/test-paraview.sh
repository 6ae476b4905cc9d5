#!/usr/bin/env bash
# Builds the ParaView plugin PlumeParaView (ParaView/, from the same Modules/*
# sources) inside the ParaView root and runs its tests there under Xvfb:
# pvbatch image tests against baselines, the property round trip, the GUI
# test, the 2-rank MPI equality tests and the client/server test. The host's
# packages are never touched (see scripts/paraview-root.sh for why ParaView
# lives in its own root).
#
# Usage: bash scripts/test-paraview.sh [TEST-NAME-REGEX]
#   PLUME_PVROOT          the root (default: /var/cache/plume/pvroot; made if missing)
#   PLUME_PV_BUILD_DIR    plugin build dir (default: build-paraview in the repo)
#   PLUME_PV_SKIP_MPI=1   skip the MPI and client/server tests
#   PLUME_PV_TEST_TIMEOUT base time limit of one test run in s (default 240; times load/15, up to 4x)
# Test output (rendered images, diffs): $PLUME_PV_BUILD_DIR/Testing/
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PLUME_PVROOT="${PLUME_PVROOT:-/var/cache/plume/pvroot}"
build="${PLUME_PV_BUILD_DIR:-$root/build-paraview}"
mkdir -p "$build"
build="$(cd "$build" && pwd)"
filter="${1:-.}"
start=$(date +%s)

bash "$root/scripts/paraview-root.sh" >/dev/null
in_root() { bash "$root/scripts/paraview-chroot.sh" "$@"; }

# --- Build (incremental) -------------------------------------------------------
jobs="${PLUME_PV_JOBS:-$(nproc)}"
if [ ! -f "$build/build.ninja" ]; then
  in_root cmake -S "$root/ParaView" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
in_root cmake --build "$build" -j "$jobs"
built=$(date +%s)
echo "test-paraview: plugin built in $((built - start)) s"

# --- Tests -----------------------------------------------------------------------
plugin="$(find "$build" -name 'PlumeParaView.so' | head -n 1)"
if [ -z "$plugin" ]; then
  echo "test-paraview: PlumeParaView.so not found under $build" >&2
  exit 1
fi
# the shared data beside the checkout, as the main build's default; resolved,
# since the root binds the real folder
data="${PLUME_DATA_DIR:-$root/../shared/data}"
data="$(cd "$data" && pwd -P)"
export PLUME_DATA_DIR="$data"
out="$build/Testing"
mkdir -p "$out"
# xvfb-run's own files (Xauthority) in a folder of ours rather than the shared
# /tmp, where other jobs' clean-ups may remove them under a running server
xtmp="$build/xvfb-tmp"
mkdir -p "$xtmp"
# Debian 12's expat defers reparsing (CVE-2023-52425 backport), which breaks
# ParaView 5.11's XML readers on appended data and so RedistributeDataSet:
# every test runs with the shim that turns deferral off (ParaView/Support).
shim="$(find "$build" -name 'libplumeExpatNoDeferral.so' | head -n 1)"
failed=()
passed=0
run_test() {
  local name="$1"
  shift
  if ! [[ "$name" =~ $filter ]]; then return; fi
  local t0 t1
  t0=$(date +%s.%N)
  local ok=0 attempt
  # A display taken between xvfb-run -a's check and the server's start (other
  # jobs on the machine start X servers too) shows as "bad X server
  # connection", or, under MPI, as a rank without a display ("remote
  # rendering ... is not available"), after which the ranks' compositing
  # never meets and they spin: every run is bounded (PLUME_PV_TEST_TIMEOUT,
  # default 240 s; a test takes 10-30 s) and those cases alone are retried.
  # Displays from 500 up, away from the ones other jobs' xvfb-run -a start at (99).
  # -noreset: without it Xvfb resets whenever its last client disconnects,
  # and connections that arrive during a reset fail ("bad X server
  # connection"). pvbatch connects, disconnects (its X display test) and
  # connects again at once; measured with xdpyinfo connecting back to back:
  # 11 of 100 connections failed without -noreset, 0 of 100 with it. A reset
  # takes longer on a loaded machine, where the failures were seen (in all 3
  # attempts at load 30+). The time limit grows with the load: the limit
  # (PLUME_PV_TEST_TIMEOUT, default 240 s) times load average / 15 when that
  # is above 1 (ClientServer took 94-136 s at load 19 and ran out of 240 s at
  # load 30-35), at most 4 times the limit.
  local rc limit
  limit=$(awk -v base="${PLUME_PV_TEST_TIMEOUT:-240}" '{ f = $1 / 15; if (f < 1) f = 1; if (f > 4) f = 4; printf "%d", base * f }' /proc/loadavg)
  for attempt in 1 2 3; do
    rc=0
    in_root env PLUME_PLUGIN="$plugin" PLUME_DATA_DIR="$data" PLUME_TEST_OUT="$out" \
      PLUME_BASELINES="$root/ParaView/Testing/Baseline" TMPDIR="$xtmp" ${shim:+LD_PRELOAD="$shim"} \
      xvfb-run -a -n $((500 + RANDOM % 400)) -s "-screen 0 1024x768x24 -noreset" \
      timeout -k 10 "$limit" "$@" >"$out/$name.log" 2>&1 || rc=$?
    if [ $rc = 0 ]; then
      ok=1
      break
    fi
    cp "$out/$name.log" "$out/$name.attempt$attempt.log"
    if [ $rc = 124 ] || [ $rc = 137 ]; then
      echo "test-paraview: $name did not finish in $limit s (attempt $attempt)" >>"$out/$name.log"
    fi
    grep -q -e "bad X server connection" -e "remote rendering which, however, is not available" \
      -e "did not finish in" -e "could not connect to pvserver" "$out/$name.log" || break
  done
  if [ $ok = 1 ]; then
    passed=$((passed + 1))
    t1=$(date +%s.%N)
    awk -v n="$name" -v a="$t0" -v b="$t1" 'BEGIN { printf "test-paraview: PASS %-28s %5.1f s\n", n, b - a }'
  else
    failed+=("$name")
    echo "test-paraview: FAIL $name (log: $out/$name.log)"
    tail -n 30 "$out/$name.log" | sed 's/^/    | /'
  fi
}
tests="$root/ParaView/Testing"
for script in "$tests"/Test*.py; do
  name="$(basename "$script" .py)"
  case "$name" in *MPI* | *ClientServer* | *GUI*) continue ;; esac
  run_test "$name" pvbatch "$script"
done
# the Qt client on its own Xvfb, the plugin from PV_PLUGIN_PATH
run_test TestPlumeGUI bash "$tests/plume_gui.sh"
if [ "${PLUME_PV_SKIP_MPI:-0}" != 1 ]; then
  for script in "$tests"/Test*MPI*.py; do
    name="$(basename "$script" .py)"
    run_test "$name.serial" pvbatch "$script" # the serial references, same reader
    run_test "$name" mpirun --allow-run-as-root --oversubscribe -np 2 pvbatch --symmetric --disable-xdisplay-test "$script"
  done
  # client/server: a pvpython client and a 2-rank pvserver on localhost,
  # compared with the serial references written by TestPlumeMPI.serial
  run_test TestPlumeClientServer bash "$tests/plume_client_server.sh" 2 "$tests/TestPlumeClientServer.py"
fi
echo "test-paraview: $passed passed, ${#failed[@]} failed, $(($(date +%s) - start)) s in all"
[ ${#failed[@]} -eq 0 ]
