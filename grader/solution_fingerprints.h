// The solution's machine code as fingerprints, and a walk that looks for them in every file a
// user can read: autograde-setup's proof that no file the student's user can open (after set-up,
// and while a part compiles) derives from the solution.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace pt::grader {

/// A fingerprint is this many bytes of compiled code, found as they are in any file that copies
/// or links the code (an object, an archive, a program, a cache entry, a core file).
constexpr size_t kFingerprintBytes = 32;

struct Fingerprints {
  /// The fingerprints by their hash (hash_window), each with its bytes and where it came from.
  struct Entry {
    std::array<unsigned char, kFingerprintBytes> bytes;
    std::string source;  ///< the object and the offset in its section, for the message
  };
  std::unordered_map<uint64_t, Entry> by_hash;
  size_t objects = 0;      ///< the solution's objects read
  size_t code_bytes = 0;   ///< the bytes of their own code (no inline or template copy)
  size_t dropped = 0;      ///< windows left out because the given code has them too
};

/// The fingerprints of `solution_objects` (ELF relocatable objects): every window of
/// kFingerprintBytes at a multiple of kFingerprintBytes in their executable sections of their
/// own (not COMDAT groups, which hold inline and template code any object may have), with no byte
/// a relocation rewrites at link time and more than 8 distinct byte values; minus every window
/// found anywhere in the executable sections of `given_objects` (code that is not the solution's
/// may compile to the same bytes). Throws naming a file that is not an ELF64 relocatable object.
Fingerprints fingerprints_of(const std::vector<std::filesystem::path>& solution_objects,
                             const std::vector<std::filesystem::path>& given_objects);

/// A file holding a fingerprint: the file, the offset of the first one found, and which.
struct Carrier {
  std::string path;
  size_t offset = 0;
  std::string fingerprint;  ///< Entry::source
};

struct WalkCount {
  size_t files = 0, bytes = 0, unreadable = 0;
};

/// Every regular file under `roots` (a root may be a file), not following links, never leaving
/// a root's file system; a folder that cannot be read is passed over alone.
std::vector<std::filesystem::path> regular_files_under(const std::vector<std::filesystem::path>& roots);

/// The regular files under `roots` that hold a fingerprint, each window of every file looked at.
std::vector<Carrier> files_carrying(const Fingerprints& prints,
                                    const std::vector<std::filesystem::path>& roots,
                                    WalkCount* count = nullptr);

/// The same walk, the files listed by the caller and opened by a child process that is user
/// `uid` as a student's process is (as_student_user, grader/sandbox.h): every file that user can
/// open is read, including those in folders it may enter but not list. Throws when the child
/// cannot become the user.
std::vector<Carrier> files_carrying_as(long uid, const Fingerprints& prints,
                                       const std::vector<std::filesystem::path>& roots,
                                       WalkCount* count = nullptr);

}  // namespace pt::grader
