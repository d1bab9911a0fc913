/**
 * The smallest VTK C++ pipeline with vtkDGMFDeformFilter: read a .vtu, rotate its moving boundary
 * about the origin, write the deformed mesh.
 *
 *   DeformMesh INPUT.vtu OUTPUT.vtu ANGLE_DEGREES
 *
 * The input carries a "BoundaryMarker" point array (0 interior, 1 static, 2 moving).
 */
#include "vtkDGMFDeformFilter.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    std::cerr << "usage: DeformMesh INPUT.vtu OUTPUT.vtu ANGLE_DEGREES\n";
    return 2;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(argv[1]);

  vtkNew<vtkDGMFDeformFilter> deform;
  deform->SetInputConnection(reader->GetOutputPort());
  deform->SetBoundaryMarkerArrayName("BoundaryMarker");
  deform->SetRotationCenter(0.0, 0.0, 0.0);
  deform->SetRotationAngles(0.0, 0.0, std::atof(argv[3]));

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputConnection(deform->GetOutputPort());
  writer->SetFileName(argv[2]);
  writer->SetDataModeToBinary(); // inline binary: appended mode breaks with Debian 12's expat
  return writer->Write() && deform->GetOutput()->GetNumberOfPoints() > 0 ? EXIT_SUCCESS
                                                                         : EXIT_FAILURE;
}
