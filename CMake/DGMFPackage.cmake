# The CMake package of the VTK module (find_package(DGMF)), in the build tree and the install
# tree: DGMFConfig.cmake and its version file in <lib>/cmake/DGMF, next to (VTK-only build) or
# pointing to (plugin build) the targets vtk_module_build exports.
include(CMakePackageConfigHelpers)
set(dgmf_package_dir "${CMAKE_INSTALL_LIBDIR}/cmake/DGMF")
if(DGMF_BUILD_PARAVIEW_PLUGIN)
  # paraview_add_plugin(MODULE_INSTALL_EXPORT) writes them with the plugin.
  set(dgmf_exports "../../dgmf-plugins/DGMFPlugin/cmake/DGMFPlugin/DGMFPlugin")
else()
  set(dgmf_exports "DGMF")
endif()
set(DGMF_TARGETS_FILE "${dgmf_exports}-targets.cmake")
set(DGMF_PROPERTIES_FILE "${dgmf_exports}-vtk-module-properties.cmake")
set(DGMF_VTK_DIR "${VTK_DIR}")
configure_file("${CMAKE_CURRENT_LIST_DIR}/DGMFConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${dgmf_package_dir}/DGMFConfig.cmake" @ONLY)
write_basic_package_version_file("${CMAKE_BINARY_DIR}/${dgmf_package_dir}/DGMFConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMajorVersion)
install(FILES "${CMAKE_BINARY_DIR}/${dgmf_package_dir}/DGMFConfig.cmake"
  "${CMAKE_BINARY_DIR}/${dgmf_package_dir}/DGMFConfigVersion.cmake"
  DESTINATION "${dgmf_package_dir}")
