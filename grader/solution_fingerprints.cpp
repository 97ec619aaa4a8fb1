#include "grader/solution_fingerprints.h"

#include <elf.h>
#include <fcntl.h>
#include <grp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <iterator>
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

/// Looks at every window of a stream fed in pieces, for the first that is a fingerprint.
class Scanner {
 public:
  Scanner(const Fingerprints& prints, const Filter& filter) : prints_(prints), filter_(filter) {}

  /// Feeds `n` more bytes; returns the offset of the first fingerprint's window, or -1.
  long long feed(const unsigned char* data, size_t n, const Fingerprints::Entry** which) {
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
      if (window != it->second.bytes) continue;
      *which = &it->second;
      return (long long)(pos_ - kFingerprintBytes);
    }
    return -1;
  }

 private:
  const Fingerprints& prints_;
  const Filter& filter_;
  std::array<unsigned char, kFingerprintBytes> ring_{};
  uint64_t hash_ = 0;
  size_t pos_ = 0;
};

std::string read_binary(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// One executable section of an object: its bytes, and which of them a relocation rewrites.
struct CodeSection {
  std::string name;
  const unsigned char* bytes = nullptr;
  size_t size = 0;
  bool in_group = false;
  std::vector<bool> relocated;
};

/// The executable sections of the ELF64 relocatable object `image` (read from `path`).
std::vector<CodeSection> code_sections(const std::string& image, const fs::path& path) {
  auto bad = [&](const std::string& why) {
    return std::runtime_error(path.string() + ": not an ELF64 object (" + why + ")");
  };
  if (image.size() < sizeof(Elf64_Ehdr) || std::memcmp(image.data(), ELFMAG, SELFMAG) != 0)
    throw bad("no ELF header");
  Elf64_Ehdr eh;
  std::memcpy(&eh, image.data(), sizeof eh);
  if (eh.e_ident[EI_CLASS] != ELFCLASS64) throw bad("not 64-bit");
  if (eh.e_shentsize != sizeof(Elf64_Shdr) || eh.e_shoff == 0 ||
      eh.e_shoff + size_t(eh.e_shnum) * sizeof(Elf64_Shdr) > image.size())
    throw bad("section headers out of the file");
  std::vector<Elf64_Shdr> sh(eh.e_shnum);
  std::memcpy(sh.data(), image.data() + eh.e_shoff, sh.size() * sizeof(Elf64_Shdr));
  auto inside = [&](const Elf64_Shdr& s) { return s.sh_offset + s.sh_size <= image.size(); };
  const Elf64_Shdr* names = eh.e_shstrndx < sh.size() ? &sh[eh.e_shstrndx] : nullptr;
  std::vector<CodeSection> code(sh.size());
  for (size_t i = 0; i < sh.size(); ++i) {
    const Elf64_Shdr& s = sh[i];
    if (s.sh_type != SHT_PROGBITS || !(s.sh_flags & SHF_EXECINSTR) || !inside(s)) continue;
    CodeSection& c = code[i];
    if (names && inside(*names) && s.sh_name < names->sh_size)
      c.name = std::string(image.c_str() + names->sh_offset + s.sh_name);
    c.bytes = reinterpret_cast<const unsigned char*>(image.data()) + s.sh_offset;
    c.size = s.sh_size;
    c.in_group = (s.sh_flags & SHF_GROUP) != 0;
    c.relocated.assign(c.size, false);
  }
  for (const Elf64_Shdr& s : sh) {
    if ((s.sh_type != SHT_RELA && s.sh_type != SHT_REL) || !inside(s) || s.sh_info >= code.size() ||
        !code[s.sh_info].bytes)
      continue;
    const size_t entry = s.sh_type == SHT_RELA ? sizeof(Elf64_Rela) : sizeof(Elf64_Rel);
    CodeSection& c = code[s.sh_info];
    for (size_t at = 0; at + entry <= s.sh_size; at += entry) {
      Elf64_Rel r;  // r_offset opens both kinds
      std::memcpy(&r, image.data() + s.sh_offset + at, sizeof r);
      for (size_t k = 0; k < 8 && r.r_offset + k < c.size; ++k) c.relocated[r.r_offset + k] = true;
    }
  }
  std::vector<CodeSection> out;
  for (CodeSection& c : code)
    if (c.bytes) out.push_back(std::move(c));
  return out;
}

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
    for (const CodeSection& c : code_sections(image, path)) {
      if (c.size < kFingerprintBytes) continue;
      uint64_t h = hash_window(c.bytes);
      for (size_t at = 0;; ++at) {
        if (filter.maybe(h)) {
          auto it = prints.by_hash.find(h);
          if (it != prints.by_hash.end() &&
              std::memcmp(it->second.bytes.data(), c.bytes + at, kFingerprintBytes) == 0)
            shared.insert(h);
        }
        if (at + kFingerprintBytes >= c.size) break;
        h = h * kBase + c.bytes[at + kFingerprintBytes] - c.bytes[at] * kOutgoing;
      }
    }
  }
  for (uint64_t h : shared) prints.by_hash.erase(h);
  prints.dropped = shared.size();
  return prints;
}

