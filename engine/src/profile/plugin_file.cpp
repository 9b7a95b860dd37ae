// ELF checks of a plugin library before dlopen (plugin_file.hpp).
#include "plugin_file.hpp"

#include <elf.h>
#include <fmt/format.h>
#include <link.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <vector>

namespace wrc {
namespace {

// [offset, offset + length) inside a file of `size` bytes, without overflow.
bool inside(std::uint64_t offset, std::uint64_t length, std::uint64_t size) {
  return offset <= size && length <= size - offset;
}

template <class T>
std::vector<T> read_table(std::ifstream& f, std::uint64_t offset, std::size_t count) {
  std::vector<T> v(count);
  f.seekg(static_cast<std::streamoff>(offset));
  f.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(count * sizeof(T)));
  if (!f) v.clear();
  return v;
}

std::optional<std::string> check_segments(std::ifstream& f, const ElfW(Ehdr)& h, std::uint64_t size) {
  if (h.e_phnum == 0) return "it has no program headers (not a loadable library)";
  if (h.e_phentsize != sizeof(ElfW(Phdr)))
    return fmt::format("program header entries of {} bytes (expected {})", h.e_phentsize, sizeof(ElfW(Phdr)));
  if (!inside(h.e_phoff, std::uint64_t{h.e_phnum} * sizeof(ElfW(Phdr)), size))
    return fmt::format("the program header table (offset {}, {} entries) lies past the end of the file ({} bytes): "
                       "the file is truncated", h.e_phoff, h.e_phnum, size);
  const auto ph = read_table<ElfW(Phdr)>(f, h.e_phoff, h.e_phnum);
  if (ph.empty()) return "the program header table cannot be read";
  for (std::size_t i = 0; i < ph.size(); ++i) {
    if (!inside(ph[i].p_offset, ph[i].p_filesz, size))
      return fmt::format("segment {} (file bytes {} .. {}) reaches past the end of the file ({} bytes): the file is "
                         "truncated", i, ph[i].p_offset, ph[i].p_offset + ph[i].p_filesz, size);
    if (ph[i].p_type == PT_LOAD && ph[i].p_filesz > ph[i].p_memsz)
      return fmt::format("segment {} holds more file bytes ({}) than memory ({})", i, ph[i].p_filesz, ph[i].p_memsz);
  }
  return std::nullopt;
}

std::optional<std::string> check_sections(std::ifstream& f, const ElfW(Ehdr)& h, std::uint64_t size) {
  if (h.e_shoff == 0) return std::nullopt;  // no section headers: allowed (the loader does not need them)
  if (h.e_shentsize != sizeof(ElfW(Shdr)))
    return fmt::format("section header entries of {} bytes (expected {})", h.e_shentsize, sizeof(ElfW(Shdr)));
  const std::uint64_t count = h.e_shnum == 0 ? 1 : h.e_shnum;  // 0: the count is in the first entry (extended)
  if (!inside(h.e_shoff, count * sizeof(ElfW(Shdr)), size))
    return fmt::format("the section header table (offset {}, {} entries) lies past the end of the file ({} bytes): "
                       "the file is truncated", h.e_shoff, count, size);
  const auto sh = read_table<ElfW(Shdr)>(f, h.e_shoff, count);
  if (sh.empty()) return "the section header table cannot be read";
  for (std::size_t i = 0; i < sh.size(); ++i)
    if (sh[i].sh_type != SHT_NOBITS && sh[i].sh_type != SHT_NULL && !inside(sh[i].sh_offset, sh[i].sh_size, size))
      return fmt::format("section {} (file bytes {} .. {}) reaches past the end of the file ({} bytes): the file is "
                         "truncated", i, sh[i].sh_offset, sh[i].sh_offset + sh[i].sh_size, size);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_library_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) return fmt::format("cannot open the file: {}", std::strerror(errno));
  const auto end = f.tellg();
  if (end < 0) return "cannot read the file";
  const auto size = static_cast<std::uint64_t>(end);
  f.seekg(0);
  ElfW(Ehdr) h{};
  f.read(reinterpret_cast<char*>(&h), sizeof h);
  if (size < SELFMAG || std::memcmp(h.e_ident, ELFMAG, SELFMAG) != 0) return "not an ELF file (no ELF magic number)";
  if (!f) return fmt::format("the file ends inside the ELF header ({} bytes): the file is truncated", size);
  const unsigned char own_class = sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32;
  if (h.e_ident[EI_CLASS] != own_class)
    return fmt::format("a {}-bit library, but this wrc is {}-bit", h.e_ident[EI_CLASS] == ELFCLASS64 ? 64 : 32,
                       8 * sizeof(void*));
  const unsigned char own_data = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? ELFDATA2LSB : ELFDATA2MSB;
  if (h.e_ident[EI_DATA] != own_data) return "a library of the other byte order than this host's";
  if (h.e_type != ET_DYN) return fmt::format("not a shared library (ELF type {}; expected {}, ET_DYN)", h.e_type, ET_DYN);
  if (auto why = check_segments(f, h, size)) return why;
  return check_sections(f, h, size);
}

}  // namespace wrc
