// The pathtracer command line: the course renderer's flags, parsed and checked into RenderSettings.
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <string>

#include "app/camera_view.h"
#include "framework/render/render_settings.h"

namespace pt {

/// Exit codes of the pathtracer: a command line that asks for something impossible is a usage
/// error; a scene or image file that cannot be read or written is an input/output error.
enum ExitCode { kExitOk = 0, kExitIoError = 1, kExitUsage = 2 };

/// What the command line asks for, beyond the render settings themselves.
struct CommandLine {
  RenderSettings settings;
  std::string scene_path;
  std::string output_path;       ///< -f; empty: <scene stem>.png in the current folder
  bool resolution_given = false; ///< -r given; else the width is 480 and the height the scene's aspect
  bool info = false;             ///< --info: describe the scene, render nothing
  bool file_camera = false;      ///< --file-camera: do not centre the camera on the scene
  bool course_view = false;      ///< --course-view: frame the scene as the course's renderer does at -r
  std::string camera_settings_path;  ///< -c: the course renderer's saved view; empty: the file's camera
  bool lens_given = false;           ///< -b given (it wins over a -c file's lens)
  bool focal_distance_given = false; ///< -d given (it wins over a -c file's focal distance)
  bool camera_given = false;     ///< --camera: place the camera at `camera` instead of the file's
  CameraView camera;
};

/// A command line that cannot be honoured; what() names the flag and what is wrong.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses argv. Returns -1 when the render should go on, otherwise the exit code (0 after
/// --help, which is printed to `out`; kExitUsage after an error, whose message goes to `err`).
int parse_command_line(int argc, char** argv, CommandLine* command, std::ostream& out,
                       std::ostream& err);

/// The image size when -r is absent: 480 wide, the height following the scene camera's aspect.
void apply_default_resolution(float camera_aspect, RenderSettings* settings);

/// Checks what can only be checked once the image size is known (the -p cell). Throws UsageError.
void check_cell(const RenderSettings& settings);

/// Checks that `path` can be written as an image before minutes go into rendering it: a known
/// extension (UsageError) and an existing, writable folder (std::runtime_error).
void check_output_path(const std::string& path);

}  // namespace pt
