# cmake -P: install the build into a scratch prefix, configure and build an
# outside project against it (tests/install/consumer), run its program.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DEXAMPLE_SOURCE=${SOURCE_DIR}/examples/flatten_bezier.cpp
                        -DCMAKE_CXX_COMPILER=${CXX} "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}"
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the outside project failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the outside project failed: ${rc}")
endif()
foreach(exe flatten_bezier flatten_only)
  execute_process(COMMAND ${WORK_DIR}/build/${exe} 0.01 RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(rc)
    message(FATAL_ERROR "${exe} failed: ${rc}")
  endif()
  message("${exe}: ${out}")
endforeach()
# The profiles are installed where the package says.
if(NOT EXISTS ${WORK_DIR}/prefix/share/bezcam/machines/fanuc.json)
  message(FATAL_ERROR "profiles not installed in share/bezcam/machines")
endif()
# The manual page, the documentation and the samples; the installed
# program finds the installed profiles and converts an installed sample.
foreach(f share/man/man1/bezcam.1 share/doc/bezcam/import.md share/doc/bezcam/images/verify-flange.png
          share/bezcam/samples/part.dxf share/bezcam/samples/part-flange.json)
  if(NOT EXISTS ${WORK_DIR}/prefix/${f})
    message(FATAL_ERROR "${f} not installed")
  endif()
endforeach()
file(READ ${WORK_DIR}/prefix/share/man/man1/bezcam.1 man)
foreach(cmd check convert import lint preview sheet simulate status stream verify)
  if(NOT man MATCHES "\\.SS \"bezcam ${cmd}\"")
    message(FATAL_ERROR "the manual page has no section for bezcam ${cmd}")
  endif()
endforeach()
execute_process(COMMAND ${WORK_DIR}/prefix/bin/bezcam convert ${WORK_DIR}/prefix/share/bezcam/samples/part-flange.json
                        --machine fanuc -o ${WORK_DIR}/flange.nc
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "the installed bezcam failed on an installed sample: ${rc}\n${err}")
endif()
