# gmsh .msh files through gmsh's own library (Debian: libgmsh-dev): GmshFile.cxx and its private
# session helper. gmsh.h is needed by these sources only; libgmsh is linked into every consumer
# of the static DGMFMeshFiles (CMake carries a static library's link dependencies as LINK_ONLY).
find_path(DGMF_GMSH_INCLUDE_DIR gmsh.h DOC "Directory of gmsh's C++ API header gmsh.h")
find_library(DGMF_GMSH_LIBRARY NAMES gmsh DOC "gmsh's library (libgmsh.so)")
if(NOT DGMF_GMSH_INCLUDE_DIR OR NOT DGMF_GMSH_LIBRARY)
  message(FATAL_ERROR "gmsh's library was not found (gmsh.h, libgmsh.so): install libgmsh-dev, "
    "or set DGMF_GMSH_INCLUDE_DIR and DGMF_GMSH_LIBRARY")
endif()
target_sources(DGMFMeshFiles PRIVATE
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/GmshFile.cxx"
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/GmshSession.cxx")
target_include_directories(DGMFMeshFiles SYSTEM PRIVATE "${DGMF_GMSH_INCLUDE_DIR}")
target_link_libraries(DGMFMeshFiles PRIVATE "${DGMF_GMSH_LIBRARY}")
