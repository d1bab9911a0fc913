# gmsh .msh files through gmsh's own library (Debian: libgmsh-dev). The gmsh calls are a module of
# their own, libDGMFGmshFile.so (GmshModel.cxx, GmshSession.cxx), which DGMFMeshFiles opens with
# dlopen when a .msh file is first read or written (GmshModule.h): libgmsh and its ~70 libraries
# cost every process that links them 0.1 - 0.15 s at start-up. So neither dgmf-deform, nor DGMF::IO,
# nor the ParaView plugin links libgmsh (environment.GmshLoadedOnDemand checks it); the gmsh tests
# still do, to make their meshes.
find_path(DGMF_GMSH_INCLUDE_DIR gmsh.h DOC "Directory of gmsh's C++ API header gmsh.h")
find_library(DGMF_GMSH_LIBRARY NAMES gmsh DOC "gmsh's library (libgmsh.so)")
if(NOT DGMF_GMSH_INCLUDE_DIR OR NOT DGMF_GMSH_LIBRARY)
  message(FATAL_ERROR "gmsh's library was not found (gmsh.h, libgmsh.so): install libgmsh-dev, "
    "or set DGMF_GMSH_INCLUDE_DIR and DGMF_GMSH_LIBRARY")
endif()
# The build's identity, made once per build tree: the loader refuses a module of another build.
if(NOT DGMF_GMSH_MODULE_IDENTITY)
  string(RANDOM LENGTH 16 ALPHABET "0123456789abcdef" dgmf_identity)
  set(DGMF_GMSH_MODULE_IDENTITY "${PROJECT_VERSION}-${dgmf_identity}" CACHE INTERNAL
    "The identity the gmsh module and its loader share")
endif()
target_sources(DGMFMeshFiles PRIVATE
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/GmshFile.cxx"
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/GmshModule.cxx"
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/MshHeader.cxx"
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/MshModel.cxx"
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/MshNodes.cxx"
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/MshReader22.cxx"
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/MshReader41.cxx")
target_link_libraries(DGMFMeshFiles PRIVATE ${CMAKE_DL_LIBS})
# Where the loader looks in the build tree (for code inside the build tree only), after the
# directory of the code that loads it.
target_compile_definitions(DGMFMeshFiles PRIVATE
  "DGMF_GMSH_MODULE_IDENTITY=\"${DGMF_GMSH_MODULE_IDENTITY}\""
  "DGMF_GMSH_MODULE_BUILD_PATH=\"$<TARGET_FILE:DGMFGmshFile>\""
  "DGMF_BUILD_DIRECTORY=\"${CMAKE_BINARY_DIR}\"")

add_library(DGMFGmshFile MODULE
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/GmshModel.cxx"
  "${CMAKE_CURRENT_SOURCE_DIR}/dgmf/meshfile/GmshSession.cxx")
target_include_directories(DGMFGmshFile SYSTEM PRIVATE "${DGMF_GMSH_INCLUDE_DIR}")
target_link_libraries(DGMFGmshFile PRIVATE DGMFMeshFiles "${DGMF_GMSH_LIBRARY}")
target_compile_definitions(DGMFGmshFile PRIVATE
  "DGMF_GMSH_MODULE_IDENTITY=\"${DGMF_GMSH_MODULE_IDENTITY}\"")
target_compile_options(DGMFGmshFile PRIVATE $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra>)
# Only the entry points are visible: the module's own code is hidden, and so is the copy of
# DGMFMeshFiles linked into it (--exclude-libs), so its calls stay inside it.
set_target_properties(DGMFGmshFile PROPERTIES CXX_VISIBILITY_PRESET hidden
  VISIBILITY_INLINES_HIDDEN ON INSTALL_RPATH_USE_LINK_PATH ON)
target_link_options(DGMFGmshFile PRIVATE "LINKER:--exclude-libs,ALL")
# Installed beside the library that loads it: DGMF::IO, in the plugin's directory when the
# ParaView plugin is built (a core-only build installs nothing that loads it).
if(NOT DGMF_CORE_ONLY)
  if(DGMF_BUILD_PARAVIEW_PLUGIN)
    set(dgmf_gmsh_module_destination "${CMAKE_INSTALL_LIBDIR}/dgmf-plugins/DGMFPlugin")
  else()
    set(dgmf_gmsh_module_destination "${CMAKE_INSTALL_LIBDIR}")
  endif()
  install(TARGETS DGMFGmshFile LIBRARY DESTINATION "${dgmf_gmsh_module_destination}")
endif()
