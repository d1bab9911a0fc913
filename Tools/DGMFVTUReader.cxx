#include "DGMFVTUReader.h"

#include "DGMFAppendedData.h"
#include "DGMFCompressedArray.h"
#include "DGMFGridCells.h"
#include "DGMFTupleAllocation.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <new>
#include <utility>
#include <vector>

namespace dgmf_cli
{
namespace
{
/// The arrays of the file, made from its header; their bytes queued in the appended data.
class ArrayMaker
{
public:
  explicit ArrayMaker(AppendedData& appended)
    : Appended(appended)
  {
  }

  /**
   * The array of the DataArray `element` with `tuples` tuples (-1: its NumberOfTuples), its
   * values from the file queued into the array at value `skip` (0, or 1 for the leading 0 of
   * VTK's cell offsets); `type`, when not 0, the type VTK's reader converts it to (the values
   * then need the same type in the file).
   */
  vtkSmartPointer<vtkDataArray> Make(
    vtkXMLDataElement* element, vtkIdType tuples, vtkIdType skip = 0, int type = 0)
  {
    const char* format = element->GetAttribute("format");
    if (!format || std::string(format) != "appended")
    {
      throw NotTaken{ "an array not in the appended section" };
    }
    // The arrays' cached ranges, which VTK's writer stores as information keys, are left out:
    // VTK 9.2's reader gives arrays without them too. Other keys: VTK's reader.
    for (int k = 0; k < element->GetNumberOfNestedElements(); ++k)
    {
      vtkXMLDataElement* key = element->GetNestedElement(k);
      const char* keyName = key->GetAttribute("name");
      const std::string name = keyName ? keyName : "";
      if (std::string(key->GetName()) != "InformationKey" ||
        (name != "L2_NORM_RANGE" && name != "COMPONENT_RANGE" && name != "L2_NORM_FINITE_RANGE" &&
          name != "COMPONENT_FINITE_RANGE"))
      {
        throw NotTaken{ "an array with information other than its cached ranges" };
      }
    }
    int fileType = 0;
    if (!element->GetWordTypeAttribute("type", fileType) || !IsNumeric(fileType))
    {
      throw NotTaken{ "an array that is not numeric" };
    }
    int idType = 0;
    if (element->GetScalarAttribute("IdType", idType) && idType != 0 &&
      vtkDataArray::GetDataTypeSize(fileType) == sizeof(vtkIdType))
    {
      fileType = VTK_ID_TYPE;
    }
    if (type != 0 && vtkDataArray::GetDataTypeSize(type) != vtkDataArray::GetDataTypeSize(fileType))
    {
      throw NotTaken{ "cells whose ids are not of vtkIdType's size" };
    }
    int components = 1;
    element->GetScalarAttribute("NumberOfComponents", components);
    if (tuples < 0 && !element->GetScalarAttribute("NumberOfTuples", tuples))
    {
      throw NotTaken{ "a field-data array without its number of tuples" };
    }
    vtkIdType offset = 0;
    if (components < 1 || tuples < 0 || !element->GetScalarAttribute("offset", offset) ||
      offset < 0)
    {
      throw NotTaken{ "an array without its size or offset" };
    }
    const auto valueBytes =
      static_cast<std::size_t>(vtkDataArray::GetDataTypeSize(type ? type : fileType));
    const std::size_t most =
      static_cast<std::size_t>(PTRDIFF_MAX) / valueBytes / static_cast<std::size_t>(components);
    if (static_cast<std::size_t>(tuples) > most - static_cast<std::size_t>(skip))
    {
      throw NotTaken{ "an array too large to be held" };
    }
    // The cells' ids straight into vtkCellArray's own storage type: SetData keeps such arrays
    // themselves (a vtkIdTypeArray would be wrapped in a new array), with what they carry.
    auto array = type == VTK_ID_TYPE
      ? vtkSmartPointer<vtkDataArray>::Take(sizeof(vtkIdType) == 8
            ? static_cast<vtkDataArray*>(vtkCellArray::ArrayType64::New())
            : static_cast<vtkDataArray*>(vtkCellArray::ArrayType32::New()))
      : vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(type ? type : fileType));
    const char* name = element->GetAttribute("Name");
    if (name && type == 0) // the cells' arrays (converted) have no name in VTK's reader
    {
      array->SetName(name);
    }
    array->SetNumberOfComponents(components);
    for (int c = 0; c < components && c < 10; ++c) // VTK's reader reads names 0 to 9
    {
      const std::string key = "ComponentName" + std::to_string(c);
      if (const char* name = element->GetAttribute(key.c_str()))
      {
        array->SetComponentName(c, name);
      }
    }
    // Not initialised: the jobs touch the pages first, huge pages when large.
    dgmf_vtk::AllocateTuples(array, tuples + skip);
    const std::size_t bytes = static_cast<std::size_t>(tuples) * components * valueBytes;
    if (array->GetNumberOfTuples() != tuples + skip || (bytes > 0 && !array->GetVoidPointer(0)))
    {
      throw std::bad_alloc(); // VTK could not allocate it (and said so)
    }
    auto* target = static_cast<unsigned char*>(array->GetVoidPointer(0)) +
      static_cast<std::size_t>(skip) * valueBytes;
    AppendedData::CompressedBlocks blocks =
      this->Appended.Queue(static_cast<std::size_t>(offset), target, bytes);
    // alive until its bytes are written, whatever the caller keeps
    this->Made.push_back(
      { array, static_cast<std::size_t>(skip) * valueBytes, bytes, std::move(blocks) });
    return array;
  }

