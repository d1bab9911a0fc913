/**
 * @file DGMFCommandMessages.h
 * @brief What dgmf-deform tells its user: VTK's errors and warnings once each, as one line
 * without the pipeline's request dump; progress on long runs; and a clean exit (code 1, a
 * message, no half-written file) when VTK aborts (its arrays call abort() when an allocation
 * fails) or the user interrupts.
 */
#ifndef DGMFCommandMessages_h
#define DGMFCommandMessages_h

#include <string>

class vtkAlgorithm;

namespace dgmf_cli
{
/**
 * Routes every VTK message of this process to stderr as "dgmf-deform: error: TEXT" (or
 * "warning:"), TEXT being the message without VTK's file, line and object prefix; the executive's
 * "returned failure for request" dump is dropped, and a message repeated word for word is printed
 * once. Call once, first thing in main().
 */
void InstallMessageWindow();

/**
 * Forgets which messages were printed: a series calls it for each frame, so that a frame's
 * warning is printed after its "time" line even if an earlier frame said the same.
 */
void ForgetPrintedMessages();

/**
 * Messages printed from now on show `text` as `shown`: an OpenFOAM patch group the user named
 * ('wall') instead of the alternatives of its patches the filter was given ('bottom|top|body').
 */
void ShowInMessagesAs(const std::string& text, const std::string& shown);

/// The number of VTK errors reported since InstallMessageWindow (or the last ResetErrorCount).
int GetErrorCount();
void ResetErrorCount();

/**
 * What the program is doing, for the message printed when VTK aborts (out of memory) or the user
 * interrupts: "reading X", "deforming", "writing Y". The string must outlive the stage.
 */
void SetStage(const std::string& stage);

/**
 * What is already written, for the same messages ("nothing was written" by default): a series
 * says how many frames it wrote before the one it is on.
 */
void SetWrittenSoFar(const std::string& written);

/**
 * A file being written: removed if VTK aborts or the user interrupts (SIGINT, SIGTERM, SIGHUP)
 * before it is renamed into place. Empty: none.
 */
void SetTemporaryFile(const std::string& path);

/**
 * Installs the handlers for SIGABRT (VTK's allocation failures), SIGINT, SIGTERM and SIGHUP: they
 * remove the temporary file, print what the program was doing, and exit with code 1 (130 for an
 * interruption). SIGXFSZ is ignored, so a file-size limit makes a write fail instead of killing
 * the program.
 */
void InstallSignalHandlers();

/**
 * Prints the progress of `algorithm` to stderr ("dgmf-deform: deforming 40%") once the run has
 * taken `delaySeconds`, at most every 10 percent.
 */
void ShowProgress(vtkAlgorithm* algorithm, const std::string& what, double delaySeconds = 2.0);
} // namespace dgmf_cli

#endif
