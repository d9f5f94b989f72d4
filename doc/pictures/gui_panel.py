# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
"""Renders doc/images/gui_panel.png: the real ParaView client after Apply
on the demo cloud, with the Properties panel of Narrow Volume
Reconstruction and the shell in the view.

    scripts/with-xvfb.sh /usr/bin/python3 doc/pictures/gui_panel.py

Starts `paraview --dr --script=doc/pictures/gui_panel_script.py` on the X
display ($DISPLAY, which scripts/with-xvfb.sh provides), waits for the script
to be done and the window to settle, grabs the screen (Pillow's ImageGrab),
crops it to the client's main window and closes the client.
"""
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
BUILD = os.environ.get("BUILD_DIR") or os.path.join(SOURCE, "build")
PLUGIN = os.path.join(BUILD, "lib", "paraview-5.11", "plugins", "NarrowVolume", "NarrowVolume.so")
OUT = os.path.join(SOURCE, "doc", "images", "gui_panel.png")


def main_window():
    """(x, y, width, height) of the largest top-level window named ParaView, from xwininfo."""
    tree = subprocess.run(["xwininfo", "-root", "-children"], capture_output=True, text=True).stdout
    best = None
    for line in tree.splitlines():
        match = re.search(r'"([^"]*ParaView[^"]*)".*?(\d+)x(\d+)\+(-?\d+)\+(-?\d+)', line)
        if match:
            w, h, x, y = (int(v) for v in match.groups()[1:])
            if best is None or w * h > best[2] * best[3]:
                best = (x, y, w, h)
    return best


def main_window_id():
    tree = subprocess.run(["xwininfo", "-root", "-children"], capture_output=True, text=True).stdout
    best = None
    for line in tree.splitlines():
        match = re.search(r'(0x[0-9a-f]+) "([^"]*ParaView[^"]*)".*?(\d+)x(\d+)\+', line)
        if match and (best is None or int(match.group(3)) * int(match.group(4)) > best[1]):
            best = (int(match.group(1), 16), int(match.group(3)) * int(match.group(4)))
    return best[0] if best else None


def resize(window, width, height):
    """Moves the window to the screen's corner and sizes it (no window manager runs on Xvfb)."""
    import ctypes
    import ctypes.util

    x11 = ctypes.CDLL(ctypes.util.find_library("X11"))
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x11.XMoveResizeWindow.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int, ctypes.c_uint,
                                      ctypes.c_uint]
    x11.XFlush.argtypes = [ctypes.c_void_p]
    x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
    display = x11.XOpenDisplay(None)
    x11.XMoveResizeWindow(display, window, 0, 0, width, height)
    x11.XFlush(display)
    x11.XCloseDisplay(display)


def main():
    if not os.environ.get("DISPLAY"):
        sys.exit("gui_panel: no X display; run it under scripts/with-xvfb.sh")
    if not os.path.exists(PLUGIN):
        sys.exit("gui_panel: %s not found: build the project first" % PLUGIN)
    scratch = tempfile.TemporaryDirectory()
    ready = os.path.join(scratch.name, "ready")
    env = dict(os.environ, NV_PLUGIN=PLUGIN, NV_CLOUD=os.path.join(SOURCE, "Data", "trefoil.vtp"), NV_READY=ready)
    client = subprocess.Popen(["paraview", "--dr", "--script=" + os.path.join(HERE, "gui_panel_script.py")],
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        start = time.time()
        while not os.path.exists(ready) and time.time() - start < 180 and client.poll() is None:
            time.sleep(0.5)
        if not os.path.exists(ready):
            sys.exit("gui_panel: the client did not run its script")
        message = open(ready).read()
        if message != "ok":
            sys.exit("gui_panel: the client's script failed:\n" + message)
        window = main_window_id()
        if window:
            resize(window, 1280, 1000)  # room for the whole Properties panel
        time.sleep(5)  # the panel and the view settle
        from PIL import ImageGrab

        screen = ImageGrab.grab(xdisplay=os.environ["DISPLAY"])
        box = main_window()
        if box:
            x, y, w, h = box
            screen = screen.crop((max(x, 0), max(y, 0), min(x + w, screen.width), min(y + h, screen.height)))
        os.makedirs(os.path.dirname(OUT), exist_ok=True)
        screen.convert("RGB").quantize(colors=256).save(OUT, optimize=True)
        print("wrote doc/images/gui_panel.png (%d x %d px, %d kB)" % (screen.width, screen.height,
                                                                    os.path.getsize(OUT) // 1024))
    finally:
        client.terminate()
        try:
            client.wait(timeout=20)
        except subprocess.TimeoutExpired:
            client.kill()


if __name__ == "__main__":
    main()
