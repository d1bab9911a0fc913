# Tests of the SU2 reader and writer: hand-made files checked field by field, meshes made by gmsh
# (su2/make_gmsh_meshes.py), write-back, hostile files, and a seeded run of mutated files.
add_executable(DGMFSU2Tests TestSU2File.cxx su2/TestSU2HostileFiles.cxx su2/TestSU2Mutations.cxx)
target_link_libraries(DGMFSU2Tests PRIVATE DGMFMeshFiles GTest::gtest GTest::gtest_main)
target_compile_definitions(DGMFSU2Tests PRIVATE DGMF_SU2_TEST_DATA="${CMAKE_CURRENT_LIST_DIR}/su2")
gtest_discover_tests(DGMFSU2Tests TEST_PREFIX "su2." DISCOVERY_TIMEOUT 60)
