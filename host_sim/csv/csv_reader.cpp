// SPDX-License-Identifier: Apache-2.0
#include "csv/csv_reader.hpp"

#include <charconv>
#include <cmath>

namespace kestrel::sim {

namespace {
std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}
}  // namespace

CsvError::CsvError(const std::string& source, std::size_t line, const std::string& what)
    : std::runtime_error(source + ":" + std::to_string(line) + ": " + what), line_(line) {}

CsvReader::CsvReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {
  if (!std::getline(in_, text_)) throw CsvError(source_, 1, "empty file: a header row is required");
  line_ = 1;
  // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first name.
  if (text_.rfind("\xEF\xBB\xBF", 0) == 0) text_.erase(0, 3);
  std::vector<std::string_view> names;
  split(text_, names);
  for (const std::string_view n : names) {
    if (find_column(n).has_value()) fail("column '" + std::string(n) + "' appears twice in the header");
    header_.emplace_back(n);
  }
}

std::size_t CsvReader::require_column(std::string_view name) const {
  const auto col = find_column(name);
  if (!col.has_value()) throw CsvError(source_, 1, "missing required column '" + std::string(name) + "'");
  return *col;
}

std::optional<std::size_t> CsvReader::find_column(std::string_view name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return i;
  }
  return std::nullopt;
}

void CsvReader::split(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
}

bool CsvReader::next() {
  while (std::getline(in_, text_)) {
    ++line_;
    if (trim(text_).empty()) continue;
    split(text_, fields_);
    if (fields_.size() != header_.size()) {
      fail("expected " + std::to_string(header_.size()) + " fields as in the header, found " +
           std::to_string(fields_.size()));
    }
    return true;
  }
  return false;
}

std::optional<double> CsvReader::optional_number(std::size_t col) const {
  const std::string_view s = fields_[col];
  if (s.empty()) return std::nullopt;
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range && end == s.data() + s.size()) {
    fail_cell(col, "is outside the range of a double");
  }
  if (ec != std::errc() || end != s.data() + s.size()) {
    fail("column '" + header_[col] + "': '" + std::string(s) + "' is not a number");
  }
  if (!std::isfinite(v)) fail("column '" + header_[col] + "': '" + std::string(s) + "' is not finite");
  return v;
}

double CsvReader::number(std::size_t col) const {
  const auto v = optional_number(col);
  if (!v.has_value()) fail("column '" + header_[col] + "' is empty");
  return *v;
}

long long CsvReader::integer(std::size_t col, long long lo, long long hi) const {
  const std::string_view s = fields_[col];
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi) {
    fail("column '" + header_[col] + "': '" + std::string(s) + "' is not an integer in [" + std::to_string(lo) +
         ", " + std::to_string(hi) + "]");
  }
  return v;
}

void CsvReader::fail(const std::string& what) const { throw CsvError(source_, line_, what); }

void CsvReader::fail_cell(std::size_t col, const std::string& why) const {
  fail("column '" + header_[col] + "': '" + std::string(fields_[col]) + "' " + why);
}

}  // namespace kestrel::sim
