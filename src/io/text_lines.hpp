#pragma once
// Text mesh files (OBJ, OFF, PLY headers, ASCII STL) line by line, as words. Internal to the
// mesh reader: the file check and the OBJ reader walk text the same way.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fabform {

// Text lines, numbered from 1, as words. Only LF ends a line (CR is white space), as in assimp.

struct Line {
  int number = 0;
  std::vector<std::string> words;
};

// Walks the non-blank lines of text from a byte offset, one at a time, so that a large file's
// lines are never all held at once.
class TextLines {
 public:
  TextLines(const std::string& text, std::size_t from, int first_number, bool hash_comments)
      : text_(text), at_(from), number_(first_number - 1), hash_comments_(hash_comments) {}

  bool next(Line* line) {
    while (at_ < text_.size()) {
      std::size_t end = text_.find('\n', at_);
      if (end == std::string::npos) end = text_.size();
      std::string_view content(text_.data() + at_, end - at_);
      at_ = end + 1;
      ++number_;
      if (hash_comments_) content = content.substr(0, content.find('#'));
      if (!continued_) {
        line->number = number_;
        line->words.clear();
      }
      continued_ = hash_comments_ && ends_with_backslash(&content);
      add_words(content, &line->words);
      if (!continued_ && !line->words.empty()) return true;
    }
    return false;
  }

  int number() const { return number_; }  // the last line read

 private:
  // OBJ's "\\" at the end of a line continues the record on the next line; removes it.
  static bool ends_with_backslash(std::string_view* content) {
    const std::size_t last = content->find_last_not_of(" \t\r");
    if (last == std::string_view::npos || (*content)[last] != '\\') return false;
    *content = content->substr(0, last);
    return true;
  }

  // The words of a line as `>>` reads them in the C locale, without a stream per line (which
  // cost more than the rest of reading a large mesh).
  static void add_words(std::string_view content, std::vector<std::string>* words) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n'; };
    std::size_t at = 0;
    while (true) {
      while (at < content.size() && space(content[at])) ++at;
      if (at == content.size()) return;
      std::size_t end = at;
      while (end < content.size() && !space(content[end])) ++end;
      words->emplace_back(content.substr(at, end - at));
      at = end;
    }
  }

  const std::string& text_;
  std::size_t at_;
  int number_;
  bool hash_comments_;
  bool continued_ = false;
};

}  // namespace fabform
