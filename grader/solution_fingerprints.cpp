#include "grader/solution_fingerprints.h"

#include "grader/elf_object.h"
#include "grader/sandbox.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cstring>
#include <set>
#include <stdexcept>

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

// A polynomial hash of a window, rolled one byte at a time: h = sum b[i] * kBase^(n-1-i).
constexpr uint64_t kBase = 0x100000001b3ull * 2 + 1;

uint64_t base_power(size_t n) {
  uint64_t p = 1;
  for (size_t i = 0; i < n; ++i) p *= kBase;
  return p;
}
const uint64_t kOutgoing = base_power(kFingerprintBytes);

uint64_t hash_window(const unsigned char* b) {
  uint64_t h = 0;
  for (size_t i = 0; i < kFingerprintBytes; ++i) h = h * kBase + b[i];
  return h;
}

/// A first look before the table: one bit per value of the hash's top 24 bits (2 MB).
class Filter {
 public:
  explicit Filter(const Fingerprints& prints) : bits_(size_t(1) << 24 >> 6) {
    for (const auto& entry : prints.by_hash) set(entry.first);
  }
  bool maybe(uint64_t h) const { return (bits_[index(h) >> 6] >> (index(h) & 63)) & 1; }

 private:
  static uint64_t index(uint64_t h) { return (h * 0x9e3779b97f4a7c15ull) >> 40; }
  void set(uint64_t h) { bits_[index(h) >> 6] |= uint64_t(1) << (index(h) & 63); }
  std::vector<uint64_t> bits_;
};

/// Looks at every window of a stream fed in pieces for the fingerprints it holds.
class Scanner {
 public:
  Scanner(const Fingerprints& prints, const Filter& filter) : prints_(prints), filter_(filter) {}

  /// Feeds `n` more bytes, calling `hit(offset, entry)` for each window (offset in the stream)
  /// that is a fingerprint, until it returns true; returns whether it did.
  template <class Hit>
  bool feed(const unsigned char* data, size_t n, Hit&& hit) {
    for (size_t i = 0; i < n; ++i) {
      const unsigned char in = data[i];
      const unsigned char out = ring_[pos_ % kFingerprintBytes];
      ring_[pos_ % kFingerprintBytes] = in;
      hash_ = hash_ * kBase + in - (pos_ >= kFingerprintBytes ? out * kOutgoing : 0);
      ++pos_;
      if (pos_ < kFingerprintBytes || !filter_.maybe(hash_)) continue;
      auto it = prints_.by_hash.find(hash_);
      if (it == prints_.by_hash.end()) continue;
      std::array<unsigned char, kFingerprintBytes> window;
      for (size_t k = 0; k < kFingerprintBytes; ++k) window[k] = ring_[(pos_ + k) % kFingerprintBytes];
      if (window == it->second.bytes && hit(pos_ - kFingerprintBytes, it->second)) return true;
    }
    return false;
  }

 private:
  const Fingerprints& prints_;
  const Filter& filter_;
  std::array<unsigned char, kFingerprintBytes> ring_{};
  uint64_t hash_ = 0;
  size_t pos_ = 0;
};

bool varied(const unsigned char* b) {
  std::set<unsigned char> values(b, b + kFingerprintBytes);
  return values.size() > 8;
}

}  // namespace

Fingerprints fingerprints_of(const std::vector<fs::path>& solution_objects,
                             const std::vector<fs::path>& given_objects) {
  Fingerprints prints;
  for (const fs::path& path : solution_objects) {
    const std::string image = read_binary(path);
    ++prints.objects;
    for (const CodeSection& c : code_sections(image, path)) {
      if (c.in_group) continue;
      prints.code_bytes += c.size;
      for (size_t at = 0; at + kFingerprintBytes <= c.size; at += kFingerprintBytes) {
        bool clean = true;
        for (size_t k = 0; k < kFingerprintBytes && clean; ++k) clean = !c.relocated[at + k];
        if (!clean || !varied(c.bytes + at)) continue;
        Fingerprints::Entry e;
        std::memcpy(e.bytes.data(), c.bytes + at, kFingerprintBytes);
        e.source = path.filename().string() + " " + c.name + "+" + std::to_string(at);
        prints.by_hash.emplace(hash_window(c.bytes + at), std::move(e));
      }
    }
  }
  // Windows the given code has too, at any offset, are no sign of the solution.
  const Filter filter(prints);
  std::set<uint64_t> shared;
  for (const fs::path& path : given_objects) {
    const std::string image = read_binary(path);
    for (const CodeSection& c : code_sections(image, path))
      Scanner(prints, filter).feed(c.bytes, c.size, [&](size_t, const Fingerprints::Entry& e) {
        shared.insert(hash_window(e.bytes.data()));
        return false;
      });
  }
  for (uint64_t h : shared) prints.by_hash.erase(h);
  prints.dropped = shared.size();
  return prints;
}

