// Not needed for the assignment.
// Opening the image module while a render runs: the image library's shared objects are many and
// slow to load (most of them are linked to bind every call at load, whatever dlopen asks), and a
// render that would open it only to write its film waits for all of them after its last ray.
// Opened beside the render, the wait is gone.
#pragma once

#include <string>
#include <thread>

namespace pt {

/// Opens the image module (load_image_codec) on a thread of its own from construction, and
/// waits for it on destruction or wait(). A failure to open is not reported here: the image
/// write that needs the module asks again and reports it, naming the image.
class ImageModulePreload {
 public:
  /// `path`: the image the module will be needed for (named only in a failure nobody sees).
  explicit ImageModulePreload(std::string path);
  ~ImageModulePreload();
  ImageModulePreload(const ImageModulePreload&) = delete;
  ImageModulePreload& operator=(const ImageModulePreload&) = delete;

  /// Blocks until the module is open (or has failed to open); idempotent.
  void wait();

 private:
  std::thread thread_;
};

}  // namespace pt
