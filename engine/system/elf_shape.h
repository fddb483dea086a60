#pragma once
// Whether a file's bytes can be handed to dlopen: an ELF shared library for this machine whose
// headers and loadable segments all lie inside the file. The dynamic loader maps the segments
// without checking them against the file's size, and a truncated library then dies of SIGBUS
// in the middle of loading (or later, on the first touch of a page past the end).

#include <string>

namespace agv {

// Throws InputError naming `who` when the bytes are not such a library.
void check_elf_shape(const std::string& bytes, const std::string& who);

}  // namespace agv
