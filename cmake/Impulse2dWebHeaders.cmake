# The header-only dependencies for the emscripten build, taken from the Debian packages the
# native build uses (libeigen3-dev, libtomlplusplus-dev). emscripten's toolchain looks for
# packages only in its own sysroot, and adding /usr/include itself would put the host's C library
# headers before emscripten's, so each library's headers are reached through a directory of its
# own: Eigen's is one already; toml++'s is linked into the build tree.
find_path(IMPULSE2D_EIGEN_DIR Eigen/Core PATHS /usr/include/eigen3 NO_DEFAULT_PATH
          NO_CMAKE_FIND_ROOT_PATH REQUIRED)
find_path(IMPULSE2D_TOMLPLUSPLUS_DIR toml++/toml.h PATHS /usr/include NO_DEFAULT_PATH
          NO_CMAKE_FIND_ROOT_PATH REQUIRED)
add_library(Eigen3::Eigen INTERFACE IMPORTED)
target_include_directories(Eigen3::Eigen SYSTEM INTERFACE ${IMPULSE2D_EIGEN_DIR})
set(toml_dir ${CMAKE_BINARY_DIR}/web-headers/toml)
file(MAKE_DIRECTORY ${toml_dir})
file(CREATE_LINK ${IMPULSE2D_TOMLPLUSPLUS_DIR}/toml++ ${toml_dir}/toml++ SYMBOLIC)
add_library(tomlplusplus::tomlplusplus INTERFACE IMPORTED)
target_include_directories(tomlplusplus::tomlplusplus SYSTEM INTERFACE ${toml_dir})
