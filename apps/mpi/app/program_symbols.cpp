#include "apps/mpi/app/program_symbols.hpp"

#include <elf.h>

#include <cstring>
#include <optional>

namespace gcsim::mpi_layer::app {
namespace {

// A copy of the object of type T at `offset`, if the bytes hold it whole (the file may be anything).
template <class T>
std::optional<T> read_at(std::string_view bytes, std::uint64_t offset) {
  if (offset > bytes.size() || bytes.size() - offset < sizeof(T)) return std::nullopt;
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

bool names_mpi_function(std::string_view name) {
  return name.starts_with("MPI_") || name.starts_with("PMPI_");
}

// The NUL-terminated name at `offset` of the string table [start, start + size), or empty.
std::string_view name_in(std::string_view bytes, std::uint64_t start, std::uint64_t size, std::uint32_t offset) {
  if (start > bytes.size() || size > bytes.size() - start || offset >= size) return {};
  const std::string_view table = bytes.substr(start, size);
  const std::size_t end = table.find('\0', offset);
  return end == std::string_view::npos ? std::string_view{} : table.substr(offset, end - offset);
}

}  // namespace

std::vector<std::string> missing_mpi_functions(std::string_view bytes) {
  std::vector<std::string> missing;
  const auto header = read_at<Elf64_Ehdr>(bytes, 0);
  if (!header || std::memcmp(header->e_ident, ELFMAG, SELFMAG) != 0 || header->e_ident[EI_CLASS] != ELFCLASS64 ||
      header->e_shentsize != sizeof(Elf64_Shdr))
    return missing;
  for (std::uint64_t i = 0; i < header->e_shnum; ++i) {
    const auto section = read_at<Elf64_Shdr>(bytes, header->e_shoff + i * sizeof(Elf64_Shdr));
    if (!section || section->sh_type != SHT_DYNSYM || section->sh_entsize != sizeof(Elf64_Sym)) continue;
    if (section->sh_link >= header->e_shnum) continue;
    const auto strings = read_at<Elf64_Shdr>(bytes, header->e_shoff + std::uint64_t(section->sh_link) * sizeof(Elf64_Shdr));
    if (!strings) continue;
    for (std::uint64_t s = 0; s < section->sh_size / sizeof(Elf64_Sym); ++s) {
      const auto symbol = read_at<Elf64_Sym>(bytes, section->sh_offset + s * sizeof(Elf64_Sym));
      if (!symbol || symbol->st_shndx != SHN_UNDEF) continue;
      const std::string_view name = name_in(bytes, strings->sh_offset, strings->sh_size, symbol->st_name);
      if (names_mpi_function(name)) missing.emplace_back(name);
    }
  }
  return missing;
}

}  // namespace gcsim::mpi_layer::app
