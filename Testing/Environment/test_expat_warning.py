"""The plugin's warning about an expat that breaks VTK 9.2's XML reading (Plugin/DGMFExpatCheck.h).

    python3 test_expat_warning.py --pvpython P --pvbatch B --plugin PLUGIN --shim SHIM
        --fake FAKE --launchers BIN_DIR --probe expat_probe.py
    python3 test_expat_warning.py --gui --paraview PARAVIEW --plugin PLUGIN --fake FAKE
        --launchers BIN_DIR                                       (under xvfb-run)

FAKE is a test library that exports XML_SetReparseDeferralEnabled (forwarding to the real one if
any): with it, a machine whose libexpat does not defer (Debian's 2.5.0-1+deb12u1) looks like one
that does (deb12u2 and later). Checks, the plugin being loaded twice in each process:
- without preload: one warning if this machine's libexpat defers, none if it does not;
- with the work-around preloaded: none, with or without FAKE;
- with FAKE: exactly one, naming the work-around's and the launcher's absolute paths;
- dgmf-pvpython with FAKE preloaded: none (its preload comes first); pvbatch with FAKE: one;
- in the GUI (--gui), the plugin auto-loaded from PV_PLUGIN_PATH with FAKE: one warning, sent once
  the main window is shown (it then opens the Output Messages window; seen on a screenshot).
"""
import argparse
import ctypes
import os
import subprocess
import sys
import time

WARNING = "DGMF: this process's libexpat"


def run(command, preload=None, extra_env=None):
    """Output (stdout and stderr) of `command` with LD_PRELOAD set to `preload` (or unset)."""
    env = dict(os.environ)
    env.pop("LD_PRELOAD", None)
    if preload:
        env["LD_PRELOAD"] = preload
    env.update(extra_env or {})
    result = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=240)
    if result.returncode != 0 or "probe: plugin loaded" not in result.stdout:
        sys.exit("FAILED: %s (LD_PRELOAD=%s) exited %d:\n%s"
                 % (" ".join(command), preload, result.returncode, result.stdout))
    return result.stdout


def expect(name, output, count, names=()):
    found = output.count(WARNING)
    if found != count:
        sys.exit("FAILED: %s: %d warnings, expected %d:\n%s" % (name, found, count, output))
    for text in names:
        if text not in output:
            sys.exit("FAILED: %s: the warning does not name %s:\n%s" % (name, text, output))
    print("%s: %d warning%s, as expected" % (name, found, "" if found == 1 else "s"))


def real_expat_defers():
    """Whether this machine's libexpat has XML_SetReparseDeferralEnabled (deb12u2 and later)."""
    return hasattr(ctypes.CDLL("libexpat.so.1"), "XML_SetReparseDeferralEnabled")


def check_programs(args):
    shim, fake = os.path.realpath(args.shim), os.path.realpath(args.fake)
    launchers = os.path.realpath(args.launchers)
    probe = [args.pvpython, args.probe, args.plugin]
    defers = real_expat_defers()
    print("this machine's libexpat defers re-parsing: %s" % ("yes" if defers else "no"))
    expect("pvpython", run(probe), 1 if defers else 0)
    expect("pvpython, work-around preloaded", run(probe, shim), 0)
    expect("pvpython, fake deferral", run(probe, fake), 1,
           ("LD_PRELOAD=%s pvpython" % shim, "%s/dgmf-pvpython" % launchers))
    expect("pvpython, fake deferral and work-around", run(probe, fake + ":" + shim), 0)
    launched = run([os.path.join(launchers, "dgmf-pvpython"), args.probe], fake)
    expect("dgmf-pvpython, fake deferral", launched, 0)
    if "work-around loaded: yes" not in launched:
        sys.exit("FAILED: dgmf-pvpython did not preload the work-around:\n" + launched)
    expect("pvbatch, fake deferral", run([args.pvbatch, args.probe, args.plugin], fake), 1,
           ("%s/dgmf-pvbatch" % launchers,))


def check_gui(args):
    """ParaView's GUI auto-loads the plugin (PV_PLUGIN_PATH): one warning within 90 s."""
    env = dict(os.environ)
    env["LD_PRELOAD"] = os.path.realpath(args.fake)
    env["PV_PLUGIN_PATH"] = os.path.dirname(os.path.realpath(args.plugin))
    log = open(args.log, "w+")
    gui = subprocess.Popen([args.paraview], env=env, stdout=log, stderr=subprocess.STDOUT)
    deadline = time.time() + 90
    output = ""
    try:
        while time.time() < deadline and WARNING not in output and gui.poll() is None:
            time.sleep(0.5)
            log.seek(0)
            output = log.read()
        time.sleep(2)  # a second warning would come now
    finally:
        gui.kill()
        gui.wait()
    log.seek(0)
    output = log.read()
    expect("paraview GUI, fake deferral, plugin auto-loaded", output, 1,
           ("%s/dgmf-paraview" % os.path.realpath(args.launchers),))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gui", action="store_true")
    parser.add_argument("--pvpython")
    parser.add_argument("--pvbatch")
    parser.add_argument("--paraview")
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--shim")
    parser.add_argument("--fake", required=True)
    parser.add_argument("--launchers", required=True)
    parser.add_argument("--probe")
    parser.add_argument("--log", default="gui_expat_warning.log")
    args = parser.parse_args()
    if args.gui:
        check_gui(args)
    else:
        check_programs(args)
    print("expat warning OK")


main()
