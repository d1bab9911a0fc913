/**
 * @file DGMFCommandSeries.h
 * @brief dgmf-deform's series of a motion in time: one output per time, their names, the .pvd
 * collection, OpenFOAM time names, and the trajectory table read from a CSV file.
 */
#ifndef DGMFCommandSeries_h
#define DGMFCommandSeries_h

#include "vtkSmartPointer.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

class vtkTable;

namespace dgmf_cli
{

/**
 * The file of frame `index` of a series of `count` for the OUTPUT given: OUTPUT's own printf
 * conversion if it has one (%d, %4d, %04d), else the frame number inserted before the extension
 * ("out.vtu" -> "out_0007.vtu", at least 4 digits). Empty when OUTPUT has a % that is not one
 * such conversion in the file's name (not in a folder), at most 20 digits wide.
 */
std::string FramePath(const std::string& output, std::size_t index, std::size_t count);

/// The .pvd collection of the series: OUTPUT without its conversion (or number) and extension.
std::string CollectionPath(const std::string& output);

/**
 * Writes ParaView's collection file (.pvd) listing (time, file) pairs, the files relative to the
 * collection's folder. False when it cannot be written.
 */
bool WriteCollection(
  const std::string& path, const std::vector<std::pair<double, std::string>>& frames);

/**
 * The names of the time directories of `times` in an OpenFOAM case ("0.02", "1", "1e-05"): 6
 * significant digits, OpenFOAM's default time precision, or as many more as make every name
 * distinct (as OpenFOAM raises its timePrecision), 17 at most.
 */
std::vector<std::string> OpenFOAMTimeNames(const std::vector<double>& times);

/**
 * The trajectory table of a CSV file with a header row (numbers detected as such), or null with
 * the error printed.
 */
vtkSmartPointer<vtkTable> ReadTrajectoryCSV(const std::string& path);

} // namespace dgmf_cli

#endif
