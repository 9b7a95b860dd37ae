// Scratch files of the doctest suites: in WRC_TEST_TMP (the build's tests/tmp, set by CTest), else /tmp.
#pragma once

#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

namespace wrc::test {

// <folder>/<pid>_<name>: the process id keeps two runs of a suite at once (ctest -j, or two builds) apart.
inline std::string tmp_path(const std::string& name) {
  const char* t = std::getenv("WRC_TEST_TMP");
  return std::string(t && *t ? t : "/tmp") + "/" + std::to_string(getpid()) + "_" + name;
}

// Writes text (bytes as given) to tmp_path(name); returns that path.
inline std::string write_tmp(const std::string& name, const std::string& text) {
  const std::string p = tmp_path(name);
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

}  // namespace wrc::test
