"""Loads the DGMF plugin twice and reports what the expat tests check (run by pvpython/pvbatch).

    pvpython expat_probe.py [PLUGIN]   (no PLUGIN when a launcher put it on PV_PLUGIN_PATH)

Prints "probe: plugin loaded, DGMFDeform available, work-around loaded: yes|no".
"""
import ctypes
import sys

from paraview import simple

plugin = sys.argv[1] if len(sys.argv) > 1 else ""
if plugin:
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    simple.LoadPlugin(plugin, remote=False, ns=globals())
assert hasattr(simple, "DGMFDeform") or "DGMFDeform" in globals(), "no DGMFDeform"
process = ctypes.CDLL(None)
loaded = hasattr(process, "dgmf_expat_fix_loaded")
print("probe: plugin loaded, DGMFDeform available, work-around loaded: %s"
      % ("yes" if loaded else "no"))
