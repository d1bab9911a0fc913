/**
 * @file DGMFExpatWarning.cxx
 * @brief WarnAboutExpatOnce, and the static initializer that calls it when the plugin library is
 * loaded.
 *
 * This file is part of the plugin library only (not of the DGMF::Filters module), so programs
 * that link the module and the work-around (dgmf-deform) never run it.
 */
#include "DGMFExpatWarning.h"

#include "DGMFExpatCheck.h"

#include <vtkObject.h>
#include <vtkSetGet.h>

#include <dlfcn.h>

namespace dgmf_plugin
{

void WarnAboutExpatOnce()
{
  static bool done = false;
  if (done)
  {
    return;
  }
  done = true;
  const ExpatState state = InspectExpat();
  if (!NeedsWorkAround(state))
  {
    return;
  }
  // A function of the plugin library: dladdr turns its address into the plugin's file.
  Dl_info info{};
  const bool found = dladdr(reinterpret_cast<void*>(&WarnAboutExpatOnce), &info) != 0;
  const WorkAroundPaths paths = FindWorkAround(
    found && info.dli_fname ? info.dli_fname : "", DGMF_PLUGIN_TO_LIB, DGMF_PLUGIN_TO_BIN);
  vtkGenericWarningMacro(<< WarningText(state, paths));
}

} // namespace dgmf_plugin

namespace
{

/**
 * Calls WarnAboutExpatOnce when the plugin library is loaded (dlopen), except in ParaView's GUI
 * when the plugin has its GUI auto-start: the GUI may load the plugin before its Output Messages
 * window exists, and the auto-start runs once it does.
 */
struct PluginLoad
{
  PluginLoad()
  {
#ifdef DGMF_PLUGIN_GUI_AUTOSTART
    if (dgmf_plugin::ProgramName() == "paraview")
    {
      return;
    }
#endif
    dgmf_plugin::WarnAboutExpatOnce();
  }
};
const PluginLoad pluginLoad;

} // namespace
