# Exodus II and CGNS files through the libraries ParaView's own readers use: ParaView (and VTK)
# ship them as vtkexodusII and vtkcgns, their symbols prefixed (vtkexodusII_ex_open_int,
# vtkcgns_cg_open), with their headers under ParaView's include directory. Found as files, without
# find_package(VTK), so that the core-only builds (sanitizers, Clang) test these readers too, and
# one copy of each library (and of HDF5 and netCDF under them) is loaded in ParaView.
set(_dgmf_vtk_include_suffixes paraview-5.13 paraview-5.12 paraview-5.11 paraview-5.10 vtk-9.4
  vtk-9.3 vtk-9.2 vtk-9.1)
find_path(DGMF_VTK_THIRDPARTY_INCLUDE_DIR vtkexodusII/include/exodusII.h
  PATH_SUFFIXES ${_dgmf_vtk_include_suffixes}
  DOC "ParaView's (or VTK's) include directory with vtkexodusII/ and vtkcgns/")
find_library(DGMF_EXODUSII_LIBRARY NAMES vtkexodusII-pv5.13 vtkexodusII-pv5.12 vtkexodusII-pv5.11
  vtkexodusII-pv5.10 vtkexodusII-9.4 vtkexodusII-9.3 vtkexodusII-9.2 vtkexodusII-9.1
  DOC "ParaView's (or VTK's) Exodus II library")
find_library(DGMF_CGNS_LIBRARY NAMES vtkcgns-pv5.13 vtkcgns-pv5.12 vtkcgns-pv5.11 vtkcgns-pv5.10
  vtkcgns-9.4 vtkcgns-9.3 vtkcgns-9.2 vtkcgns-9.1 DOC "ParaView's (or VTK's) CGNS library")
if(NOT DGMF_VTK_THIRDPARTY_INCLUDE_DIR OR NOT DGMF_EXODUSII_LIBRARY OR NOT DGMF_CGNS_LIBRARY)
  message(FATAL_ERROR "ParaView's Exodus II and CGNS libraries were not found (vtkexodusII, "
    "vtkcgns): install paraview-dev, or set DGMF_VTK_THIRDPARTY_INCLUDE_DIR, "
    "DGMF_EXODUSII_LIBRARY and DGMF_CGNS_LIBRARY")
endif()
target_sources(DGMFMeshFiles PRIVATE
  "${CMAKE_CURRENT_LIST_DIR}/dgmf/meshfile/ExodusFile.cxx"
  "${CMAKE_CURRENT_LIST_DIR}/dgmf/meshfile/CGNSFile.cxx"
  "${CMAKE_CURRENT_LIST_DIR}/dgmf/meshfile/CGNSZone.cxx")
target_include_directories(DGMFMeshFiles SYSTEM PRIVATE "${DGMF_VTK_THIRDPARTY_INCLUDE_DIR}")
# netCDF (the library under Exodus, the system's: ParaView's vtk_netcdf.h includes <netcdf.h>):
# coordinates of the old combined layout are written through it.
find_library(DGMF_NETCDF_LIBRARY NAMES netcdf DOC "netCDF's C library")
if(NOT DGMF_NETCDF_LIBRARY)
  message(FATAL_ERROR "netCDF's library was not found: install libnetcdf-dev")
endif()
target_link_libraries(DGMFMeshFiles PRIVATE "${DGMF_EXODUSII_LIBRARY}" "${DGMF_CGNS_LIBRARY}"
  "${DGMF_NETCDF_LIBRARY}")
