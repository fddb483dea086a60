// A plugin file is checked before dlopen maps it (engine/system/elf_shape.h): a real shared library
// passes; its truncated copies, which the loader would map past their end (SIGBUS), are refused.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <exception>
#include <fstream>
#include <iterator>
#include <string>

#include "core/input_error.h"
#include "engine/system/elf_shape.h"

namespace agv {
namespace {

// The bytes of the C++ runtime library this test runs with: a shared library of this machine.
std::string runtime_library() {
  Dl_info info{};
  const auto terminate = &std::terminate;
  if (::dladdr(reinterpret_cast<void*>(terminate), &info) == 0 || info.dli_fname == nullptr)
    return "";
  std::ifstream in(info.dli_fname, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string refusal(const std::string& bytes) {
  try {
    check_elf_shape(bytes, "--plugin \"x.so\"");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ElfShape, ARealLibraryPassesItsTruncatedCopiesDoNot) {
  const std::string lib = runtime_library();
  ASSERT_GT(lib.size(), 4096U);
  EXPECT_EQ(refusal(lib), "");
  for (const std::size_t keep :
       {lib.size() - 1, lib.size() * 2 / 3, lib.size() / 3, std::size_t{200}})
    EXPECT_NE(refusal(lib.substr(0, keep)).find("truncated or damaged shared library"),
              std::string::npos)
        << keep << " bytes: " << refusal(lib.substr(0, keep));
  EXPECT_NE(refusal(lib.substr(0, 40)).find("shorter than an ELF header"), std::string::npos);
  EXPECT_NE(refusal("not a library at all").find("no ELF header"), std::string::npos);
  std::string executable_type = lib;
  executable_type[16] = 2;  // e_type ET_EXEC
  EXPECT_NE(refusal(executable_type).find("not a shared library"), std::string::npos);
  std::string other_machine = lib;
  other_machine[18] = 40;  // e_machine EM_ARM
  other_machine[19] = 0;
  EXPECT_NE(refusal(other_machine).find("for another machine"), std::string::npos);
}

}  // namespace
}  // namespace agv
