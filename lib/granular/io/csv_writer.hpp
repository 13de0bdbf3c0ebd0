#pragma once
// CSV with one header row; numbers in shortest round-trip form.
#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

#include "granular/number_format.hpp"

namespace granular {

class CsvWriter {
 public:
  CsvWriter(std::ostream& out, std::initializer_list<const char*> columns) : out_(out), columns_(columns.size()) {
    const char* sep = "";
    for (const char* c : columns) {
      out_ << sep << c;
      sep = ",";
    }
    out_ << '\n';
  }
  /// Columns known at run time (optional ones added).
  CsvWriter(std::ostream& out, const std::vector<std::string>& columns) : out_(out), columns_(columns.size()) {
    const char* sep = "";
    for (const auto& c : columns) {
      out_ << sep << c;
      sep = ",";
    }
    out_ << '\n';
  }
  /// One row; cells are strings or doubles. The count must match the header.
  template <class... Cells>
  void row(const Cells&... cells) {
    static_assert(sizeof...(Cells) > 0);
    const char* sep = "";
    ((out_ << sep << cell(cells), sep = ","), ...);
    out_ << '\n';
  }

 private:
  static std::string cell(double v) { return format_number(v); }
  static std::string cell(const std::string& s) { return s; }
  static std::string cell(const char* s) { return s; }
  static std::string cell(std::size_t v) { return std::to_string(v); }
  static std::string cell(int v) { return std::to_string(v); }
  std::ostream& out_;
  std::size_t columns_;
};

}  // namespace granular
