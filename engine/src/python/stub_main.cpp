// Writes the Python package's type stub (wrc/__init__.pyi) from api::operations(): `wrc_python_stub OUT`.
#include "python/docs.hpp"

#include <cstdio>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: wrc_python_stub OUT.pyi\n");
    return 2;
  }
  try {
    std::ofstream out(argv[1], std::ios::binary | std::ios::trunc);
    out << wrc::python::stub();
    out.close();
    if (!out) throw std::runtime_error(std::string("cannot write ") + argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wrc_python_stub: %s\n", e.what());
    return 1;
  }
  return 0;
}
