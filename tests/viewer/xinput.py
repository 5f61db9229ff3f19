"""Real X input events for the viewer tests (the XTEST extension, through libXtst and ctypes).

ImGui 1.86 sees a key only if it is still down at the start of a frame, so keys are held for 0.4 s,
several frames even on a loaded 2-core CI machine. Importing this module exits 77 (CTest: skipped)
when libX11/libXtst cannot be loaded (Debian: libx11-6, libxtst6).
"""
import ctypes
import glob
import os
import subprocess
import sys
import tempfile
import time

try:
    _x11 = ctypes.CDLL("libX11.so.6")
    _xtst = ctypes.CDLL("libXtst.so.6")
except OSError as e:
    print(f"{e}: skipping the input test")
    sys.exit(77)
_x11.XOpenDisplay.restype = ctypes.c_void_p
_x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
_x11.XStringToKeysym.restype = ctypes.c_ulong
_x11.XStringToKeysym.argtypes = [ctypes.c_char_p]
_x11.XKeysymToKeycode.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
_x11.XFlush.argtypes = [ctypes.c_void_p]
for _name in ("XTestFakeKeyEvent", "XTestFakeButtonEvent"):
    getattr(_xtst, _name).argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_ulong]
_xtst.XTestFakeMotionEvent.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_ulong]
_x11.XDefaultRootWindow.restype = ctypes.c_ulong
_x11.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
_x11.XGetImage.restype = ctypes.c_void_p
_x11.XGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int, ctypes.c_uint, ctypes.c_uint,
                           ctypes.c_ulong, ctypes.c_int]
_x11.XFree.argtypes = [ctypes.c_void_p]


class _XImage(ctypes.Structure):  # the head of Xlib's XImage, up to bits_per_pixel
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("xoffset", ctypes.c_int), ("format", ctypes.c_int),
                ("data", ctypes.POINTER(ctypes.c_ubyte)), ("byte_order", ctypes.c_int), ("bitmap_unit", ctypes.c_int),
                ("bitmap_bit_order", ctypes.c_int), ("bitmap_pad", ctypes.c_int), ("depth", ctypes.c_int),
                ("bytes_per_line", ctypes.c_int), ("bits_per_pixel", ctypes.c_int)]


def start_viewer(args, cwd, config=None):
    """Starts shadelab (args[0]) with -v and returns (process, display) once its window is mapped. The
    viewer remembers its layout under XDG_CONFIG_HOME: `config` (default: a new temporary folder), so a
    test never reads what another test or a person left."""
    env = dict(os.environ, XDG_CONFIG_HOME=config or tempfile.mkdtemp(prefix="shadelab-test-config-"))
    proc = subprocess.Popen(list(args) + ["-v"], cwd=cwd, stderr=subprocess.PIPE, text=True, env=env)
    for line in proc.stderr:  # the window is mapped once the viewer reports its renderer
        if "viewer on" in line:
            break
    return proc, Display()


def quit_viewer(proc, display):
    """Presses Q and returns the viewer's stderr once it has exited; ends the test if it does not quit."""
    display.key("q")
    try:
        _, err = proc.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        proc.kill()
        sys.exit("the viewer did not quit on Q")
    return err


def screenshot(display, folder):
    """Presses F12 and returns the bytes of the PNG the viewer wrote into `folder` (its working folder),
    or None when none appeared within 30 s (a loaded CI machine renders and encodes slowly). The newest
    name is taken (they are timestamped), so a late earlier file is never mistaken for this one; the
    PNG is written atomically, so a file that exists is whole."""
    before = set(glob.glob(os.path.join(folder, "shadelab-*.png")))
    display.key("F12")
    for _ in range(300):
        new = set(glob.glob(os.path.join(folder, "shadelab-*.png"))) - before
        if new:
            return open(max(new), "rb").read()
        time.sleep(0.1)
    return None


class Display:
    def __init__(self):
        self.handle = _x11.XOpenDisplay(None)

    def flush(self, pause):
        _x11.XFlush(self.handle)
        time.sleep(pause)

    def key(self, name, shift=False, hold=0.4, after=0.3, ctrl=False):
        """Presses and releases a key (with Shift and/or Ctrl held around it); `hold` and `after` are the
        pauses after the press and the release (the viewer queues presses, so shorter pauses lose none;
        they only leave it less time to draw)."""
        code = _x11.XKeysymToKeycode(self.handle, _x11.XStringToKeysym(name.encode()))
        modifiers = [_x11.XKeysymToKeycode(self.handle, _x11.XStringToKeysym(m))
                     for m, on in ((b"Shift_L", shift), (b"Control_L", ctrl)) if on]
        for m in modifiers:
            _xtst.XTestFakeKeyEvent(self.handle, m, 1, 0)
        _xtst.XTestFakeKeyEvent(self.handle, code, 1, 0)
        self.flush(hold)
        _xtst.XTestFakeKeyEvent(self.handle, code, 0, 0)
        for m in modifiers:
            _xtst.XTestFakeKeyEvent(self.handle, m, 0, 0)
        self.flush(after)

    def move(self, x, y, pause=0.05):
        _xtst.XTestFakeMotionEvent(self.handle, -1, x, y, 0)
        self.flush(pause)

    def grab(self, x, y, width, height):
        """What the screen shows now in the rectangle, as read_png returns a PNG: (width, height, rows of RGB
        tuples), read from the X server (XGetImage of the root window: the window as a person sees it,
        whatever the viewer is doing, e.g. while it records). Xvfb's 24-bit screen: 32 bits a pixel, BGRX."""
        _x11.XFlush(self.handle)
        image = ctypes.cast(_x11.XGetImage(self.handle, _x11.XDefaultRootWindow(self.handle), x, y, width, height,
                                           0xFFFFFFFF, 2), ctypes.POINTER(_XImage))  # AllPlanes, ZPixmap
        head = image.contents
        assert head.bits_per_pixel == 32, f"a {head.bits_per_pixel}-bit X screen (the tests expect Xvfb's 24-bit one)"
        data = ctypes.string_at(head.data, head.bytes_per_line * height)
        rows = [[(data[o + 2], data[o + 1], data[o]) for o in range(y * head.bytes_per_line, y * head.bytes_per_line + 4 * width, 4)]
                for y in range(height)]
        _x11.XFree(head.data)
        _x11.XFree(image)
        return width, height, rows

    def button(self, b, down, pause=0.3):
        _xtst.XTestFakeButtonEvent(self.handle, b, 1 if down else 0, 0)
        self.flush(pause)
