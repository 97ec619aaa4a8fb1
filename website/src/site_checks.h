// The checks that save a submission: every path a page uses is relative, stays inside the
// folder, names an existing file with exactly its capitalisation, has the extension of what the
// file really is, and can be read by everyone. Used by `website build` and `website check`.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pt::web {

/// One thing wrong with a submission, located where a student can fix it.
struct Problem {
  std::filesystem::path file;  ///< the file that holds the bad reference (as the user named it)
  int line = 0;                ///< 1-based line in that file; 0 when the problem is the file itself
  std::string message;
  /// "file:line: message", the form compilers use, so editors can jump to it.
  std::string to_string() const;
};

/// A path that a page uses, found in HTML or CSS text.
struct FoundReference {
  std::string target;     ///< the attribute or url() value as written
  int line = 0;           ///< 1-based line of the text it was found in
  bool embedded = false;  ///< loaded by the page (img, stylesheet, font) rather than followed
};

/// Every src/href attribute and CSS url() of an HTML text, with its line; comments are skipped.
std::vector<FoundReference> find_html_references(const std::string& html);

/// Every url(...) of a stylesheet, with its line.
std::vector<FoundReference> find_css_references(const std::string& css);

/// Checks one reference made from `where` (a file in or, for a Markdown source, beside the
/// folder `root`). `base` is the folder the reference is relative to. Problems are appended to
/// `problems`; the file it resolves to is returned when it exists inside the folder.
std::optional<std::filesystem::path> check_reference(const std::filesystem::path& root,
                                                     const std::filesystem::path& base,
                                                     const FoundReference& ref,
                                                     const std::filesystem::path& where,
                                                     std::vector<Problem>& problems);

/// Why the file's content does not match its extension (a JPEG named .png), or nothing when it
/// does or the extension is not one the check knows.
std::optional<std::string> content_mismatch(const std::filesystem::path& file);

/// Why a file, or a folder on the way to it from `root`, cannot be read by others, or nothing.
std::optional<std::string> permission_problem(const std::filesystem::path& root,
                                              const std::filesystem::path& file);

/// Checks a whole folder: index.html, and every page and stylesheet it reaches. Problems name
/// the file (relative to the folder, prefixed by `root` as given) and the line.
std::vector<Problem> check_folder(const std::filesystem::path& root);

}  // namespace pt::web
