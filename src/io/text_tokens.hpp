// Words and numbers of the text mesh formats (OFF, OBJ, PLY's header and text data): lines split
// into views of themselves, numbers parsed by std::from_chars (exact, locale-free, and several
// times faster than stream extraction on large files).
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cvtmesh {

// The words of `text`, separated by blanks (space, tab, CR, VT, FF), as views of it.
inline void split_words(std::string_view text, std::vector<std::string_view>& words) {
  constexpr std::string_view kBlanks = " \t\r\v\f";
  words.clear();
  for (std::size_t at = text.find_first_not_of(kBlanks); at != std::string_view::npos;) {
    const std::size_t end = std::min(text.find_first_of(kBlanks, at), text.size());
    words.push_back(text.substr(at, end - at));
    at = text.find_first_not_of(kBlanks, end);
  }
}

// The whole of `token` as a double, or none. A leading '+' is taken (from_chars refuses it);
// "inf" and "nan" are numbers here, left for the readers' check of finite coordinates, and so is
// a magnitude past the double range, read as infinite.
inline std::optional<double> text_double(std::string_view token) {
  if (token.starts_with('+')) token.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec == std::errc::result_out_of_range) return std::strtod(std::string(token).c_str(), nullptr);
  if (ec != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

// The whole of `token` as a count (an integer without sign), or none.
inline std::optional<std::uint64_t> text_count(std::string_view token) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

// The whole of `token` as an integer, or none.
inline std::optional<long long> text_integer(std::string_view token) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

}  // namespace cvtmesh
