"""Run by plume_gui.sh while the GUI pauses in its event playback (after
TestPlumeGUI.py built the scene, so the panels show it): copies the whole
Xvfb screen (the -fbdir XWD file, PLUME_GUI_FBDIR) to
PLUME_TEST_OUT/PlumeGUI-window.png, the picture of Documentation/ParaView.md.
Not an assertion."""
import os
import struct

import numpy as np
from PIL import Image

fbdir = os.environ.get("PLUME_GUI_FBDIR")
if fbdir:
    with open(os.path.join(fbdir, "Xvfb_screen0"), "rb") as f:
        data = f.read()
    h = struct.unpack(">25I", data[:100])
    header_size, width, height = h[0], h[4], h[5]
    byte_order, bpp, bytes_per_line, ncolors = h[7], h[11], h[12], h[19]
    start = header_size + 12 * ncolors
    if bpp == 32:
        pixels = np.frombuffer(data, np.uint8, bytes_per_line * height, start).reshape(height, bytes_per_line)
        pixels = pixels[:, : 4 * width].reshape(height, width, 4)
        rgb = pixels[:, :, [2, 1, 0]] if byte_order == 0 else pixels[:, :, [1, 2, 3]]
        # the main window only: the screen around it is black (no window manager)
        rows = np.flatnonzero(rgb.max(axis=(1, 2)) > 0)
        cols = np.flatnonzero(rgb.max(axis=(0, 2)) > 0)
        if rows.size and cols.size:
            rgb = rgb[rows[0] : rows[-1] + 1, cols[0] : cols[-1] + 1]
        Image.fromarray(np.ascontiguousarray(rgb)).save(
            os.path.join(os.environ["PLUME_TEST_OUT"], "PlumeGUI-window.png"))
