// Not needed for the assignment.
// How much memory this process may still take: what the machine has free, under its own limits.
#pragma once

#include <cstdint>
#include <string>

namespace pt {

/// The least of: the machine's available memory (MemAvailable), what the process's address-space
/// and data limits (RLIMIT_AS, RLIMIT_DATA) leave beyond what it already maps, and what its
/// cgroup's memory.max leaves beyond memory.current. UINT64_MAX where none of them can be read,
/// so that a check against it never refuses on a system that cannot say.
uint64_t available_memory_bytes();

/// "15.8 GiB", "512.0 MiB", "900 bytes": a byte count as a person reads it.
std::string describe_bytes(uint64_t bytes);

}  // namespace pt
