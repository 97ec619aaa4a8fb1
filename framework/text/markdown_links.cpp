// Not needed for the assignment: the definitions of framework/text/markdown_links.h.
#include "framework/text/markdown_links.h"

namespace pt {

bool is_relative_link(const std::string& target) {
  if (target.empty() || target[0] == '#' || target[0] == '/') return false;
  const size_t colon = target.find(':'), slash = target.find('/');
  return colon == std::string::npos || (slash != std::string::npos && slash < colon);
}

std::string rewrite_markdown_links(const std::string& markdown,
                                   const std::function<std::string(const std::string&)>& rewrite) {
  std::string out;
  bool fenced = false;
  for (size_t pos = 0; pos < markdown.size();) {
    size_t end = markdown.find('\n', pos);
    if (end == std::string::npos) end = markdown.size();
    const std::string line = markdown.substr(pos, end - pos);
    const size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) fenced = !fenced;
    if (fenced) {
      out += line;
    } else {
      bool code = false;
      for (size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '`') code = !code;
        if (!code && line[i] == ']' && i + 1 < line.size() && line[i + 1] == '(') {
          const size_t close = line.find(')', i + 2);
          if (close != std::string::npos) {
            out += "](" + rewrite(line.substr(i + 2, close - i - 2)) + ")";
            i = close;
            continue;
          }
        }
        out += line[i];
      }
    }
    if (end < markdown.size()) out += '\n';
    pos = end + 1;
  }
  return out;
}

}  // namespace pt
