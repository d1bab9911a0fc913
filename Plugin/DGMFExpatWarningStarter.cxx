/**
 * @file DGMFExpatWarningStarter.cxx
 * @brief The GUI auto-start of DGMFExpatWarningStarter.h.
 */
#include "DGMFExpatWarningStarter.h"

#include "DGMFExpatWarning.h"

#include <pqCoreUtilities.h>

#include <QTimer>
#include <QWidget>

namespace
{

/**
 * Warns once the main window is shown, looking every 100 ms for at most `tries` times. A message
 * sent earlier reaches the Output Messages window, but the window does not open for it: the main
 * window restores its docks' state when it is shown.
 */
void WarnWhenMainWindowShown(int tries)
{
  QWidget* mainWindow = pqCoreUtilities::mainWidget();
  if (tries > 0 && !(mainWindow && mainWindow->isVisible()))
  {
    QTimer::singleShot(100, [tries] { WarnWhenMainWindowShown(tries - 1); });
    return;
  }
  // One more turn of the event loop, after the show event.
  QTimer::singleShot(0, [] { dgmf_plugin::WarnAboutExpatOnce(); });
}

} // namespace

void DGMFExpatWarningStarter::startup()
{
  // A plugin loaded at start-up (Auto Load, PV_PLUGIN_PATH) is started before the main window
  // exists: warn from the event loop, once the window is shown.
  WarnWhenMainWindowShown(100);
}