  /// Writes the bytes of the arrays made so far, and remembers for each array of a compressed
  /// file the blocks it was read from (CompressedArray: written again as they are if the array
  /// is not modified).
  void Run()
  {
    this->Appended.Run();
    for (Queued& made : this->Made)
    {
      if (!made.Blocks.Blocks.empty())
      {
        CompressedArray compressed;
        compressed.Keep = this->Appended.GetFile();
        compressed.CompressorClass = this->Appended.GetCompressorName();
        compressed.BlockSize = made.Blocks.BlockSize;
        compressed.Offset = made.Offset;
        compressed.Bytes = made.Bytes;
        compressed.Blocks = std::move(made.Blocks.Blocks);
        CompressedArray::Remember(made.Array, std::move(compressed));
      }
    }
    this->Made.clear();
  }

private:
  static bool IsNumeric(int type)
  {
    switch (type)
    {
      case VTK_FLOAT:
      case VTK_DOUBLE:
      case VTK_CHAR:
      case VTK_SIGNED_CHAR:
      case VTK_UNSIGNED_CHAR:
      case VTK_SHORT:
      case VTK_UNSIGNED_SHORT:
      case VTK_INT:
      case VTK_UNSIGNED_INT:
      case VTK_LONG:
      case VTK_UNSIGNED_LONG:
      case VTK_LONG_LONG:
      case VTK_UNSIGNED_LONG_LONG:
      case VTK_ID_TYPE:
        return true;
      default:
        return false;
    }
  }

  /// An array made, its values' place in its memory (bytes from its start, bytes in all) and
  /// its compressed blocks in the file.
  struct Queued
  {
    vtkSmartPointer<vtkDataArray> Array;
    std::size_t Offset;
    std::size_t Bytes;
    AppendedData::CompressedBlocks Blocks;
  };

