# SU2's native mesh format (.su2): read with its markers, written back with new coordinates.
target_sources(DGMFMeshFiles PRIVATE "${CMAKE_CURRENT_LIST_DIR}/dgmf/meshfile/SU2File.cxx")
# IO/MeshFiles/CMakeLists.txt does not give DGMFMeshFiles the sanitizer flags (only DGMFCore has
# them): the SU2 reader, which parses hostile files, is instrumented here, and whatever links the
# library links the sanitizer runtimes.
if(DGMF_ENABLE_SANITIZERS)
  set_property(SOURCE "${CMAKE_CURRENT_LIST_DIR}/dgmf/meshfile/SU2File.cxx" APPEND
    PROPERTY COMPILE_OPTIONS -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(DGMFMeshFiles INTERFACE -fsanitize=address,undefined)
endif()
