"""An X display for the examples that render (imported by animate_circle.py and
openfoam_wing_pictures.py).

Debian's ParaView renders through X (GLX), even with --force-offscreen-rendering: without an X
display pvpython dies with SIGSEGV in its first render. ensure_display() returns at once when
DISPLAY is set or ParaView does not render through X (an EGL or OSMesa build). Otherwise it starts
the same command again under xvfb-run (Xvfb's arguments: XVFB_ARGS), the expat work-around's
LD_PRELOAD given to the command after xvfb-run, not to Xvfb; or, without xvfb-run, it exits with
a message that says what to run.
"""
import os
import shlex
import shutil
import sys

#: Xvfb's arguments. -noreset: by default Xvfb resets when its last client disconnects, and a
#: client connecting during the reset fails; pvpython connects twice (a capability check, then
#: the render window), so under CPU load its second connection failed with "bad X server
#: connection" (the pvpython.AnimateCircle failure of issue 17).
XVFB_ARGS = "-screen 0 1280x1024x24 -noreset"


def renders_through_x():
    """True when ParaView's render windows are X windows (vtkXOpenGLRenderWindow)."""
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (registers the render window factory)
    from vtkmodules.vtkRenderingCore import vtkRenderWindow
    return vtkRenderWindow().GetClassName() == "vtkXOpenGLRenderWindow"


def this_command():
    """The command line of this process (pvpython, its options, the script and its arguments)."""
    with open("/proc/self/cmdline", "rb") as f:
        argv = [a.decode() for a in f.read().split(b"\0")[:-1]]
    return [os.path.realpath("/proc/self/exe")] + argv[1:]


def xvfb_command(command):
    """xvfb-run -a ... [env LD_PRELOAD=...] COMMAND: the preload applies to COMMAND only."""
    preload = os.environ.get("LD_PRELOAD")
    env = ["env", "LD_PRELOAD=" + preload] if preload else []
    return ["xvfb-run", "-a", "-s", XVFB_ARGS] + env + command


def ensure_display(script):
    """Returns when rendering can work; else re-runs this command under xvfb-run, or exits."""
    if os.environ.get("DISPLAY") or not renders_through_x():
        return
    command = xvfb_command(this_command())
    xvfb_run = shutil.which("xvfb-run")
    if not xvfb_run or os.environ.get("DGMF_UNDER_XVFB"):
        sys.exit("%s: no X display (DISPLAY is not set), and this ParaView renders through X even "
                 "offscreen. Run it under Xvfb (apt-get install xvfb xauth):\n  %s"
                 % (script, " ".join(shlex.quote(a) for a in command)))
    print("%s: no X display, running under xvfb-run" % script, file=sys.stderr, flush=True)
    env = dict(os.environ, DGMF_UNDER_XVFB="1")
    env.pop("LD_PRELOAD", None)
    sys.stdout.flush()
    os.execve(xvfb_run, [xvfb_run] + command[1:], env)
