# find_package(DGMF) from a project outside this one: Testing/Package/consumer is configured,
# built and run against the build tree (DGMF_DIR = BUILD/lib/cmake/DGMF), then against an install
# tree (cmake --install BUILD --prefix WORK/install).
#   cmake -DBUILD=<this build> -DWORK=<scratch folder> -DCONSUMER=<consumer sources>
#         -DGENERATOR=<generator> -P TestFindPackage.cmake
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output
    ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}\n${output}")
  endif()
  set(output "${output}" PARENT_SCOPE)
endfunction()

function(consume name dgmf_dir)
  set(binary "${WORK}/${name}")
  file(REMOVE_RECURSE "${binary}")
  run(${CMAKE_COMMAND} -S "${CONSUMER}" -B "${binary}" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DDGMF_DIR=${dgmf_dir}")
  run(${CMAKE_COMMAND} --build "${binary}")
  run("${binary}/dgmf-consumer")
  message(STATUS "${name}: ${output}")
  if(NOT output MATCHES "consumer OK")
    message(FATAL_ERROR "${name}: the program did not deform the grid")
  endif()
endfunction()

consume(build-tree "${BUILD}/lib/cmake/DGMF")
file(REMOVE_RECURSE "${WORK}/install")
run(${CMAKE_COMMAND} --install "${BUILD}" --prefix "${WORK}/install")
if(NOT EXISTS "${WORK}/install/lib/cmake/DGMF/DGMFConfig.cmake")
  message(FATAL_ERROR "the install tree has no lib/cmake/DGMF/DGMFConfig.cmake")
endif()
consume(install-tree "${WORK}/install/lib/cmake/DGMF")
message(STATUS "find_package(DGMF) works from the build tree and from the install tree")
