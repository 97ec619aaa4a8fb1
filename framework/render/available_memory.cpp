// Not needed for the assignment: the definitions of framework/render/available_memory.h.
#include "framework/render/available_memory.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#if defined(__linux__)
#include <sys/resource.h>
#endif

namespace pt {
namespace {

constexpr uint64_t kUnknown = UINT64_MAX;

/// The value of the "Key:  1234 kB" line `key` of a /proc file, in bytes; kUnknown without it.
uint64_t proc_kilobytes(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, key.size() + 1, key + ":") == 0) {
      std::istringstream fields(line.substr(key.size() + 1));
      uint64_t kb = 0;
      if (fields >> kb) return kb * 1024;
    }
  return kUnknown;
}

/// A cgroup v2 memory file of this process's cgroup as a number; kUnknown when absent or "max".
uint64_t cgroup_value(const std::string& name) {
  std::ifstream groups("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(groups, line))
    if (line.compare(0, 3, "0::") == 0) path = line.substr(3);
  if (path.empty()) return kUnknown;
  std::ifstream in("/sys/fs/cgroup" + path + "/" + name);
  uint64_t v = 0;
  if (!(in >> v)) return kUnknown;
  return v;
}

/// What a soft resource limit leaves beyond `used`; kUnknown when unlimited.
uint64_t left_under_limit(int resource, uint64_t used) {
#if defined(__linux__)
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnknown;
  if (used == kUnknown) used = 0;
  return limit.rlim_cur > used ? uint64_t(limit.rlim_cur) - used : 0;
#else
  (void)resource, (void)used;
  return kUnknown;
#endif
}

}  // namespace

uint64_t available_memory_bytes() {
  uint64_t have = proc_kilobytes("/proc/meminfo", "MemAvailable");
#if defined(__linux__)
  have = std::min(have, left_under_limit(RLIMIT_AS, proc_kilobytes("/proc/self/status", "VmSize")));
  have = std::min(have, left_under_limit(RLIMIT_DATA, proc_kilobytes("/proc/self/status", "VmData")));
#endif
  const uint64_t max = cgroup_value("memory.max"), current = cgroup_value("memory.current");
  if (max != kUnknown) {
    const uint64_t used = current == kUnknown ? 0 : current;
    have = std::min(have, max > used ? max - used : 0);
  }
  return have;
}

std::string describe_bytes(uint64_t bytes) {
  char text[64];
  if (bytes >= (uint64_t(1) << 30))
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(uint64_t(1) << 30));
  else if (bytes >= (uint64_t(1) << 20))
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(uint64_t(1) << 20));
  else
    std::snprintf(text, sizeof text, "%llu bytes", (unsigned long long)bytes);
  return text;
}

}  // namespace pt
