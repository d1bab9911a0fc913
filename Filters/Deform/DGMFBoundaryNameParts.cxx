#include "DGMFBoundaryNameParts.h"

#include "dgmf/ResultNames.h"

#include "vtkCellTypes.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataAssembly.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

namespace dgmf_vtk
{
std::string NameOf(std::string entry)
{
  for (const char* prefix : { "patch/", "boundary/" })
  {
    if (entry.rfind(prefix, 0) == 0)
    {
      entry = entry.substr(std::string(prefix).size());
    }
  }
  return entry;
}

std::vector<std::string> Alternatives(const std::string& entry)
{
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (begin <= entry.size())
  {
    const std::size_t end = std::min(entry.find('|', begin), entry.size());
    std::string part = entry.substr(begin, end - begin);
    const std::size_t first = part.find_first_not_of(" \t");
    if (first != std::string::npos)
    {
      parts.push_back(part.substr(first, part.find_last_not_of(" \t") - first + 1));
    }
    begin = end + 1;
  }
  return parts;
}

std::string SelectorOf(const std::string& entry)
{
  if (!entry.empty() && entry[0] == '/')
  {
    return entry;
  }
  return "//" + vtkDataAssembly::MakeValidNodeName(NameOf(entry).c_str());
}

int NonBoundaryGroupDimension(vtkCompositeDataSet* input, const std::string& name)
{
  vtkFieldData* fields = input ? input->GetFieldData() : nullptr;
  auto* groups = vtkStringArray::SafeDownCast(
    fields ? fields->GetAbstractArray(dgmf::names::NonBoundaryGroups) : nullptr);
  vtkDataArray* dimensions =
    fields ? fields->GetArray(dgmf::names::NonBoundaryGroupDimensions) : nullptr;
  if (!groups || !dimensions || dimensions->GetNumberOfTuples() != groups->GetNumberOfValues())
  {
    return -1;
  }
  for (vtkIdType g = 0; g < groups->GetNumberOfValues(); ++g)
  {
    if (groups->GetValue(g) == name)
    {
      return static_cast<int>(dimensions->GetTuple1(g));
    }
  }
  return -1;
}

std::string FamilyOfBlock(vtkDataObject* block)
{
  vtkFieldData* fields = block ? block->GetFieldData() : nullptr;
  auto* family = fields
    ? vtkStringArray::SafeDownCast(fields->GetAbstractArray(dgmf::names::BoundaryFamily))
    : nullptr;
  return family && family->GetNumberOfValues() > 0 ? family->GetValue(0) : std::string();
}

std::string FamilyOf(vtkCompositeDataSet* input, const CompositeMesh::Leaf& leaf)
{
  return FamilyOfBlock(input ? input->GetDataSet(leaf.FlatIndex) : nullptr);
}

std::string WithFamily(const std::string& name, const std::string& family)
{
  return family.empty() || family == name ? name : name + " (family " + family + ")";
}

vtkIdType GhostVolumeCellsOfAPatch(
  vtkCompositeDataSet* input, const CompositeMesh::Leaf& leaf, int dimension)
{
  auto* block = input && leaf.CellDimension >= dimension
    ? vtkDataSet::SafeDownCast(input->GetDataSet(leaf.FlatIndex))
    : nullptr;
  vtkUnsignedCharArray* ghosts = block ? block->GetCellGhostArray() : nullptr;
  vtkIdType volumeGhosts = 0;
  bool faces = false;
  for (vtkIdType c = 0; ghosts && c < block->GetNumberOfCells(); ++c)
  {
    const int cellDimension =
      vtkCellTypes::GetDimension(static_cast<unsigned char>(block->GetCellType(c)));
    faces = faces || (ghosts->GetValue(c) == 0 && cellDimension < dimension);
    volumeGhosts += ghosts->GetValue(c) != 0 && cellDimension >= dimension ? 1 : 0;
  }
  return faces ? volumeGhosts : 0;
}

} // namespace dgmf_vtk
