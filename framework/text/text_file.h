// Not needed for the assignment.
// Reading a whole file into a string: the one reader every tool and test of the project uses.
#pragma once

#include <filesystem>
#include <string>

namespace pt {

/// The bytes of the file at `path`, unchanged (no newline translation). Throws
/// std::runtime_error naming the file when it cannot be opened or read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace pt