std::vector<fs::path> regular_files_under(const std::vector<fs::path>& roots) {
  std::vector<fs::path> files;
  for (const fs::path& root : roots) {
    struct stat top;
    if (lstat(root.c_str(), &top) != 0) continue;
    if (S_ISREG(top.st_mode)) {
      files.push_back(root);
      continue;
    }
    if (!S_ISDIR(top.st_mode)) continue;
    // Folder by folder: one that cannot be read, or an entry that vanishes, is passed over alone.
    std::vector<fs::path> folders = {root};
    while (!folders.empty()) {
      const fs::path folder = folders.back();
      folders.pop_back();
      std::error_code ec;
      for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        struct stat st;
        if (lstat(it->path().c_str(), &st) != 0) continue;
        if (S_ISDIR(st.st_mode) && st.st_dev == top.st_dev) folders.push_back(it->path());
        if (S_ISREG(st.st_mode)) files.push_back(it->path());
      }
    }
  }
  return files;
}

namespace {

/// Reads each of `files` that this process can open, for the first fingerprint it holds.
std::vector<Carrier> scan_files(const Fingerprints& prints, const std::vector<fs::path>& files,
                                WalkCount* count) {
  std::vector<Carrier> found;
  WalkCount local;
  WalkCount& n = count ? *count : local;
  if (prints.by_hash.empty()) return found;
  const Filter filter(prints);
  std::vector<unsigned char> buffer(size_t(1) << 20);
  for (const fs::path& path : files) {
    const int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
      ++n.unreadable;
      continue;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
      close(fd);
      continue;
    }
    ++n.files;
    Scanner scan(prints, filter);
    for (ssize_t got; (got = read(fd, buffer.data(), buffer.size())) > 0;) {
      n.bytes += size_t(got);
      const bool hit = scan.feed(buffer.data(), size_t(got),
                                 [&](size_t at, const Fingerprints::Entry& e) {
                                   found.push_back({path.string(), at, e.source});
                                   return true;
                                 });
      if (hit) break;
    }
    close(fd);
  }
  return found;
}

}  // namespace

std::vector<Carrier> files_carrying(const Fingerprints& prints, const std::vector<fs::path>& roots,
                                    WalkCount* count) {
  return scan_files(prints, regular_files_under(roots), count);
}

std::vector<Carrier> files_carrying_as(long uid, const Fingerprints& prints,
                                       const std::vector<fs::path>& roots, WalkCount* count) {
  // Listed as the caller (a folder the user may enter but not list still holds files it can
  // open by name), opened as the user.
  const std::vector<fs::path> files = regular_files_under(roots);
  const std::string got = as_student_user(uid, [&] {
    WalkCount n;
    std::string out;
    for (const Carrier& c : scan_files(prints, files, &n))
      out += c.path + '\0' + std::to_string(c.offset) + '\0' + c.fingerprint + '\0';
    return out + std::to_string(n.files) + '\0' + std::to_string(n.bytes) + '\0' +
           std::to_string(n.unreadable) + '\0';
  });
  std::vector<std::string> fields;
  for (size_t at = 0; at < got.size();) {
    const size_t end = got.find('\0', at);
    if (end == std::string::npos) break;
    fields.push_back(got.substr(at, end - at));
    at = end + 1;
  }
  if (fields.size() < 3 || fields.size() % 3 != 0)
    throw std::runtime_error("the walk as user " + std::to_string(uid) + " answered nonsense");
  std::vector<Carrier> found;
  for (size_t i = 0; i + 3 < fields.size(); i += 3)
    found.push_back({fields[i], size_t(std::stoull(fields[i + 1])), fields[i + 2]});
  if (count) {
    const size_t k = fields.size() - 3;
    count->files = std::stoull(fields[k]);
    count->bytes = std::stoull(fields[k + 1]);
    count->unreadable = std::stoull(fields[k + 2]);
  }
  return found;
}

}  // namespace pt::grader
