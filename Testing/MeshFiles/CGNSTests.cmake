# Tests of the CGNS reader and writer (CGNSFile.h): files written by the CGNS library in the tests
# (ParaView's vtkcgns), read back; write-back; hostile files.
add_executable(DGMFCGNSTests TestCGNSFile.cxx)
target_include_directories(DGMFCGNSTests SYSTEM PRIVATE "${DGMF_VTK_THIRDPARTY_INCLUDE_DIR}")
target_link_libraries(DGMFCGNSTests PRIVATE DGMFMeshFiles "${DGMF_CGNS_LIBRARY}" GTest::gtest
  GTest::gtest_main)
# Under AddressSanitizer the readers' children have no address-space limit (LibraryIsolation.cxx):
# a corrupted header's allocation fails in ASan's allocator instead.
if(DGMF_ENABLE_SANITIZERS)
  gtest_discover_tests(DGMFCGNSTests TEST_PREFIX "cgns." DISCOVERY_TIMEOUT 60 PROPERTIES ENVIRONMENT
    "ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1:max_allocation_size_mb=2048")
else()
  gtest_discover_tests(DGMFCGNSTests TEST_PREFIX "cgns." DISCOVERY_TIMEOUT 60)
endif()