  AppendedData& Appended;
  std::vector<Queued> Made;
};

/// The active attributes (Scalars="name", ...) of a PointData or CellData element.
void SetAttributes(vtkXMLDataElement* element, vtkDataSetAttributes* data)
{
  for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
  {
    const char* name = element->GetAttribute(vtkDataSetAttributes::GetAttributeTypeAsString(a));
    if (!name)
    {
      continue;
    }
    for (int k = 0; k < data->GetNumberOfArrays(); ++k)
    {
      const char* arrayName = data->GetArrayName(k);
      if (arrayName && std::string(arrayName) == name)
      {
        data->SetActiveAttribute(k, a);
        break;
      }
    }
  }
}

/// The nested element named `name` of `parent` (null when there is none).
vtkXMLDataElement* Child(vtkXMLDataElement* parent, const char* name)
{
  return parent ? parent->FindNestedElementWithName(name) : nullptr;
}

/// The DataArray children of `parent` into `data`, with `tuples` tuples each.
void AddArrays(ArrayMaker& maker, vtkXMLDataElement* parent, vtkIdType tuples, vtkFieldData* data)
{
  if (!parent)
  {
    return;
  }
  for (int k = 0; k < parent->GetNumberOfNestedElements(); ++k)
  {
    vtkXMLDataElement* element = parent->GetNestedElement(k);
    if (std::string(element->GetName()) != "DataArray")
    {
      throw NotTaken{ std::string("an element ") + element->GetName() + " among the arrays" };
    }
    const char* name = element->GetAttribute("Name");
    if (!name || data->HasArray(name))
    {
      throw NotTaken{ "an array without a name, or two of the same name" };
    }
    data->AddArray(maker.Make(element, tuples));
  }
}

vtkSmartPointer<vtkUnstructuredGrid> Read(const std::string& path)
{
  // The header, by VTK's parser: it stops at the appended data and says where it starts.
  std::ifstream stream(path, std::ios::in | std::ios::binary);
  if (!stream)
  {
    throw NotTaken{ "the file cannot be opened" };
  }
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&stream);
  if (!parser->Parse() || !parser->GetRootElement())
  {
    throw NotTaken{ "its XML header does not parse" };
  }
  vtkXMLDataElement* root = parser->GetRootElement();
  const auto attribute = [&](const char* name)
  {
    const char* value = root->GetAttribute(name);
    return std::string(value ? value : "");
  };
  const std::string version = attribute("version");
  if (std::string(root->GetName()) != "VTKFile" || attribute("type") != "UnstructuredGrid" ||
    (version != "0.1" && version != "1.0"))
  {
    throw NotTaken{ "not an unstructured grid of XML format 0.1 or 1.0" };
  }
  if (attribute("byte_order") != "LittleEndian")
  {
    throw NotTaken{ "not little-endian" };
  }
  const std::string headerType = attribute("header_type");
  const int headerBytes = headerType == "UInt64" ? 8 : 4;
  if (!headerType.empty() && headerType != "UInt64" && headerType != "UInt32")
  {
    throw NotTaken{ "header type " + headerType };
  }
  const std::string compressorName = attribute("compressor");
  if (!AppendedData::CanDecompress(compressorName))
  {
    throw NotTaken{ "compressor " + compressorName };
  }
  vtkXMLDataElement* grid = Child(root, "UnstructuredGrid");
  vtkXMLDataElement* appended = Child(root, "AppendedData");
  const char* encoding = appended ? appended->GetAttribute("encoding") : nullptr;
  if (!grid || !appended || !encoding || std::string(encoding) != "raw" ||
    parser->GetAppendedDataPosition() <= 0)
  {
    throw NotTaken{ "no raw appended data" };
  }
  vtkXMLDataElement* piece = nullptr;
  vtkXMLDataElement* fieldData = nullptr;
  for (int k = 0; k < grid->GetNumberOfNestedElements(); ++k)
  {
    vtkXMLDataElement* element = grid->GetNestedElement(k);
    const std::string name = element->GetName();
    if (name == "Piece" && !piece)
    {
      piece = element;
    }
    else if (name == "FieldData" && !fieldData)
    {
      fieldData = element;
    }
    else
    {
      throw NotTaken{ "more than one piece, or an element " + name };
    }
  }
  vtkIdType points = 0;
  vtkIdType cells = 0;
  if (!piece || !piece->GetScalarAttribute("NumberOfPoints", points) ||
    !piece->GetScalarAttribute("NumberOfCells", cells) || points <= 0 || cells <= 0)
  {
    throw NotTaken{ "no piece with points and cells" };
  }

