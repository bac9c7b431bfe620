# cmake -DCLOSURE=<file> -DTARGET=<name> -DMUST=<lib> -P check_link_closure.cmake: fails when the
# link closure written at configure time (link_closure.cmake) names OpenCV or OpenImageIO, or
# lacks MUST (so that an empty or broken walk cannot pass).
cmake_minimum_required(VERSION 3.22)
file(STRINGS "${CLOSURE}" _libs)
if(NOT MUST IN_LIST _libs)
  message(FATAL_ERROR "${CLOSURE}: the link closure of ${TARGET} lacks ${MUST}: is the walk broken?")
endif()
set(_bad "")
foreach(_l ${_libs})
  string(TOLOWER "${_l}" _low)
  if(_low MATCHES "opencv|openimageio|oiio")
    list(APPEND _bad "${_l}")
  endif()
endforeach()
if(_bad)
  list(JOIN _bad ", " _bad)
  message(FATAL_ERROR "${TARGET} links, directly or through its libraries: ${_bad} "
                      "(the farm must link only the plan model, libspt and the JSON layer)")
endif()
list(JOIN _libs ", " _all)
message(STATUS "${TARGET} links: ${_all}")
