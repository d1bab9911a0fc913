# Tests of the Exodus II reader and writer (ExodusFile.h): files written by the Exodus library in
# the tests.
add_executable(DGMFExodusTests TestExodusFile.cxx)
target_include_directories(DGMFExodusTests SYSTEM PRIVATE "${DGMF_VTK_THIRDPARTY_INCLUDE_DIR}")
target_link_libraries(DGMFExodusTests PRIVATE DGMFMeshFiles "${DGMF_EXODUSII_LIBRARY}"
  GTest::gtest GTest::gtest_main)
# Under AddressSanitizer the readers' children have no address-space limit (LibraryIsolation.cxx):
# a corrupted header's allocation fails in ASan's allocator instead.
if(DGMF_ENABLE_SANITIZERS)
  gtest_discover_tests(DGMFExodusTests TEST_PREFIX "exodus." DISCOVERY_TIMEOUT 60 PROPERTIES ENVIRONMENT
    "ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1:max_allocation_size_mb=2048")
else()
  gtest_discover_tests(DGMFExodusTests TEST_PREFIX "exodus." DISCOVERY_TIMEOUT 60)
endif()
