"""Connects to the X server and disconnects, again and again (run under xvfb-run).

    python3 xvfb_reconnect.py [TIMES]

Prints "reconnected N of TIMES". By default Xvfb resets when its last client disconnects, and a
connection made during the reset fails: 2 to 5 of 200 failed here without -noreset, none with it.
pvpython connects twice (a capability check, then the render window), so its second connection
could land in the reset; under CPU load it did (the pvpython.AnimateCircle failure of issue 17).
Exits 1 if any connection failed.
"""
import ctypes
import sys

times = int(sys.argv[1]) if len(sys.argv) > 1 else 400
x11 = ctypes.CDLL("libX11.so.6")
x11.XOpenDisplay.restype = ctypes.c_void_p
x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
connected = 0
for _ in range(times):
    display = x11.XOpenDisplay(None)
    if display:
        connected += 1
        x11.XCloseDisplay(display)
print("reconnected %d of %d" % (connected, times))
sys.exit(0 if connected == times else 1)
