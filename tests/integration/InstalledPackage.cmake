# ctest, script mode: installs the build into a fresh prefix, copies
# examples/cpp out of the source tree, builds it against the installed
# package (find_package(eikon)) and runs it; its first frame must be a
# picture. -DBUILD=<build folder> -DSOURCE=<source folder> -DWORK=<scratch folder>
cmake_minimum_required(VERSION 3.25)
function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nexited ${rc}\n${out}\n${err}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix)
# The public header is the only one installed.
file(GLOB_RECURSE headers RELATIVE ${WORK}/prefix ${WORK}/prefix/include/*)
if(NOT headers STREQUAL "include/eikon/eikon.h")
  message(FATAL_ERROR "installed headers: expected include/eikon/eikon.h alone, found ${headers}")
endif()
file(COPY ${SOURCE}/examples/cpp/ DESTINATION ${WORK}/example)
run(${CMAKE_COMMAND} -S ${WORK}/example -B ${WORK}/example-build -G Ninja -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${WORK}/prefix)
run(${CMAKE_COMMAND} --build ${WORK}/example-build)
run(${WORK}/example-build/heated_plume 1)
file(READ ${WORK}/plume_0.ppm header LIMIT 12)
if(NOT header MATCHES "^P6\n64 48\n255")
  message(FATAL_ERROR "plume_0.ppm: expected a 64×48 binary PPM, found a header \"${header}\"")
endif()
file(SIZE ${WORK}/plume_0.ppm bytes)
if(NOT bytes EQUAL 9229)  # 13 header bytes + 64·48·3
  message(FATAL_ERROR "plume_0.ppm: expected 9229 bytes, found ${bytes}")
endif()
file(REMOVE_RECURSE ${WORK})
