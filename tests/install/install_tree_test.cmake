# The installed tree as a user gets it (see CMakeLists.txt). Run with cmake -P and
# BUILD_DIR, SOURCE_DIR, WORK_DIR, OFX_PLUGIN_DIR, OFX_ARCHITECTURE, LIB_DIR, OFX_HOST_TEST,
# STRIP and, when the Python module is built, PYTHON_DIR.
cmake_minimum_required(VERSION 3.20)

function(run)
  cmake_parse_arguments(ARG "" "WHAT" "COMMAND" ${ARGN})
  execute_process(COMMAND ${ARG_COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${ARG_WHAT} failed (${status}):\n${ARG_COMMAND}\n${out}\n${err}")
  endif()
  set(run_output "${out}${err}" PARENT_SCOPE)
endfunction()

function(require_file path)
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "not installed: ${path}")
  endif()
endfunction()

# Stage the install: an arbitrary prefix under DESTDIR, so the tree is not where it was
# configured for (it must not care) and the absolute bundle folder lands in the stage too.
set(stage ${WORK_DIR}/stage)
set(prefix /opt/taa-install-test)
set(root ${stage}${prefix})
file(REMOVE_RECURSE ${WORK_DIR})
set(ENV{DESTDIR} ${stage})
run(WHAT "cmake --install" COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
unset(ENV{DESTDIR})

set(bundle ${stage}${OFX_PLUGIN_DIR}/TAAResolve.ofx.bundle/Contents/${OFX_ARCHITECTURE}/TAAResolve.ofx)
set(binaries ${root}/bin/taatool ${root}/bin/taa-farm ${root}/${LIB_DIR}/libtaa.so.0 ${bundle})
foreach(path ${binaries} ${root}/include/taa/taa.h ${root}/${LIB_DIR}/libtaa.so
             ${root}/${LIB_DIR}/cmake/taa/taaConfig.cmake
             ${root}/share/taa/blender/taa_blender_addon.zip)
  require_file(${path})
endforeach()

# Stripped, and no run path into the build tree (nothing installed needs one).
foreach(binary ${binaries})
  run(WHAT "readelf" COMMAND readelf -S -d ${binary})
  if(STRIP AND run_output MATCHES "\\.debug_info|\\.symtab")
    message(FATAL_ERROR "${binary} is not stripped")
  endif()
  if(run_output MATCHES "(RPATH|RUNPATH)[^\n]*\\[([^]\n]*)\\]")
    if(NOT CMAKE_MATCH_2 MATCHES "^\\$ORIGIN")
      message(FATAL_ERROR "${binary} has the run path ${CMAKE_MATCH_2}")
    endif()
  endif()
  file(SIZE ${binary} size)
  message(STATUS "installed ${binary}: ${size} bytes")
endforeach()

run(WHAT "installed taatool" COMMAND ${root}/bin/taatool --help)
run(WHAT "installed taa-farm" COMMAND ${root}/bin/taa-farm --help)

# The bundle loaded from where hosts look, by the OpenFX test host.
set(ENV{OFX_PLUGIN_PATH} ${stage}${OFX_PLUGIN_DIR})
run(WHAT "the OpenFX test host on the installed bundle"
    COMMAND ${OFX_HOST_TEST} --gtest_brief=1
            "--gtest_filter=OfxHostTest.SequentialRenderMatchesTaatool:OfxHostTest.ClipPreferences*:*HostContextIsCurrentAfterEveryCall/egl")
if(NOT run_output MATCHES "PASSED")
  message(FATAL_ERROR "the OpenFX test host ran no test:\n${run_output}")
endif()
unset(ENV{OFX_PLUGIN_PATH})

# The C sample built against the installed tree with find_package(taa), and run.
run(WHAT "configuring the C sample"
    COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/samples/capi_host -B ${WORK_DIR}/consumer
            -DCMAKE_PREFIX_PATH=${root} -DCMAKE_BUILD_TYPE=Release)
run(WHAT "building the C sample" COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(WHAT "the C sample" COMMAND ${WORK_DIR}/consumer/taa_minimal_c_host)

if(PYTHON_DIR)
  set(ENV{PYTHONPATH} ${root}/${PYTHON_DIR})
  run(WHAT "importing the installed Python module"
      COMMAND /usr/bin/python3 -c "import taa\nprint(taa.__file__)")
  if(NOT run_output MATCHES "${root}")
    message(FATAL_ERROR "Python imported another taa module: ${run_output}")
  endif()
endif()
message(STATUS "the installed tree works")
