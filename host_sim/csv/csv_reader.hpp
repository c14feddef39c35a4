// SPDX-License-Identifier: Apache-2.0
// A small reader for the plain-text CSV files of docs/host_sim.md: a header
// row naming the columns, then one record per line, comma-separated, no
// quoting (the files hold numbers). Columns are looked up by name, so their
// order is free and unknown columns are ignored. Any malformed record
// throws CsvError carrying the file name and 1-based line number: a bad row
// stops the run, it is never skipped.
#pragma once

#include <cstddef>
#include <istream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace kestrel::sim {

class CsvError : public std::runtime_error {
 public:
  CsvError(const std::string& source, std::size_t line, const std::string& what);
  /// 1-based line number of the offending line (1 = header).
  std::size_t line() const { return line_; }

 private:
  std::size_t line_;
};

class CsvReader {
 public:
  /// Reads the header at once. @param source a name for messages (the path).
  /// Throws CsvError if the input is empty or the header repeats a column.
  CsvReader(std::istream& in, std::string source);

  /// Index of a required column; throws CsvError (line 1) when absent.
  std::size_t require_column(std::string_view name) const;
  /// Index of an optional column, if present.
  std::optional<std::size_t> find_column(std::string_view name) const;

  /// Advance to the next record, skipping blank lines. false at the end.
  /// Throws CsvError when the record has a different number of fields.
  bool next();
  /// 1-based line number of the current record.
  std::size_t line() const { return line_; }

  /// A finite number in column `col`; throws CsvError naming the column.
  double number(std::size_t col) const;
  /// A finite number, or nullopt for an empty cell.
  std::optional<double> optional_number(std::size_t col) const;
  /// An integer in [lo, hi]; throws CsvError.
  long long integer(std::size_t col, long long lo, long long hi) const;
  /// Raw text of a cell (trimmed).
  std::string_view cell(std::size_t col) const { return fields_[col]; }

  /// A CsvError at the current line.
  [[noreturn]] void fail(const std::string& what) const;
  /// A CsvError at the current line: "column 'NAME': 'TEXT' " + why.
  [[noreturn]] void fail_cell(std::size_t col, const std::string& why) const;

 private:
  static void split(std::string_view line, std::vector<std::string_view>& out);

  std::istream& in_;
  std::string source_;
  std::vector<std::string> header_;
  std::string text_;                      // current line
  std::vector<std::string_view> fields_;  // views into text_
  std::size_t line_ = 0;
};

}  // namespace kestrel::sim
