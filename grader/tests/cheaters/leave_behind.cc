// Cheater (attacks every later process; replaces parts/1-raygen/triangle_intersect.cpp): before
// main, every process of the student's first looks for what an earlier one left, then leaves a
// copy of its own machine code (which, in a part's isolated renderer or probes, holds the
// solution of the other parts) wherever a later process could open it: a file in every shared
// writable folder (/run/lock, /tmp, /dev/shm, ...), a SysV shared memory segment and message
// queue, a POSIX message queue. A later process that found one would map the code back and
// forward the graded functions to it; this one says how many bytes it found, on a line the
// grader quotes. The bundle's test puts the part above the stubs' line below before a Part 2 file
// too, grades Parts 1 and 2 in one submission and two in `grader batch`, with namespaces and
// with them refused, and requires 0 bytes found and the stubs' score.
#include <fcntl.h>
#include <mqueue.h>
#include <sys/ipc.h>
#include <sys/mman.h>
#include <sys/msg.h>
#include <sys/shm.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

constexpr key_t kLeftKey = 0x50544c42;
constexpr size_t kLeftBytes = 64 << 10;
const char* const kLeftName = "/pt-left-behind";
const char* const kSharedFolders[] = {"/run/lock", "/var/lock", "/tmp", "/var/tmp", "/dev/shm",
                                      "/dev/mqueue", "/run/shm", "/var/crash"};

struct LeftMessage {
  long type;
  char bytes[4096];
};

/// The first bytes of this program's own machine code (its first executable mapping).
std::string own_code() {
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);) {
    unsigned long from = 0, to = 0;
    char perms[8] = {0};
    if (std::sscanf(line.c_str(), "%lx-%lx %7s", &from, &to, perms) == 3 && perms[2] == 'x' &&
        line.find("/") != std::string::npos) {
      size_t n = std::min<size_t>(to - from, kLeftBytes);
      return std::string(reinterpret_cast<const char*>(from), n);
    }
  }
  return std::string(kLeftBytes, 'x');
}

long found_left_behind() {
  long found = 0;
  for (const char* folder : kSharedFolders) {
    std::ifstream in(std::string(folder) + kLeftName, std::ios::binary);
    if (in) found += long(std::string((std::istreambuf_iterator<char>(in)), {}).size());
  }
  int shm = shmget(kLeftKey, 0, 0);
  if (shm >= 0) {
    void* at = shmat(shm, nullptr, SHM_RDONLY);
    if (at != reinterpret_cast<void*>(-1)) {
      found += long(std::strlen(static_cast<const char*>(at)) > 0 ? kLeftBytes : 0);
      shmdt(at);
    }
  }
  int msq = msgget(kLeftKey, 0);
  LeftMessage m;
  if (msq >= 0) {
    ssize_t n = msgrcv(msq, &m, sizeof m.bytes, 0, IPC_NOWAIT);
    if (n > 0) found += n;
  }
  mqd_t q = mq_open(kLeftName, O_RDONLY | O_NONBLOCK);
  if (q != mqd_t(-1)) {
    mq_attr a;
    if (mq_getattr(q, &a) == 0 && a.mq_curmsgs > 0) found += a.mq_curmsgs * a.mq_msgsize;
    mq_close(q);
  }
  return found;
}

int leave_behind(const std::string& code) {
  int left = 0;
  for (const char* folder : kSharedFolders) {
    std::string path = std::string(folder) + kLeftName;
    int fd = open(path.c_str(), O_CREAT | O_WRONLY | O_TRUNC, 0666);
    if (fd < 0) continue;
    if (write(fd, code.data(), code.size()) == ssize_t(code.size())) ++left;
    fchmod(fd, 0666);
    close(fd);
  }
  int shm = shmget(kLeftKey, kLeftBytes, IPC_CREAT | 0666);
  if (shm >= 0) {
    void* at = shmat(shm, nullptr, 0);
    if (at != reinterpret_cast<void*>(-1)) {
      std::memcpy(at, code.data(), std::min(code.size(), kLeftBytes));
      static_cast<char*>(at)[0] = 'C';  // never empty, whatever the code's first byte
      shmdt(at);
      ++left;
    }
  }
  int msq = msgget(kLeftKey, IPC_CREAT | 0666);
  LeftMessage m;
  m.type = 1;
  std::memcpy(m.bytes, code.data(), std::min(code.size(), sizeof m.bytes));
  if (msq >= 0 && msgsnd(msq, &m, sizeof m.bytes, IPC_NOWAIT) == 0) ++left;
  mq_attr a = {};
  a.mq_maxmsg = 1;
  a.mq_msgsize = 4096;
  mqd_t q = mq_open(kLeftName, O_CREAT | O_WRONLY | O_NONBLOCK, 0666, &a);
  if (q != mqd_t(-1)) {
    if (mq_send(q, code.data(), std::min<size_t>(code.size(), 4096), 0) == 0) ++left;
    mq_close(q);
  }
  return left;
}

struct LeaveBehind {
  LeaveBehind() {
    if (std::getenv("PT_LEFT_BEHIND_DONE")) return;
    setenv("PT_LEFT_BEHIND_DONE", "1", 1);
    long found = found_left_behind();
    int left = leave_behind(own_code());
    // "not implemented" makes the grader quote the line in the step's message.
    std::printf("CHEAT found %ld bytes left behind, left %d copies (not implemented)\n", found, left);
    std::fflush(stdout);
  }
} leave_behind_now;

}  // namespace
// The stubs of the file it replaces.
#include "parts/1-raygen/triangle_intersect.h"

namespace pt {

bool intersect_triangle(const Ray&, const glm::vec3&, const glm::vec3&, const glm::vec3&,
                        TriangleHit*) {
  return false;
}

glm::vec3 interpolate_normal(const TriangleHit&, const glm::vec3& n0, const glm::vec3&,
                             const glm::vec3&) {
  return n0;
}

}  // namespace pt
