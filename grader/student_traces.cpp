#include "grader/student_traces.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/ipc.h>
#include <sys/msg.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <sys/statvfs.h>
#include <sys/xattr.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <functional>
#include <map>
#include <sstream>

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

// statfs(2)'s f_type of the pseudo-file systems a walk of the machine skips: they hold no file a
// user made (proc's and sys's entries are the kernel's).
constexpr long kProcMagic = 0x9fa0, kSysfsMagic = 0x62656572, kCgroupMagic = 0x27e0eb,
               kCgroup2Magic = 0x63677270, kDebugfsMagic = 0x64626720, kTracefsMagic = 0x74726163,
               kSecurityfsMagic = 0x73636673, kBpfMagic = 0xcafe4a11;

bool pseudo_file_system(int dir_fd) {
  struct statfs s;
  if (fstatfs(dir_fd, &s) != 0) return true;
  long t = long(s.f_type);
  return t == kProcMagic || t == kSysfsMagic || t == kCgroupMagic || t == kCgroup2Magic ||
         t == kDebugfsMagic || t == kTracefsMagic || t == kSecurityfsMagic || t == kBpfMagic;
}

/// Walks the tree under `path` (an open folder `fd`), calling `visit` with each entry's path and
/// lstat; descends into a folder when `enter` says so. Never follows a link.
void walk(int fd, const std::string& path, dev_t parent_dev,
          const std::function<void(const std::string&, const struct stat&)>& visit,
          const std::function<bool(const struct stat&)>& enter) {
  DIR* d = fdopendir(fd);
  if (!d) {
    close(fd);
    return;
  }
  std::vector<std::pair<std::string, struct stat>> folders;
  while (dirent* e = readdir(d)) {
    if (std::strcmp(e->d_name, ".") == 0 || std::strcmp(e->d_name, "..") == 0) continue;
    struct stat st;
    if (fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
    std::string child = (path == "/" ? "" : path) + "/" + e->d_name;
    visit(child, st);
    if (S_ISDIR(st.st_mode) && enter(st)) folders.push_back({child, st});
  }
  for (const auto& [child, st] : folders) {
    int cfd = open(child.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (cfd < 0) continue;
    // A mount point: a file system of the kernel's own is not walked.
    if (st.st_dev != parent_dev && pseudo_file_system(cfd)) {
      close(cfd);
      continue;
    }
    walk(cfd, child, st.st_dev, visit, enter);
  }
  closedir(d);
}

void walk_machine(const std::function<void(const std::string&, const struct stat&)>& visit,
                  const std::function<bool(const struct stat&)>& enter) {
  int fd = open("/", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  struct stat st;
  fstat(fd, &st);
  walk(fd, "/", st.st_dev, visit, enter);
}

bool read_only_file_system(const std::string& path) {
  struct statvfs s;
  return statvfs(path.c_str(), &s) == 0 && (s.f_flag & ST_RDONLY) != 0;
}

/// The rows of a /proc/sysvipc table, each as its columns by the header's names.
std::vector<std::map<std::string, long>> sysv_table(const std::string& name) {
  std::vector<std::map<std::string, long>> rows;
  std::ifstream in("/proc/sysvipc/" + name);
  std::string header;
  if (!std::getline(in, header)) return rows;
  std::vector<std::string> columns;
  std::istringstream hs(header);
  for (std::string c; hs >> c;) columns.push_back(c);
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    std::map<std::string, long> row;
    for (size_t i = 0; i < columns.size(); ++i) {
      long v = 0;
      if (!(ls >> v)) break;
      row[columns[i]] = v;
    }
    rows.push_back(row);
  }
  return rows;
}

// The on-disk form of a POSIX ACL (the system.posix_acl_access extended attribute).
constexpr uint32_t kAclVersion = 2;
constexpr uint16_t kUserObj = 0x01, kUser = 0x02, kGroupObj = 0x04, kGroup = 0x08, kMask = 0x10,
                   kOther = 0x20;
constexpr uint32_t kUndefinedId = 0xffffffffu;
struct AclEntry {
  uint16_t tag, perm;
  uint32_t id;
};

}  // namespace

WritablePlaces writable_places(long gid) {
  WritablePlaces found;
  auto student_may = [&](const struct stat& st, mode_t other_bits, mode_t group_bits) {
    if ((st.st_mode & other_bits) == other_bits) return true;
    return gid >= 0 && st.st_gid == gid_t(gid) && (st.st_mode & group_bits) == group_bits;
  };
  walk_machine(
      [&](const std::string& path, const struct stat& st) {
        if (S_ISDIR(st.st_mode) && student_may(st, S_IWOTH | S_IXOTH, S_IWGRP | S_IXGRP)) {
          if (!read_only_file_system(path)) found.folders.push_back(path);
        } else if (S_ISREG(st.st_mode) && student_may(st, S_IWOTH, S_IWGRP)) {
          if (!read_only_file_system(path)) found.files.push_back(path);
        }
      },
      [&](const struct stat& st) { return student_may(st, S_IXOTH, S_IXGRP); });
  return found;
}

const WritablePlaces& world_writable_places() {
  static const WritablePlaces places = writable_places(-1);
  return places;
}

std::string deny_group_write(const std::string& path, long gid) {
  struct stat st;
  if (lstat(path.c_str(), &st) != 0) return path + ": " + std::strerror(errno);
  std::vector<AclEntry> entries;
  std::vector<char> raw(4096);
  ssize_t n = getxattr(path.c_str(), "system.posix_acl_access", raw.data(), raw.size());
  if (n >= ssize_t(sizeof(uint32_t))) {
    for (size_t at = sizeof(uint32_t); at + sizeof(AclEntry) <= size_t(n); at += sizeof(AclEntry)) {
      AclEntry e;
      std::memcpy(&e, raw.data() + at, sizeof e);
      entries.push_back(e);
    }
  } else {
    // No ACL yet: the one the mode stands for.
    entries = {{kUserObj, uint16_t((st.st_mode >> 6) & 7), kUndefinedId},
               {kGroupObj, uint16_t((st.st_mode >> 3) & 7), kUndefinedId},
               {kOther, uint16_t(st.st_mode & 7), kUndefinedId}};
  }
  bool has_mask = false;
  uint16_t named = 0, group_obj = 0;
  std::vector<AclEntry> kept;
  for (const AclEntry& e : entries) {
    if (e.tag == kGroup && e.id == uint32_t(gid)) continue;
    if (e.tag == kMask) has_mask = true;
    if (e.tag == kGroupObj) group_obj = e.perm;
    if (e.tag == kUser || e.tag == kGroup) named |= e.perm;
    kept.push_back(e);
  }
  // Read and enter, never write (a named entry that matches decides, whatever "other" allows).
  kept.push_back({kGroup, 5, uint32_t(gid)});
  if (!has_mask) kept.push_back({kMask, uint16_t(group_obj | named | 5), kUndefinedId});
  std::stable_sort(kept.begin(), kept.end(), [](const AclEntry& a, const AclEntry& b) {
    return a.tag != b.tag ? a.tag < b.tag : a.id < b.id;
  });
  std::string value(sizeof(uint32_t) + kept.size() * sizeof(AclEntry), '\0');
  std::memcpy(value.data(), &kAclVersion, sizeof kAclVersion);
  for (size_t i = 0; i < kept.size(); ++i)
    std::memcpy(value.data() + sizeof(uint32_t) + i * sizeof(AclEntry), &kept[i], sizeof(AclEntry));
  if (lsetxattr(path.c_str(), "system.posix_acl_access", value.data(), value.size(), 0) != 0)
    return path + ": cannot set an ACL (" + std::strerror(errno) + ")";
  return "";
}

std::vector<IpcObject> sysv_objects() {
  std::vector<IpcObject> all;
  const std::pair<const char*, const char*> tables[] = {
      {"shm", "SysV shared memory"}, {"sem", "SysV semaphores"}, {"msg", "SysV message queue"}};
  for (const auto& [table, kind] : tables) {
    const std::string id_column = std::string(table) == "msg" ? "msqid" : std::string(table) + "id";
    for (const auto& row : sysv_table(table)) {
      IpcObject o;
      o.kind = kind;
      auto at = [&](const std::string& c) { auto it = row.find(c); return it == row.end() ? -1L : it->second; };
      o.id = int(at(id_column));
      o.uid = at("uid");
      o.creator = at("cuid");
      all.push_back(o);
    }
  }
  return all;
}

std::string remove_traces_of(long uid, const std::vector<std::string>& folders) {
  if (uid < 0) return "";
  auto remove_all = [&]() {
    for (const IpcObject& o : sysv_objects()) {
      if (o.uid != uid && o.creator != uid) continue;
      if (o.kind == "SysV shared memory") shmctl(o.id, IPC_RMID, nullptr);
      else if (o.kind == "SysV semaphores") semctl(o.id, 0, IPC_RMID);
      else msgctl(o.id, IPC_RMID, nullptr);
    }
    for (const std::string& folder : folders) {
      std::error_code ec;
      for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        struct stat st;
        if (lstat(it->path().c_str(), &st) == 0 && st.st_uid == uid_t(uid)) {
          std::error_code rec;
          fs::remove_all(it->path(), rec);
        }
      }
    }
  };
  remove_all();
  std::string left;
  for (const IpcObject& o : sysv_objects())
    if (o.uid == uid || o.creator == uid)
      left += o.kind + " " + std::to_string(o.id) + "; ";
  for (const std::string& folder : folders) {
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      struct stat st;
      if (lstat(it->path().c_str(), &st) == 0 && st.st_uid == uid_t(uid))
        left += it->path().string() + "; ";
    }
  }
  if (left.empty()) return "";
  return "user " + std::to_string(uid) + " left what cannot be removed: " + left;
}

std::vector<std::string> traces_of_uids(long first, long last) {
  std::vector<std::string> found;
  auto theirs = [&](long uid) { return uid >= first && uid <= last; };
  walk_machine(
      [&](const std::string& path, const struct stat& st) {
        if (theirs(long(st.st_uid)) || theirs(long(st.st_gid)))
          found.push_back(path + " (owner " + std::to_string(st.st_uid) + ")");
      },
      [](const struct stat&) { return true; });
  for (const IpcObject& o : sysv_objects())
    if (theirs(o.uid) || theirs(o.creator))
      found.push_back(o.kind + " " + std::to_string(o.id) + " (owner " + std::to_string(o.uid) + ")");
  return found;
}

}  // namespace pt::grader
