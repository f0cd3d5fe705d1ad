# The program as a user meets it when something is wrong: one line naming
# what and where, a non-zero exit, and no output folder left behind.
function(expect_failure name expected_rc)
  cmake_parse_arguments(ARG "" "" "ENV;ARGS;FRAGMENTS" ${ARGN})
  file(REMOVE_RECURSE "${WORK}/${name}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${ARG_ENV} "${PLANET}" ${ARG_ARGS}
                          --out "${WORK}/${name}" --quiet
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
  if(NOT rc EQUAL expected_rc)
    message(FATAL_ERROR "${name}: exit ${rc}, expected ${expected_rc}\n${err}")
  endif()
  string(STRIP "${err}" err)
  string(FIND "${err}" "\n" newline)
  if(NOT newline EQUAL -1)
    message(FATAL_ERROR "${name}: the error is more than one line:\n${err}")
  endif()
  foreach(fragment ${ARG_FRAGMENTS})
    string(FIND "${err}" "${fragment}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${name}: '${fragment}' missing from: ${err}")
    endif()
  endforeach()
  if(EXISTS "${WORK}/${name}")
    message(FATAL_ERROR "${name}: the failed run left ${WORK}/${name} behind")
  endif()
  message(STATUS "${name}: ${err}")
endfunction()

expect_failure(missing_flight 2 ARGS capture --flight "${WORK}/no_such_flight.json"
               FRAGMENTS "no_such_flight.json" "cannot open")
file(WRITE "${WORK}/late.json" "{\"body\": \"earth\", \"image\": {\"width\": 64, \"height\": 32},
  \"frame_rate\": 1, \"sun\": {\"elevation_deg\": 10, \"azimuth_deg\": 0},
  \"keyframes\": [{\"time\": 5, \"lat_deg\": 0, \"lon_deg\": 0, \"height_m\": 2},
                 {\"time\": 4, \"lat_deg\": 0, \"lon_deg\": 0, \"height_m\": 3}]}")
expect_failure(backwards_keyframe 2 ARGS capture --flight "${WORK}/late.json"
               FRAGMENTS "late.json" "keyframes[1].time" "does not come after")
expect_failure(bad_slice 2 ARGS capture --flight "${FLIGHT}" --frames 2:99
               FRAGMENTS "frames 2:99" "outside")
# No EGL vendor library at all: glvnd finds no driver.
expect_failure(no_egl 1 ENV "__EGL_VENDOR_LIBRARY_FILENAMES=${WORK}/none.json"
               ARGS capture --flight "${FLIGHT}" FRAGMENTS "EGL" "install")
# A driver that offers only OpenGL 3.3.
expect_failure(old_gl 1 ENV "MESA_GL_VERSION_OVERRIDE=3.3"
               ARGS capture --flight "${FLIGHT}" FRAGMENTS "4.5" "install")
# A schedule that is none of software, plain or auto.
expect_failure(bad_schedule 2 ARGS capture --flight "${FLIGHT}" --schedule fast
               FRAGMENTS "--schedule" "fast")
# A body whose clouds are out of range: the file and the field, before any
# frame.
file(READ "$ENV{PLANET_ROOT}/data/planets/earth.json" earth)
string(JSON earth SET "${earth}" clouds extinction_per_m "-0.04")
file(WRITE "${WORK}/cloudy_earth.json" "${earth}")
file(WRITE "${WORK}/cloudy.json" "{\"body\": \"${WORK}/cloudy_earth.json\",
  \"image\": {\"width\": 64, \"height\": 32, \"clouds\": true},
  \"frame_rate\": 1, \"sun\": {\"elevation_deg\": 10, \"azimuth_deg\": 0},
  \"keyframes\": [{\"time\": 0, \"lat_deg\": 0, \"lon_deg\": 0, \"height_m\": 2}]}")
expect_failure(bad_clouds 2 ARGS capture --flight "${WORK}/cloudy.json"
               FRAGMENTS "cloudy_earth.json" "clouds.extinction_per_m" "out of range")
