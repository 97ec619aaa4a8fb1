// What a student's process could leave on the machine for a later one, found rather than listed:
// every folder and file its user could write (by walking the file systems), the files and IPC
// objects (SysV shared memory, semaphores, message queues; POSIX shared memory and message
// queues, which are files) a user owns, and their removal. The sandbox (grader/sandbox.h) uses it
// to leave nothing behind each process; the bundle's test uses it to prove nothing is left.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace pt::grader {

/// Every folder and regular file on the machine that a user with no files of its own and no
/// group but `gid` could write: world-writable ones (/tmp, /var/tmp, /dev/shm, /run/lock,
/// /dev/mqueue, ...) and any owned by `gid` with group write. Found by walking every mounted
/// file system from `/` (proc and sys pruned, and every folder such a user cannot enter), so a
/// machine's own odd folder is found as /tmp is. `uid` is not used to find them: a fresh uid owns
/// nothing.
struct WritablePlaces {
  std::vector<std::string> folders, files;
};
WritablePlaces writable_places(long gid);

/// The places found once per process (the walk takes a second or more): writable_places(-1).
const WritablePlaces& world_writable_places();

/// Makes `path` unwritable by the members of `gid` with a POSIX ACL entry (group `gid`: r-x),
/// which other users never match. Returns "" when done, else why not (a file system without
/// ACLs).
std::string deny_group_write(const std::string& path, long gid);

/// One IPC object: its kind ("SysV shared memory", ...), id and owner.
struct IpcObject {
  std::string kind;
  int id = -1;
  long uid = -1, creator = -1;
};

/// The SysV IPC objects of this IPC namespace (/proc/sysvipc/{shm,sem,msg}).
std::vector<IpcObject> sysv_objects();

/// Removes every SysV IPC object owned or created by `uid` in this IPC namespace, and every file
/// owned by `uid` directly in one of `folders` (what it could make there: files, folders,
/// sockets, POSIX shared memory and message queues), then looks again. Returns "" when nothing
/// of `uid` is left, else what is.
std::string remove_traces_of(long uid, const std::vector<std::string>& folders);

/// Every file and SysV IPC object anywhere on the machine owned by a uid in [first, last]
/// (`/` walked with proc and sys pruned), described one a line: what a whole grading must leave
/// empty.
std::vector<std::string> traces_of_uids(long first, long last);

}  // namespace pt::grader
