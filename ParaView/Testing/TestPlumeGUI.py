"""The paraview GUI (Qt client) under Xvfb, started by ParaView/Testing/plume_gui.sh
with the plugin on PV_PLUGIN_PATH (auto-loaded as a user's would be) and this
file as a --test-script: the 'volume' scene of TestPlumeVolume built in the
GUI's Python shell renders as that test's baseline Baseline/PlumeVolume.png
(within 2 levels on >= 99.5 % of the pixels, the pvbatch test's criteria) and
draws on at least 2 % of the image. The result goes to
PLUME_TEST_OUT/TestPlumeGUI.result ("OK" or "FAILED"), which the wrapper
checks (the GUI's exit status does not carry a script's failure).
"""
import os
import sys
import traceback

result = os.path.join(os.environ.get("PLUME_TEST_OUT", "."), "TestPlumeGUI.result")
ok = False
try:
    sys.path.insert(0, os.environ["PLUME_TESTING_DIR"])
    import plume_pvtest as T
    import plume_scenes
    from paraview import simple

    # the plugin comes from PV_PLUGIN_PATH: its representations must be there
    # without a LoadPlugin call
    v = simple.GetActiveViewOrCreate("RenderView")
    v.ViewSize = T.SIZE
    v.OrientationAxesVisibility = 0
    v.Background = [0.32, 0.34, 0.43]
    try:
        v.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    rep = plume_scenes.volume(T.carotid(), v)
    image = T.render_image(v)
    drawn = T.not_blank(image, v.Background)
    print("drawn on %.1f %% of the pixels" % (100 * drawn))
    same = T.check_baseline(image, "PlumeVolume")
    if same:
        import shutil

        shutil.copy(os.path.join(T.OUT, "PlumeVolume.png"), os.path.join(T.OUT, "PlumeGUI.png"))
    ok = drawn > 0.02 and same
except Exception:
    traceback.print_exc()
    with open(result + ".log", "w") as f:
        traceback.print_exc(file=f)
finally:
    with open(result, "w") as f:
        f.write("OK\n" if ok else "FAILED\n")
