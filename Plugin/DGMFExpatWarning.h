/**
 * @file DGMFExpatWarning.h
 * @brief The plugin's warning about an expat that breaks VTK 9.2's XML reading (private to the
 * plugin): issued once per process, when the plugin library is loaded (pvpython, pvbatch) or when
 * ParaView's GUI starts the plugin (DGMFExpatWarningStarter), so that it reaches the Output
 * Messages window.
 */
#ifndef DGMFExpatWarning_h
#define DGMFExpatWarning_h

namespace dgmf_plugin
{

/**
 * Warns (vtkGenericWarningMacro: ParaView's output window, or the standard error of pvpython and
 * pvbatch) when NeedsWorkAround(InspectExpat()), with the commands of WarningText(). Does nothing
 * on the second and later calls.
 */
void WarnAboutExpatOnce();

} // namespace dgmf_plugin

#endif
