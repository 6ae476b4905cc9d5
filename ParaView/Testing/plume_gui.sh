#!/usr/bin/env bash
# The GUI test: paraview (Qt client) on its own Xvfb with the plugin on
# PV_PLUGIN_PATH, running TestPlumeGUI.py at startup (--script), then an
# event playback (plume_gui_exit.xml) that pauses and lets --exit end it.
# Passes when TestPlumeGUI.py wrote "OK". The whole screen is saved as
# $PLUME_TEST_OUT/PlumeGUI-window.png (the picture of Documentation/ParaView.md).
# Runs inside the ParaView root (scripts/test-paraview.sh).
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${PLUME_TEST_OUT:?}"
rm -f "$out/TestPlumeGUI.result" "$out/TestPlumeGUI.result.log"
fbdir="$(mktemp -d)"
export PV_PLUGIN_PATH="$(dirname "$PLUME_PLUGIN")" PLUME_TESTING_DIR="$here" PLUME_GUI_FBDIR="$fbdir"
# the screen is copied (plume_gui_capture.py) while the playback pauses,
# once the startup script has written its result. -noreset: see
# scripts/test-paraview.sh (a server that resets refuses connections for a while).
xvfb-run -a -n $((500 + RANDOM % 400)) -s "-screen 0 1280x800x24 -noreset -fbdir $fbdir" \
  paraview --dr --script="$here/TestPlumeGUI.py" --test-script="$here/plume_gui_exit.xml" --exit &
gui=$!
for _ in $(seq 1 600); do
  [ -f "$out/TestPlumeGUI.result" ] && break
  kill -0 "$gui" 2>/dev/null || break
  sleep 0.2
done
sleep 2
python3 "$here/plume_gui_capture.py" || echo "plume_gui: no screen capture"
wait "$gui"
rc=$?
rm -rf "$fbdir"
echo "plume_gui: paraview exited with $rc; result: $(cat "$out/TestPlumeGUI.result" 2>/dev/null || echo none)"
cat "$out/TestPlumeGUI.result.log" 2>/dev/null
# the playback's checks (plume_gui_exit.xml) fail paraview's exit status
[ "$rc" = 0 ] || { echo "plume_gui: the event playback failed (paraview exit status $rc)"; exit 1; }
grep -qx OK "$out/TestPlumeGUI.result" 2>/dev/null
