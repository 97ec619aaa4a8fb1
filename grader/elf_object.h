// What an ELF64 relocatable object holds, read without the linker: its sections, its code with the
// bytes a relocation rewrites, and whether a linker would do more than place its machine code.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace pt::grader {

/// The bytes of a file; throws naming it when it cannot be read.
std::string read_binary(const std::filesystem::path& path);

/// One executable section of an object: its bytes (inside the image it was read from), and which
/// of them a relocation rewrites at link time.
struct CodeSection {
  std::string name;
  const unsigned char* bytes = nullptr;
  size_t size = 0;
  bool in_group = false;  ///< a COMDAT group: inline or template code any object may hold
  std::vector<bool> relocated;
};

/// The executable sections of `image`, an ELF64 relocatable object read from `path`. Throws
/// "PATH: not an ELF64 relocatable object (why)".
std::vector<CodeSection> code_sections(const std::string& image, const std::filesystem::path& path);

/// Why linking the object at `path` would make the linker compile or run anything ("" when it
/// only places machine code): not an ELF64 relocatable object at all (an LLVM bitcode file, a
/// linker script, an archive), or a section of link-time code (GCC's .gnu.lto_*, LLVM's
/// .llvmbc), which a linker with GCC's or LLVM's plugin hands to the compiler. The grader links a
/// student's objects with its own rights, so it links only objects for which this is "".
std::string link_time_code_in(const std::filesystem::path& path);

}  // namespace pt::grader