std::vector<Carrier> files_carrying(const Fingerprints& prints, const std::vector<fs::path>& roots,
                                    WalkCount* count) {
  std::vector<Carrier> found;
  WalkCount local;
  WalkCount& n = count ? *count : local;
  if (prints.by_hash.empty()) return found;
  const Filter filter(prints);
  std::vector<unsigned char> buffer(size_t(1) << 20);
  auto look = [&](const fs::path& path) {
    const int fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
      ++n.unreadable;
      return;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
      close(fd);
      return;
    }
    ++n.files;
    Scanner scan(prints, filter);
    for (ssize_t got; (got = read(fd, buffer.data(), buffer.size())) > 0;) {
      n.bytes += size_t(got);
      const Fingerprints::Entry* which = nullptr;
      const long long hit = scan.feed(buffer.data(), size_t(got), &which);
      if (hit >= 0) {
        found.push_back({path.string(), size_t(hit), which->source});
        break;
      }
    }
    close(fd);
  };
  for (const fs::path& root : roots) {
    struct stat top;
    if (lstat(root.c_str(), &top) != 0) continue;
    if (S_ISREG(top.st_mode)) {
      look(root);
      continue;
    }
    std::error_code ec;
    fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      struct stat st;
      if (lstat(it->path().c_str(), &st) != 0) continue;
      if (S_ISDIR(st.st_mode) && st.st_dev != top.st_dev) {
        it.disable_recursion_pending();  // another file system mounted here
        continue;
      }
      if (S_ISREG(st.st_mode)) look(it->path());
    }
  }
  return found;
}

std::vector<Carrier> files_carrying_as(long uid, long gid, const Fingerprints& prints,
                                       const std::vector<fs::path>& roots, WalkCount* count) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("cannot make a pipe");
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("cannot fork");
  if (child == 0) {
    close(fds[0]);
    const gid_t group = gid_t(gid);
    if (setgroups(1, &group) != 0 || setgid(gid_t(uid)) != 0 || setuid(uid_t(uid)) != 0 ||
        getuid() != uid_t(uid))
      _exit(2);
    WalkCount n;
    std::string out;
    for (const Carrier& c : files_carrying(prints, roots, &n))
      out += c.path + '\0' + std::to_string(c.offset) + '\0' + c.fingerprint + '\0';
    out += std::to_string(n.files) + '\0' + std::to_string(n.bytes) + '\0' +
           std::to_string(n.unreadable) + '\0';
    for (size_t at = 0; at < out.size();) {
      const ssize_t w = write(fds[1], out.data() + at, out.size() - at);
      if (w <= 0) _exit(3);
      at += size_t(w);
    }
    _exit(0);
  }
  close(fds[1]);
  std::string got;
  char buf[65536];
  for (ssize_t r; (r = read(fds[0], buf, sizeof buf)) > 0;) got.append(buf, size_t(r));
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the walk as user " + std::to_string(uid) + " failed (status " +
                             std::to_string(status) + ")");
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
