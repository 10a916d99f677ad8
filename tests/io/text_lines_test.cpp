// TextLines (text_lines.hpp) against the way it used to read words, a string stream per line:
// random texts of words, every kind of white space, comments, OBJ's continued lines and blank
// lines give the same lines, numbers and words.
#include "io/text_lines.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fabform::text_lines_test {
namespace {

// The reference: `>>` on each line's text, '#' comments and "\" continuations as OBJ has them.
std::vector<Line> reference_lines(const std::string& text, bool hash_comments) {
  std::vector<Line> lines;
  std::vector<std::string> lines_of_text;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    lines_of_text.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  Line pending;
  bool continued = false;
  for (std::size_t k = 0; k < lines_of_text.size(); ++k) {
    std::string content = lines_of_text[k];
    if (hash_comments) content = content.substr(0, content.find('#'));
    if (!continued) pending = Line{static_cast<int>(k) + 1, {}};
    const std::size_t last = content.find_last_not_of(" \t\r");
    continued = hash_comments && last != std::string::npos && content[last] == '\\';
    if (continued) content.erase(last);
    std::istringstream in(content);
    for (std::string word; in >> word;) pending.words.push_back(word);
    if (!continued && !pending.words.empty()) lines.push_back(pending);
  }
  return lines;
}

std::string random_text(std::mt19937& rng) {
  const std::vector<std::string> pieces = {"v", "f", "1.5e-3", "-2", "7/8/9", "#", " ", "  ", "\t", "\r",
                                           "\v", "\f", "\n", "\n", "\n", "\\", "é", "vt", "0x1p3"};
  std::uniform_int_distribution<std::size_t> any(0, pieces.size() - 1);
  std::uniform_int_distribution<int> length(0, 120);
  std::string text;
  for (int k = length(rng); k > 0; --k) text += pieces[any(rng)];
  return text;
}

TEST(TextLines, ReadsTheWordsAStringStreamReads) {
  std::mt19937 rng(2026);
  for (int trial = 0; trial < 3000; ++trial) {
    const std::string text = random_text(rng);
    for (const bool hash_comments : {false, true}) {
      const std::vector<Line> want = reference_lines(text, hash_comments);
      std::vector<Line> got;
      Line line;
      for (TextLines lines(text, 0, 1, hash_comments); lines.next(&line);) got.push_back(line);
      ASSERT_EQ(got.size(), want.size()) << "text " << testing::PrintToString(text);
      for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_EQ(got[k].number, want[k].number) << testing::PrintToString(text);
        EXPECT_EQ(got[k].words, want[k].words) << testing::PrintToString(text);
      }
    }
  }
}

TEST(TextLines, StartsAtAnOffsetWithTheLineNumberGiven) {
  const std::string text = "skipped line\nv 1 2 3\n\n  f 1 2 3  \n";
  TextLines lines(text, text.find('v'), 10, true);
  Line line;
  ASSERT_TRUE(lines.next(&line));
  EXPECT_EQ(line.number, 10);
  EXPECT_EQ(line.words, (std::vector<std::string>{"v", "1", "2", "3"}));
  ASSERT_TRUE(lines.next(&line));
  EXPECT_EQ(line.number, 12);
  EXPECT_EQ(line.words, (std::vector<std::string>{"f", "1", "2", "3"}));
  EXPECT_FALSE(lines.next(&line));
}

}  // namespace
}  // namespace fabform::text_lines_test
