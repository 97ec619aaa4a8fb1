// Small folders for the website's tests: made fresh in the temp directory, removed afterwards,
// with helpers that write text, real PNG and JPEG images, and set permissions.
#pragma once

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pt::web::testing {

/// A temporary folder that is deleted when the test ends.
class TestFolder {
 public:
  TestFolder() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "pt-website-test-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) std::abort();
    root_ = tmpl;
    std::filesystem::permissions(root_, std::filesystem::perms(0755));
  }
  ~TestFolder() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  TestFolder(const TestFolder&) = delete;
  TestFolder& operator=(const TestFolder&) = delete;

  const std::filesystem::path& path() const { return root_; }

  std::filesystem::path write(const std::string& rel, const std::string& text) {
    std::filesystem::path p = root_ / rel;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    std::filesystem::permissions(p, std::filesystem::perms(0644));
    return p;
  }

  /// A real 4x4 image in the format OIIO picks from `format_file`'s extension, saved as `rel`
  /// (so a JPEG can be saved under a .png name).
  std::filesystem::path image(const std::string& rel, const std::string& format_ext = "") {
    std::filesystem::path p = root_ / rel;
    std::filesystem::create_directories(p.parent_path());
    std::string ext = format_ext.empty() ? p.extension().string() : format_ext;
    std::filesystem::path made = p.string() + ".tmp" + ext;
    auto out = OIIO::ImageOutput::create(made.string());
    OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::UINT8);
    std::vector<unsigned char> px(4 * 4 * 3, 200);
    if (!out || !out->open(made.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::UINT8, px.data()) || !out->close()) {
      std::abort();
    }
    std::filesystem::rename(made, p);
    std::filesystem::permissions(p, std::filesystem::perms(0644));
    return p;
  }

 private:
  std::filesystem::path root_;
};

}  // namespace pt::web::testing
