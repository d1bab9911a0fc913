/**
 * @file CGNSZone.h
 * @brief Private to CGNSFile.cxx: the parts of a CGNS file's tree the reader and writer use, read
 * through the CGNS library with every call checked (the open file, the first base and its zone,
 * the coordinate arrays, the element sections).
 */
#ifndef dgmf_meshfile_CGNSZone_h
#define dgmf_meshfile_CGNSZone_h

#include "dgmf/meshfile/NamedMesh.h"

#include <vtkcgns/src/cgnslib.h>

#include <string>
#include <vector>

namespace dgmf
{
namespace meshfile
{
namespace cgns
{
using ElementType = CGNS_ENUMT(ElementType_t);
using DataType = CGNS_ENUMT(DataType_t);

/// What the library says about its last error, as " (...)".
std::string LastError();

/// An open CGNS file, closed when it goes out of scope; every call's error becomes a FileError
/// naming the file, the node of the tree being read, and what the library said.
class CGNSHandle
{
public:
  CGNSHandle(const std::string& path, int mode)
    : Path(path)
  {
    if (cg_open(path.c_str(), mode, &this->Id) != CG_OK)
    {
      this->Id = -1;
      throw FileError(path + ": not a CGNS file that can be opened" + LastError());
    }
  }
  ~CGNSHandle()
  {
    if (this->Id >= 0)
    {
      cg_close(this->Id);
    }
  }
  CGNSHandle(const CGNSHandle&) = delete;
  CGNSHandle& operator=(const CGNSHandle&) = delete;

  /// Throws FileError when `status` is not CG_OK.
  void Check(int status, const std::string& what) const
  {
    if (status != CG_OK)
    {
      throw FileError(this->Path + ": cannot read " + what + LastError());
    }
  }

  /// Throws FileError("<file>: <what>").
  [[noreturn]] void Fail(const std::string& what) const
  {
    throw FileError(this->Path + ": " + what);
  }

  /// Closes the file, with its error (a write that could not be flushed) as a FileError.
  void Close()
  {
    const int status = cg_close(this->Id);
    this->Id = -1;
    if (status != CG_OK)
    {
      throw FileError(this->Path + ": cannot be written" + LastError());
    }
  }

  int Id = -1;
  std::string Path;
};

/// One coordinate array of the zone, as the file stores it.
struct Coordinate
{
  std::string Name; ///< CoordinateX, CoordinateY, CoordinateZ
  DataType Type;    ///< RealSingle or RealDouble
};

/// The node the reader uses: the first base, its zone, and its coordinate arrays.
struct ZoneLayout
{
  std::string Base, Zone; ///< names, for the messages
  int CellDimension = 0;
  int PhysicalDimension = 0;
  cgsize_t Vertices = 0;
  std::vector<Coordinate> Coordinates; ///< X, Y (, Z when the physical dimension is 3)
};

/// The most entries (of 8 bytes) an array read from the file may have: a count the file cannot
/// back is refused before it drives an allocation. A compressed (HDF5) file holds its arrays in at
/// least 1/64 of their size, with 64 MiB allowed for any file.
double EntryBudget(const std::string& path);

/// The first base and its one unstructured zone, and the zone's Cartesian coordinate arrays.
ZoneLayout ReadLayout(const CGNSHandle& file);

/// VTK's cell type of a linear CGNS element type; 0 for the others.
std::uint8_t CellTypeOf(cgsize_t type);

/// The elements of one section: element numbers First..First + Size() - 1 of the zone.
struct Section
{
  std::string Name; ///< "section '<name>'", for the messages
  cgsize_t First = 0;
  Cells Elements; ///< on 0-based nodes
};

/// The elements of the zone's sections, with their element numbers.
class ZoneElements
{
public:
  /// Reads every section, checking node indices; sections ordered by element number.
  void Read(const CGNSHandle& file, const ZoneLayout& layout);

  /// The section holding element `number`, or nullptr.
  const Section* Find(cgsize_t number) const;

  std::vector<Section> Sections; ///< in the file's order
  cgsize_t Total = 0;            ///< the number of elements of all sections

private:
  std::vector<const Section*> ByNumber;
};

} // namespace cgns
} // namespace meshfile
} // namespace dgmf

#endif
