# Every dependency comes from a Debian package; a missing one stops configuration and names the package.
find_package(PkgConfig QUIET)
if(NOT PkgConfig_FOUND)
  message(FATAL_ERROR "pkg-config not found: apt-get install pkg-config")
endif()

find_package(Eigen3 3.3 NO_MODULE QUIET)
if(NOT Eigen3_FOUND)
  message(FATAL_ERROR "Eigen3 not found: apt-get install libeigen3-dev")
endif()

find_package(fmt QUIET)
if(NOT fmt_FOUND)
  message(FATAL_ERROR "fmt not found: apt-get install libfmt-dev")
endif()

pkg_check_modules(LUA QUIET IMPORTED_TARGET lua5.4)
if(NOT LUA_FOUND)
  message(FATAL_ERROR "Lua 5.4 not found: apt-get install liblua5.4-dev")
endif()

pkg_check_modules(FFTW3 QUIET IMPORTED_TARGET fftw3)
if(NOT FFTW3_FOUND)
  message(FATAL_ERROR "FFTW3 not found: apt-get install libfftw3-dev")
endif()

find_package(Threads REQUIRED)

if(WRC_BUILD_TESTS)
  find_package(doctest QUIET)
  if(NOT doctest_FOUND)
    message(FATAL_ERROR "doctest not found: apt-get install doctest-dev (or configure with -DWRC_BUILD_TESTS=OFF)")
  endif()
endif()
