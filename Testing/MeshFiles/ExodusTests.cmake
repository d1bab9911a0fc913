# Tests of the Exodus II reader and writer (ExodusFile.h): files written by the Exodus library in
# the tests.
add_executable(DGMFExodusTests TestExodusFile.cxx)
target_include_directories(DGMFExodusTests SYSTEM PRIVATE "${DGMF_VTK_THIRDPARTY_INCLUDE_DIR}")
target_link_libraries(DGMFExodusTests PRIVATE DGMFMeshFiles "${DGMF_EXODUSII_LIBRARY}"
  GTest::gtest GTest::gtest_main)
dgmf_discover_library_reader_tests(DGMFExodusTests exodus)
