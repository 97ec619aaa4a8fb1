// What the viewer's server was doing when its process crashed: a signal handler writes it to the
// supervisor that starts the server again, so the page can say which request or render it was.
#pragma once

#include <string>

namespace pt {

/// Installs handlers for SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGABRT that write to `fd` what the
/// crashing thread was doing (or, on a thread that names nothing, what the render in flight is),
/// then let the process die of the same signal. Call once, in the server's process.
void install_crash_witness(int fd);

/// Names what this thread is doing until the next call ("answered POST /api/sampling"); an empty
/// text names nothing. At most 255 bytes are kept.
void set_thread_activity(const std::string& what);

/// Names the render in flight, whose pixels are computed on the task arena's threads (which name
/// nothing of their own); an empty text: no render. At most 511 bytes are kept.
void set_render_activity(const std::string& what);

}  // namespace pt
