/**
 * @file DGMFExpatWarningStarter.h
 * @brief The plugin's auto-start in ParaView's GUI (paraview_plugin_add_auto_start): issues the
 * expat warning (DGMFExpatWarning.h) once the GUI, and its Output Messages window, are up.
 */
#ifndef DGMFExpatWarningStarter_h
#define DGMFExpatWarningStarter_h

/// Called by ParaView's GUI when it starts the plugin and when it shuts it down.
class DGMFExpatWarningStarter
{
public:
  /// Warns once, from the event loop, if the process's expat breaks VTK 9.2's XML reading.
  void startup();
  /// Nothing to undo.
  void shutdown() {}
};

#endif