  AppendedData appendedData(
    path, static_cast<std::size_t>(parser->GetAppendedDataPosition()), headerBytes, compressorName);
  ArrayMaker maker(appendedData);
  auto output = vtkSmartPointer<vtkUnstructuredGrid>::New();
  // Points: their DataArray as it is (Float32 or Float64).
  vtkXMLDataElement* coordinates = Child(Child(piece, "Points"), "DataArray");
  int pointComponents = 1;
  if (!coordinates || !coordinates->GetScalarAttribute("NumberOfComponents", pointComponents) ||
    pointComponents != 3)
  {
    throw NotTaken{ "no points array of 3 components" };
  }
  vtkNew<vtkPoints> outputPoints;
  outputPoints->SetData(maker.Make(coordinates, points));
  output->SetPoints(outputPoints);
  // Cells: connectivity and offsets as vtkIdType (the offsets after a leading 0), types as bytes.
  vtkSmartPointer<vtkDataArray> offsets, types;
  vtkXMLDataElement* connectivityElement = nullptr; // read once the offsets give its length
  if (vtkXMLDataElement* cellsElement = Child(piece, "Cells"))
  {
    for (int k = 0; k < cellsElement->GetNumberOfNestedElements(); ++k)
    {
      vtkXMLDataElement* element = cellsElement->GetNestedElement(k);
      const char* name = element->GetAttribute("Name");
      const std::string which = name ? name : "";
      int components = 1;
      element->GetScalarAttribute("NumberOfComponents", components);
      if (components != 1 || (which == "offsets" && offsets) || (which == "types" && types) ||
        (which == "connectivity" && connectivityElement))
      {
        throw NotTaken{ "cells given twice, or with several components" };
      }
      if (which == "offsets")
      {
        offsets = maker.Make(element, cells, 1, VTK_ID_TYPE);
        offsets->SetComponent(0, 0, 0.0);
      }
      else if (which == "types")
      {
        types = maker.Make(element, cells, 0, VTK_UNSIGNED_CHAR);
      }
      else if (which == "connectivity")
      {
        connectivityElement = element;
      }
      else
      {
        throw NotTaken{ "cells with " + which + " (polyhedra)" };
      }
    }
  }
  if (!offsets || !types)
  {
    throw NotTaken{ "cells without their offsets or types" };
  }
  // Point, cell and field data.
  AddArrays(maker, Child(piece, "PointData"), points, output->GetPointData());
  AddArrays(maker, Child(piece, "CellData"), cells, output->GetCellData());
  if (fieldData)
  {
    vtkNew<vtkFieldData> field;
    AddArrays(maker, fieldData, -1, field);
    output->SetFieldData(field);
  }
  maker.Run();
  // The connectivity, now that its length (the last offset) is known.
  {
    const auto* offsetValues = static_cast<const vtkIdType*>(offsets->GetVoidPointer(0));
    const vtkIdType ids = offsetValues[cells];
    for (vtkIdType c = 0; c < cells; ++c)
    {
      if (offsetValues[c + 1] < offsetValues[c])
      {
        throw NotTaken{ "cell offsets that decrease" };
      }
    }
    if (!connectivityElement || ids < 0)
    {
      throw NotTaken{ "cells without their connectivity" };
    }
    vtkSmartPointer<vtkDataArray> connectivity =
      maker.Make(connectivityElement, ids, 0, VTK_ID_TYPE);
    maker.Run();
    const auto* idValues = static_cast<const vtkIdType*>(connectivity->GetVoidPointer(0));
    std::atomic<bool> outside(false);
    vtkSMPTools::For(0, ids,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          if (idValues[k] < 0 || idValues[k] >= points)
          {
            outside = true;
          }
        }
      });
    if (outside)
    {
      throw NotTaken{ "a cell with a point id outside the points" };
    }
    vtkNew<vtkCellArray> cellArray;
    if (sizeof(vtkIdType) == 8)
    {
      cellArray->SetData(vtkCellArray::ArrayType64::SafeDownCast(offsets),
        vtkCellArray::ArrayType64::SafeDownCast(connectivity));
    }
    else
    {
      cellArray->SetData(vtkCellArray::ArrayType32::SafeDownCast(offsets),
        vtkCellArray::ArrayType32::SafeDownCast(connectivity));
    }
    dgmf_vtk::SetGridCells(output, vtkUnsignedCharArray::SafeDownCast(types), cellArray);
  }
  if (vtkXMLDataElement* pointData = Child(piece, "PointData"))
  {
    SetAttributes(pointData, output->GetPointData());
  }
  if (vtkXMLDataElement* cellData = Child(piece, "CellData"))
  {
    SetAttributes(cellData, output->GetCellData());
  }
  return output;
}
} // namespace

vtkSmartPointer<vtkUnstructuredGrid> ReadAppendedVTU(const std::string& path, std::string& whyNot)
{
  try
  {
    whyNot.clear();
    return Read(path);
  }
  catch (const NotTaken& reason)
  {
    whyNot = reason.Why;
  }
  catch (const std::bad_alloc&)
  {
    whyNot = "out of memory";
  }
  return nullptr;
}

} // namespace dgmf_cli
