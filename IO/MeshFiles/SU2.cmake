# SU2's native mesh format (.su2): read with its markers, written back with new coordinates.
target_sources(DGMFMeshFiles PRIVATE "${CMAKE_CURRENT_LIST_DIR}/dgmf/meshfile/SU2File.cxx")
