/**
 * @file DGMFVTUReader.h
 * @brief dgmf-deform's .vtu reader for the files it writes (one piece, appended raw data, LZ4,
 * zlib, LZMA or no compression): the same grid as VTK's vtkXMLUnstructuredGridReader, with the
 * compressed blocks decompressed on all threads.
 *
 * VTK 9.2's reader decompresses an array's blocks one after the other, into memory touched for
 * the first time: about 0.9 s for an 8.26M-node grid written by dgmf-deform (390 MB of LZ4),
 * a third of the whole command. Here the XML header is parsed by VTK's own parser
 * (vtkXMLDataParser, which stops at the appended data), the file is mapped, and every block of
 * every array is decompressed by VTK's compressor class into the arrays where they belong, in
 * parallel (vtkSMPTools; DGMFAppendedData.h). See Documentation/speed.md.
 */
#ifndef DGMFVTUReader_h
#define DGMFVTUReader_h

#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <string>

namespace dgmf_cli
{

/**
 * Reads the .vtu file `path` as vtkXMLUnstructuredGridReader would (the same points, cells,
 * point, cell and field data arrays with their types, names, component names and active
 * attributes), when the file is of the kind this reader takes: VTK's XML format version 0.1 or
 * 1.0, little-endian, one piece with points and cells, every array numeric and named once, in
 * the appended section, raw (not base64), compressed with LZ4, zlib, LZMA or not at all, and no
 * polyhedra (the arrays' cached ranges, which VTK's writer stores as information keys, are left
 * out, as VTK 9.2's reader leaves them; other information keys go to VTK's reader). Every size
 * and offset of the header is checked against the file before it is used. Otherwise,
 * or when the file does not hold what its header says, returns null and `whyNot` says why: the
 * caller then reads the file with VTK's reader (which reports errors as VTK does).
 */
vtkSmartPointer<vtkUnstructuredGrid> ReadAppendedVTU(const std::string& path, std::string& whyNot);

} // namespace dgmf_cli

#endif
