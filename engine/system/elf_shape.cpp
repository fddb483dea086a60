#include "engine/system/elf_shape.h"

#include <elf.h>

#include <cstdint>
#include <cstring>

#include "core/input_error.h"

namespace agv {

namespace {

#if defined(__x86_64__)
constexpr int kMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr int kMachine = EM_AARCH64;
#else
constexpr int kMachine = -1;  // not checked
#endif

// Whether [offset, offset + count * size) lies inside a file of `file` bytes, without overflow.
bool inside(std::uint64_t offset, std::uint64_t count, std::uint64_t size, std::uint64_t file) {
  if (offset > file) return false;
  if (size != 0 && count > (file - offset) / size) return false;
  return true;
}

void check_segments(const std::string& bytes, const Elf64_Ehdr& h, const std::string& who) {
  const std::uint64_t file = bytes.size();
  if (h.e_phentsize != sizeof(Elf64_Phdr) || h.e_phnum == 0 ||
      !inside(h.e_phoff, h.e_phnum, sizeof(Elf64_Phdr), file))
    throw InputError(who +
                     ": truncated or damaged shared library (its program headers lie "
                     "outside the file's " +
                     std::to_string(file) + " bytes)");
  for (int i = 0; i < h.e_phnum; ++i) {
    Elf64_Phdr p;
    std::memcpy(&p, bytes.data() + h.e_phoff + static_cast<std::uint64_t>(i) * sizeof p, sizeof p);
    if (p.p_type != PT_LOAD && p.p_type != PT_DYNAMIC) continue;
    if (!inside(p.p_offset, 1, p.p_filesz, file))
      throw InputError(who + ": truncated or damaged shared library (segment " + std::to_string(i) +
                       " ends at byte " + std::to_string(p.p_offset + p.p_filesz) +
                       " of a file of " + std::to_string(file) + ")");
  }
  if (h.e_shnum != 0 && !inside(h.e_shoff, h.e_shnum, h.e_shentsize, file))
    throw InputError(who +
                     ": truncated or damaged shared library (its section headers lie "
                     "outside the file)");
}

}  // namespace

void check_elf_shape(const std::string& bytes, const std::string& who) {
  if (bytes.size() < 4 || std::memcmp(bytes.data(), ELFMAG, SELFMAG) != 0)
    throw InputError(who + ": not a shared library (no ELF header)");
  if (bytes.size() < sizeof(Elf64_Ehdr))
    throw InputError(who + ": truncated shared library (" + std::to_string(bytes.size()) +
                     " bytes, shorter than an ELF header)");
  Elf64_Ehdr h;
  std::memcpy(&h, bytes.data(), sizeof h);
  if (h.e_ident[EI_CLASS] != ELFCLASS64 || h.e_ident[EI_DATA] != ELFDATA2LSB)
    throw InputError(who + ": not a 64-bit little-endian library, as this agvbench is");
  if (h.e_type != ET_DYN) throw InputError(who + ": an ELF file, but not a shared library");
  if (kMachine >= 0 && h.e_machine != kMachine)
    throw InputError(who + ": a shared library for another machine (ELF machine " +
                     std::to_string(h.e_machine) + ")");
  check_segments(bytes, h, who);
}

}  // namespace agv
