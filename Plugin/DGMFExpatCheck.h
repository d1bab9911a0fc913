/**
 * @file DGMFExpatCheck.h
 * @brief Finds out whether this process parses XML with a libexpat that breaks VTK 9.2's XML
 * reading (re-parse deferral on, the work-around libdgmf_expat_fix.so not loaded), and writes the
 * warning that tells the user how to start ParaView instead (private to the plugin).
 *
 * Debian 12's libexpat 2.5.0-1+deb12u2 and later defer re-parsing of partial input (they have
 * XML_SetReparseDeferralEnabled); VTK 9.2 does not turn that off, so appended-mode .vtu files read
 * back empty and MPI redistribution silently drops data. Tools/dgmf_expat_fix.c wraps
 * XML_ParserCreate to turn it off, and exports the marker dgmf_expat_fix_loaded.
 */
#ifndef DGMFExpatCheck_h
#define DGMFExpatCheck_h

#include <string>

namespace dgmf_plugin
{

/** What the dynamic linker of this process says about expat. */
struct ExpatState
{
  /** XML_SetReparseDeferralEnabled is visible (dlsym(RTLD_DEFAULT)): the expat defers re-parsing.
   */
  bool DefersReparse = false;
  /** XML_ParserCreate is served by the library that exports dgmf_expat_fix_loaded. */
  bool WorkAroundServes = false;
  /** The file of the library that serves XML_ParserCreate (dladdr); empty if none is visible. */
  std::string ParserLibrary;
};

/** Looks the expat functions up in this process (dlsym(RTLD_DEFAULT) and dladdr). */
ExpatState InspectExpat();

/** True when VTK's XML parsing in this process is affected: deferral on, work-around absent. */
bool NeedsWorkAround(const ExpatState& state);

/**
 * This process's program, from /proc/self/exe: "pvpython", "pvbatch" or "paraview" for ParaView's
 * (Debian's pvpython3.11 included), else the file name.
 */
std::string ProgramName();

/** Where the files the warning names are, found from the plugin library's own location. */
struct WorkAroundPaths
{
  std::string Library;   ///< libdgmf_expat_fix.so of the build or install tree of the plugin
  std::string Launchers; ///< the folder of dgmf-pvpython, dgmf-pvbatch and dgmf-paraview
  std::string Program;   ///< ProgramName()
};

/**
 * The paths for the plugin library `pluginFile`: the library `libToPlugin`-relative (the plugin is
 * in LIBDIR/dgmf-plugins/DGMFPlugin, the work-around in LIBDIR), the launchers in `pluginToBin`
 * relative to the plugin's folder, the program from ProgramName(). Paths are made absolute and
 * normalised when they exist.
 */
WorkAroundPaths FindWorkAround(
  const std::string& pluginFile, const std::string& pluginToLib, const std::string& pluginToBin);

/** The warning: what breaks, and the exact command lines that start the program correctly. */
std::string WarningText(const ExpatState& state, const WorkAroundPaths& paths);

} // namespace dgmf_plugin

#endif
