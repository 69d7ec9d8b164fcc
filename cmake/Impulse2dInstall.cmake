# What `cmake --install` puts where, and the Debian package CPack makes of it (docs/packaging.md):
#   include/impulse2d/...                  the public headers of the parts built
#   lib/libimpulse2d*.a                    the libraries (static)
#   lib/cmake/impulse2d/                   find_package(impulse2d 0.2 COMPONENTS scene render ...)
#   lib/pkgconfig/impulse2d.pc             pkg-config for the core
#   bin/i2d, share/impulse2d/scenes/       the command line and the lecture scenes it runs by name
include(CMakePackageConfigHelpers)

set(IMPULSE2D_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/impulse2d)
set(IMPULSE2D_INSTALL_SCENES_DIR ${CMAKE_INSTALL_DATADIR}/impulse2d/scenes)
set(include_dir ${PROJECT_SOURCE_DIR}/lib/include/impulse2d)

# The core and each part: its library, its headers and its own export set, so the package loads
# a component's targets (and looks for its dependencies) only when it is asked for.
install(TARGETS impulse2d EXPORT impulse2d-targets ARCHIVE LIBRARY RUNTIME)
install(DIRECTORY ${include_dir} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        PATTERN render EXCLUDE PATTERN box2d EXCLUDE PATTERN scene_file.h EXCLUDE
        PATTERN setting_ranges.h EXCLUDE)
install(EXPORT impulse2d-targets NAMESPACE impulse2d:: DESTINATION ${IMPULSE2D_INSTALL_CMAKEDIR})
set(IMPULSE2D_COMPONENTS "")
foreach(part ${IMPULSE2D_PARTS})
  string(REPLACE "impulse2d_" "" component ${part})
  if(component STREQUAL "impulse2d")
    continue()
  endif()
  list(APPEND IMPULSE2D_COMPONENTS ${component})
  install(TARGETS ${part} EXPORT impulse2d-${component}-targets ARCHIVE LIBRARY RUNTIME)
  install(EXPORT impulse2d-${component}-targets NAMESPACE impulse2d::
          DESTINATION ${IMPULSE2D_INSTALL_CMAKEDIR})
endforeach()
if(IMPULSE2D_BUILD_SCENE)
  # A scene file carries its view (render/view.h, plain data), so scene_file.h includes it.
  install(FILES ${include_dir}/scene/scene_file.h ${include_dir}/scene/setting_ranges.h
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impulse2d/scene)
  install(FILES ${include_dir}/render/view.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impulse2d/render)
endif()
foreach(component render box2d)
  if(component IN_LIST IMPULSE2D_COMPONENTS)
    install(DIRECTORY ${include_dir}/${component} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impulse2d)
  endif()
endforeach()

if(IMPULSE2D_BUILD_APPS)
  install(TARGETS i2d RUNTIME)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/demos/scenes/ DESTINATION ${IMPULSE2D_INSTALL_SCENES_DIR}
        FILES_MATCHING PATTERN "*.toml")
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

list(JOIN IMPULSE2D_COMPONENTS ", " IMPULSE2D_COMPONENT_NAMES)

# The CMake package: impulse2d-config.cmake with its version file (0.2 accepts 0.2.x).
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/impulse2d-config.cmake.in
  ${PROJECT_BINARY_DIR}/impulse2d-config.cmake
  INSTALL_DESTINATION ${IMPULSE2D_INSTALL_CMAKEDIR}
  PATH_VARS IMPULSE2D_INSTALL_SCENES_DIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/impulse2d-config-version.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/impulse2d-config.cmake
              ${PROJECT_BINARY_DIR}/impulse2d-config-version.cmake
        DESTINATION ${IMPULSE2D_INSTALL_CMAKEDIR})

# pkg-config, for the core: its paths are taken from where the .pc file lies, so the same file
# serves any prefix (/usr from the Debian package, a student's own with --prefix).
file(RELATIVE_PATH pc_to_prefix ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" pc_to_prefix "${pc_to_prefix}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/impulse2d.pc.in ${PROJECT_BINARY_DIR}/impulse2d.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/impulse2d.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# The Debian package: `cpack -G DEB` in the build directory makes impulse2d_<version>_amd64.deb.
# Depends: the shared libraries i2d runs on (found by dpkg-shlibdeps), and the development
# packages a program built on impulse2d needs: the headers include Eigen, and the libraries are
# static, so a component's dependencies are linked by the program (impulse2d-config.cmake finds
# them). A component's packages are listed only when it is built; each part's list here goes
# with its find_package calls in CMakeLists.txt and its find_dependency in impulse2d-config.cmake.in.
set(IMPULSE2D_DEBIAN_DEPENDS libeigen3-dev)
if(IMPULSE2D_BUILD_SCENE)
  list(APPEND IMPULSE2D_DEBIAN_DEPENDS libtomlplusplus-dev)
endif()
if(IMPULSE2D_BUILD_RENDER)
  list(APPEND IMPULSE2D_DEBIAN_DEPENDS libgif-dev libstb-dev libcairo2-dev libdeflate-dev
       fonts-dejavu-core)
endif()
if(IMPULSE2D_BUILD_BOX2D)
  list(APPEND IMPULSE2D_DEBIAN_DEPENDS libbox2d-dev)
endif()
list(JOIN IMPULSE2D_DEBIAN_DEPENDS ", " CPACK_DEBIAN_PACKAGE_DEPENDS)

set(CPACK_PACKAGE_NAME impulse2d)
set(CPACK_PACKAGE_VENDOR "impulse2d maintainers")
set(CPACK_PACKAGE_CONTACT "impulse2d maintainers" CACHE STRING "The Debian package's Maintainer")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "impulse2d teaches how a physics engine resolves resting contacts and friction: the lecture's micro-collisions, sequential impulses, a global LCP reference and Box2D v3's soft step, each switch of each method shown in PNG frames. The package holds the C++ library (headers, static libraries, CMake and pkg-config files), the i2d command line and the lecture scenes.")
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_STRIP_FILES bin/i2d)
include(CPack)
