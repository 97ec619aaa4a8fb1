#include "website/src/math_spans.h"

#include <cctype>
#include <cstdio>

namespace pt::web {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

/// Length of the run of character `c` starting at `i`.
size_t run_length(const std::string& s, size_t i, char c) {
  size_t n = 0;
  while (i + n < s.size() && s[i + n] == c) ++n;
  return n;
}

/// Where the inline span opened by the '$' at `open` closes, or npos. It may wrap onto the
/// next line of the paragraph but never crosses a blank line.
size_t inline_close(const std::string& s, size_t open) {
  if (open + 1 >= s.size() || is_space(s[open + 1]) || s[open + 1] == '$') return std::string::npos;
  for (size_t i = open + 1; i < s.size(); ++i) {
    if (s[i] == '\\') {
      ++i;
      continue;
    }
    if (s[i] == '\n' && i + 1 < s.size()) {
      size_t j = i + 1;
      while (j < s.size() && (s[j] == ' ' || s[j] == '\t')) ++j;
      if (j >= s.size() || s[j] == '\n') return std::string::npos;
    }
    if (s[i] == '$') {
      bool after_digit = i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1]));
      if (is_space(s[i - 1]) || after_digit) continue;
      return i;
    }
  }
  return std::string::npos;
}

/// The scanner shared by whole sources and single captions.
class MathScanner {
 public:
  MathScanner(const std::string& src, int first_line, std::vector<MathSpan>& spans)
      : src_(src), line_(first_line), spans_(spans) {
    out_.line_map = {0, first_line};
  }

  ProtectedMarkdown run(bool block_structure) {
    size_t i = 0;
    bool line_start = true;
    while (i < src_.size()) {
      if (block_structure && line_start) {
        size_t fence_end = fenced_block_end(i);
        if (fence_end != i) {
          copy(i, fence_end);
          i = fence_end;
          continue;
        }
      }
      char c = src_[i];
      line_start = false;
      if (c == '\\' && i + 1 < src_.size()) {
        copy(i, i + 2);
        line_start = src_[i + 1] == '\n';
        i += 2;
      } else if (c == '`') {
        size_t n = run_length(src_, i, '`');
        size_t close = src_.find(std::string(n, '`'), i + n);
        while (close != std::string::npos && run_length(src_, close, '`') != n) {
          close = src_.find(std::string(n, '`'), close + run_length(src_, close, '`'));
        }
        size_t end = close == std::string::npos ? i + n : close + n;
        copy(i, end);
        i = end;
      } else if (c == '$' && i + 1 < src_.size() && src_[i + 1] == '$') {
        size_t close = src_.find("$$", i + 2);
        if (close == std::string::npos) {
          copy(i, i + 2);
          i += 2;
        } else {
          take(i, i + 2, close, close + 2, true);
          i = close + 2;
        }
      } else if (c == '$') {
        size_t close = inline_close(src_, i);
        if (close == std::string::npos) {
          copy(i, i + 1);
          ++i;
        } else {
          take(i, i + 1, close, close + 1, false);
          i = close + 1;
        }
      } else {
        copy(i, i + 1);
        line_start = c == '\n';
        ++i;
      }
    }
    return std::move(out_);
  }

 private:
  /// If a fenced code block (``` or ~~~) opens at `i`, where it ends; otherwise `i`.
  size_t fenced_block_end(size_t i) const {
    size_t j = i;
    while (j < src_.size() && j - i < 3 && src_[j] == ' ') ++j;
    if (j >= src_.size() || (src_[j] != '`' && src_[j] != '~')) return i;
    char fence = src_[j];
    size_t n = run_length(src_, j, fence);
    if (n < 3) return i;
    size_t pos = src_.find('\n', j);
    while (pos != std::string::npos) {
      size_t k = pos + 1;
      while (k < src_.size() && k - pos - 1 < 3 && src_[k] == ' ') ++k;
      if (run_length(src_, k, fence) >= n) {
        size_t end = src_.find('\n', k);
        return end == std::string::npos ? src_.size() : end + 1;
      }
      pos = src_.find('\n', pos + 1);
    }
    return src_.size();  // an unclosed fence runs to the end, as in CommonMark
  }

  void copy(size_t from, size_t to) {
    for (size_t k = from; k < to; ++k) {
      out_.text += src_[k];
      if (src_[k] == '\n') {
        ++line_;
        out_.line_map.push_back(line_);
      }
    }
  }

  void take(size_t open, size_t body, size_t close, size_t end, bool display) {
    spans_.push_back({src_.substr(body, close - body), display, line_});
    out_.text += math_token(spans_.size() - 1);
    for (size_t k = open; k < end; ++k) {
      if (src_[k] == '\n') ++line_;
    }
  }

  const std::string& src_;
  int line_;
  std::vector<MathSpan>& spans_;
  ProtectedMarkdown out_;
};

}  // namespace

int ProtectedMarkdown::source_line(int line) const {
  if (line <= 0) return 0;
  if (static_cast<size_t>(line) >= line_map.size()) return line_map.back();
  return line_map[line];
}

std::string math_token(size_t index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "PTMATH%06zuX", index);
  return buf;
}

ProtectedMarkdown protect_math(const std::string& markdown, std::vector<MathSpan>& spans) {
  return MathScanner(markdown, 1, spans).run(true);
}

std::string protect_inline_math(const std::string& text, int line, std::vector<MathSpan>& spans) {
  return MathScanner(text, line, spans).run(false).text;
}

}  // namespace pt::web
