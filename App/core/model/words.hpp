// SPDX-License-Identifier: LGPL-2.1-or-later
// Words and numbers of the text mesh formats (OBJ, OFF), read the same way by both readers.
#pragma once

#include <algorithm>
#include <charconv>
#include <string_view>
#include <system_error>
#include <vector>

namespace sliceform {

// The words of a line, split at blanks, up to a '#' comment.
inline std::vector<std::string_view> wordsOf(std::string_view text) {
  text = text.substr(0, text.find('#'));
  std::vector<std::string_view> words;
  const char* blanks = " \t\r\f\v";
  for (size_t start = text.find_first_not_of(blanks); start != std::string_view::npos;) {
    const size_t end = std::min(text.find_first_of(blanks, start), text.size());
    words.push_back(text.substr(start, end - start));
    start = text.find_first_not_of(blanks, end);
  }
  return words;
}

// The whole word as a number (from_chars: no locale, "nan" and "inf" read as such, so
// validateMesh names them); a leading '+' is allowed.
template <class T>
bool parseNumber(std::string_view word, T& value) {
  if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc() && end == word.data() + word.size();
}

}  // namespace sliceform
