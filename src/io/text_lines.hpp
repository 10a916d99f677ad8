#pragma once
// Text mesh files (OBJ, OFF, PLY headers, ASCII STL) line by line, as words. Internal to the
// mesh reader: the file check and the OBJ reader walk text the same way.
#include <cstddef>
#include <sstream>
#include <string>
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
      std::string content = text_.substr(at_, end - at_);
      at_ = end + 1;
      ++number_;
      if (hash_comments_) content = content.substr(0, content.find('#'));
      if (!continued_) *line = Line{number_, {}};
      continued_ = hash_comments_ && ends_with_backslash(&content);
      std::istringstream in(content);
      for (std::string word; in >> word;) line->words.push_back(word);
      if (!continued_ && !line->words.empty()) return true;
    }
    return false;
  }

  int number() const { return number_; }  // the last line read

 private:
  // OBJ's "\\" at the end of a line continues the record on the next line; removes it.
  static bool ends_with_backslash(std::string* content) {
    const std::size_t last = content->find_last_not_of(" \t\r");
    if (last == std::string::npos || (*content)[last] != '\\') return false;
    content->erase(last);
    return true;
  }

  const std::string& text_;
  std::size_t at_;
  int number_;
  bool hash_comments_;
  bool continued_ = false;
};

}  // namespace fabform
