#!/usr/bin/env bash
# The GUI test: paraview (Qt client) on its own Xvfb with the plugin on
# PV_PLUGIN_PATH, playing TestPlumeGUI.py and then plume_gui_capture.py as
# test scripts, and leaving (--exit). Passes when TestPlumeGUI.py wrote "OK".
# Runs inside the ParaView root (scripts/test-paraview.sh).
set -u
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${PLUME_TEST_OUT:?}"
rm -f "$out/TestPlumeGUI.result" "$out/TestPlumeGUI.result.log"
fbdir="$(mktemp -d)"
export PV_PLUGIN_PATH="$(dirname "$PLUME_PLUGIN")" PLUME_TESTING_DIR="$here" PLUME_GUI_FBDIR="$fbdir"
xvfb-run -a -n $((500 + RANDOM % 400)) -s "-screen 0 1280x800x24 -fbdir $fbdir" \
  paraview --dr --script="$here/TestPlumeGUI.py" --test-script="$here/plume_gui_exit.xml" --exit
rc=$?
rm -rf "$fbdir"
echo "plume_gui: paraview exited with $rc; result: $(cat "$out/TestPlumeGUI.result" 2>/dev/null || echo none)"
cat "$out/TestPlumeGUI.result.log" 2>/dev/null
grep -qx OK "$out/TestPlumeGUI.result" 2>/dev/null
