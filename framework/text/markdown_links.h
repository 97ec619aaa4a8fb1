// Not needed for the assignment.
// Markdown link targets, found and rewritten: the handout's README and the handbook's pages both
// move pages to another folder and must keep every relative link working.
#pragma once

#include <functional>
#include <string>

namespace pt {

/// Whether a link target names a file relative to its page: not empty, not an anchor (#...), not
/// rooted (/...), and without a URL scheme (http:, mailto:; a colon after a slash is a path's).
bool is_relative_link(const std::string& target);

/// `markdown` with the target of every inline link `[text](target)` replaced by
/// `rewrite(target)`, except in code spans and fenced code blocks, which are left as they are.
std::string rewrite_markdown_links(const std::string& markdown,
                                   const std::function<std::string(const std::string&)>& rewrite);

}  // namespace pt
