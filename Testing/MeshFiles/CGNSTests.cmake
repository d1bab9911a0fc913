# Tests of the CGNS reader and writer (CGNSFile.h): files written by the CGNS library in the tests
# (ParaView's vtkcgns), read back; write-back; hostile files.
add_executable(DGMFCGNSTests TestCGNSFile.cxx TestCGNSHostileFiles.cxx)
target_include_directories(DGMFCGNSTests SYSTEM PRIVATE "${DGMF_VTK_THIRDPARTY_INCLUDE_DIR}")
target_link_libraries(DGMFCGNSTests PRIVATE DGMFMeshFiles "${DGMF_CGNS_LIBRARY}" GTest::gtest
  GTest::gtest_main)
dgmf_discover_library_reader_tests(DGMFCGNSTests cgns)
