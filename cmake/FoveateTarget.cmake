# foveate_library(NAME <name> SOURCES ... [DEPS ...] [PRIVATE_DEPS ...])
# Declares foveate_<name> with alias foveate::<name>, public headers under
# <dir>/include, warnings as errors, and installation into the export set.
set(FOVEATE_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Werror)
# GCC 12 at -O3 reports impossible overlaps inside std::string assignment
# (GCC bug 105329, a false positive); every other warning stays an error.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  list(APPEND FOVEATE_WARNINGS -Wno-restrict)
endif()

function(foveate_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(foveate_${name} ${ARG_SOURCES})
  add_library(foveate::${name} ALIAS foveate_${name})
  set_target_properties(foveate_${name} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(foveate_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(foveate_${name} PUBLIC cxx_std_20)
  target_compile_options(foveate_${name} PRIVATE ${FOVEATE_WARNINGS})
  target_link_libraries(foveate_${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  install(TARGETS foveate_${name} EXPORT foveateTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

# foveate_forbid_includes(<dir> <regex> <message>): fails the configure step
# when a source under <dir> includes a header matching <regex>.
function(foveate_forbid_includes dir regex message)
  file(GLOB_RECURSE files ${dir}/*.cpp ${dir}/*.hpp ${dir}/*.h)
  foreach(f ${files})
    file(STRINGS ${f} hits REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](${regex})")
    if(hits)
      message(FATAL_ERROR "${f}: ${message}: ${hits}")
    endif()
  endforeach()
endfunction()
