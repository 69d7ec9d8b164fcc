# impulse2d added to another project with add_subdirectory: that project's
#   find_package(impulse2d 0.2 REQUIRED COMPONENTS scene render)
# finds the targets just defined (through their ALIASes impulse2d::...) instead of an installed
# copy, so the same CMakeLists.txt builds against either. CMake 3.24 and later look in
# CMAKE_FIND_PACKAGE_REDIRECTS_DIR first; older ones need impulse2d installed, or the ALIASes used
# without find_package.
if(NOT DEFINED CMAKE_FIND_PACKAGE_REDIRECTS_DIR)
  return()
endif()
include(CMakePackageConfigHelpers)
set(IMPULSE2D_COMPONENTS "")
foreach(part ${IMPULSE2D_PARTS})
  if(NOT part STREQUAL "impulse2d")
    string(REPLACE "impulse2d_" "" component ${part})
    list(APPEND IMPULSE2D_COMPONENTS ${component})
  endif()
endforeach()
file(WRITE ${CMAKE_FIND_PACKAGE_REDIRECTS_DIR}/impulse2d-config.cmake "\
# Written by impulse2d's cmake/Impulse2dSubproject.cmake: the targets of the source tree.
set(impulse2d_SCENES_DIR \"${PROJECT_SOURCE_DIR}/demos/scenes\")
set(_impulse2d_built ${IMPULSE2D_COMPONENTS})
foreach(component \${impulse2d_FIND_COMPONENTS})
  if(component IN_LIST _impulse2d_built)
    set(impulse2d_\${component}_FOUND TRUE)
  elseif(impulse2d_FIND_REQUIRED_\${component})
    set(impulse2d_FOUND FALSE)
    set(impulse2d_NOT_FOUND_MESSAGE \"impulse2d was added without its '\${component}' part\")
  endif()
endforeach()
")
write_basic_package_version_file(${CMAKE_FIND_PACKAGE_REDIRECTS_DIR}/impulse2d-config-version.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
